// Twin pairing of the half-edges of an indexed triangle list: the one builder of index topology.
// Half-edge h = 3 f + k of triangle f runs from tris[f][k] to tris[f][(k + 1) % 3]. The half-edges
// are grouped by the undirected edge they lie on (sorted by edge key, then by index): an edge with
// one half-edge is a boundary, with two a manifold edge (its twins), with more a non-manifold edge.
// O(F), no vcg adjacency needed, the mesh is never touched.
#ifndef VCG_EXT_COMMON_EDGE_PAIRING_H
#define VCG_EXT_COMMON_EDGE_PAIRING_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include <vcg_ext/common/edge_key.h>

namespace vcg_ext {

class EdgePairing
{
public:
    typedef std::array<int, 3> Triangle;

    static int From(const std::vector<Triangle> &tris, int h) { return tris[h / 3][h % 3]; }
    static int To(const std::vector<Triangle> &tris, int h) { return tris[h / 3][(h % 3 + 1) % 3]; }

    // The half-edges grouped by undirected edge. Left out: triangles whose first index is negative
    // (deleted), half-edges from a vertex to itself, and half-edges h with skip[h] set.
    struct Groups {
        std::vector<int> halfEdges;  // grouped, each group in index order
        std::vector<int> start;      // group g is halfEdges[start[g] .. start[g + 1])

        int Count() const { return int(start.size()) - 1; }
        int Size(int g) const { return start[g + 1] - start[g]; }
        const int *Begin(int g) const { return halfEdges.data() + start[g]; }
    };

    static Groups Group(const std::vector<Triangle> &tris, const std::vector<char> &skip = std::vector<char>())
    {
        // Linear: the half-edges bucketed by their edge's lower vertex (a counting sort, stable in
        // half-edge order), then each bucket (one vertex's few edges) sorted by the higher vertex;
        // the same order as sorting by (edge key, half-edge), without an O(F log F) sort of
        // millions of keys (it ran on every whole-mesh topology build).
        auto kept = [&](size_t f, int k) {
            const int h = int(3 * f) + k;
            return tris[f][k] != tris[f][(k + 1) % 3] && (skip.empty() || !skip[h]);
        };
        int vertices = 0;
        for (const Triangle &t : tris)
            if (t[0] >= 0) vertices = std::max(vertices, std::max(t[0], std::max(t[1], t[2])) + 1);
        std::vector<int> bucketStart(size_t(vertices) + 1, 0);
        for (size_t f = 0; f < tris.size(); ++f)
            if (tris[f][0] >= 0)
                for (int k = 0; k < 3; ++k)
                    if (kept(f, k)) ++bucketStart[size_t(std::min(tris[f][k], tris[f][(k + 1) % 3])) + 1];
        for (int v = 0; v < vertices; ++v) bucketStart[v + 1] += bucketStart[v];
        std::vector<std::pair<int, int>> entries(size_t(bucketStart[vertices]));  // (higher vertex, half-edge)
        std::vector<int> fill(bucketStart.begin(), bucketStart.end() - 1);
        for (size_t f = 0; f < tris.size(); ++f)
            if (tris[f][0] >= 0)
                for (int k = 0; k < 3; ++k)
                    if (kept(f, k)) {
                        const int a = tris[f][k], b = tris[f][(k + 1) % 3];
                        entries[size_t(fill[std::min(a, b)]++)] = {std::max(a, b), int(3 * f) + k};
                    }
        Groups g;
        g.halfEdges.resize(entries.size());
        g.start.push_back(0);
        for (int v = 0; v < vertices; ++v) {
            const auto first = entries.begin() + bucketStart[v], last = entries.begin() + bucketStart[v + 1];
            std::sort(first, last);
            for (auto it = first; it != last; ++it) {
                const size_t i = size_t(it - entries.begin());
                g.halfEdges[i] = it->second;
                if (it + 1 == last || (it + 1)->first != it->first) g.start.push_back(int(i + 1));
            }
        }
        return g;
    }

    // Per half-edge (3 per triangle): the other half-edge of its edge when the edge has exactly
    // two, else -1.
    static std::vector<int> Twins(const std::vector<Triangle> &tris, const std::vector<char> &skip = std::vector<char>())
    {
        return Twins(Group(tris, skip), 3 * tris.size());
    }
    static std::vector<int> Twins(const Groups &g, size_t halfEdgeCount)
    {
        std::vector<int> twin(halfEdgeCount, -1);
        for (int e = 0; e < g.Count(); ++e)
            if (g.Size(e) == 2) {
                const int *h = g.Begin(e);
                twin[h[0]] = h[1];
                twin[h[1]] = h[0];
            }
        return twin;
    }
};

}  // namespace vcg_ext

#endif
