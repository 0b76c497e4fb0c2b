// What Q-Morph writes back: the patches' polygons in terms of output vertex ids, the moved input
// vertices and the new points, collected patch after patch, then written into the vcg mesh at once
// in MeshLab's polygonal form (a quad is two triangles sharing a faux edge), the front selected.
#ifndef VCG_EXT_QMORPH_QUAD_OUTPUT_H
#define VCG_EXT_QMORPH_QUAD_OUTPUT_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/common/edge_key.h>
#include <vcg_ext/common/face_face_adjacency.h>
#include <vcg_ext/qmorph/mixed_mesh.h>
#include <vcg_ext/qmorph/partition.h>
#include <vcg_ext/qmorph/surface_projector.h>

namespace vcg_ext {
namespace qmorph {

// Output vertex ids: an input vertex index (>= 0), or new point k as NewPointId(k) (< 0).
inline int NewPointId(int k) { return -1 - k; }
inline int NewPointIndex(int id) { return -1 - id; }

class QuadOutput
{
public:
    // Points added to the mesh: nodes made inside patches.
    std::vector<P3> newPoints;
    int quads = 0, triangles = 0;
    // Per polygon, in the order they are written: the input surface's unit normal under it.
    std::vector<P3> referenceNormals;

    explicit QuadOutput(size_t inputVertices) : movedTo(inputVertices, -1), used(inputVertices, 0) {}

    // What one meshed patch contributes, made on any thread (Collect) and appended in patch
    // order on one (Append): the output is the same whatever thread meshed which patch.
    struct PatchPolygons;

    // Collects the faces of a meshed patch.
    void AddPatch(const MixedMesh &mm, const SurfaceProjector &surface, const std::vector<int> &home, const PatchInput &in)
    {
        Append(Collect(mm, surface, home, in));
    }

    // The faces of a meshed patch; new points numbered from 0 within the patch (NewPointId).
    static PatchPolygons Collect(const MixedMesh &mm, const SurfaceProjector &surface, const std::vector<int> &home,
                                 const PatchInput &in)
    {
        PatchPolygons out;
        std::vector<int> outId(mm.VertexCount(), 0);
        for (int v = 0; v < mm.VertexCount(); ++v) {
            if (!mm.vertAlive[v]) continue;
            if (v < int(in.globalOf.size())) {
                const int g = in.globalOf[v];
                outId[v] = g;
                out.used.push_back(g);
                if (!mm.vertFixed[v] && !(mm.pos[v] == in.points[v])) out.moved.push_back({g, mm.pos[v]});
            } else {
                out.newPoints.push_back(mm.pos[v]);
                outId[v] = NewPointId(int(out.newPoints.size()) - 1);
            }
        }
        for (int f = 0; f < mm.FaceCount(); ++f) {
            if (!mm.FaceAlive(f)) continue;
            Polygon poly;
            poly.size = mm.faceSize[f];
            poly.quality = in.quality;
            int h = mm.faceHe[f];
            int corner[4] = {-1, -1, -1, -1};
            for (int k = 0; k < poly.size; ++k, h = mm.heNext[h]) {
                corner[k] = mm.Org(h);
                poly.v[k] = outId[corner[k]];
            }
            poly.diagonal = poly.size == 4 ? PreferredDiagonal(mm, surface, home, corner) : kEitherDiagonal;
            P3 normal = mm.InputFaceNormal(f, true);
            if (in.reversed) {  // back to the input's orientation: same first corner, same diagonal
                std::reverse(poly.v.begin() + 1, poly.v.begin() + poly.size);
                normal = -normal;
            }
            out.polygons.push_back(poly);
            out.referenceNormals.push_back(normal);
        }
        return out;
    }

    // Adds a collected patch after the ones already added.
    void Append(const PatchPolygons &patch)
    {
        const int base = int(newPoints.size());
        newPoints.insert(newPoints.end(), patch.newPoints.begin(), patch.newPoints.end());
        for (int g : patch.used) used[g] = 1;
        for (const auto &mv : patch.moved) {
            movedTo[mv.first] = int(moved.size());
            moved.push_back(mv.second);
        }
        for (Polygon poly : patch.polygons) {
            for (int k = 0; k < poly.size; ++k)
                if (poly.v[k] < 0) poly.v[k] = NewPointId(base + NewPointIndex(poly.v[k]));
            polygons.push_back(poly);
            if (poly.size == 4) ++quads; else ++triangles;
        }
        referenceNormals.insert(referenceNormals.end(), patch.referenceNormals.begin(), patch.referenceNormals.end());
    }

    // Replaces the faces of m by the polygons (quads as faux pairs), front edges selected.
    // `in` is the partition the polygons were made from.
    template <class MeshType>
    void WriteTo(MeshType &m, const FrontPartition &in) const
    {
        typedef typename MeshType::FaceType FaceType;
        typedef typename MeshType::CoordType CoordType;
        const bool hasQuality = vcg::tri::HasPerFaceQuality(m);
        // The selection is kept as vertex pairs: flips do not carry per-edge flags, and the
        // initial front edges survive unchanged, so the pairs are still edges.
        const int firstNew = int(m.vert.size());
        auto resolve = [&](int id) { return id >= 0 ? id : firstNew + NewPointIndex(id); };
        const std::unordered_set<uint64_t> &frontPairs = in.selectedPairs;

        for (size_t v = 0; v < m.vert.size(); ++v) {
            if (m.vert[v].IsD()) continue;
            if (movedTo[v] >= 0) m.vert[v].P() = CoordType::Construct(moved[movedTo[v]]);
        }
        if (!newPoints.empty()) {
            auto vi = vcg::tri::Allocator<MeshType>::AddVertices(m, newPoints.size());
            for (size_t i = 0; i < newPoints.size(); ++i, ++vi) vi->P() = CoordType::Construct(newPoints[i]);
        }
        for (auto &f : m.face)
            if (!f.IsD()) vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
        size_t triCount = 0;
        for (const Polygon &p : polygons) triCount += p.size == 4 ? 2 : 1;
        // polygon sides and chosen diagonals, so a quad is never split along an edge that exists elsewhere
        std::unordered_set<uint64_t> sides;
        for (const Polygon &p : polygons)
            for (int k = 0; k < p.size; ++k) sides.insert(EdgeKey(resolve(p.v[k]), resolve(p.v[(k + 1) % p.size])));
        auto fi = vcg::tri::Allocator<MeshType>::AddFaces(m, triCount);
        auto setFace = [&](FaceType &f, int a, int b, int c, float q) {
            f.V(0) = &m.vert[a];
            f.V(1) = &m.vert[b];
            f.V(2) = &m.vert[c];
            f.Flags() = 0;
            if (hasQuality) f.Q() = q;
            const int vv[3] = {a, b, c};
            for (int k = 0; k < 3; ++k)
                if (frontPairs.count(EdgeKey(vv[k], vv[(k + 1) % 3]))) f.SetFaceEdgeS(k);
        };
        for (size_t i = 0; i < polygons.size(); ++i) {
            const Polygon &p = polygons[i];
            const int a = resolve(p.v[0]), b = resolve(p.v[1]), c = resolve(p.v[2]);
            if (p.size == 3) {
                setFace(*fi, a, b, c, p.quality);
                ++fi;
                continue;
            }
            const int d = resolve(p.v[3]);
            // the diagonal that follows the input surface, else the one giving the better pair of
            // triangles (the larger smallest angle)
            const P3 pa = P3::Construct(m.vert[a].cP()), pb = P3::Construct(m.vert[b].cP()), pc = P3::Construct(m.vert[c].cP()),
                     pd = P3::Construct(m.vert[d].cP());
            bool acDiagonal = p.diagonal != kEitherDiagonal
                                  ? p.diagonal == kDiagonal02
                                  : std::min(TriangleMinAngle(pa, pb, pc), TriangleMinAngle(pa, pc, pd)) >= std::min(TriangleMinAngle(pb, pc, pd), TriangleMinAngle(pb, pd, pa));
            // never a triangle upside down on the surface when the other diagonal avoids it
            auto up = [&](const P3 &x, const P3 &y, const P3 &z) { return ((y - x) ^ (z - x)) * referenceNormals[i] > 0; };
            const bool acUp = up(pa, pb, pc) && up(pa, pc, pd), bdUp = up(pb, pc, pd) && up(pb, pd, pa);
            if (acUp != bdUp) acDiagonal = acUp;
            if (sides.count(EdgeKey(a, c))) acDiagonal = false;
            else if (sides.count(EdgeKey(b, d))) acDiagonal = true;
            sides.insert(acDiagonal ? EdgeKey(a, c) : EdgeKey(b, d));  // two quads around a doublet node must not share a diagonal
            if (acDiagonal) {
                setFace(*fi, a, b, c, p.quality); fi->SetF(2); ++fi;  // c->a faux
                setFace(*fi, a, c, d, p.quality); fi->SetF(0); ++fi;  // a->c faux
            } else {
                setFace(*fi, b, c, d, p.quality); fi->SetF(2); ++fi;  // d->b faux
                setFace(*fi, b, d, a, p.quality); fi->SetF(0); ++fi;  // b->d faux
            }
        }
        std::vector<char> wasUsed(used.size(), 0);  // isolated input vertices stay as they are
        for (auto &t : in.tri)
            for (int k = 0; k < 3; ++k) wasUsed[t[k]] = 1;
        for (size_t v = 0; v < used.size(); ++v)
            if (wasUsed[v] && !used[v] && !m.vert[v].IsD()) vcg::tri::Allocator<MeshType>::DeleteVertex(m, m.vert[v]);
        vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
        vcg::tri::UpdateBounding<MeshType>::Box(m);
        if (vcg::tri::HasFFAdjacency(m)) FaceFaceAdjacency<MeshType>::Update(m);
        if (vcg::tri::HasVFAdjacency(m)) vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
        vcg::tri::UpdateNormal<MeshType>::PerVertexNormalizedPerFace(m);
    }

private:
    // Which diagonal splits a quad into the two triangles written: corners 0-2, 1-3, or either
    // (decided by shape when written).
    enum Diagonal : signed char { kEitherDiagonal = -1, kDiagonal13 = 0, kDiagonal02 = 1 };

    struct Polygon {
        int size = 0;
        std::array<int, 4> v{{0, 0, 0, 0}};  // output vertex ids, counter-clockwise
        float quality = 0;
        Diagonal diagonal = kEitherDiagonal;
    };

public:
    struct PatchPolygons {
        std::vector<Polygon> polygons;
        std::vector<P3> referenceNormals;          // per polygon
        std::vector<P3> newPoints;                 // nodes made inside the patch
        std::vector<int> used;                     // input vertices still nodes
        std::vector<std::pair<int, P3>> moved;     // input vertex, new position
    };

private:
    std::vector<Polygon> polygons;
    std::vector<int> movedTo;  // per input vertex: its new position in `moved`, -1 if it stays
    std::vector<P3> moved;
    std::vector<char> used;    // per input vertex: still a node of the output

    // A non-planar quad is written as two triangles: the diagonal whose triangles lie clearly
    // nearer the input surface keeps the shape; either when the quad is about flat.
    static Diagonal PreferredDiagonal(const MixedMesh &mm, const SurfaceProjector &surface, const std::vector<int> &home,
                                      const int (&corner)[4])
    {
        // the two choices differ by less than this fraction of the mean side: about flat
        const double kFlatTolerance = 0.02;
        auto distance = [&](const P3 &q, int near) {
            int hm = near < int(home.size()) ? home[near] : 0;
            return (surface.Project(q, hm) - q).Norm();
        };
        // the farthest of the diagonal's midpoint and the two triangles' centres
        auto offSurface = [&](int i) {
            const P3 &u = mm.pos[corner[i]], &w = mm.pos[corner[(i + 2) % 4]];
            const P3 &x = mm.pos[corner[(i + 1) % 4]], &y = mm.pos[corner[(i + 3) % 4]];
            return std::max({distance((u + w) * 0.5, corner[i]), distance((u + w + x) / 3.0, corner[(i + 1) % 4]),
                             distance((u + w + y) / 3.0, corner[(i + 3) % 4])});
        };
        const double ac = offSurface(0), bd = offSurface(1);
        double side = 0;
        for (int k = 0; k < 4; ++k) side += (mm.pos[corner[(k + 1) % 4]] - mm.pos[corner[k]]).Norm();
        if (std::fabs(ac - bd) <= kFlatTolerance * side / 4) return kEitherDiagonal;
        return ac < bd ? kDiagonal02 : kDiagonal13;
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
