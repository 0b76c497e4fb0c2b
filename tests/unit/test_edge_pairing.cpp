// EdgePairing (common/edge_pairing.h), the one builder of index topology: its linear grouping
// gives exactly the groups of sorting the half-edges by (edge key, half-edge index), on triangle
// soups with boundary, non-manifold and degenerate edges, deleted triangles and skipped half-edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include <vcg_ext/common/edge_key.h>
#include <vcg_ext/common/edge_pairing.h>

using vcg_ext::EdgePairing;

namespace {

// The reference: every kept half-edge keyed by its undirected edge, sorted, cut where the key changes.
std::vector<std::vector<int>> SortedGroups(const std::vector<EdgePairing::Triangle> &tris, const std::vector<char> &skip)
{
    std::vector<std::pair<uint64_t, int>> keyed;
    for (size_t f = 0; f < tris.size(); ++f) {
        if (tris[f][0] < 0) continue;
        for (int k = 0; k < 3; ++k) {
            const int h = int(3 * f) + k, a = tris[f][k], b = tris[f][(k + 1) % 3];
            if (a != b && (skip.empty() || !skip[h])) keyed.push_back({vcg_ext::EdgeKey(a, b), h});
        }
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::vector<int>> groups;
    for (size_t i = 0; i < keyed.size(); ++i) {
        if (i == 0 || keyed[i].first != keyed[i - 1].first) groups.emplace_back();
        groups.back().push_back(keyed[i].second);
    }
    return groups;
}

std::vector<std::vector<int>> Groups(const EdgePairing::Groups &g)
{
    std::vector<std::vector<int>> groups;
    for (int e = 0; e < g.Count(); ++e) groups.emplace_back(g.Begin(e), g.Begin(e) + g.Size(e));
    return groups;
}

}  // namespace

TEST(EdgePairing, LinearGroupingEqualsSortingByEdgeKeyOnSoups)
{
    std::mt19937 rng(7);
    for (int trial = 0; trial < 40; ++trial) {
        const int vertices = 3 + trial * 5, triangles = 2 + trial * 12;
        std::uniform_int_distribution<int> vertex(0, vertices - 1);
        std::vector<EdgePairing::Triangle> tris(static_cast<size_t>(triangles));
        for (auto &t : tris) t = {vertex(rng), vertex(rng), vertex(rng)};  // repeats: degenerate and non-manifold edges
        for (size_t f = 0; f < tris.size(); f += 7) tris[f] = {-1, -1, -1};  // deleted
        std::vector<char> skip;
        if (trial % 2) {
            skip.assign(3 * tris.size(), 0);
            for (size_t h = 0; h < skip.size(); h += 5) skip[h] = 1;
        }
        EXPECT_EQ(Groups(EdgePairing::Group(tris, skip)), SortedGroups(tris, skip)) << "trial " << trial;
    }
}

TEST(EdgePairing, TwinsOfATetrahedronAndAnOpenFan)
{
    // a closed tetrahedron: every half-edge has a twin running the other way
    const std::vector<EdgePairing::Triangle> tet = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
    const std::vector<int> twin = EdgePairing::Twins(tet);
    for (int h = 0; h < 12; ++h) {
        ASSERT_GE(twin[h], 0);
        EXPECT_EQ(twin[twin[h]], h);
        EXPECT_EQ(EdgePairing::From(tet, h), EdgePairing::To(tet, twin[h]));
    }
    // three triangles on edge 0-1 (non-manifold): no twins there; the fan's outer edges are borders
    const std::vector<EdgePairing::Triangle> fan = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const std::vector<int> fanTwin = EdgePairing::Twins(fan);
    for (int h = 0; h < 9; ++h) EXPECT_EQ(fanTwin[h], -1) << h;
    const EdgePairing::Groups g = EdgePairing::Group(fan);
    EXPECT_EQ(g.Count(), 7);  // 0-1 (three half-edges) and six border edges
    EXPECT_EQ(g.Size(0), 3);
}
