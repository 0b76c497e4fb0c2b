// Edge topology and region boundary graph (vcg_ext/region_boundary.h).
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "boundary_test_meshes.h"
#include "test_mesh.h"
#include <vcg_ext/boundary/boundary_smoothing.h>
#include <vcg_ext/boundary/region_boundary.h>

using namespace qmf_test;
using namespace qmf_test::boundary;
typedef vcg_ext::RegionBoundaryGraph<TMesh> Graph;

namespace {

// The side of the cube [-1,1]^3 a face lies on (0..5), from its centroid.
int CubeSide(const TMesh &m, int f)
{
    D3 c = Centroid(m, f);
    int axis = 0;
    for (int k = 1; k < 3; ++k)
        if (std::fabs(c[k]) > std::fabs(c[axis])) axis = k;
    return 2 * axis + (c[axis] > 0 ? 1 : 0);
}

std::set<int> Corners(const Graph &g) { return std::set<int>(g.corners.begin(), g.corners.end()); }

}  // namespace

TEST(MeshEdgeTopology, ClosedCubeHasEulerCharacteristicTwoAndFlatEdgeVertices)
{
    TMesh m;
    MakeCube(m, 4, 0.3f, 3);
    Topo t;
    t.Build(m);
    EXPECT_EQ(m.vn - t.EdgeCount() + m.fn, 2);
    for (int e = 0; e < t.EdgeCount(); ++e) ASSERT_TRUE(t.IsManifoldEdge(e));
    Topo::Fan fan;
    int cubeCorners = 0;
    for (int v = 0; v < m.vn; ++v) {
        ASSERT_TRUE(t.VertexFan(v, fan));
        ASSERT_TRUE(fan.closed);
        ASSERT_EQ(int(fan.faces.size()), t.FacesAround(v));
        const auto &p = m.vert[v].cP();
        bool corner = std::fabs(std::fabs(p[0]) - 1) < 1e-6 && std::fabs(std::fabs(p[1]) - 1) < 1e-6 &&
                      std::fabs(std::fabs(p[2]) - 1) < 1e-6;
        cubeCorners += corner;
        // Intrinsically flat everywhere except the 8 cube corners (3 right angles).
        EXPECT_NEAR(fan.total, corner ? 1.5 * M_PI : 2 * M_PI, 1e-5) << "vertex " << v;
        for (size_t j = 0; j < fan.ring.size(); ++j)
            EXPECT_EQ(fan.spokeEdge[j], t.EdgeBetween(v, fan.ring[j]));
    }
    EXPECT_EQ(cubeCorners, 8);
}

TEST(MeshEdgeTopology, OpenGridHasBorderEdgesAndOpenFans)
{
    const int n = 5;
    TMesh m;
    MakeGrid(m, n);
    Topo t;
    t.Build(m);
    int border = 0;
    for (int e = 0; e < t.EdgeCount(); ++e) border += t.edgeKind[e] == Topo::Border;
    EXPECT_EQ(border, 4 * n);
    EXPECT_EQ(t.EdgeCount(), 3 * n * n + 2 * n);  // n(n+1) per direction + n^2 diagonals
    Topo::Fan fan;
    ASSERT_TRUE(t.VertexFan(0, fan));  // corner (0,0)
    EXPECT_FALSE(fan.closed);
    EXPECT_EQ(fan.Spokes(), int(fan.faces.size()) + 1);
    EXPECT_NEAR(fan.total, M_PI / 2, 1e-6);
    ASSERT_TRUE(t.VertexFan(n / 2 * (n + 1) + n / 2, fan));  // interior
    EXPECT_TRUE(fan.closed);
    EXPECT_NEAR(fan.total, 2 * M_PI, 1e-6);
}

TEST(MeshEdgeTopology, NonManifoldEdgeIsFlaggedAndItsVerticesHaveNoFan)
{
    TMesh m;  // three triangles on the edge 0-1
    Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, -1, 0), P3(0, 0, 1)}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    Topo t;
    t.Build(m);
    int e = t.EdgeBetween(0, 1);
    ASSERT_GE(e, 0);
    EXPECT_EQ(t.edgeKind[e], Topo::NonManifold);
    Topo::Fan fan;
    EXPECT_FALSE(t.VertexFan(0, fan));
    EXPECT_TRUE(t.vertOnBorder[0]);
}

TEST(RegionBoundaryGraph, CubeSidesGiveTwelveCurvesBetweenEightCorners)
{
    const int n = 4;
    TMesh m;
    MakeCube(m, n, 0.3f, 5);
    auto region = SetRegions(m, [&](int f) { return CubeSide(m, f); });
    Topo t;
    t.Build(m);
    Graph g = Graph::Build(t, region);
    ASSERT_EQ(g.error, "");
    EXPECT_EQ(g.regions, 6);
    EXPECT_EQ(g.corners.size(), 8u);
    EXPECT_EQ(g.curves.size(), 12u);
    EXPECT_EQ(g.closedLoops, 0);
    EXPECT_EQ(g.boundaryEdges, 12 * n);
    std::set<std::pair<int, int>> pairs;
    for (auto &c : g.curves) {
        EXPECT_FALSE(c.closed);
        ASSERT_EQ(int(c.edges.size()), n);
        ASSERT_EQ(c.vertices.size(), c.edges.size() + 1);
        EXPECT_TRUE(g.isCorner[c.vertices.front()] && g.isCorner[c.vertices.back()]);
        for (size_t i = 1; i + 1 < c.vertices.size(); ++i) EXPECT_FALSE(g.isCorner[c.vertices[i]]);
        double len = 0;
        for (size_t i = 0; i + 1 < c.vertices.size(); ++i) {
            EXPECT_EQ(t.EdgeBetween(c.vertices[i], c.vertices[i + 1]), c.edges[i]);
            len += (t.Position(c.vertices[i + 1]) - t.Position(c.vertices[i])).Norm();
        }
        EXPECT_NEAR(len, 2.0, 1e-6) << "a cube edge";
        // The two sides are adjacent sides of the cube (different axes).
        EXPECT_NE(c.regionLeft / 2, c.regionRight / 2);
        pairs.insert({std::min(c.regionLeft, c.regionRight), std::max(c.regionLeft, c.regionRight)});
        // Left is the face whose half-edge runs along the curve (outward orientation).
        int e = c.edges[0], h = t.edgeHalf[e];
        int f = t.faceVerts[h / 3][h % 3] == c.vertices[0] ? h / 3 : t.twin[h] / 3;
        EXPECT_EQ(region[f], c.regionLeft);
    }
    EXPECT_EQ(pairs.size(), 12u) << "each pair of adjacent sides once";
}

TEST(RegionBoundaryGraph, BandAroundACylinderGivesTwoClosedLoops)
{
    TMesh m;
    MakeCylinder(m, 16, 6);
    auto region = SetRegions(m, [&](int f) {
        D3 c = Centroid(m, f);
        return (c[2] > -1.0 / 3 && c[2] < 1.0 / 3) ? 1 : 0;  // caps are at z = +-1
    });
    Topo t;
    t.Build(m);
    Graph g = Graph::Build(t, region);
    ASSERT_EQ(g.error, "");
    EXPECT_TRUE(g.corners.empty());
    ASSERT_EQ(g.curves.size(), 2u);
    EXPECT_EQ(g.closedLoops, 2);
    for (auto &c : g.curves) {
        EXPECT_TRUE(c.closed);
        EXPECT_EQ(c.vertices.size(), 16u);
        EXPECT_EQ(c.edges.size(), 16u);
        EXPECT_EQ(std::set<int>(c.vertices.begin(), c.vertices.end()).size(), 16u);
    }
}

TEST(RegionBoundaryGraph, SingleFaceRegionIsATriangleLoop)
{
    TMesh m;
    MakeSphere(m, 2);
    auto region = SetRegions(m, [](int f) { return f == 17 ? 5 : 2; });
    Topo t;
    t.Build(m);
    Graph g = Graph::Build(t, region);
    ASSERT_EQ(g.error, "");
    ASSERT_EQ(g.curves.size(), 1u);
    EXPECT_TRUE(g.curves[0].closed);
    EXPECT_EQ(g.curves[0].vertices.size(), 3u);
    EXPECT_TRUE(g.corners.empty());
    EXPECT_EQ(std::min(g.curves[0].regionLeft, g.curves[0].regionRight), 2);
    EXPECT_EQ(std::max(g.curves[0].regionLeft, g.curves[0].regionRight), 5);
}

TEST(RegionBoundaryGraph, RegionTouchingItselfAtAVertexMakesACorner)
{
    // Checkerboard of four quadrants on a grid: regions 0 and 1 each touch themselves at the centre.
    const int n = 6;
    TMesh m;
    MakeGrid(m, n, 1.f, 0.f, 1, true);
    auto region = SetRegions(m, [&](int f) {
        int i, j;
        GridCell(n, f, i, j);
        return (i < n / 2) == (j < n / 2) ? 0 : 1;
    });
    Topo t;
    t.Build(m);
    Graph g = Graph::Build(t, region);
    ASSERT_EQ(g.error, "");
    const int centre = n / 2 * (n + 1) + n / 2;
    std::set<int> corners = Corners(g);
    EXPECT_TRUE(corners.count(centre)) << "four boundary edges, two regions";
    EXPECT_EQ(corners.size(), 5u) << "the centre and four border vertices";
    ASSERT_EQ(g.curves.size(), 4u);
    for (auto &c : g.curves) {
        EXPECT_EQ(c.edges.size(), size_t(n / 2));
        EXPECT_TRUE(c.vertices.front() == centre || c.vertices.back() == centre);
    }
}

TEST(RegionBoundaryGraph, ThreeRegionsAtAVertexMakeACornerAndBorderEndsToo)
{
    const int n = 8;
    TMesh m;
    MakeGrid(m, n);
    // Left half 0; right half split into 1 (bottom) and 2 (top): a T junction at (n/2, n/2).
    auto region = SetRegions(m, [&](int f) {
        int i, j;
        GridCell(n, f, i, j);
        return i < n / 2 ? 0 : (j < n / 2 ? 1 : 2);
    });
    Topo t;
    t.Build(m);
    Graph g = Graph::Build(t, region);
    ASSERT_EQ(g.error, "");
    std::set<int> corners = Corners(g);
    EXPECT_EQ(corners, (std::set<int>{n / 2, n / 2 * (n + 1) + n / 2, n * (n + 1) + n / 2, n / 2 * (n + 1) + n}));
    EXPECT_EQ(g.curves.size(), 3u);
    for (auto &c : g.curves) EXPECT_EQ(c.edges.size(), size_t(n / 2));
}

TEST(RegionBoundaryGraph, NonManifoldEdgeOnABoundaryIsAnError)
{
    TMesh m;
    Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, -1, 0), P3(0, 0, 1)}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    auto region = SetRegions(m, [](int f) { return f == 2 ? 1 : 0; });
    Topo t;
    t.Build(m);
    Graph g = Graph::Build(t, region);
    EXPECT_NE(g.error.find("1 non-manifold edges"), std::string::npos) << g.error;
    // Same labels on all three faces: not on a boundary, no error.
    auto same = SetRegions(m, [](int f) { return f == 0 ? 0 : 0; });
    EXPECT_EQ(Graph::Build(t, same).error, "");
}

TEST(MergeSmallRegions, TinyRegionJoinsTheNeighbourWithTheLongestSharedBoundary)
{
    const int n = 10;
    TMesh m;
    MakeGrid(m, n);
    // Bottom half 0, top half 1, and a 1-cell region 2 in the bottom half touching only region 0,
    // and a 2-cell region 3 straddling the middle with 3 cell sides on region 1 and 1 on region 0.
    auto region = SetRegions(m, [&](int f) {
        int i, j;
        GridCell(n, f, i, j);
        if (i == 2 && j == 2) return 2;
        if (i == 6 && (j == 5 || j == 6)) return 3;
        return j < n / 2 ? 0 : 1;
    });
    Topo t;
    t.Build(m);
    int merged = -1;
    std::vector<int> out = vcg_ext::MergeSmallRegions(t, region, 5, &merged);
    EXPECT_EQ(merged, 2);
    for (size_t f = 0; f < out.size(); ++f) {
        int i, j;
        GridCell(n, int(f), i, j);
        int expected = (i == 6 && (j == 5 || j == 6)) ? 1 : (j < n / 2 ? 0 : 1);
        ASSERT_EQ(out[f], expected) << "cell " << i << "," << j;
    }
    EXPECT_EQ(vcg_ext::MergeSmallRegions(t, region, 0, &merged), region);
    EXPECT_EQ(merged, 0);
}

namespace {

// A 10 x 10 grid of the unit square whose row of cells j = 5 is squeezed to 0.0005 high: that row
// is region 2, a strip of width 2 * area / boundary = 2 * 0.0005 / 2 = 0.0005 (its ends are on the
// grid's border, not shared). Below it region 0, above region 1, and one cell (0.1 x 0.1, width
// 2 * 0.01 / 0.4 = 0.05) is region 3.
std::vector<int> MakeSqueezedStrip(TMesh &m)
{
    const int n = 10;
    MakeGrid(m, n, 1.f, 0.f, 1, true);
    for (auto &v : m.vert) {
        const int row = int(std::lround(v.P()[1] * n));
        v.P()[1] = row <= 5 ? float(row) / n : float(row - 1) / n + 0.0005f;
    }
    return SetRegions(m, [&](int f) {
        int i, j;
        GridCell(n, f, i, j);
        if (i == 2 && j == 2) return 3;
        return j == 5 ? 2 : (j < 5 ? 0 : 1);
    });
}

}  // namespace

TEST(MergeThinRegions, AStripAHairWideJoinsANeighbourAndASmallFatRegionStays)
{
    TMesh m;
    const std::vector<int> region = MakeSqueezedStrip(m);
    Topo t;
    t.Build(m);
    int merged = -1;
    // The strip shares 1.0 with regions 0 and 1: the tie goes to the lower id.
    std::vector<int> out = vcg_ext::MergeThinRegions(t, region, 0.001, &merged);
    EXPECT_EQ(merged, 1);
    for (size_t f = 0; f < out.size(); ++f) ASSERT_EQ(out[f], region[f] == 2 ? 0 : region[f]) << f;
    // Wider than the strip, narrower than the cell: the same; wider than the cell: the cell goes too.
    EXPECT_EQ(vcg_ext::MergeThinRegions(t, region, 0.049, &merged), out);
    vcg_ext::MergeThinRegions(t, region, 0.051, &merged);
    EXPECT_EQ(merged, 2);
    EXPECT_EQ(vcg_ext::MergeThinRegions(t, region, 0, &merged), region);
    EXPECT_EQ(merged, 0);
}

TEST(MergeThinRegions, TheSmoothingMergesStripsThinnerThanItsShareOfTheMeanTriangleSide)
{
    // MakeSqueezedStrip through the whole filter: the mean triangle side is
    // sqrt(area / (faces * sqrt(3) / 4)) = sqrt(0.9005 / (200 * 0.4330)) = 0.1020, so strips below
    // 0.05 * 0.1020 = 0.0051 go; the 0.0005 strip does, the cell (0.05) stays.
    TMesh m;
    const std::vector<int> region = MakeSqueezedStrip(m);
    ASSERT_LT(0.0005, vcg_ext::RegionBoundarySmoothing<TMesh>::kThinRegionWidth * 0.1020);
    ASSERT_GT(0.05, vcg_ext::RegionBoundarySmoothing<TMesh>::kThinRegionWidth * 0.1020);
    vcg_ext::RegionBoundarySmoothing<TMesh>::Params p;
    auto r = vcg_ext::RegionBoundarySmoothing<TMesh>::Smooth(m, region, p);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.thinRegions, 1);
    // Left: the loop around the cell and one curve between regions 0 (with the strip) and 1.
    ASSERT_EQ(r.curves.size(), 2u);
    std::set<std::pair<int, int>> pairs;
    for (const auto &c : r.curves) pairs.insert({std::min(c.regionLeft, c.regionRight), std::max(c.regionLeft, c.regionRight)});
    EXPECT_EQ(pairs, (std::set<std::pair<int, int>>{{0, 1}, {0, 3}}));
}

TEST(MeshEdgeTopology, FacesWithARepeatedVertexAreLeftOut)
{
    const int n = 4;
    TMesh m;
    MakeGrid(m, n);
    Topo clean;
    clean.Build(m);
    auto fi = vcg::tri::Allocator<TMesh>::AddFaces(m, 1);  // (a, a, b): AddFace() would assert
    fi->V(0) = &m.vert[6];
    fi->V(1) = &m.vert[6];
    fi->V(2) = &m.vert[7];
    Topo t;
    t.Build(m);
    EXPECT_EQ(t.ignoredFaces, 1);
    EXPECT_EQ(t.EdgeCount(), clean.EdgeCount());
    EXPECT_EQ(t.FacesAround(6), clean.FacesAround(6));
    auto region = SetRegions(m, [&](int f) { return f < 2 * n * n ? (f % (2 * n) < n ? 0 : 1) : 5; });
    Graph g = Graph::Build(t, region);
    ASSERT_EQ(g.error, "");
    EXPECT_EQ(g.regions, 2) << "the left-out face's id does not count";
}
