// Node placement on a patch after Q-Morph: tangent-plane smoothing sweeps (projected back onto the
// input surface, no face folded or made worse) and a pattern search that re-places the free nodes
// of the quads still below 0.3 scaled Jacobian.
#ifndef VCG_EXT_QMORPH_NODE_PLACEMENT_H
#define VCG_EXT_QMORPH_NODE_PLACEMENT_H

#include <algorithm>
#include <cmath>
#include <vector>

#include <vcg_ext/qmorph/patch_stage.h>

namespace vcg_ext {
namespace qmorph {

class NodePlacement : public PatchStage
{
public:
    explicit NodePlacement(PatchContext &context) : PatchStage(context) {}

    // ---- smoothing ------------------------------------------------------------------------------
    // keepToSurface: a move is undone when it takes one of the node's edges farther from the input
    // surface than it was (and than a twentieth of the mean input edge).
    void SmoothAll(bool keepToSurface = false)
    {
        for (int v = 0; v < m.VertexCount(); ++v)
            if (m.vertAlive[v] && !m.vertFixed[v]) {
                if (!keepToSurface) { SmoothNode(v); continue; }
                const P3 old = m.pos[v];
                const double before = EdgeDeviation(v);
                SmoothNode(v);
                if (EdgeDeviation(v) > std::max(before, kChordTolerance * meanLength)) m.pos[v] = old;  // an edge would cut a bend
            }
    }

    // Quads still below 0.3 scaled Jacobian and triangles turned over on the surface (or nearly):
    // each free node of theirs moves (in its tangent plane, back onto the input surface) to the
    // nearby position that most raises the worst quality of its faces. A local pattern search;
    // only moves that raise that worst quality are kept.
    void ImproveBadFaces()
    {
        for (int pass = 0; pass < kRescuePasses; ++pass) {
            int moved = 0;
            for (int f = 0; f < m.FaceCount(); ++f) {
                if (!m.FaceAlive(f)) continue;
                const double q = FaceQualityAt(f, m.InputFaceNormal(f, true));
                if (q >= (m.IsQuad(f) ? kFairQuad : kPoorTriangle)) continue;
                int g = m.faceHe[f];
                for (int k = 0; k < m.faceSize[f]; ++k, g = m.heNext[g])
                    if (!m.vertFixed[m.Org(g)]) moved += OptimizeNode(m.Org(g));
            }
            if (!moved) break;
        }
    }

private:
    // Smoothing and the search never take a node's edges or faces farther from the input surface
    // than this times the mean input edge (or than they were).
    static constexpr double kChordTolerance = 0.05;
    static constexpr int kRescuePasses = 4;
    // Triangles below this quality (1 equilateral, <= 0 turned over) have their nodes re-placed.
    static constexpr double kPoorTriangle = 0.05;
    // Pattern search: steps (fractions of the mean edge at the node) in this many directions; a
    // move is kept when it raises the worst face quality by at least kMinGain.
    static constexpr double kSearchSteps[3] = {0.3, 0.15, 0.07};
    static constexpr int kSearchDirections = 8;
    static constexpr double kMinGain = 0.01;

    // How far the midpoints of v's edges are from the input surface.
    double EdgeDeviation(int v) const
    {
        double d = 0;
        m.ForEachOutgoing(v, [&](int g) {
            const P3 mid = (m.pos[v] + m.pos[m.Dst(g)]) * 0.5;
            int hm = home[v];
            d = std::max(d, (proj.Project(mid, hm) - mid).Norm());
        });
        return d;
    }

    bool OptimizeNode(int v)
    {
        std::vector<int> faces;
        double length = 0;
        int edges = 0;
        m.ForEachOutgoing(v, [&](int g) {
            faces.push_back(m.heFace[g]);
            length += m.Length(g);
            ++edges;
        });
        if (!edges) return false;
        length /= edges;
        auto worst = [&]() {
            double w = 1e9;
            for (int f : faces) w = std::min(w, FaceQualityAt(f, m.InputFaceNormal(f, true)));
            return w;
        };
        // how far the faces' centres are from the input surface: a move must not cut a feature
        auto deviation = [&]() {
            double d = 0;
            for (int f : faces) {
                P3 c(0, 0, 0);
                int g = m.faceHe[f];
                for (int k = 0; k < m.faceSize[f]; ++k, g = m.heNext[g]) c += m.pos[m.Org(g)];
                c /= m.faceSize[f];
                int hm = home[v];
                d = std::max(d, (proj.Project(c, hm) - c).Norm());
            }
            return d;
        };
        const P3 start = m.pos[v];
        const double current = worst();
        const double allowed = std::max(deviation(), kChordTolerance * meanLength);
        const P3 n = m.InputNormal(v);
        P3 t1 = std::fabs(n[0]) < 0.9 ? P3(1, 0, 0) : P3(0, 1, 0);
        t1 = (t1 - n * (t1 * n)).Normalize();
        const P3 t2 = n ^ t1;
        double best = current;
        P3 bestPos = start;
        int bestHome = home[v];
        for (double step : kSearchSteps) {
            const P3 centre = bestPos;
            for (int k = 0; k < kSearchDirections; ++k) {
                const double angle = k * (2 * M_PI / kSearchDirections);
                int hm = bestHome;
                const P3 candidate = proj.Project(centre + (t1 * std::cos(angle) + t2 * std::sin(angle)) * (step * length), hm);
                m.pos[v] = candidate;
                const double q = worst();
                if (q > best + 1e-6 && deviation() <= allowed) { best = q; bestPos = candidate; bestHome = hm; }
            }
        }
        if (best < current + kMinGain) {
            m.pos[v] = start;
            return false;
        }
        m.pos[v] = bestPos;
        home[v] = bestHome;
        return true;
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
