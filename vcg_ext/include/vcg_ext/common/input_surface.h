// A frozen copy of the input surface with a spatial grid: closest points and the surface's normal
// under any point, the reference that re-meshed and quad faces are judged against (a face is
// flipped when its vector area points away from the normal of the input triangle closest to its
// centroid, ALGORITHMS.md section 5). Next to a crease sharper than 90 degrees the closest
// triangle can lie on the other side of the crease (evalquad documents the same false positives):
// the closest one still decides (a face whose centroid is nearer the other sheet counts as flipped,
// as evalquad counts it); only where a triangle facing the other way is exactly as close (a point on
// the crease) the caller's own normal under the face (the surface it was made on) decides.
//
// The copy is read canonically (common/canonical_faces.h: every triangle from its lowest vertex on,
// components of negative orientation reversed), so closest points and normals round the same way on
// a consistently flipped copy of the input; normals are handed out in the input's orientation, or
// in the canonical one while the re-meshing (which works on the mesh read canonically) asks.
#ifndef VCG_EXT_COMMON_INPUT_SURFACE_H
#define VCG_EXT_COMMON_INPUT_SURFACE_H

#include <algorithm>
#include <cmath>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <wrap/callback.h>

#include <vcg_ext/common/canonical_faces.h>
#include <vcg_ext/common/edge_pairing.h>
#include <vcg_ext/common/face_corners.h>
#include <vcg_ext/common/triangle_grid.h>
#include <vcg_ext/quad_quality.h>

namespace vcg_ext {

template <class MeshType>
class InputSurface
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::CoordType CoordType;
    typedef typename MeshType::ScalarType ScalarType;
    typedef vcg::Point3d P3;

    MeshType mesh;  // read canonically (normals too, as vcg's closest-point code needs); no adjacency
    TriangleGrid<MeshType> grid;  // of `mesh`

    // cb (optional): each step reported at `percent` (seconds each on millions of faces).
    explicit InputSurface(MeshType &m, vcg::CallBackPos *cb = nullptr, int percent = 0)
    {
        if (cb) cb(percent, "Q-Morph: the input surface, copy");
        EnableMark(mesh.face, 0);  // our queries need no marks; vcglib's (e.g. the re-meshing's) may
        vcg::tri::Append<MeshType, MeshType>::MeshCopy(mesh, m);
        if (cb) cb(percent, "Q-Morph: the input surface, read canonically");
        CanonicalFaces canon;
        canon.Read(mesh);
        for (size_t f = 0; f < mesh.face.size(); ++f) FaceCorners<MeshType>::Reorder(mesh, mesh.face[f], canon.corner[f]);
        reversed = canon.reversed;
        vcg::tri::UpdateNormal<MeshType>::PerFaceNormalized(mesh);
        vcg::tri::UpdateBounding<MeshType>::Box(mesh);
        if (cb) cb(percent, "Q-Morph: the input surface, grid");
        grid.Build(mesh, int(kCellsPerFace * mesh.face.size()));
        if (cb) cb(percent, "Q-Morph: the input surface, sharp creases");
        std::vector<EdgePairing::Triangle> tris;
        for (const FaceType &f : mesh.face)
            tris.push_back({int(vcg::tri::Index(mesh, f.cV(0))), int(vcg::tri::Index(mesh, f.cV(1))), int(vcg::tri::Index(mesh, f.cV(2)))});
        const std::vector<int> twin = EdgePairing::Twins(tris);
        besideSharpCrease.assign(mesh.face.size(), 0);
        for (size_t h = 0; h < twin.size(); ++h)
            if (twin[h] >= 0 && mesh.face[h / 3].cN() * mesh.face[twin[h] / 3].cN() < 0) besideSharpCrease[h / 3] = 1;
    }

    // Next to a crease sharper than 90 degrees, the closest triangle decides unless a triangle
    // facing the other way is as close, up to kTieDiagonal of the diagonal (a point on the crease
    // itself): a face is judged by the side its centroid is nearest, as evalquad judges it.
    static constexpr double kTieDiagonal = 1e-7;

    // Normals in the canonical orientation (on) or the input's (off, the default).
    void UseCanonicalOrientation(bool on) { canonical = on; }

    // The unit normal of an input triangle (one of `mesh`), in the orientation asked for.
    CoordType Normal(const FaceType *f) const
    {
        return reversed[vcg::tri::Index(mesh, f)] && !canonical ? -f->cN() : f->cN();
    }

    // The input triangle closest to p (its closest point in `closest`), or null. Queries only read
    // (no face marks: a triangle in several cells may be tested twice), so threads may share them.
    // `within` >= 0: first only within (about) that distance (a cheap search when the caller knows a
    // surface that close), then everywhere.
    const FaceType *Closest(const CoordType &p, CoordType &closest, double within = -1)
    {
        if (within >= 0)
            if (const FaceType *f = ClosestWithin(p, within * kNearSearchSlack + kTieDiagonal * mesh.bbox.Diag(), closest)) return f;
        return ClosestWithin(p, mesh.bbox.Diag(), closest);
    }

    // The input triangle closest to p if it lies within maxDistance of p (its closest point in
    // `closest`), or null.
    const FaceType *ClosestWithin(const CoordType &p, double maxDistance, CoordType &closest)
    {
        return Search(p, maxDistance, [](int) { return true; }, closest);
    }

    // The input triangle closest to p among those facing `direction` (normal * direction > 0), or
    // null: where two sheets of the input lie closer than an output face's chord error (fingers
    // touching, two bones side by side), the closest point may be on the sheet behind.
    // maxDistance < 0: anywhere; else only within that distance.
    const FaceType *ClosestFacing(const CoordType &p, const P3 &direction, CoordType &closest, double maxDistance = -1)
    {
        return Search(p, maxDistance < 0 ? mesh.bbox.Diag() : maxDistance,
                      [&](int f) { return P3::Construct(Normal(&mesh.face[f])) * direction > 0; }, closest);
    }

    // One closest-point search at a point, for the several questions a caller asks there (each
    // search is the cost of those questions); the triangles tied with the closest are searched once
    // too, when a question needs them.
    struct Near {
        CoordType q, closest;               // the point (in the mesh's scalar type) and its closest point
        const FaceType *face = nullptr;     // the closest input triangle (null: none)
        std::vector<FaceType *> tied;       // TiedWithClosest, once `tiedKnown`
        bool tiedKnown = false;
    };
    Near Nearest(const P3 &p, double within = -1)
    {
        Near near;
        near.q = CoordType::Construct(p);
        near.face = Closest(near.q, near.closest, within);
        return near;
    }

    // Unit normal of the input triangle closest to p, or `own` when a triangle facing the other way
    // across a crease sharper than 90 degrees is as close (or there is none). `within`: a
    // distance to a surface near p known to the caller, where the search starts (< 0: unknown).
    P3 NormalUnder(const P3 &p, const P3 &own, double within = -1)
    {
        Near near = Nearest(p, within);
        return NormalUnder(near, own);
    }
    P3 NormalUnder(Near &near, const P3 &own)
    {
        const FaceType *f = UnambiguousClosest(near);
        return f ? P3::Construct(Normal(f)) : own;
    }

    // Whether `direction` points the way of every input triangle closest to p: when p is as close to
    // several (up to kTieDiagonal, e.g. its closest point is on an edge they share), any of them may
    // be the one an independent check finds, so a face standing on edge over that edge (facing one,
    // away from the other) would count as flipped or not by chance. Triangles facing the other way
    // than the closest (across a crease sharper than 90 degrees) are left out, as NormalUnder leaves
    // them. True when there is no triangle. `within`: as for NormalUnder.
    bool FacesEveryClosest(const P3 &p, const P3 &direction, double within = -1)
    {
        Near near = Nearest(p, within);
        return FacesEveryClosest(near, direction);
    }
    bool FacesEveryClosest(Near &near, const P3 &direction)
    {
        if (!near.face) return true;
        if (!(P3::Construct(Normal(near.face)) * direction > 0)) return false;
        for (const FaceType *f : Tied(near))
            if (f->cN() * near.face->cN() >= 0 && !(P3::Construct(Normal(f)) * direction > 0)) return false;
        return true;
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
            for (int v : f) corners.push_back(pm.points[v]);
            // summed in the same order whichever way the polygon runs: from its lowest vertex toward
            // the lower of that one's two neighbours
            const int n = int(f.size()), low = int(std::min_element(f.begin(), f.end()) - f.begin());
            const int step = f[(low + 1) % n] < f[(low + n - 1) % n] ? 1 : n - 1;
            P3 c(0, 0, 0);
            for (int i = 0, k = low; i < n; ++i, k = (k + step) % n) c += pm.points[f[k]];
            const FaceType *near = UnambiguousClosest(c / double(f.size()));
            normals.push_back(near ? P3::Construct(Normal(near))
                                   : own.size() == pm.faces.size() ? own[normals.size()]
                                                                   : VectorArea(corners.data(), int(corners.size())).Normalize());
        }
        return normals;
    }

    // Whether p lies on a sharp input edge or corner: two of the input triangles closest to p (up
    // to kOnCreaseDiagonal of the diagonal farther) meet at more than creaseAngleDeg.
    bool OnCrease(const P3 &p, double creaseAngleDeg)
    {
        CoordType closest;
        const CoordType q = CoordType::Construct(p);
        if (!Closest(q, closest)) return false;
        const ScalarType radius = ScalarType(vcg::Distance(q, closest) + kOnCreaseDiagonal * mesh.bbox.Diag());
        const std::vector<FaceType *> around = Within(q, radius);
        const double creaseCos = std::cos(creaseAngleDeg * M_PI / 180);
        for (size_t i = 0; i < around.size(); ++i)
            for (size_t j = i + 1; j < around.size(); ++j)
                if (double(around[i]->cN() * around[j]->cN()) < creaseCos) return true;
        return false;
    }

private:
    // A point of the output on an input crease is there up to float rounding of its coordinates.
    static constexpr double kOnCreaseDiagonal = 1e-5;

    std::vector<char> besideSharpCrease;  // per input triangle
    std::vector<char> reversed;           // per input triangle: read the other way round than the input's
    bool canonical = false;               // see UseCanonicalOrientation

    // Grid cells per triangle: a surface fills few cells of its box, so vcglib's default (one per
    // triangle) leaves dozens of triangles in each cell a query near the surface must test.
    static constexpr double kCellsPerFace = 8;
    // A search near a known surface goes a little beyond it (float rounding of the copy).
    static constexpr double kNearSearchSlack = 1.01;

    // The input triangle nearest p, nearer than maxDistance, among those `accept` takes (its
    // closest point in `closest`), or null (TriangleGrid::Closest: vcglib's GridClosest's answer).
    template <class Accept>
    const FaceType *Search(const CoordType &p, double maxDistance, const Accept &accept, CoordType &closest)
    {
        const int f = grid.Closest(p, ScalarType(maxDistance), accept, closest);
        return f < 0 ? nullptr : &mesh.face[f];
    }

    // The triangles as close to q as the closest one (at `closest`), up to the tie slack.
    std::vector<FaceType *> TiedWithClosest(const CoordType &q, const CoordType &closest)
    {
        return Within(q, ScalarType(vcg::Distance(q, closest) + kTieDiagonal * mesh.bbox.Diag()));
    }

    // The input triangles nearer q than radius (TriangleGrid::ForEachWithin). A triangle in several
    // cells comes once per cell: callers ask whether any or every one of them does something.
    std::vector<FaceType *> Within(const CoordType &q, ScalarType radius)
    {
        std::vector<FaceType *> around;
        grid.ForEachWithin(q, radius, [&](int f) { around.push_back(&mesh.face[f]); });
        return around;
    }

    const std::vector<FaceType *> &Tied(Near &near)
    {
        if (!near.tiedKnown) near.tied = TiedWithClosest(near.q, near.closest);
        near.tiedKnown = true;
        return near.tied;
    }

    // The input triangle closest to the point, or null when there is none or the point is as close
    // to a triangle facing the other way across a crease sharper than 90 degrees.
    const FaceType *UnambiguousClosest(Near &near)
    {
        if (!near.face || !besideSharpCrease[vcg::tri::Index(mesh, near.face)]) return near.face;
        for (const FaceType *f : Tied(near))
            if (f->cN() * near.face->cN() < 0) return nullptr;
        return near.face;
    }
    const FaceType *UnambiguousClosest(const P3 &p, double within = -1)
    {
        Near near = Nearest(p, within);
        return UnambiguousClosest(near);
    }

    // Optional per-face marks (MeshLab's CMeshO) are switched on; a mesh type with fixed ones has no switch.
    template <class Container>
    static auto EnableMark(Container &c, int) -> decltype(c.EnableMark(), void()) { c.EnableMark(); }
    template <class Container>
    static void EnableMark(Container &, long) {}
};

}  // namespace vcg_ext

#endif
