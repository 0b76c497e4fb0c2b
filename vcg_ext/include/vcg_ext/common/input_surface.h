// A frozen copy of the input surface with a spatial grid: closest points and the surface's normal
// under any point, the reference that re-meshed and quad faces are judged against (a face is
// flipped when its vector area points away from the normal of the input triangle closest to its
// centroid, ALGORITHMS.md section 5). Next to a crease sharper than 90 degrees the closest
// triangle can lie on the other side of the crease (evalquad documents the same false positives):
// where a triangle facing the other way is about as close, the caller's own normal under the face
// (the surface it was made on) decides.
#ifndef VCG_EXT_COMMON_INPUT_SURFACE_H
#define VCG_EXT_COMMON_INPUT_SURFACE_H

#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/closest.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/space/index/grid_static_ptr.h>

#include <vcg_ext/common/edge_pairing.h>
#include <vcg_ext/quad_quality.h>

namespace vcg_ext {

template <class MeshType>
class InputSurface
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::CoordType CoordType;
    typedef typename MeshType::ScalarType ScalarType;
    typedef vcg::GridStaticPtr<FaceType, ScalarType> Grid;
    typedef vcg::Point3d P3;

    MeshType mesh;  // no adjacency; per-face normals and marks
    Grid grid;

    explicit InputSurface(MeshType &m)
    {
        vcg::tri::Append<MeshType, MeshType>::MeshCopy(mesh, m);
        vcg::tri::UpdateNormal<MeshType>::PerFaceNormalized(mesh);
        vcg::tri::UpdateBounding<MeshType>::Box(mesh);
        grid.Set(mesh.face.begin(), mesh.face.end(), int(kCellsPerFace * mesh.face.size()));
        std::vector<EdgePairing::Triangle> tris;
        for (const FaceType &f : mesh.face)
            tris.push_back({int(vcg::tri::Index(mesh, f.cV(0))), int(vcg::tri::Index(mesh, f.cV(1))), int(vcg::tri::Index(mesh, f.cV(2)))});
        const std::vector<int> twin = EdgePairing::Twins(tris);
        besideSharpCrease.assign(mesh.face.size(), 0);
        for (size_t h = 0; h < twin.size(); ++h)
            if (twin[h] >= 0 && mesh.face[h / 3].cN() * mesh.face[twin[h] / 3].cN() < 0) besideSharpCrease[h / 3] = 1;
    }

    // The input triangle closest to p (its closest point in `closest`), or null. Queries only read
    // (no face marks: a triangle in several cells may be tested twice), so threads may share them.
    // `within` >= 0: first only within (about) that distance (a cheap search when the caller knows a
    // surface that close), then everywhere.
    const FaceType *Closest(const CoordType &p, CoordType &closest, double within = -1)
    {
        vcg::face::PointDistanceBaseFunctor<ScalarType> distance;
        vcg::tri::EmptyTMark<MeshType> noMarks;
        ScalarType dist = 0;
        if (within >= 0) {
            const ScalarType radius = ScalarType(within * kNearSearchSlack + kOtherSideDiagonal * mesh.bbox.Diag());
            dist = radius;
            if (const FaceType *f = grid.GetClosest(distance, noMarks, p, radius, dist, closest)) return f;
        }
        dist = mesh.bbox.Diag();
        return grid.GetClosest(distance, noMarks, p, mesh.bbox.Diag(), dist, closest);
    }

    // Unit normal of the input triangle closest to p, or `own` when a triangle facing the other way
    // across a crease sharper than 90 degrees is about as close (or there is none). `within`: a
    // distance to a surface near p known to the caller, where the search starts (< 0: unknown).
    P3 NormalUnder(const P3 &p, const P3 &own, double within = -1)
    {
        const FaceType *near = UnambiguousClosest(p, within);
        return near ? P3::Construct(near->cN()) : own;
    }

    // Per face of pm: the unit normal of the input triangle closest to its corner centroid, or
    // own[i] when that triangle borders a crease sharper than 90 degrees (own: per face, or empty
    // for the face's own normal).
    std::vector<P3> NormalsUnder(const PolygonMesh &pm, const std::vector<P3> &own = std::vector<P3>())
    {
        std::vector<P3> normals;
        normals.reserve(pm.faces.size());
        std::vector<P3> corners;
        for (const std::vector<int> &f : pm.faces) {
            corners.clear();
            P3 c(0, 0, 0);
            for (int v : f) {
                c += pm.points[v];
                corners.push_back(pm.points[v]);
            }
            const FaceType *near = UnambiguousClosest(c / double(f.size()));
            normals.push_back(near ? P3::Construct(near->cN())
                                   : own.size() == pm.faces.size() ? own[normals.size()]
                                                                   : VectorArea(corners.data(), int(corners.size())).Normalize());
        }
        return normals;
    }

private:
    std::vector<char> besideSharpCrease;  // per input triangle

    // Next to a crease sharper than 90 degrees, the closest triangle decides only when every
    // triangle facing the other way is farther than kOtherSideFactor times its distance (plus
    // kOtherSideDiagonal of the diagonal): a face lying on one side of a thin fin is judged by that
    // side, a point between the two sides by nobody.
    static constexpr double kOtherSideFactor = 2, kOtherSideDiagonal = 1e-7;
    // Grid cells per triangle: a surface fills few cells of its box, so vcglib's default (one per
    // triangle) leaves dozens of triangles in each cell a query near the surface must test.
    static constexpr double kCellsPerFace = 8;
    // A search near a known surface goes a little beyond it (float rounding of the copy).
    static constexpr double kNearSearchSlack = 1.01;

    // The input triangle closest to p, or null when there is none or p is about as close to a
    // triangle facing the other way across a crease sharper than 90 degrees.
    const FaceType *UnambiguousClosest(const P3 &p, double within = -1)
    {
        CoordType closest;
        const CoordType q = CoordType::Construct(p);
        const FaceType *near = Closest(q, closest, within);
        if (!near || !besideSharpCrease[vcg::tri::Index(mesh, near)]) return near;
        const ScalarType radius = ScalarType(kOtherSideFactor * vcg::Distance(q, closest) + kOtherSideDiagonal * mesh.bbox.Diag());
        std::vector<FaceType *> around;
        std::vector<ScalarType> distances;
        std::vector<CoordType> points;
        vcg::face::PointDistanceBaseFunctor<ScalarType> distance;
        vcg::tri::EmptyTMark<MeshType> noMarks;  // a triangle may come twice: harmless here
        grid.GetInSphere(distance, noMarks, q, radius, around, distances, points);
        for (const FaceType *f : around)
            if (f->cN() * near->cN() < 0) return nullptr;
        return near;
    }
};

}  // namespace vcg_ext

#endif
