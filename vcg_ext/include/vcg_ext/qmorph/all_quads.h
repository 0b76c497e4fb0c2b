// All quads: one split of every face of a quad-dominant mesh (MeshLab's polygonal form, a quad is two
// triangles sharing a faux edge) into quads, as the first step of Catmull-Clark subdivision without
// its smoothing: a point at every edge's midpoint and at every face's centre; a quad becomes four
// quads, a triangle three. Every vertex keeps its valence, the new ones are regular (face centres
// of triangles: valence 3), so no triangle is left and the structure is kept.
//
// Where new points go: on a selected (front) edge or a sharp edge (faces meeting at more than the
// crease angle) the exact midpoint, so the front and the creases keep their geometry and stay
// chains of (selected) edges, each cut in two the same way for both sides; elsewhere the midpoint
// and the face centre are moved onto the input surface, unless that would turn one of the new quads
// against the input surface's normal (then they stay where they are). Region ids (face quality)
// are kept per face.
//
// Orientation: a consistently flipped mesh must give the same split mirrored, bit for bit. Every
// polygon is read from its lowest vertex on, new points are numbered by edge key and polygon, sums
// of points are taken in vertex index order and each new quad's corners are also visited from its
// lower-numbered side, so the flipped copy makes the same points in the same order and the same
// quads reversed (normals exactly negated, as the input surface's then are too).
#ifndef VCG_EXT_QMORPH_ALL_QUADS_H
#define VCG_EXT_QMORPH_ALL_QUADS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/common/edge_key.h>
#include <vcg_ext/common/input_surface.h>
#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/quad_quality.h>

namespace vcg_ext {
namespace qmorph {

template <class MeshType>
class AllQuads
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef typename MeshType::CoordType CoordType;
    typedef vcg::Point3d P3;

    // Splits every face of m (faux-edge quads and triangles) into quads; surface: the input.
    // Returns the number of quads made.
    static int Split(MeshType &m, InputSurface<MeshType> &surface, double creaseAngleDeg)
    {
        vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
        vcg::tri::UpdateTopology<MeshType>::FaceFace(m);
        const bool hasQuality = vcg::tri::HasPerFaceQuality(m);
        std::vector<Polygon> polygons = Gather(m);
        std::unordered_set<uint64_t> selected;
        for (FaceType &f : m.face)
            for (int k = 0; k < 3; ++k)
                if (f.IsFaceEdgeS(k)) selected.insert(Key(m, f.V0(k), f.V1(k)));

        std::vector<P3> pos;
        for (const VertexType &v : m.vert) pos.push_back(P3::Construct(v.cP()));
        std::vector<P3> normal;  // per polygon, unit
        for (const Polygon &p : polygons) normal.push_back(PolygonNormal(pos, p));

        // edge midpoints: one new point per edge, shared by its two faces
        std::unordered_map<uint64_t, std::array<int, 2>> sides;  // edge -> the (at most two) polygons on it
        for (size_t i = 0; i < polygons.size(); ++i)
            for (int k = 0; k < polygons[i].size; ++k) {
                auto it = sides.emplace(EdgeKey(polygons[i].v[k], polygons[i].v[(k + 1) % polygons[i].size]), std::array<int, 2>{int(i), -1});
                if (!it.second) it.first->second[1] = int(i);
            }
        const double creaseCos = std::cos(creaseAngleDeg * M_PI / 180);
        const size_t oldVertices = pos.size();
        std::vector<P3> straight;  // per new point, its place before it was moved onto the surface
        std::unordered_map<uint64_t, int> midpoint;
        // by key, not in the map's order (which follows the order the edges were met in: flipped
        // polygons meet them otherwise)
        std::vector<uint64_t> edges;
        edges.reserve(sides.size());
        for (const auto &e : sides) edges.push_back(e.first);
        std::sort(edges.begin(), edges.end());
        for (uint64_t key : edges) {
            const std::array<int, 2> &side = sides[key];
            const int a = int(key >> 32), b = int(key & 0xffffffffu);
            P3 mid = (pos[a] + pos[b]) * 0.5;
            straight.push_back(mid);
            const bool sharp = side[1] < 0 || normal[side[0]] * normal[side[1]] < creaseCos;
            if (!sharp && !selected.count(key)) mid = OnSurface(surface, mid, normal[side[0]]);
            midpoint[key] = int(pos.size());
            pos.push_back(mid);
        }
        // face centres and the new quads (corner, midpoint, centre, midpoint)
        struct NewQuad {
            std::array<int, 4> v;
            float quality;
        };
        std::vector<NewQuad> quads;
        for (size_t i = 0; i < polygons.size(); ++i) {
            const Polygon &p = polygons[i];
            const std::vector<int> byIndex = CornersByIndex(p);
            P3 centre(0, 0, 0);
            for (int k : byIndex) centre += pos[p.v[k]];
            centre /= double(p.size);
            const int c = int(pos.size());
            straight.push_back(centre);
            pos.push_back(OnSurface(surface, centre, normal[i]));
            for (int k : byIndex) {  // the same quads in the same order, whichever way p runs
                const int prev = p.v[(k + p.size - 1) % p.size], here = p.v[k], next = p.v[(k + 1) % p.size];
                quads.push_back({{here, midpoint[EdgeKey(here, next)], c, midpoint[EdgeKey(prev, here)]}, p.quality});
            }
        }
        // a new quad turned against the input surface's normal, or folded: its new points go back to
        // their straight places (the parent face is neither, so neither are its straight quarters)
        for (int round = 0; round < kUnprojectRounds; ++round) {
            int reverted = 0;
            for (const NewQuad &q : quads) {
                // from the old corner towards the lower-numbered midpoint: the same array both ways round
                const bool backwards = q.v[3] < q.v[1];
                const P3 corners[4] = {pos[q.v[0]], pos[q.v[backwards ? 3 : 1]], pos[q.v[2]], pos[q.v[backwards ? 1 : 3]]};
                P3 n = VectorArea(corners, 4);
                if (backwards) n = -n;
                const P3 centroid = (corners[0] + corners[1] + corners[2] + corners[3]) / 4.0;
                if (n.Norm() > 0 && surface.NormalUnder(centroid, n / n.Norm()) * n > 0 && !IsFolded(corners)) continue;
                for (int k = 1; k < 4; ++k) {
                    const int x = q.v[k] - int(oldVertices);
                    if (pos[q.v[k]] != straight[x]) {
                        pos[q.v[k]] = straight[x];
                        ++reverted;
                    }
                }
            }
            if (!reverted) break;
        }

        // m rebuilt: the new points appended, two triangles (faux diagonal) per quad
        auto vi = vcg::tri::Allocator<MeshType>::AddVertices(m, pos.size() - oldVertices);
        for (size_t i = oldVertices; i < pos.size(); ++i, ++vi) vi->P() = CoordType::Construct(pos[i]);
        for (FaceType &f : m.face) vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
        std::unordered_set<uint64_t> front;  // the halves of every selected edge
        for (uint64_t e : selected) {
            const int a = int(e >> 32), b = int(e & 0xffffffffu), mid = midpoint[e];
            front.insert(EdgeKey(a, mid));
            front.insert(EdgeKey(mid, b));
        }
        auto fi = vcg::tri::Allocator<MeshType>::AddFaces(m, 2 * quads.size());
        for (const NewQuad &q : quads) {
            // the diagonal from the old corner to the face centre: no other face has that edge (the
            // other diagonal, between two midpoints, would be an edge twice around a doublet node)
            const std::array<int, 4> &v = q.v;
            const std::array<int, 3> t1{v[0], v[1], v[2]}, t2{v[0], v[2], v[3]};
            for (const std::array<int, 3> &t : {t1, t2}) {
                FaceType &f = *fi++;
                for (int k = 0; k < 3; ++k) f.V(k) = &m.vert[t[k]];
                f.Flags() = 0;
                if (hasQuality) f.Q() = q.quality;
                for (int k = 0; k < 3; ++k)
                    if (front.count(EdgeKey(t[k], t[(k + 1) % 3]))) f.SetFaceEdgeS(k);
            }
            (fi - 2)->SetF(2);  // t1's edge v[2] - v[0] and t2's edge v[0] - v[2]: the diagonal
            (fi - 1)->SetF(0);
        }
        vcg::tri::UpdateTopology<MeshType>::FaceFace(m);
        return int(quads.size());
    }

private:
    // Rounds of putting back new points whose quads turned over on the surface (a round can turn
    // a neighbour's quad back only by moving points it shares).
    static constexpr int kUnprojectRounds = 4;

    struct Polygon {
        std::array<int, 4> v;  // indices into m.vert, counter-clockwise
        int size;
        float quality;
    };

    static uint64_t Key(MeshType &m, VertexType *a, VertexType *b)
    {
        return EdgeKey(int(vcg::tri::Index(m, a)), int(vcg::tri::Index(m, b)));
    }

    // The faces of m as polygons (QuadQuality::ForEachFauxPolygon), each from its lowest vertex on
    // (a quad's first corner depends on which of its triangles comes first), with their region ids.
    static std::vector<Polygon> Gather(MeshType &m)
    {
        const bool hasQuality = vcg::tri::HasPerFaceQuality(m);
        std::vector<Polygon> polygons;
        QuadQuality::ForEachFauxPolygon(m, [&](FaceType &f, const std::array<int, 4> &corners, int n) {
            const int r = int(std::min_element(corners.begin(), corners.begin() + n) - corners.begin());
            std::array<int, 4> v{{-1, -1, -1, -1}};
            for (int k = 0; k < n; ++k) v[k] = corners[(r + k) % n];
            polygons.push_back({v, n, hasQuality ? float(f.Q()) : 0.f});
        });
        return polygons;
    }

    // The corner positions of p in the order of their vertex indices.
    static std::vector<int> CornersByIndex(const Polygon &p)
    {
        std::vector<int> k(p.size);
        for (int i = 0; i < p.size; ++i) k[i] = i;
        std::sort(k.begin(), k.end(), [&](int a, int b) { return p.v[a] < p.v[b]; });
        return k;
    }

    static P3 PolygonNormal(const std::vector<P3> &pos, const Polygon &p)
    {
        P3 corners[4];
        for (int k = 0; k < p.size; ++k) corners[k] = pos[p.v[k]];
        P3 n = VectorArea(corners, p.size);
        return n.Norm() > 0 ? n / n.Norm() : n;
    }
    static P3 QuadNormal(const std::vector<P3> &pos, const std::array<int, 4> &v)
    {
        const P3 corners[4] = {pos[v[0]], pos[v[1]], pos[v[2]], pos[v[3]]};
        return VectorArea(corners, 4);
    }

    // p moved onto the input surface, unless the input there faces away from `normal` (a thin part).
    static P3 OnSurface(InputSurface<MeshType> &surface, const P3 &p, const P3 &normal)
    {
        CoordType closest;
        const FaceType *f = surface.Closest(CoordType::Construct(p), closest);
        if (!f || P3::Construct(surface.Normal(f)) * normal <= 0) return p;
        return P3::Construct(closest);
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
