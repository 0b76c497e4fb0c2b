// The written-back output as polygons for the last passes that move its vertices (the worst-element
// smoothing, the flipped-face mend): quads and triangles by vertex index, the faces around each
// vertex, the corners that never move (on the front or a border), and the geometry those passes
// share. Built once; the passes move vertices only, so it stays valid.
//
// Orientation: a consistently flipped mesh must get the same moves. Corners are visited, and
// neighbours summed, in vertex index order, never in the order a polygon runs.
#ifndef VCG_EXT_QMORPH_OUTPUT_POLYGONS_H
#define VCG_EXT_QMORPH_OUTPUT_POLYGONS_H

#include <algorithm>
#include <array>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/quad_quality.h>

namespace vcg_ext {
namespace qmorph {

struct OutputPolygons {
    typedef vcg::Point3d P3;

    std::vector<std::array<int, 4>> corners;  // vertex indices, counter-clockwise
    std::vector<int> size;                    // 3 or 4
    std::vector<int> face;                    // one of its faces of m (a triangle's own)
    std::vector<std::vector<int>> facesOf;    // per vertex
    std::vector<char> fixed;                  // per vertex: on a front edge (selected face-edge) or a border

    // m in MeshLab's polygonal form (faux-edge quads), with face-face adjacency.
    template <class MeshType>
    static OutputPolygons Gather(MeshType &m)
    {
        OutputPolygons pg;
        pg.facesOf.resize(m.vert.size());
        QuadQuality::ForEachFauxPolygon(m, [&](typename MeshType::FaceType &f, const std::array<int, 4> &c, int n) {
            for (int k = 0; k < n; ++k) pg.facesOf[c[k]].push_back(int(pg.size.size()));
            pg.corners.push_back(c);
            pg.size.push_back(n);
            pg.face.push_back(int(vcg::tri::Index(m, f)));
        });
        pg.fixed.assign(m.vert.size(), 0);
        for (const auto &f : m.face)
            if (!f.IsD())
                for (int k = 0; k < 3; ++k)
                    if (f.IsFaceEdgeS(k) || f.cFFp(k) == &f) pg.fixed[vcg::tri::Index(m, f.cV0(k))] = pg.fixed[vcg::tri::Index(m, f.cV1(k))] = 1;
        return pg;
    }

    int FaceCount() const { return int(size.size()); }

    // Per face of m (MeshLab's polygonal form): the index of its polygon in the output's order
    // (the order of Gather's polygons).
    template <class MeshType>
    static std::vector<int> PolygonOfFace(MeshType &m)
    {
        std::vector<int> polygon(m.face.size(), -1);
        int count = 0;
        QuadQuality::ForEachFauxPolygon(m, [&](typename MeshType::FaceType &f, const std::array<int, 4> &, int n) {
            polygon[vcg::tri::Index(m, f)] = count;
            if (n == 4)
                for (int k = 0; k < 3; ++k)
                    if (f.IsF(k)) polygon[vcg::tri::Index(m, f.FFp(k))] = count;
            ++count;
        });
        return polygon;
    }

    // The corners of `face` at their positions, counter-clockwise (q[0..size-1]).
    template <class Position>
    void Points(int face, Position position, P3 *q) const
    {
        for (int k = 0; k < size[face]; ++k) q[k] = position(corners[face][k]);
    }

    template <class Position>
    P3 VectorArea(int face, Position position) const
    {
        P3 q[4];
        Points(face, position, q);
        return vcg_ext::VectorArea(q, size[face]);
    }

    template <class Position>
    P3 Centroid(int face, Position position) const
    {
        P3 q[4];
        Points(face, position, q);
        return Centroid(q, size[face]);
    }

    // The input's unit normal under `face`'s centroid (InputSurface::NormalUnder; its own direction
    // where that is ambiguous): what the quality report judges it on.
    template <class Position, class Surface>
    P3 NormalUnder(int face, Position position, Surface &surface) const
    {
        P3 q[4];
        Points(face, position, q);
        return NormalUnder(q, size[face], surface);
    }

    // Whether `face` has an area and faces the way of every input triangle closest to its centroid
    // (InputSurface::FacesEveryClosest): the two passes' test for a face turned over.
    template <class Position, class Surface>
    bool FacesInput(int face, Position position, Surface &surface) const
    {
        P3 q[4];
        Points(face, position, q);
        return FacesInput(q, size[face], surface);
    }

    // The same two for a polygon given by its n corners q (counter-clockwise): one not in the
    // output yet (a collapse's or a flip's result).
    template <class Surface>
    static P3 NormalUnder(const P3 *q, int n, Surface &surface)
    {
        const P3 own = vcg_ext::VectorArea(q, n);
        return surface.NormalUnder(Centroid(q, n), own.Norm() > 0 ? own / own.Norm() : own);
    }
    template <class Surface>
    static bool FacesInput(const P3 *q, int n, Surface &surface)
    {
        const P3 a = vcg_ext::VectorArea(q, n);
        return a.Norm() > 0 && surface.FacesEveryClosest(Centroid(q, n), a);
    }
    // Whether every corner of the polygon q (n corners, counter-clockwise) lies on an input triangle
    // facing away from it (NormalUnder at the corner; a corner on a crease sharper than 90 degrees
    // counts as facing). Such a face is upside down even when its centroid is nearer a sheet it
    // faces: where the input is a plate thinner than the face's chord error, the chord between
    // corners on one sheet passes nearer the other (bones, kept aside). FacesInput (the judge of
    // the quality report, as of evalquad) passes such a face; the smaller faces the all-quads split
    // makes of it fail.
    template <class Surface>
    static bool CornersFaceAway(const P3 *q, int n, Surface &surface)
    {
        const P3 a = vcg_ext::VectorArea(q, n);
        for (int k = 0; k < n; ++k)
            if (!(surface.NormalUnder(q[k], P3(0, 0, 0)) * a < 0)) return false;
        return true;
    }

    // Whether one of the straight quads the all-quads split would make of the polygon q (a corner,
    // the midpoints of its sides, the centre) is turned away from the input under its centroid (as
    // FacesInput judges it): a face bridging two sheets of the input closer than its size, some
    // corners on the sheet behind, passes at its own centroid and its children do not (man, bones,
    // kept aside; block).
    template <class Surface>
    static bool ChildFacesAway(const P3 *q, int n, Surface &surface)
    {
        const P3 centre = Centroid(q, n);
        for (int k = 0; k < n; ++k) {
            const P3 child[4] = {q[k], (q[k] + q[(k + 1) % n]) / 2.0, centre, (q[(k + n - 1) % n] + q[k]) / 2.0};
            if (!FacesInput(child, 4, surface)) return true;
        }
        return false;
    }

    // A quad's scaled Jacobian on the input's normal under it (as the quality report reads it); -1
    // when it is folded or has no area.
    template <class Surface>
    static double QuadJacobian(const P3 *q, Surface &surface)
    {
        if (IsFolded(q) || !(vcg_ext::VectorArea(q, 4).Norm() > 0)) return -1.0;
        return ScaledJacobian(q, NormalUnder(q, 4, surface));
    }
    static P3 Centroid(const P3 *q, int n)
    {
        P3 c(0, 0, 0);
        for (int k = 0; k < n; ++k) c += q[k];
        return c / double(n);
    }

    // Whether corner v, at p, never moves: on the front, on a border or on a sharp crease of the
    // input (the passes on the output keep the features where they are).
    template <class Surface>
    bool NeverMoves(int v, const P3 &p, Surface &surface, double creaseAngleDeg) const
    {
        return fixed[v] || surface.OnCrease(p, creaseAngleDeg);
    }

    // The corners of `face` in vertex index order.
    std::vector<int> CornersByIndex(int face) const
    {
        std::vector<int> c(corners[face].begin(), corners[face].begin() + size[face]);
        std::sort(c.begin(), c.end());
        return c;
    }

    // The vertices sharing a polygon side with v, in index order.
    std::vector<int> Neighbours(int v) const
    {
        std::vector<int> n;
        for (int face : facesOf[v]) {
            const int s = size[face];
            for (int k = 0; k < s; ++k)
                if (corners[face][k] == v) {
                    n.push_back(corners[face][(k + 1) % s]);
                    n.push_back(corners[face][(k + s - 1) % s]);
                }
        }
        std::sort(n.begin(), n.end());
        n.erase(std::unique(n.begin(), n.end()), n.end());
        return n;
    }

    // The centroid of v's neighbours (v itself when it has none).
    template <class Position>
    P3 NeighbourCentroid(int v, Position position) const
    {
        const std::vector<int> n = Neighbours(v);
        P3 sum(0, 0, 0);
        for (int w : n) sum += position(w);
        return n.empty() ? position(v) : sum / double(n.size());
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
