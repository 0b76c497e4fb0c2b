// The output's final shape pass, after the write-back (and before and after the all-quads split):
// a local optimisation that raises the worst elements (the "shape" step of ALGORITHMS.md section
// 6, in the spirit of optimisation-based smoothing, Canann et al. 1998, and the untangling passes
// of Gmsh's quasi-structured pipeline). Each free corner of a poor element is tried at a few places, each
// projected onto the input surface: its neighbours' centroid, the average of the places that make
// each quad around it a parallelogram, half-way to either, and short steps toward and away from
// each neighbour (a pattern search). The best place is kept only when it raises the worst quality
// around the corner, leaves no element that was fair below kFair and turns no face away from the
// input. Corners on the front, on a border or on a sharp crease of the input never move;
// connectivity never changes. Measured on the 14 shared meshes with All quads: quads below 0.3
// 10-50% fewer; the rest sit where three corners are fixed or the parent face was poor.
//
// Quality of an element against the input surface's normal n under its centroid: for a quad its
// scaled Jacobian (-1 when folded), for a triangle the least over its corners of
// ((e1 x e2) . n) / (|e1| |e2|) over sin 60 degrees (1 equilateral). Flipped is negative.
#ifndef VCG_EXT_QMORPH_WORST_ELEMENT_SMOOTHING_H
#define VCG_EXT_QMORPH_WORST_ELEMENT_SMOOTHING_H

#include <algorithm>
#include <cmath>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/input_surface.h>
#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/qmorph/output_polygons.h>

namespace vcg_ext {
namespace qmorph {

template <class MeshType>
class WorstElementSmoothing
{
public:
    typedef typename MeshType::CoordType CoordType;
    typedef vcg::Point3d P3;

    struct Stats {
        int poorBefore = 0, poorAfter = 0;  // elements below kPoor before and after
        int moves = 0;                      // corner moves kept
    };

    // m in MeshLab's polygonal form (faux-edge quads), with face-face adjacency; front edges are
    // its selected face-edges. Moves vertices only.
    static Stats Do(MeshType &m, InputSurface<MeshType> &surface, double creaseAngleDeg)
    {
        const OutputPolygons pg = OutputPolygons::Gather(m);
        auto position = [&](int v) { return P3::Construct(m.vert[v].cP()); };
        auto normalUnder = [&](int face) { return pg.NormalUnder(face, position, surface); };
        auto facesInput = [&](int face) { return pg.FacesInput(face, position, surface); };
        std::vector<signed char> free(m.vert.size(), -1);  // -1: not known yet
        auto isFree = [&](int v) {
            if (free[v] < 0) free[v] = !pg.NeverMoves(v, position(v), surface, creaseAngleDeg);
            return free[v] == 1;
        };
        std::vector<double> quality(pg.FaceCount());  // kept up to date as corners move
        for (int face = 0; face < pg.FaceCount(); ++face) quality[face] = Quality(pg, face, position, normalUnder(face));
        Stats st;
        st.poorBefore = int(std::count_if(quality.begin(), quality.end(), [](double q) { return q < kPoor; }));
        std::vector<double> after;
        std::vector<P3> normals;
        std::vector<char> facedBefore;
        for (int round = 0; round < kRounds; ++round) {
            std::vector<int> corners;  // free corners of the elements below kRaiseBelow, by index
            for (int face = 0; face < pg.FaceCount(); ++face)
                if (quality[face] < kRaiseBelow)
                    for (int k = 0; k < pg.size[face]; ++k) corners.push_back(pg.corners[face][k]);
            std::sort(corners.begin(), corners.end());
            corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
            int moved = 0;
            for (int v : corners) {
                const std::vector<int> &star = pg.facesOf[v];
                double worstBefore = 1;
                for (int g : star) worstBefore = std::min(worstBefore, quality[g]);
                if (worstBefore >= kRaiseBelow || !isFree(v)) continue;  // a neighbour's move may have raised it
                // candidates ranked with the input's normals under the faces as they are (a short
                // move rarely changes them), the best one then checked exactly
                normals.clear();
                for (int g : star) normals.push_back(normalUnder(g));
                const CoordType old = m.vert[v].cP();
                CoordType best = old;
                double bestWorst = worstBefore + kMinGain;
                for (const P3 &target : Targets(pg, v, position)) {
                    CoordType onSurface(0, 0, 0);  // set by Closest when it finds a triangle
                    if (!surface.Closest(CoordType::Construct(target), onSurface, (target - position(v)).Norm())) continue;
                    m.vert[v].P() = onSurface;
                    double worst = 1;
                    bool fair = true;
                    for (size_t i = 0; i < star.size() && fair; ++i) {
                        const double q = Quality(pg, star[i], position, normals[i]);
                        fair = q >= std::min(quality[star[i]], kFair);
                        worst = std::min(worst, q);
                    }
                    if (fair && worst > bestWorst) {
                        best = onSurface;
                        bestWorst = worst;
                    }
                    m.vert[v].P() = old;
                }
                if (best == old) continue;
                facedBefore.clear();
                for (int g : star) facedBefore.push_back(facesInput(g));
                m.vert[v].P() = best;
                after.clear();
                double worst = 1;
                bool fair = true;
                for (size_t i = 0; i < star.size(); ++i) {
                    after.push_back(Quality(pg, star[i], position, normalUnder(star[i])));
                    worst = std::min(worst, after.back());
                    fair = fair && after.back() >= std::min(quality[star[i]], kFair) && (!facedBefore[i] || facesInput(star[i]));
                }
                if (!fair || !(worst > worstBefore + kMinGain)) {
                    m.vert[v].P() = old;
                    continue;
                }
                for (size_t i = 0; i < star.size(); ++i) quality[star[i]] = after[i];
                ++moved;
            }
            st.moves += moved;
            if (!moved) break;
        }
        st.poorAfter = int(std::count_if(quality.begin(), quality.end(), [](double q) { return q < kPoor; }));
        return st;
    }

    // The element's quality against the unit normal of the input under it (see the top of the file).
    template <class Position>
    static double Quality(const OutputPolygons &pg, int face, Position position, const P3 &normal)
    {
        P3 q[4];
        pg.Points(face, position, q);
        const int n = pg.size[face];
        if (!(vcg_ext::VectorArea(q, n).Norm() > 0)) return -1;
        if (n == 4) return IsFolded(q) ? -1.0 : ScaledJacobian(q, normal);
        double worst = 1;
        for (int k = 0; k < 3; ++k) {
            const P3 e1 = q[(k + 1) % 3] - q[k], e2 = q[(k + 2) % 3] - q[k];
            const double d = e1.Norm() * e2.Norm();
            worst = std::min(worst, d > 0 ? ((e1 ^ e2) * normal) / (d * kSin60) : -1.0);
        }
        return worst;
    }

private:
    // Elements below this are raised (their free corners tried), rounds over them at most, and
    // the least rise of the worst quality around a corner that moves it.
    static constexpr double kRaiseBelow = 0.5;
    static constexpr int kRounds = 4;
    static constexpr double kMinGain = 1e-3;
    // No move may take an element that was at least this fair below it.
    static constexpr double kFair = 0.3;
    // Poor elements, counted for the log (the quality report's "below 0.3").
    static constexpr double kPoor = 0.3;
    static constexpr double kSin60 = 0.86602540378443865;
    // Pattern-search steps, as fractions of the distance to a neighbour.
    static constexpr double kPatternSteps[2] = {0.25, 0.08};

    // The places tried for v: its neighbours' centroid, the average of the places that make each
    // quad around it a parallelogram, half-way to each (v's star may be too bent for a full step),
    // and the pattern-search steps.
    template <class Position>
    static std::vector<P3> Targets(const OutputPolygons &pg, int v, Position position)
    {
        const P3 here = position(v), centroid = pg.NeighbourCentroid(v, position);
        std::vector<P3> targets{centroid, (here + centroid) * 0.5};
        // summed in face index order (facesOf is), the same on a flipped copy
        P3 sum(0, 0, 0);
        int quads = 0;
        for (int face : pg.facesOf[v]) {
            if (pg.size[face] != 4) continue;
            const std::array<int, 4> &c = pg.corners[face];
            const int k = int(std::find(c.begin(), c.end(), v) - c.begin());
            sum += position(c[(k + 1) % 4]) + position(c[(k + 3) % 4]) - position(c[(k + 2) % 4]);
            ++quads;
        }
        if (quads) {
            const P3 parallelogram = sum / double(quads);
            targets.push_back(parallelogram);
            targets.push_back((here + parallelogram) * 0.5);
        }
        // a pattern search: short steps toward and away from each neighbour
        for (int w : pg.Neighbours(v))
            for (double step : kPatternSteps) {
                const P3 d = (position(w) - here) * step;
                targets.push_back(here + d);
                targets.push_back(here - d);
            }
        return targets;
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
