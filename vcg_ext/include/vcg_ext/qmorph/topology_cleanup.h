// Topological clean-up of a patch's quads after Q-Morph: edge turns, diagonal collapses and quad
// opens, each applied only when it brings the valences of the nodes involved closer to their ideal
// (4 inside; on the patch boundary, one more than the number of right angles that fit in the
// node's angle), the quads around stay fair, and the surface is not flattened.
#ifndef VCG_EXT_QMORPH_TOPOLOGY_CLEANUP_H
#define VCG_EXT_QMORPH_TOPOLOGY_CLEANUP_H

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <vcg_ext/qmorph/patch_stage.h>

namespace vcg_ext {
namespace qmorph {

class TopologyCleanup : public PatchStage
{
public:
    explicit TopologyCleanup(PatchContext &context) : PatchStage(context) {}

    // One round: turns, collapses, opens (and the doublets they leave), turns again.
    template <class DissolveDoublets>
    void Round(DissolveDoublets dissolveDoublets)
    {
        ImproveValences();
        CollapseQuadDiagonals();
        OpenQuads();
        dissolveDoublets();
        ImproveValences();
    }

private:
    // Passes of each operation (each pass stops early when it changes nothing).
    static constexpr int kTurnPasses = 4, kCollapsePasses = 3, kOpenPasses = 2;
    // A diagonal collapse leaves the faces around at least this good.
    static constexpr double kMinCollapseQuality = 0.05;
    // Quad open: nodes of valence 5..8 only, when the squared valence deviation drops by more than
    // the gain; the two halves straddle the line between the opened neighbours at a foot kept inside
    // [min, max] of it, the new rhombus as wide as this fraction of that line.
    static constexpr int kOpenMinValence = 5, kOpenMaxValence = 8;
    static constexpr double kOpenMinGain = 0.5, kOpenFootMin = 0.25, kOpenFootMax = 0.75, kOpenHalfWidth = 0.3;

    // Edge turn: an edge shared by two quads is turned to join the other pair of opposite corners
    // of their hexagon when that brings the four nodes' valences closer to their ideal and the two
    // new quads are not worse than 0.3 scaled Jacobian (or than the old ones).
    void ImproveValences()
    {
        const std::vector<int> ideal = IdealValences();
        auto dev = [&](int v, int val) { return ValenceDeviation(ideal, v, val); };
        for (int pass = 0; pass < kTurnPasses; ++pass) {
            int turned = 0;
            for (int h = 0; h < m.HalfEdgeCount(); ++h) {
                int t = m.heTwin[h];
                if (t < h || !m.HeAlive(h) || !m.IsQuad(m.heFace[h]) || !m.IsQuad(m.heFace[t])) continue;
                // hexagon b c d a e f (quads (a b c d) and (b a e f) share a-b)
                std::vector<int> loop{m.heNext[h], m.heNext[m.heNext[h]], m.hePrev[h], m.heNext[t], m.heNext[m.heNext[t]], m.hePrev[t]};
                int v[6];
                for (int k = 0; k < 6; ++k) v[k] = m.Org(loop[k]);
                bool distinct = true;
                for (int i = 0; i < 6; ++i)
                    for (int j = i + 1; j < 6; ++j) distinct = distinct && m.vertKey[v[i]] != m.vertKey[v[j]];
                if (!distinct) continue;
                int val[6];
                for (int k = 0; k < 6; ++k) val[k] = m.Valence(v[k]);
                const int a = 3, b = 0;  // positions of the current diagonal's ends
                // the shapes (closest-point queries each) are measured only for a turn that gains
                auto oldQuality = [&]() {
                    return std::min(FaceQualityAt(m.heFace[h], m.InputFaceNormal(m.heFace[h])),
                                    FaceQualityAt(m.heFace[t], m.InputFaceNormal(m.heFace[t])));
                };
                double oldDev = dev(v[a], val[a]) + dev(v[b], val[b]);
                int bestI = -1;
                double bestGain = 1e-9;
                for (int i : {1, 2}) {  // new diagonal between positions i and i+3
                    int j = i + 3;
                    if (m.EdgeExists(v[i], v[j]) || m.NewChordBetweenFrontNodes(v[i], v[j])) continue;
                    double before = oldDev + dev(v[i], val[i]) + dev(v[j], val[j]);
                    double after = dev(v[a], val[a] - 1) + dev(v[b], val[b] - 1) + dev(v[i], val[i] + 1) + dev(v[j], val[j] + 1);
                    if (!(before - after > bestGain)) continue;
                    double q = std::min(QuadShape(v[i], v[i + 1], v[i + 2], v[j]), QuadShape(v[j], v[(j + 1) % 6], v[(j + 2) % 6], v[i]));
                    if (q <= 0 || (q < kFairQuad && q < oldQuality())) continue;  // never invalid, even where it was
                    bestGain = before - after;
                    bestI = i;
                }
                if (bestI < 0) continue;
                const int i = bestI, j = i + 3;
                std::vector<int> corners1{v[i], v[i + 1], v[i + 2], v[j]}, corners2{v[j], v[(j + 1) % 6], v[(j + 2) % 6], v[i]};
                if (!m.QuadHasFreeDiagonal(corners1[0], corners1[1], corners1[2], corners1[3], {m.heFace[h], m.heFace[t]}) ||
                    !m.QuadHasFreeDiagonal(corners2[0], corners2[1], corners2[2], corners2[3], {m.heFace[h], m.heFace[t]}))
                    continue;
                int level = std::max(m.faceLevel[m.heFace[h]], m.faceLevel[m.heFace[t]]);
                m.ReplaceRegion(loop, {m.heFace[h], m.heFace[t]}, {}, {{i, i + 1, i + 2, j}, {j, (j + 1) % 6, (j + 2) % 6, i}}, level);
                ++turned;
            }
            stats.valenceTurns += turned;
            if (!turned) break;
        }
    }

    // Quad clean-up by diagonal collapse: the quad (a b c d) vanishes and c joins a at their
    // midpoint (a and c inside the patch) when that brings the valences of a, b, c, d closer to
    // their ideal: typically a and c of valence 3 with b or d of valence 5. The quads around must
    // stay fair (not below 0.3 scaled Jacobian or below the worst of them now).
    void CollapseQuadDiagonals()
    {
        const std::vector<int> ideal = IdealValences();
        auto dev = [&](int v, int val) { return ValenceDeviation(ideal, v, val); };
        for (int pass = 0; pass < kCollapsePasses; ++pass) {
            int collapsed = 0;
            for (int f = 0; f < m.FaceCount(); ++f) {
                if (!m.FaceAlive(f) || !m.IsQuad(f)) continue;
                std::vector<int> loop{m.faceHe[f], m.heNext[m.faceHe[f]], m.heNext[m.heNext[m.faceHe[f]]], m.hePrev[m.faceHe[f]]};
                for (int i = 0; i < 2; ++i) {
                    const int a = m.Org(loop[i]), b = m.Org(loop[i + 1]), c = m.Org(loop[i + 2]), d = m.Org(loop[(i + 3) % 4]);
                    if (m.vertFixed[a] || m.vertFixed[c] || !m.DistinctNodes({a, b, c, d})) continue;
                    const int va = m.Valence(a), vb = m.Valence(b), vc = m.Valence(c), vd = m.Valence(d);
                    const double before = dev(a, va) + dev(b, vb) + dev(c, vc) + dev(d, vd);
                    const double after = dev(a, va + vc - 2) + dev(b, vb - 1) + dev(d, vd - 1);
                    if (after >= before || vb <= 3 || vd <= 3) continue;
                    if (CollapseQuad(f, i)) { ++collapsed; break; }
                }
            }
            stats.diagonalCollapses += collapsed;
            if (!collapsed) break;
        }
    }

    // Collapses quad f along its diagonal from corner i to corner i+2 (the second joins the first).
    bool CollapseQuad(int f, int i)
    {
        std::vector<int> loop{m.faceHe[f], m.heNext[m.faceHe[f]], m.heNext[m.heNext[m.faceHe[f]]], m.hePrev[m.faceHe[f]]};
        const int a = m.Org(loop[i]), c = m.Org(loop[i + 2]);
        int hm = home[a];
        const P3 at = proj.Project((m.pos[a] + m.pos[c]) * 0.5, hm);
        // the faces around a and c but f, with a and c at `at`
        const std::vector<int> faces = m.FacesAround({a, c}, {f});
        const double after = WorstQualityIfMoved({a, c}, at, faces);
        // the surface must not flatten: the old nodes stay near the new faces (as in quad formation)
        const P3 oldA = m.pos[a], oldC = m.pos[c];
        m.pos[a] = m.pos[c] = at;
        double farthest = 0;
        for (const P3 &old : {oldA, oldC}) {
            double nearest = 1e300;
            for (int h : faces) {
                const int g = m.faceHe[h];
                const int v0 = m.Org(g), v1 = m.Dst(g), v2 = m.Dst(m.heNext[g]);
                nearest = std::min(nearest, PointTriangleDistance(old, m.pos[v0], m.pos[v1], m.pos[v2]));
                if (m.IsQuad(h)) nearest = std::min(nearest, PointTriangleDistance(old, m.pos[v0], m.pos[v2], m.pos[m.Org(m.hePrev[g])]));
            }
            farthest = std::max(farthest, nearest);
        }
        m.pos[a] = oldA;
        m.pos[c] = oldC;
        // the quality now matters only when the collapse leaves a face below kFairQuad
        if (after <= kMinCollapseQuality || farthest > kFlattening * meanLength || (after < kFairQuad && after < WorstQuality(faces)))
            return false;
        const int level = m.faceLevel[f];
        m.ReplaceRegion(loop, {f}, {}, {{i, i + 1, i + 2}, {i, i + 2, (i + 3) % 4}}, level);
        const int diagonal = m.FindHalfEdge(a, c);
        if (diagonal >= 0 && m.CollapseEdge(diagonal, at)) {
            home[a] = hm;
            return true;
        }
        if (diagonal >= 0) m.MergeTriangles(diagonal, level);  // undo the split
        return false;
    }

    // Quad open, the inverse of a diagonal collapse: an interior node whose neighbours a and b,
    // `span` edges apart around it, are short of edges (typically valence 5 with two valence-3
    // neighbours two edges apart) is split in two with a new quad between a and b: valences
    // 5, 3, 3 become 3, 4, 4, 4. Each half moves a third of the way toward its own neighbours and
    // back onto the surface; every quad around must stay fair.
    void OpenQuads()
    {
        const std::vector<int> ideal = IdealValences();
        auto dev = [&](int v, int val) { return ValenceDeviation(ideal, v, val); };
        auto devInside = [](int val) { return ValenceDeviation({}, 0, val); };
        for (int pass = 0; pass < kOpenPasses; ++pass) {
            int opened = 0;
            const int count = m.VertexCount();
            for (int v = 0; v < count && m.VertexCount() < vertexCap; ++v) {
                if (!m.vertAlive[v] || m.vertFixed[v] || m.OnBoundary(v)) continue;
                std::vector<int> out;
                bool allQuads = true;
                m.ForEachOutgoing(v, [&](int g) {
                    out.push_back(g);
                    allQuads = allQuads && m.IsQuad(m.heFace[g]);
                });
                const int n = int(out.size());
                if (!allQuads || n < kOpenMinValence || n > kOpenMaxValence) continue;
                double bestGain = kOpenMinGain;
                int bestI = -1, bestSpan = 0;
                for (int i = 0; i < n; ++i)
                    for (int span = 2; span <= n - 2; ++span) {
                        const int a = m.Dst(out[i]), b = m.Dst(out[(i + span) % n]);
                        if (!m.DistinctNodes({v, a, b})) continue;
                        const int va = m.Valence(a), vb = m.Valence(b);
                        const double before = devInside(n) + dev(a, va) + dev(b, vb);
                        const double after = devInside(span + 1) + devInside(n - span + 1) + dev(a, va + 1) + dev(b, vb + 1);
                        if (before - after > bestGain) { bestGain = before - after; bestI = i; bestSpan = span; }
                    }
                if (bestI >= 0 && OpenQuadAt(v, out, bestI, (bestI + bestSpan) % n)) ++opened;
            }
            stats.quadsOpened += opened;
            if (!opened) break;
        }
    }

    bool OpenQuadAt(int v, const std::vector<int> &out, int i, int j)
    {
        const int n = int(out.size());
        // the two halves sit on either side of the line a-b, around v's foot on it: the new quad
        // (a v b v') is then a rhombus with diagonals a-b and v-v'
        const int a = m.Dst(out[i]), b = m.Dst(out[j]);
        const P3 normal = m.InputNormal(v), ab = m.pos[b] - m.pos[a];
        const double t = std::max(kOpenFootMin, std::min(kOpenFootMax, ((m.pos[v] - m.pos[a]) * ab) / ab.SquaredNorm()));
        const P3 centre = (m.pos[v] + (m.pos[a] + ab * t)) * 0.5;
        P3 side = normal ^ ab;
        P3 own(0, 0, 0);  // v's own neighbours (strictly between a and b) tell which side is its
        for (int k = (i + 1) % n; k != j; k = (k + 1) % n) own += m.pos[m.Dst(out[k])] - centre;
        if (!(side.Norm() > 0)) return false;
        side.Normalize();
        if (side * own < 0) side = -side;
        const double half = kOpenHalfWidth * ab.Norm();
        int home1 = home[v], home2 = home[v];
        const P3 p1 = proj.Project(centre + side * half, home1), p2 = proj.Project(centre - side * half, home2);
        // every quad around (v replaced by its half's position) and the new quad must be fair
        auto fair = [&](int k, const P3 &at) {
            const int g = out[k];
            const P3 n0 = m.InputFaceNormal(m.heFace[g], true);
            const std::array<P3, 4> q{at, m.pos[m.Dst(g)], m.pos[m.Dst(m.heNext[g])], m.pos[m.Org(m.hePrev[g])]};
            const double before = QuadShape({m.pos[v], q[1], q[2], q[3]}, n0);
            const double after = QuadShape(q, n0);
            return after > 0 && after >= std::min(kFairQuad, before);
        };
        for (int k = i; k != j; k = (k + 1) % n)
            if (!fair(k, p1)) return false;
        for (int k = j; k != i; k = (k + 1) % n)
            if (!fair(k, p2)) return false;
        if (QuadShape({m.pos[a], p1, m.pos[b], p2}, normal) < kFairQuad) return false;
        // the surface must not flatten: v's old place stays near the new quad (as in quad formation)
        if (std::min(PointTriangleDistance(m.pos[v], m.pos[a], p1, m.pos[b]), PointTriangleDistance(m.pos[v], m.pos[a], m.pos[b], p2)) >
            kFlattening * meanLength)
            return false;
        const int w = m.OpenQuad(v, i, j, p1, p2, m.faceLevel[m.heFace[out[i]]]);
        home.resize(m.VertexCount(), 0);
        home[v] = home1;
        home[w] = home2;
        for (int it = 0; it < 2; ++it)
            for (int x : {v, w}) SmoothNode(x);
        return true;
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
