// Boundaries between face regions (region ids per face, e.g. from the VSA segmentation), on a
// MeshEdgeTopology:
//   RegionBoundaryGraph boundary edges (a manifold edge whose two faces have different ids),
//                      corners and curves: maximal chains of boundary edges between corners, each
//                      separating one pair of regions; chains without corners are closed loops.
//   MergeRegions       clean-up: regions below a face count (optional) or a width join the
//                      neighbour they share the longest boundary with (on a copy of the labels).
// Used by the boundary smoothing (filter 2).
#ifndef VCG_EXT_BOUNDARY_REGION_BOUNDARY_H
#define VCG_EXT_BOUNDARY_REGION_BOUNDARY_H

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <vcg_ext/boundary/mesh_edge_topology.h>
#include <vcg_ext/common/edge_key.h>

namespace vcg_ext {

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
            g.error = std::to_string(nonManifold) + " non-manifold edges (with more than two faces) lie on a region boundary; "
                      "run 'Repair non Manifold Edges by removing faces' first";
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

// Region sizes for the clean-ups below.
struct RegionSize {
    int faces = 0;
    double area = 0;
    double boundaryLength = 0;  // edges shared with other regions
};

// Regions that `merge(size)` picks join the edge-adjacent region they share the longest boundary
// with, smallest first (by faces), repeated until none is left (or it has no neighbour); a region
// that receives another one in a round waits for the next. Returns the new labels (ids of
// surviving regions unchanged) and the number of regions merged away.
template <class MeshType, class Pick>
std::vector<int> MergeRegions(const MeshEdgeTopology<MeshType> &t, const std::vector<int> &faceRegion, Pick merge,
                              int *mergedCount = nullptr)
{
    std::vector<int> label = faceRegion;
    int merged = 0;
    std::vector<double> faceArea(t.faceCount);  // the same every round
    for (int f = 0; f < t.faceCount; ++f) faceArea[f] = t.DoubleArea(f) / 2;
    for (int round = 0; round < 64; ++round) {
        std::unordered_map<int, RegionSize> size;
        for (int f = 0; f < t.faceCount; ++f)
            if (t.faceVerts[f][0] >= 0) {
                RegionSize &r = size[label[f]];
                ++r.faces;
                r.area += faceArea[f];
            }
        std::vector<double> edgeLength(t.EdgeCount(), -1);
        for (int e = 0; e < t.EdgeCount(); ++e) {
            if (!t.IsManifoldEdge(e)) continue;
            const int h = t.edgeHalf[e], a = label[h / 3], b = label[t.twin[h] / 3];
            if (a == b) continue;
            edgeLength[e] = t.EdgeLength(e);
            size[a].boundaryLength += edgeLength[e];
            size[b].boundaryLength += edgeLength[e];
        }
        std::unordered_map<int, char> picked;
        for (const auto &r : size)
            if (merge(r.second)) picked[r.first] = 1;
        if (picked.empty()) break;
        // Longest shared boundary per (picked region, neighbour).
        std::unordered_map<uint64_t, double> shared;
        for (int e = 0; e < t.EdgeCount(); ++e) {
            if (edgeLength[e] < 0) continue;
            const int h = t.edgeHalf[e], a = label[h / 3], b = label[t.twin[h] / 3];
            if (picked.count(a)) shared[DirectedKey(a, b)] += edgeLength[e];
            if (picked.count(b)) shared[DirectedKey(b, a)] += edgeLength[e];
        }
        std::unordered_map<int, std::pair<int, double>> best;  // picked region -> (neighbour, length)
        for (auto &sh : shared) {
            int a = int(uint32_t(sh.first >> 32)), b = int(uint32_t(sh.first));
            auto it = best.find(a);
            if (it == best.end() || sh.second > it->second.second ||
                (sh.second == it->second.second && b < it->second.first))
                best[a] = {b, sh.second};
        }
        if (best.empty()) break;
        std::vector<int> small;
        for (auto &b : best) small.push_back(b.first);
        std::sort(small.begin(), small.end(),
                  [&](int a, int b) { return size[a].faces != size[b].faces ? size[a].faces < size[b].faces : a < b; });
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

// Regions with fewer than `minFaces` faces join their neighbour (MergeRegions).
template <class MeshType>
std::vector<int> MergeSmallRegions(const MeshEdgeTopology<MeshType> &t, const std::vector<int> &faceRegion, int minFaces,
                                   int *mergedCount = nullptr)
{
    return MergeRegions(t, faceRegion, [minFaces](const RegionSize &r) { return r.faces < minFaces; }, mergedCount);
}

// Regions narrower than `minWidth` join their neighbour (MergeRegions). A region's width is twice
// its area over its boundary length (a strip's width; a disc's radius): CAD tessellations have
// slivers folded across a crease whose normal makes them regions of their own, a few thousandths
// of an edge wide, and their boundaries would become front curves a hair apart.
template <class MeshType>
std::vector<int> MergeThinRegions(const MeshEdgeTopology<MeshType> &t, const std::vector<int> &faceRegion, double minWidth,
                                  int *mergedCount = nullptr)
{
    return MergeRegions(
        t, faceRegion, [minWidth](const RegionSize &r) { return r.boundaryLength > 0 && 2 * r.area < minWidth * r.boundaryLength; },
        mergedCount);
}

}  // namespace vcg_ext

#endif
