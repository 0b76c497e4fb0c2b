// Boundaries between face regions (region ids per face, e.g. from the VSA segmentation):
//
//   MeshEdgeTopology   index-based edge adjacency of a const triangle mesh (no vcg adjacency
//                      component needed, the mesh is never touched): vertex -> face lists, and the
//                      edges of the shared twin pairing (EdgePairing) numbered in face order.
//                      Also the ordered fan of faces around a vertex, with its corner angles.
//   RegionBoundaryGraph boundary edges (a manifold edge whose two faces have different ids),
//                      corners and curves: maximal chains of boundary edges between corners, each
//                      separating one pair of regions; chains without corners are closed loops.
//   MergeSmallRegions  optional clean-up: regions below a face count join the neighbour they share
//                      the longest boundary with (on a copy of the labels).
//
// Shared by the boundary smoothing (filter 2), the splitting (filter 3) and Q-Morph (filter 4).
#ifndef VCG_EXT_BOUNDARY_REGION_BOUNDARY_H
#define VCG_EXT_BOUNDARY_REGION_BOUNDARY_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/edge_key.h>
#include <vcg_ext/common/edge_pairing.h>

namespace vcg_ext {

// Half-edge h = 3 * face + k runs from the face's vertex k to vertex (k + 1) % 3.
template <class MeshType>
class MeshEdgeTopology
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef vcg::Point3<double> Vec;

    enum EdgeKind : char { Border = 1, Manifold = 2, NonManifold = 3 };

    // Faces around a vertex v in order: face j has the corners v, ring[j], ring[j + 1] and the
    // corner angle angle[j] at v; start[j] is the sum of the angles before face j (so spoke j,
    // the edge v-ring[j], sits at the unfolded polar angle start[j]). A closed fan (interior
    // vertex) has ring.size() == faces.size() and wraps around; an open fan (mesh border) has one
    // more ring vertex than faces.
    struct Fan {
        std::vector<int> faces;
        std::vector<int> ring;
        std::vector<int> spokeEdge;  // edge id of each spoke v-ring[j]
        std::vector<double> angle;
        std::vector<double> start;
        double total = 0;    // sum of the corner angles
        bool closed = false;
        int Spokes() const { return int(ring.size()); }
        double SpokeAngle(int j) const { return j < int(start.size()) ? start[j] : total; }
    };

    const MeshType *mesh = nullptr;
    int vertexCount = 0;                       // size of m.vert (deleted vertices included)
    int faceCount = 0;                         // size of m.face (deleted faces included)
    std::vector<std::array<int, 3>> faceVerts; // vertex indices per face, {-1,-1,-1} when deleted or ignored
    int ignoredFaces = 0;                      // live faces with a repeated vertex: left out (no edges, no area)
    std::vector<int> vertFaceStart, vertFaces; // live faces around each vertex (CSR)
    std::vector<int> edgeOf;                   // edge id per half-edge, -1 for deleted faces
    std::vector<int> twin;                     // the other half-edge of a manifold edge, else -1
    std::vector<std::array<int, 2>> edgeVerts; // end points per edge: edge parameters run from [0] to [1]
    std::vector<int> edgeHalf;                 // a half-edge of each edge
    std::vector<char> edgeKind;                // EdgeKind per edge
    std::vector<char> vertOnBorder;            // vertex touches a border or non-manifold edge

    void Build(const MeshType &m)
    {
        mesh = &m;
        vertexCount = int(m.vert.size());
        faceCount = int(m.face.size());
        faceVerts.assign(faceCount, {-1, -1, -1});
        std::vector<int> count(vertexCount + 1, 0);
        ignoredFaces = 0;
        for (int f = 0; f < faceCount; ++f) {
            const FaceType &face = m.face[f];
            if (face.IsD()) continue;
            std::array<int, 3> v;
            for (int k = 0; k < 3; ++k) v[k] = int(vcg::tri::Index(m, face.cV(k)));
            if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) { ++ignoredFaces; continue; }  // no edges, no area
            faceVerts[f] = v;
            for (int k = 0; k < 3; ++k) ++count[v[k]];
        }
        vertFaceStart.assign(vertexCount + 1, 0);
        for (int v = 0; v < vertexCount; ++v) vertFaceStart[v + 1] = vertFaceStart[v] + count[v];
        vertFaces.assign(vertFaceStart[vertexCount], -1);
        std::vector<int> fill(vertFaceStart.begin(), vertFaceStart.end() - 1);
        for (int f = 0; f < faceCount; ++f)
            if (faceVerts[f][0] >= 0)
                for (int k = 0; k < 3; ++k) vertFaces[fill[faceVerts[f][k]]++] = f;

        // Edges numbered in the order of their first half-edge (face order).
        const EdgePairing::Groups groups = EdgePairing::Group(faceVerts);
        std::vector<int> order(groups.Count());
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](int x, int y) { return groups.Begin(x)[0] < groups.Begin(y)[0]; });
        edgeOf.assign(3 * size_t(faceCount), -1);
        twin.assign(3 * size_t(faceCount), -1);
        edgeVerts.clear();
        edgeHalf.clear();
        edgeKind.clear();
        vertOnBorder.assign(vertexCount, 0);
        for (int g : order) {
            const int id = int(edgeVerts.size()), n = groups.Size(g), *h = groups.Begin(g);
            const int a = EdgePairing::From(faceVerts, h[0]), b = EdgePairing::To(faceVerts, h[0]);
            edgeVerts.push_back({a, b});
            edgeHalf.push_back(h[0]);
            for (int i = 0; i < n; ++i) edgeOf[h[i]] = id;
            if (n == 2) {
                edgeKind.push_back(Manifold);
                twin[h[0]] = h[1];
                twin[h[1]] = h[0];
            } else {
                edgeKind.push_back(n == 1 ? Border : NonManifold);
                vertOnBorder[a] = vertOnBorder[b] = 1;
            }
        }
    }

    int EdgeCount() const { return int(edgeVerts.size()); }
    int FacesAround(int v) const { return vertFaceStart[v + 1] - vertFaceStart[v]; }
    const int *FacesBegin(int v) const { return vertFaces.data() + vertFaceStart[v]; }
    const int *FacesEnd(int v) const { return vertFaces.data() + vertFaceStart[v + 1]; }
    bool IsManifoldEdge(int e) const { return edgeKind[e] == Manifold; }

    // The one or two faces of a border or manifold edge (count returned).
    int EdgeFaces(int e, int faces[2]) const
    {
        int h = edgeHalf[e];
        faces[0] = h / 3;
        if (twin[h] < 0) return 1;
        faces[1] = twin[h] / 3;
        return 2;
    }

    bool FaceHasVertex(int f, int v) const
    {
        return faceVerts[f][0] == v || faceVerts[f][1] == v || faceVerts[f][2] == v;
    }
    int CornerOf(int f, int v) const
    {
        for (int k = 0; k < 3; ++k)
            if (faceVerts[f][k] == v) return k;
        return -1;
    }
    int EdgeInFace(int f, int a, int b) const  // the edge a-b of face f, or -1
    {
        for (int k = 0; k < 3; ++k) {
            int u = faceVerts[f][k], w = faceVerts[f][(k + 1) % 3];
            if ((u == a && w == b) || (u == b && w == a)) return edgeOf[3 * f + k];
        }
        return -1;
    }
    int SideOf(int f, int e) const  // k with edgeOf[3f+k] == e, or -1
    {
        for (int k = 0; k < 3; ++k)
            if (edgeOf[3 * f + k] == e) return k;
        return -1;
    }
    // The edge between two vertices, or -1 (searches the faces of a).
    int EdgeBetween(int a, int b) const
    {
        for (const int *it = FacesBegin(a); it != FacesEnd(a); ++it) {
            int f = *it, c = CornerOf(f, a);
            if (faceVerts[f][(c + 1) % 3] == b) return edgeOf[3 * f + c];
            if (faceVerts[f][(c + 2) % 3] == b) return edgeOf[3 * f + (c + 2) % 3];
        }
        return -1;
    }

    Vec Position(int v) const { return Vec::Construct(mesh->vert[v].cP()); }
    double EdgeLength(int e) const { return (Position(edgeVerts[e][1]) - Position(edgeVerts[e][0])).Norm(); }

    // The ordered fan around v; false when v is not a manifold vertex with a single fan of
    // non-degenerate faces (non-manifold edges, several fans, repeated vertices).
    bool VertexFan(int v, Fan &fan) const
    {
        fan.faces.clear();
        fan.ring.clear();
        fan.closed = false;
        const int n = FacesAround(v);
        if (n == 0) return false;
        const int f0 = *FacesBegin(v);
        int c = CornerOf(f0, v);
        // Forward: leave each face through the spoke to its last ring vertex (into fan's own
        // vectors: fans are rebuilt for every vertex move, so no allocation once they have grown).
        fan.faces.push_back(f0);
        fan.ring.push_back(faceVerts[f0][(c + 1) % 3]);
        fan.ring.push_back(faceVerts[f0][(c + 2) % 3]);
        int f = f0;
        for (;;) {
            int out = fan.ring.back();
            int g = Across(f, v, out);
            if (g == -2) return false;
            if (g < 0) break;
            if (g == f0) { fan.closed = true; break; }
            if (int(fan.faces.size()) >= n) return false;
            fan.faces.push_back(g);
            fan.ring.push_back(ThirdVertex(g, v, out));
            f = g;
        }
        if (fan.closed) {
            fan.ring.pop_back();  // back at the first ring vertex
        } else {
            // Backward from f0 through the spoke to its first ring vertex, prepended (border vertices only).
            std::vector<int> backFaces, backRing;
            f = f0;
            int in = fan.ring.front();
            for (;;) {
                int g = Across(f, v, in);
                if (g == -2) return false;
                if (g < 0) break;
                if (int(fan.faces.size() + backFaces.size()) >= n) return false;
                backFaces.push_back(g);
                in = ThirdVertex(g, v, in);
                backRing.push_back(in);
                f = g;
            }
            fan.faces.insert(fan.faces.begin(), backFaces.rbegin(), backFaces.rend());
            fan.ring.insert(fan.ring.begin(), backRing.rbegin(), backRing.rend());
        }
        if (int(fan.faces.size()) != n) return false;  // more than one fan
        fan.spokeEdge.resize(fan.ring.size());
        for (size_t j = 0; j < fan.ring.size(); ++j)
            fan.spokeEdge[j] = EdgeInFace(fan.faces[std::min(j, fan.faces.size() - 1)], v, fan.ring[j]);
        const Vec p = Position(v);
        fan.angle.resize(n);
        fan.start.resize(n);
        fan.total = 0;
        for (int j = 0; j < n; ++j) {
            fan.start[j] = fan.total;
            fan.angle[j] = Angle(Position(fan.ring[j]) - p, Position(fan.ring[(j + 1) % fan.ring.size()]) - p);
            fan.total += fan.angle[j];
        }
        return true;
    }

    // Angle between two vectors in [0, pi] (atan2: accurate near 0 and pi).
    static double Angle(const Vec &a, const Vec &b)
    {
        return std::atan2((a ^ b).Norm(), a * b);
    }

private:
    // The face across the edge v-w of face f: -1 across a border, -2 when not manifold.
    int Across(int f, int v, int w) const
    {
        for (int k = 0; k < 3; ++k) {
            int a = faceVerts[f][k], b = faceVerts[f][(k + 1) % 3];
            if ((a == v && b == w) || (a == w && b == v)) {
                int e = edgeOf[3 * f + k];
                if (edgeKind[e] == Border) return -1;
                if (edgeKind[e] != Manifold) return -2;
                int g = twin[3 * f + k] / 3;
                if (CornerOf(g, v) < 0 || ThirdVertex(g, v, w) < 0) return -2;
                return g;
            }
        }
        return -2;
    }
    int ThirdVertex(int g, int v, int w) const
    {
        for (int k = 0; k < 3; ++k)
            if (faceVerts[g][k] != v && faceVerts[g][k] != w) return faceVerts[g][k];
        return -1;
    }
};

// A chain of boundary edges between two corners, or a closed loop.
struct BoundaryCurve {
    std::vector<int> vertices;  // mesh vertices in order; a closed loop does not repeat its first one
    std::vector<int> edges;     // mesh edge ids: edges[i] joins vertices[i] and vertices[i + 1] (cyclically if closed)
    bool closed = false;
    int regionLeft = -1;        // region of the face whose edge runs along the curve (left side on an outward-oriented mesh)
    int regionRight = -1;
};

template <class MeshType>
class RegionBoundaryGraph
{
public:
    typedef MeshEdgeTopology<MeshType> Topology;

    std::string error;                 // empty on success
    std::vector<char> isBoundaryEdge;  // per edge id
    int boundaryEdges = 0;
    std::vector<char> isCorner;        // per vertex
    std::vector<int> corners;          // corner vertices, ascending
    std::vector<BoundaryCurve> curves;
    int closedLoops = 0;
    int regions = 0;                   // distinct ids on live faces

    // Corners: vertices with boundary edges where the boundary cannot be followed through: not
    // exactly two boundary edges (branching, a region touching itself at the vertex, an end), three
    // or more regions around the vertex, or a vertex on the mesh border or not manifold.
    // Fails (error set) when a non-manifold edge separates different regions.
    static RegionBoundaryGraph Build(const Topology &t, const std::vector<int> &faceRegion)
    {
        RegionBoundaryGraph g;
        g.regions = CountRegions(t, faceRegion);
        const int E = t.EdgeCount();
        g.isBoundaryEdge.assign(E, 0);
        int nonManifold = 0;
        std::vector<int> degree(t.vertexCount, 0);
        for (int e = 0; e < E; ++e) {
            if (t.edgeKind[e] == Topology::Border) continue;
            if (t.edgeKind[e] == Topology::NonManifold) {
                if (!SameRegionAround(t, faceRegion, e)) ++nonManifold;
                continue;
            }
            int h = t.edgeHalf[e];
            if (faceRegion[h / 3] == faceRegion[t.twin[h] / 3]) continue;
            g.isBoundaryEdge[e] = 1;
            ++g.boundaryEdges;
            ++degree[t.edgeVerts[e][0]];
            ++degree[t.edgeVerts[e][1]];
        }
        if (nonManifold) {
            g.error = std::to_string(nonManifold) + " non-manifold edges (with more than two faces) lie on a region boundary";
            return g;
        }
        // Boundary edges around each vertex (CSR over all vertices; empty for most).
        std::vector<int> start(t.vertexCount + 1, 0);
        for (int v = 0; v < t.vertexCount; ++v) start[v + 1] = start[v] + degree[v];
        std::vector<int> around(start[t.vertexCount]), fill(start.begin(), start.end() - 1);
        for (int e = 0; e < E; ++e)
            if (g.isBoundaryEdge[e]) {
                around[fill[t.edgeVerts[e][0]]++] = e;
                around[fill[t.edgeVerts[e][1]]++] = e;
            }
        g.isCorner.assign(t.vertexCount, 0);
        typename Topology::Fan fan;
        for (int v = 0; v < t.vertexCount; ++v) {
            if (degree[v] == 0) continue;
            bool corner = degree[v] != 2 || t.vertOnBorder[v] || RegionsAround(t, faceRegion, v) >= 3 ||
                          !t.VertexFan(v, fan);
            if (corner) { g.isCorner[v] = 1; g.corners.push_back(v); }
        }
        // Curves from each corner, then the loops left over.
        std::vector<char> used(E, 0);
        auto walk = [&](int v0, int e0, bool loop) {
            BoundaryCurve c;
            c.closed = loop;
            c.vertices.push_back(v0);
            int v = v0, e = e0;
            for (;;) {
                used[e] = 1;
                c.edges.push_back(e);
                int w = t.edgeVerts[e][0] == v ? t.edgeVerts[e][1] : t.edgeVerts[e][0];
                if (loop ? w == v0 : bool(g.isCorner[w])) {
                    if (!loop) c.vertices.push_back(w);
                    break;
                }
                c.vertices.push_back(w);
                int next = around[start[w]] == e ? around[start[w] + 1] : around[start[w]];
                v = w;
                e = next;
            }
            SetRegions(t, faceRegion, c);
            g.curves.push_back(c);
        };
        for (int v : g.corners)
            for (int i = start[v]; i < start[v + 1]; ++i)
                if (!used[around[i]]) walk(v, around[i], false);
        for (int e = 0; e < E; ++e)
            if (g.isBoundaryEdge[e] && !used[e]) {
                walk(t.edgeVerts[e][0], e, true);
                ++g.closedLoops;
            }
        return g;
    }

    static int CountRegions(const Topology &t, const std::vector<int> &faceRegion)
    {
        std::unordered_set<int> ids;
        int last = 0;
        bool first = true;
        for (int f = 0; f < t.faceCount; ++f)
            if (t.faceVerts[f][0] >= 0 && (first || faceRegion[f] != last)) {  // runs of one id are common
                last = faceRegion[f];
                first = false;
                ids.insert(last);
            }
        return int(ids.size());
    }

private:
    static bool SameRegionAround(const Topology &t, const std::vector<int> &faceRegion, int e)
    {
        int a = t.edgeVerts[e][0], r = -1;
        bool first = true;
        for (const int *it = t.FacesBegin(a); it != t.FacesEnd(a); ++it)
            for (int k = 0; k < 3; ++k)
                if (t.edgeOf[3 * *it + k] == e) {
                    if (!first && faceRegion[*it] != r) return false;
                    r = faceRegion[*it];
                    first = false;
                }
        return true;
    }
    static int RegionsAround(const Topology &t, const std::vector<int> &faceRegion, int v)
    {
        int ids[3], n = 0;
        for (const int *it = t.FacesBegin(v); it != t.FacesEnd(v); ++it) {
            int r = faceRegion[*it];
            if (std::find(ids, ids + n, r) != ids + n) continue;
            ids[n++] = r;
            if (n == 3) return 3;
        }
        return n;
    }
    // Left: the face whose half-edge runs from vertices[0] to vertices[1].
    static void SetRegions(const Topology &t, const std::vector<int> &faceRegion, BoundaryCurve &c)
    {
        int e = c.edges[0], h = t.edgeHalf[e], o = t.twin[h];
        int f = h / 3, g = o / 3;
        if (t.faceVerts[f][h % 3] != c.vertices[0]) std::swap(f, g);
        c.regionLeft = faceRegion[f];
        c.regionRight = faceRegion[g];
    }
};

// Regions with fewer than `minFaces` faces join the edge-adjacent region they share the longest
// boundary with, smallest first, repeated until none is left (or it has no neighbour). Returns
// the new labels (ids of surviving regions unchanged) and the number of regions merged away.
template <class MeshType>
std::vector<int> MergeSmallRegions(const MeshEdgeTopology<MeshType> &t, const std::vector<int> &faceRegion, int minFaces,
                                   int *mergedCount = nullptr)
{
    std::vector<int> label = faceRegion;
    int merged = 0;
    for (int round = 0; round < 64 && minFaces > 1; ++round) {
        std::unordered_map<int, int> size;
        for (int f = 0; f < t.faceCount; ++f)
            if (t.faceVerts[f][0] >= 0) ++size[label[f]];
        // Longest shared boundary per (small region, neighbour).
        std::unordered_map<uint64_t, double> shared;
        for (int e = 0; e < t.EdgeCount(); ++e) {
            if (!t.IsManifoldEdge(e)) continue;
            int h = t.edgeHalf[e];
            int a = label[h / 3], b = label[t.twin[h] / 3];
            if (a == b) continue;
            double len = t.EdgeLength(e);
            if (size[a] < minFaces) shared[DirectedKey(a, b)] += len;
            if (size[b] < minFaces) shared[DirectedKey(b, a)] += len;
        }
        std::unordered_map<int, std::pair<int, double>> best;  // small region -> (neighbour, length)
        for (auto &s : shared) {
            int a = int(uint32_t(s.first >> 32)), b = int(uint32_t(s.first));
            auto it = best.find(a);
            if (it == best.end() || s.second > it->second.second ||
                (s.second == it->second.second && b < it->second.first))
                best[a] = {b, s.second};
        }
        if (best.empty()) break;
        // Smallest first; a region that receives another one this round is not merged itself.
        std::vector<int> small;
        for (auto &b : best) small.push_back(b.first);
        std::sort(small.begin(), small.end(), [&](int a, int b) { return size[a] != size[b] ? size[a] < size[b] : a < b; });
        std::unordered_map<int, int> target;
        std::unordered_map<int, char> receives;
        for (int r : small) {
            int to = best[r].first;
            if (receives.count(r) || target.count(to)) continue;
            target[r] = to;
            receives[to] = 1;
        }
        for (int f = 0; f < t.faceCount; ++f) {
            if (t.faceVerts[f][0] < 0) continue;
            auto it = target.find(label[f]);
            if (it != target.end()) label[f] = it->second;
        }
        merged += int(target.size());
    }
    if (mergedCount) *mergedCount = merged;
    return label;
}

}  // namespace vcg_ext

#endif
