// A frozen copy of the input surface with a spatial grid: closest points and the surface's normal
// under any point, the reference that re-meshed and quad faces are judged against (a face is
// flipped when its vector area points away from the normal of the input triangle closest to its
// centroid, ALGORITHMS.md section 5). Next to a crease sharper than 90 degrees the closest
// triangle can lie on the other side of the crease (evalquad documents the same false positives):
// there the caller's own normal under the face (the surface it was made on) decides.
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
        EnableMark(mesh.face, 0);  // closest-point queries mark faces
        vcg::tri::Append<MeshType, MeshType>::MeshCopy(mesh, m);
        vcg::tri::UpdateNormal<MeshType>::PerFaceNormalized(mesh);
        vcg::tri::UpdateBounding<MeshType>::Box(mesh);
        grid.Set(mesh.face.begin(), mesh.face.end());
        std::vector<EdgePairing::Triangle> tris;
        for (const FaceType &f : mesh.face)
            tris.push_back({int(vcg::tri::Index(mesh, f.cV(0))), int(vcg::tri::Index(mesh, f.cV(1))), int(vcg::tri::Index(mesh, f.cV(2)))});
        const std::vector<int> twin = EdgePairing::Twins(tris);
        besideSharpCrease.assign(mesh.face.size(), 0);
        for (size_t h = 0; h < twin.size(); ++h)
            if (twin[h] >= 0 && mesh.face[h / 3].cN() * mesh.face[twin[h] / 3].cN() < 0) besideSharpCrease[h / 3] = 1;
    }

    // The input triangle closest to p (its closest point in `closest`), or null.
    const FaceType *Closest(const CoordType &p, CoordType &closest)
    {
        ScalarType dist = mesh.bbox.Diag();
        return vcg::tri::GetClosestFaceBase(mesh, grid, p, mesh.bbox.Diag(), dist, closest);
    }

    // Unit normal of the input triangle closest to p, or `own` when that triangle borders a crease
    // sharper than 90 degrees (or there is none).
    P3 NormalUnder(const P3 &p, const P3 &own)
    {
        const FaceType *near = UnambiguousClosest(p);
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

    // The input triangle closest to p, or null when there is none or it borders a crease sharper
    // than 90 degrees (where the closest one can lie on the other side).
    const FaceType *UnambiguousClosest(const P3 &p)
    {
        CoordType closest;
        const FaceType *near = Closest(CoordType::Construct(p), closest);
        return near && !besideSharpCrease[vcg::tri::Index(mesh, near)] ? near : nullptr;
    }

    // Optional per-face marks (MeshLab's CMeshO) are switched on; a mesh type with fixed ones has no switch.
    template <class Container>
    static auto EnableMark(Container &c, int) -> decltype(c.EnableMark(), void()) { c.EnableMark(); }
    template <class Container>
    static void EnableMark(Container &, long) {}
};

}  // namespace vcg_ext

#endif
