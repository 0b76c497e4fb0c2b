// Triangles in disguise, after the output's final shape pass: a quad whose corner at a node that
// never moves (on the front, a border or a sharp crease of the input) is nearly straight has a
// scaled Jacobian below 0.3 that no smoothing can raise. On rough scans (man, kept aside: 0.63% of
// its quads below 0.3, most with a corner of 160-180 degrees at a front node whose side holds no
// other polygon) they are where Q-Morph's front closed around a corner of a small region. Such a
// quad is split along its diagonal from that corner into two triangles, when both face the input
// and have no angle below kMinTriangleAngle; worst quads first, and only while the triangles' share
// of the area stays within kMaxTriangleArea (the output stays quad-dominant: issue 11 asks for at
// least 99.5% of the area in quads).
//
// A dart, a quad with a corner reflex in its own plane (a bent quad can face the input at every
// corner and still be one), is split the same way from that corner, wherever it is.
//
// Orientation: the quads are visited in the order of their scaled Jacobians, ties in polygon order,
// and every test reads the corners' positions only: a consistently flipped mesh gets the same splits.
#ifndef VCG_EXT_QMORPH_FLAT_QUAD_SPLIT_H
#define VCG_EXT_QMORPH_FLAT_QUAD_SPLIT_H

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/edge_flip.h>
#include <vcg_ext/common/input_surface.h>
#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/qmorph/output_polygons.h>

namespace vcg_ext {
namespace qmorph {

template <class MeshType>
class FlatQuadSplit
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef vcg::Point3d P3;

    // m in MeshLab's polygonal form (faux-edge quads), with face-face adjacency; front edges are
    // its selected face-edges. Faces keep their places in m.face (a split quad's two faces become
    // two triangles); returns the number of quads split.
    static int Do(MeshType &m, InputSurface<MeshType> &surface, double creaseAngleDeg)
    {
        const OutputPolygons pg = OutputPolygons::Gather(m);
        auto position = [&](int v) { return P3::Construct(m.vert[v].cP()); };
        double area = 0, triangleArea = 0;
        std::vector<std::pair<double, int>> poor;  // (scaled Jacobian, polygon)
        for (int face = 0; face < pg.FaceCount(); ++face) {
            const double a = pg.VectorArea(face, position).Norm() / 2;
            area += a;
            if (pg.size[face] == 3) {
                triangleArea += a;
                continue;
            }
            P3 q[4];
            pg.Points(face, position, q);
            // a dart (a corner reflex in the quad's own plane) may still face the input at every
            // corner when the quad is bent: its own scaled Jacobian ranks it
            const double jacobian = std::min(OutputPolygons::QuadJacobian(q, surface), ScaledJacobian(q));
            if (jacobian < kPoor) poor.push_back({jacobian, face});
        }
        std::sort(poor.begin(), poor.end());
        int split = 0;
        for (const auto &candidate : poor) {
            const int face = candidate.second;
            P3 q[4];
            pg.Points(face, position, q);
            const int reflex = ReflexCorner(q);
            const int c = reflex >= 0 ? reflex : FlatCorner(q);
            if (c < 0) continue;
            const int v = pg.corners[face][c];
            // a dart is split from its reflex corner wherever it is (any two triangles facing the
            // input are better than a quad no smoothing made convex)
            if (reflex < 0 && !pg.NeverMoves(v, position(v), surface, creaseAngleDeg)) continue;
            const P3 t0[3] = {q[c], q[(c + 1) % 4], q[(c + 2) % 4]}, t1[3] = {q[c], q[(c + 2) % 4], q[(c + 3) % 4]};
            if (reflex < 0 && (MinAngle(t0) < kMinTriangleAngle || MinAngle(t1) < kMinTriangleAngle)) continue;
            if (!OutputPolygons::FacesInput(t0, 3, surface) || !OutputPolygons::FacesInput(t1, 3, surface)) continue;
            const double a = pg.VectorArea(face, position).Norm() / 2;
            if (triangleArea + a > kMaxTriangleArea * area) break;
            // the quad's faux diagonal joins its corners 0 and 2 (OutputPolygons' order)
            FaceType &f = m.face[pg.face[face]];
            int k = 0;
            while (k < 3 && !f.IsF(k)) ++k;
            if (k == 3) continue;
            if (c % 2 == 1) {  // the other diagonal: flipped there (it carries no flag)
                if (!vcg::face::CheckFlipEdge(f, k)) continue;
                FlipEdgeKeepingFlags(f, k);
            } else {
                f.FFp(k)->ClearF(f.FFi(k));
                f.ClearF(k);
            }
            triangleArea += a;
            ++split;
        }
        return split;
    }

private:
    // The corner of quad q whose angle is at least kFlatCorner, or -1.
    static int FlatCorner(const P3 *q)
    {
        int flat = -1;
        double widest = kFlatCorner;
        for (int k = 0; k < 4; ++k) {
            const double angle = AngleBetween(q[(k + 1) % 4] - q[k], q[(k + 3) % 4] - q[k]) * 180 / M_PI;
            if (angle >= widest) widest = angle, flat = k;
        }
        return flat;
    }
    // The corner of quad q reflex in its own plane (its corner Jacobian against the quad's vector
    // area at most 0; the most negative one), or -1 (also for a quad of zero area).
    static int ReflexCorner(const P3 *q)
    {
        const P3 a = VectorArea(q, 4);
        const double area = a.Norm();
        if (!(area > 0)) return -1;
        int reflex = -1;
        double worst = 0;
        for (int k = 0; k < 4; ++k) {
            bool degenerate = false;
            const double j = CornerJacobian(q, k, a / area, &degenerate);
            if (!degenerate && j <= worst) worst = j, reflex = k;
        }
        return reflex;
    }
    static double MinAngle(const P3 *t) { return TriangleMinAngle(t[0], t[1], t[2]) * 180 / M_PI; }  // degrees

    // The quality report's threshold of a poor quad.
    static constexpr double kPoor = 0.3;
    // A corner this straight (degrees) makes the quad a triangle with a node on one side: its
    // scaled Jacobian is at most sin 20 degrees = 0.34.
    static constexpr double kFlatCorner = 160;
    // The two triangles' smallest angle, at least (degrees): below it a triangle is no better than
    // the quad (a quad of scaled Jacobian 0.3 has a corner of 17.5 or 162.5 degrees).
    static constexpr double kMinTriangleAngle = 15;
    // The share of the output's area in triangles the splits may fill up to.
    static constexpr double kMaxTriangleArea = 0.004;
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
