// All quads: one split of every face of a quad-dominant mesh (MeshLab's polygonal form, a quad is two
// triangles sharing a faux edge) into quads, as the first step of Catmull-Clark subdivision without
// its smoothing: a point at every edge's midpoint and at every face's centre; a quad becomes four
// quads, a triangle three. Every vertex keeps its valence, the new ones are regular (face centres
// of triangles: valence 3), so no triangle is left and the structure is kept.
//
// A triangle that would split badly is first merged with a quad across one of its edges (not a
// front edge, not a sharp one) into a pentagon, split into five quads around its centre: a sliver
// left between a kink of the front and a quad's chord across it stands on edge on the input, and
// its three children turned over (armadillo_52k, feline_100k) or fell below 0.3 (block's knife
// edge). The merge is made only when the pentagon's worst child is clearly better than the worst
// child of the triangle and the quad split apart (scaled Jacobian against the input's normal, the
// new points where the split puts them); the pentagon's centre has valence 5 where the triangle's
// had 3, and the shared edge's two ends lose one edge each.
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
#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/common/edge_key.h>
#include <vcg_ext/common/face_face_adjacency.h>
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

    struct Stats {
        int quads = 0;       // quads made
        int pentagons = 0;   // triangles merged with a quad first (each pentagon makes 5 quads, not 4 + 3)
    };

    // Splits every face of m (faux-edge quads and triangles) into quads; surface: the input.
    static Stats Split(MeshType &m, InputSurface<MeshType> &surface, double creaseAngleDeg)
    {
        vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
        FaceFaceAdjacency<MeshType>::Update(m);
        const bool hasQuality = vcg::tri::HasPerFaceQuality(m);
        std::vector<Polygon> polygons = Gather(m);
        std::unordered_set<uint64_t> selected;
        for (FaceType &f : m.face)
            for (int k = 0; k < 3; ++k)
                if (f.IsFaceEdgeS(k)) selected.insert(Key(m, f.V0(k), f.V1(k)));

        std::vector<P3> pos;
        for (const VertexType &v : m.vert) pos.push_back(P3::Construct(v.cP()));
        const double creaseCos = std::cos(creaseAngleDeg * M_PI / 180);
        Stats st;
        st.pentagons = MergePoorTriangles(polygons, pos, selected, surface, creaseAngleDeg);
        std::vector<P3> normal;  // per polygon, unit
        for (const Polygon &p : polygons) normal.push_back(PolygonNormal(pos, p));

        // edge midpoints: one new point per edge, shared by its two faces
        const std::unordered_map<uint64_t, std::array<int, 2>> sides = Sides(polygons);  // edge -> its (at most two) polygons
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
            const std::array<int, 2> &side = sides.at(key);
            const int a = int(key >> 32), b = int(key & 0xffffffffu);
            P3 mid = (pos[a] + pos[b]) * 0.5;
            straight.push_back(mid);
            const bool sharp = side[1] < 0 || normal[side[0]] * normal[side[1]] < creaseCos;
            if (!sharp && !selected.count(key)) mid = OnSurface(surface, mid, normal[side[0]], kReachOfSize * vcg::Distance(pos[a], pos[b]));
            midpoint[key] = int(pos.size());
            pos.push_back(mid);
        }
        // face centres and the new quads
        std::vector<NewQuad> quads;
        std::vector<int> firstQuad;  // per polygon: its first quad (the others follow)
        for (size_t i = 0; i < polygons.size(); ++i) {
            const Polygon &p = polygons[i];
            firstQuad.push_back(int(quads.size()));
            const std::vector<int> byIndex = CornersByIndex(p);
            P3 centre(0, 0, 0);
            for (int k : byIndex) centre += pos[p.v[k]];
            centre /= double(p.size);
            const int c = int(pos.size());
            straight.push_back(centre);
            pos.push_back(OnSurface(surface, centre, normal[i], kReachOfSize * Size(pos, p)));
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
                P3 under;
                if (StateOf(ChildShape(q, pos), surface, under) == ChildState::Upright) continue;
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
        // a polygon whose quarters still turn over or invert (a thin or twisted face on a crease, a
        // face turning the other way than the input under one of its corners): its centre, its own
        // point, moved to where the worst of them is best
        const Children children{polygons, firstQuad, quads};
        for (size_t i = 0; i < polygons.size(); ++i)
            if (WorstQuadOf(children, int(i), pos, surface) <= 0) {
                const int centre = quads[firstQuad[i]].v[2];
                PlaceCentre(children, int(i), pos, straight[centre - oldVertices], surface);
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
        FaceFaceAdjacency<MeshType>::Update(m);
        st.quads = int(quads.size());
        return st;
    }

private:
    // Rounds of putting back new points whose quads turned over on the surface (a round can turn
    // a neighbour's quad back only by moving points it shares).
    static constexpr int kUnprojectRounds = 4;

    // A pentagon made of a triangle and a quad must be clearly better than the two split apart:
    // its worst child's scaled Jacobian (against the input's normal) above theirs by this much.
    static constexpr double kMergeGain = 0.05;

    // The search for a better centre: its steps in the first round, as fractions of the way from
    // the straight centre to each corner (negative: away from it), its rounds (the steps halved
    // each), and the least rise of the worst quad that moves the centre.
    static constexpr double kCentreSteps[4] = {0.25, 0.5, -0.25, -0.5};
    static constexpr int kCentreRounds = 4;
    static constexpr double kMinGain = 1e-3;
    // How far a new point may go to the input facing its face, as a fraction of the face's size
    // (its edge for a midpoint, its longest side for a centre): half, the most a midpoint's chord
    // can be off a sheet that faces the right way.
    static constexpr double kReachOfSize = 0.5;
    // A new quad turned over (the quality report's flipped face), below any scaled Jacobian.
    static constexpr double kTurnedOver = -2;

    struct NewQuad {
        std::array<int, 4> v;  // an old corner, a midpoint, the centre, a midpoint
        float quality;
    };

    struct Polygon {
        std::array<int, 5> v;  // indices into m.vert, counter-clockwise (a pentagon only from a merge)
        int size;
        float quality;
    };

    typedef std::unordered_map<uint64_t, std::array<int, 2>> SideMap;

    // Each edge of the polygons -> the (at most two) polygons on it (-1: none).
    static SideMap Sides(const std::vector<Polygon> &polygons)
    {
        SideMap sides;
        for (size_t i = 0; i < polygons.size(); ++i)
            for (int k = 0; k < polygons[i].size; ++k) {
                auto it = sides.emplace(EdgeKey(polygons[i].v[k], polygons[i].v[(k + 1) % polygons[i].size]), std::array<int, 2>{int(i), -1});
                if (!it.second) it.first->second[1] = int(i);
            }
        return sides;
    }

    // The worst scaled Jacobian, against the input surface's normal under each, of the quads the
    // split makes of p, with its new points about where the split puts them: the centre and the
    // midpoints of unselected edges on the input surface, those of selected edges straight (a
    // border or sharp edge's midpoint, which the split keeps straight too, is taken as projected:
    // on the polygon's own edge the two places differ little, and this only decides merges).
    // Corners visited in index order: the same value on a flipped copy.
    static double WorstChild(const Polygon &p, const std::vector<P3> &pos, const std::unordered_set<uint64_t> &selected,
                             InputSurface<MeshType> &surface)
    {
        const std::vector<int> byIndex = CornersByIndex(p);
        const P3 normal = PolygonNormal(pos, p);
        P3 centre(0, 0, 0);
        for (int k : byIndex) centre += pos[p.v[k]];
        centre = OnSurface(surface, centre / double(p.size), normal, kReachOfSize * Size(pos, p));
        auto midpoint = [&](int a, int b) {
            const P3 mid = (pos[a] + pos[b]) * 0.5;
            return selected.count(EdgeKey(a, b)) ? mid : OnSurface(surface, mid, normal, kReachOfSize * vcg::Distance(pos[a], pos[b]));
        };
        double worst = 1;
        for (int k : byIndex) {
            const int here = p.v[k], next = p.v[(k + 1) % p.size], prev = p.v[(k + p.size - 1) % p.size];
            const P3 q[4] = {pos[here], midpoint(here, next), centre, midpoint(prev, here)};
            const P3 area = VectorArea(q, 4);
            if (!(area.Norm() > 0)) return -1;
            const P3 n = surface.NormalUnder((q[0] + q[1] + q[2] + q[3]) / 4.0, area / area.Norm());
            worst = std::min(worst, IsFolded(q) ? -1.0 : ScaledJacobian(q, n));
        }
        return worst;
    }

    // Triangles whose children would be clearly worse than those of the pentagon they make with a
    // quad across a plain edge (not selected, not on a sharp edge of the input) are merged with the best such quad; a quad
    // takes at most one triangle. Triangles in the order of their lowest vertex, so a flipped copy
    // merges the same pairs. Merged quads become pentagons, merged triangles are removed. Returns
    // the merges.
    static int MergePoorTriangles(std::vector<Polygon> &polygons, const std::vector<P3> &pos,
                                  const std::unordered_set<uint64_t> &selected, InputSurface<MeshType> &surface,
                                  double creaseAngleDeg)
    {
        std::vector<int> triangles;
        for (size_t i = 0; i < polygons.size(); ++i)
            if (polygons[i].size == 3) triangles.push_back(int(i));
        if (triangles.empty()) return 0;
        std::sort(triangles.begin(), triangles.end(), [&](int a, int b) { return polygons[a].v[0] < polygons[b].v[0]; });
        const SideMap sides = Sides(polygons);
        std::vector<char> taken(polygons.size(), 0), removed(polygons.size(), 0);
        int merges = 0;
        for (int t : triangles) {
            const Polygon &tri = polygons[t];
            const double alone = WorstChild(tri, pos, selected, surface);
            double best = -std::numeric_limits<double>::infinity();
            int bestQuad = -1;
            Polygon bestPentagon{};
            for (int k = 0; k < 3; ++k) {
                const int a = tri.v[k], b = tri.v[(k + 1) % 3], apex = tri.v[(k + 2) % 3];
                const uint64_t key = EdgeKey(a, b);
                if (selected.count(key)) continue;
                const std::array<int, 2> &side = sides.at(key);
                const int q = side[0] == t ? side[1] : side[0];
                if (q < 0 || polygons[q].size != 4 || taken[q]) continue;
                const Polygon &quad = polygons[q];
                // a sharp edge of the input stays (the two faces' own angle would not tell: a sliver
                // standing on edge meets its quad at a right angle over smooth input)
                if (surface.OnCrease((pos[a] + pos[b]) * 0.5, creaseAngleDeg)) continue;
                // the quad runs b -> a (the triangle a -> b): the apex goes between them
                int at = -1;
                for (int j = 0; j < 4; ++j)
                    if (quad.v[j] == b && quad.v[(j + 1) % 4] == a) at = j;
                if (at < 0) continue;
                Polygon pentagon{{{-1, -1, -1, -1, -1}}, 5, quad.quality};
                for (int j = 0; j < 4; ++j) pentagon.v[j] = quad.v[(at + 1 + j) % 4];  // a, ..., b
                pentagon.v[4] = apex;
                pentagon = FromLowest(pentagon);
                const double merged = WorstChild(pentagon, pos, selected, surface);
                // the pair's worst child, split apart, against the pentagon's
                if (merged <= std::min(alone, WorstChild(quad, pos, selected, surface)) + kMergeGain) continue;
                if (merged > best || (merged == best && bestQuad >= 0 && q < bestQuad)) {
                    best = merged;
                    bestQuad = q;
                    bestPentagon = pentagon;
                }
            }
            if (bestQuad < 0) continue;
            polygons[bestQuad] = bestPentagon;
            taken[bestQuad] = 1;
            removed[t] = 1;
            ++merges;
        }
        if (merges) {
            size_t kept = 0;
            for (size_t i = 0; i < polygons.size(); ++i)
                if (!removed[i]) polygons[kept++] = polygons[i];
            polygons.resize(kept);
        }
        return merges;
    }

    // p from its lowest vertex on, in its own order.
    static Polygon FromLowest(const Polygon &p)
    {
        const int r = int(std::min_element(p.v.begin(), p.v.begin() + p.size) - p.v.begin());
        Polygon q = p;
        for (int k = 0; k < p.size; ++k) q.v[k] = p.v[(r + k) % p.size];
        return q;
    }

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
            Polygon p{{{-1, -1, -1, -1, -1}}, n, hasQuality ? float(f.Q()) : 0.f};
            std::copy(corners.begin(), corners.begin() + n, p.v.begin());
            polygons.push_back(FromLowest(p));
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
        P3 corners[5];
        for (int k = 0; k < p.size; ++k) corners[k] = pos[p.v[k]];
        P3 n = VectorArea(corners, p.size);
        return n.Norm() > 0 ? n / n.Norm() : n;
    }
    static P3 QuadNormal(const std::vector<P3> &pos, const std::array<int, 4> &v)
    {
        const P3 corners[4] = {pos[v[0]], pos[v[1]], pos[v[2]], pos[v[3]]};
        return VectorArea(corners, 4);
    }

    // A new quad's corners read from the old corner towards the lower-numbered midpoint (the same
    // array both ways round, so a flipped copy gets the same values) and its own vector area.
    struct ChildShape {
        P3 corners[4];
        P3 area;
        bool backwards;
        ChildShape(const NewQuad &q, const std::vector<P3> &pos) : backwards(q.v[3] < q.v[1])
        {
            corners[0] = pos[q.v[0]];
            corners[1] = pos[q.v[backwards ? 3 : 1]];
            corners[2] = pos[q.v[2]];
            corners[3] = pos[q.v[backwards ? 1 : 3]];
            area = VectorArea(corners, 4);  // of the corners as read: the quad's own is the other way when backwards
            if (backwards) area = -area;
        }
    };
    enum class ChildState { Upright, FoldedOrFlat, TurnedOver };

    // Whether a new quad is folded or without area, turned against the input surface's normal under
    // its centroid, or upright (then `under` is that normal).
    static ChildState StateOf(const ChildShape &s, InputSurface<MeshType> &surface, P3 &under)
    {
        if (!(s.area.Norm() > 0) || IsFolded(s.corners)) return ChildState::FoldedOrFlat;
        under = surface.NormalUnder((s.corners[0] + s.corners[1] + s.corners[2] + s.corners[3]) / 4.0, s.area / s.area.Norm());
        return under * s.area > 0 ? ChildState::Upright : ChildState::TurnedOver;
    }

    // A new quad's quality against the input surface: its scaled Jacobian with the normal under it,
    // -1 when folded or without area, kTurnedOver (worse) when turned over.
    static double ChildQuality(const NewQuad &q, const std::vector<P3> &pos, InputSurface<MeshType> &surface)
    {
        const ChildShape s(q, pos);
        P3 under;
        switch (StateOf(s, surface, under)) {
        case ChildState::FoldedOrFlat: return -1;
        case ChildState::TurnedOver: return kTurnedOver;
        default: return ScaledJacobian(s.corners, s.backwards ? -under : under);
        }
    }

    // The polygons and their new quads: polygon i's from firstQuad[i] on, one per corner, the
    // polygon's centre their third corner.
    struct Children {
        const std::vector<Polygon> &polygons;
        const std::vector<int> &firstQuad;
        const std::vector<NewQuad> &quads;
    };

    // The worst ChildQuality of polygon i's quads (as they are now).
    static double WorstQuadOf(const Children &ch, int i, const std::vector<P3> &pos, InputSurface<MeshType> &surface)
    {
        double worst = 1;
        for (int k = 0; k < ch.polygons[i].size; ++k) worst = std::min(worst, ChildQuality(ch.quads[ch.firstQuad[i] + k], pos, surface));
        return worst;
    }

    // Polygon i's centre (a point no other polygon has) searched for about its straight place
    // `centre`: a pattern search of steps toward and away from each corner, each place tried as it
    // is and moved onto the surface, the steps halved each round from the best place so far; the
    // place whose worst quad is best is kept if it is better than where the centre is.
    static void PlaceCentre(const Children &ch, int i, std::vector<P3> &pos, const P3 &centre, InputSurface<MeshType> &surface)
    {
        const Polygon &p = ch.polygons[i];
        P3 &c = pos[ch.quads[ch.firstQuad[i]].v[2]];
        const P3 normal = PolygonNormal(pos, p);
        const double reach = kReachOfSize * Size(pos, p);
        P3 best = c, base = centre;  // base: the best place's straight place, where the next steps start
        double bestWorst = WorstQuadOf(ch, i, pos, surface) + kMinGain, scale = 1;
        for (int round = 0; round < kCentreRounds; ++round, scale /= 2) {
            const P3 from = base;
            for (int k : CornersByIndex(p))
                for (double step : kCentreSteps) {
                    const P3 place = from + (pos[p.v[k]] - centre) * (step * scale);
                    for (const P3 &candidate : {place, OnSurface(surface, place, normal, reach)}) {
                        c = candidate;
                        const double worst = WorstQuadOf(ch, i, pos, surface);
                        if (worst > bestWorst) {
                            bestWorst = worst;
                            best = candidate;
                            base = place;
                        }
                    }
                }
        }
        c = best;
    }

    // p moved onto the input surface. Where the input closest to p faces away from `normal` (a part
    // thinner than the face: p is nearer the sheet behind), onto the nearest input facing `normal`
    // within `reach` (left in place if there is none): a point left between the sheets makes its
    // quads' centroids nearer the sheet behind, so they face away from the input under them.
    static P3 OnSurface(InputSurface<MeshType> &surface, const P3 &p, const P3 &normal, double reach)
    {
        CoordType closest;
        const FaceType *f = surface.Closest(CoordType::Construct(p), closest);
        if (!f) return p;
        if (P3::Construct(surface.Normal(f)) * normal > 0) return P3::Construct(closest);
        return surface.ClosestFacing(CoordType::Construct(p), normal, closest, reach) ? P3::Construct(closest) : p;
    }

    // A polygon's size: its longest side.
    static double Size(const std::vector<P3> &pos, const Polygon &p)
    {
        double longest = 0;
        for (int k = 0; k < p.size; ++k) longest = std::max(longest, vcg::Distance(pos[p.v[k]], pos[p.v[(k + 1) % p.size]]));
        return longest;
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
