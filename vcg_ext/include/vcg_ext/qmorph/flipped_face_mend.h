// The output's last check, after the write-back (and after the all-quads split). A face whose
// vector area points away from the input surface (the quality report's flipped face), or a quad
// inverted (a corner turning the other way) or folded, is mended by moving one of its free corners
// to the centroid of its neighbours, projected onto the input, when that mends it and makes no
// face around the corner worse: none turned away from an input triangle closest to its centroid,
// no quad folded or made concave. Corners on the front or on a sharp crease of the input never move.
//
// Every operation of the patch meshing is judged against the input already; this catches what
// still slips through: on armadillo_52k x16 (832k faces) a tangle of 8 small triangles standing on
// edge inside one patch (where it comes from is not traced), and the all-quads split of a
// near-degenerate face (needle children at 92-97 degrees to the surface).
#ifndef VCG_EXT_QMORPH_FLIPPED_FACE_MEND_H
#define VCG_EXT_QMORPH_FLIPPED_FACE_MEND_H

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/input_surface.h>
#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/quad_quality.h>

namespace vcg_ext {
namespace qmorph {

template <class MeshType>
class FlippedFaceMend
{
public:
    typedef typename MeshType::CoordType CoordType;
    typedef vcg::Point3d P3;

    struct Stats {
        int mended = 0;  // flipped faces and inverted quads found and turned back
        int left = 0;    // those no move could mend
    };

    // m in MeshLab's polygonal form (faux-edge quads), with face-face adjacency; front edges are
    // its selected face-edges. Moves vertices only.
    static Stats Do(MeshType &m, InputSurface<MeshType> &surface, double creaseAngleDeg)
    {
        Polygons pg = Gather(m);
        const std::vector<char> onFront = FrontCorners(m);
        auto position = [&](int v) { return P3::Construct(m.vert[v].cP()); };
        auto facesInput = [&](int face) {
            const P3 a = VectorArea(pg, face, position);
            return a.Norm() > 0 && surface.FacesEveryClosest(Centroid(pg, face, position), a);
        };
        auto jacobian = [&](int face) {  // of a quad, on its own normal; 1 for a triangle
            if (pg.size[face] < 4) return 1.0;
            P3 q[4];
            for (int k = 0; k < 4; ++k) q[k] = position(pg.corners[face][k]);
            return IsFolded(q) ? -1.0 : ScaledJacobian(q);
        };
        auto bad = [&](int face) { return !facesInput(face) || jacobian(face) <= 0; };
        Stats st;
        std::vector<char> facedBefore;
        std::vector<double> jacobianBefore;
        for (int round = 0; round < kRounds; ++round) {
            std::vector<int> badFaces;
            for (int face = 0; face < int(pg.size.size()); ++face)
                if (bad(face)) badFaces.push_back(face);
            int mendedNow = 0;
            for (int face : badFaces) {
                if (!bad(face)) { ++mendedNow; continue; }  // a neighbour's move mended it
                bool done = false;
                for (int v : CornersByIndex(pg, face)) {
                    if (done) break;
                    if (onFront[v] || surface.OnCrease(position(v), creaseAngleDeg)) continue;
                    CoordType onSurface;
                    if (!surface.Closest(CoordType::Construct(NeighbourCentroid(pg, v, position)), onSurface)) continue;
                    // the face mended, and no face around v made worse: none turned over, no quad
                    // folded or made concave (one already bad no worse than before)
                    facedBefore.clear();
                    jacobianBefore.clear();
                    for (int g : pg.facesOf[v]) {
                        facedBefore.push_back(facesInput(g));
                        jacobianBefore.push_back(std::min(kConvex, jacobian(g)));
                    }
                    const CoordType old = m.vert[v].cP();
                    m.vert[v].P() = onSurface;
                    done = !bad(face);
                    for (size_t i = 0; i < pg.facesOf[v].size() && done; ++i) {
                        const int g = pg.facesOf[v][i];
                        done = (facesInput(g) || !facedBefore[i]) && jacobian(g) >= jacobianBefore[i];
                    }
                    if (!done) m.vert[v].P() = old;
                }
                mendedNow += done;
            }
            st.mended += mendedNow;
            if (mendedNow == 0) break;
        }
        st.left = 0;
        for (int face = 0; face < int(pg.size.size()); ++face) st.left += bad(face);
        return st;
    }

private:
    // Rounds over the faces still flipped: a tangle may need a neighbour moved first.
    static constexpr int kRounds = 4;
    // A move may leave a quad around the corner at any scaled Jacobian down to this (a convex
    // quad, its corners turning the same way), or no lower than it was.
    static constexpr double kConvex = 1e-3;

    struct Polygons {
        std::vector<std::array<int, 4>> corners;  // vertex indices, counter-clockwise
        std::vector<int> size;                    // 3 or 4
        std::vector<std::vector<int>> facesOf;    // per vertex
    };

    static Polygons Gather(MeshType &m)
    {
        Polygons pg;
        pg.facesOf.resize(m.vert.size());
        QuadQuality::ForEachFauxPolygon(m, [&](typename MeshType::FaceType &, const std::array<int, 4> &corners, int n) {
            for (int k = 0; k < n; ++k) pg.facesOf[corners[k]].push_back(int(pg.size.size()));
            pg.corners.push_back(corners);
            pg.size.push_back(n);
        });
        return pg;
    }

    template <class Position>
    static P3 VectorArea(const Polygons &pg, int face, Position position)
    {
        P3 q[4];
        for (int k = 0; k < pg.size[face]; ++k) q[k] = position(pg.corners[face][k]);
        return vcg_ext::VectorArea(q, pg.size[face]);
    }

    template <class Position>
    static P3 Centroid(const Polygons &pg, int face, Position position)
    {
        P3 c(0, 0, 0);
        for (int k = 0; k < pg.size[face]; ++k) c += position(pg.corners[face][k]);
        return c / double(pg.size[face]);
    }

    // Orientation: a consistently flipped mesh gets the same moves. Corners are tried, and
    // neighbours summed, in vertex index order, not in the order the polygons run.
    static std::vector<int> CornersByIndex(const Polygons &pg, int face)
    {
        std::vector<int> corners(pg.corners[face].begin(), pg.corners[face].begin() + pg.size[face]);
        std::sort(corners.begin(), corners.end());
        return corners;
    }

    // The centroid of the vertices sharing a polygon side with v.
    template <class Position>
    static P3 NeighbourCentroid(const Polygons &pg, int v, Position position)
    {
        std::vector<int> neighbours;
        for (int face : pg.facesOf[v]) {
            const int s = pg.size[face];
            for (int k = 0; k < s; ++k)
                if (pg.corners[face][k] == v) {
                    neighbours.push_back(pg.corners[face][(k + 1) % s]);
                    neighbours.push_back(pg.corners[face][(k + s - 1) % s]);
                }
        }
        std::sort(neighbours.begin(), neighbours.end());
        neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
        P3 sum(0, 0, 0);
        for (int w : neighbours) sum += position(w);
        return neighbours.empty() ? position(v) : sum / double(neighbours.size());
    }

    // Corners on a front edge (selected face-edge).
    static std::vector<char> FrontCorners(MeshType &m)
    {
        std::vector<char> fixed(m.vert.size(), 0);
        for (const auto &f : m.face)
            if (!f.IsD())
                for (int k = 0; k < 3; ++k)
                    if (f.IsFaceEdgeS(k)) fixed[vcg::tri::Index(m, f.cV0(k))] = fixed[vcg::tri::Index(m, f.cV1(k))] = 1;
        return fixed;
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
