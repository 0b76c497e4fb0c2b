// Cavity patterns: a disk of quads around irregular nodes re-meshed as a regular grid.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include <vcg_ext/qmorph/cavity_patterns.h>

namespace {

namespace qm = vcg_ext::qmorph;
typedef qm::P3 D3;

constexpr int kCells = 6;  // the grid has kCells x kCells quads of side 1

// The grid of nodes (x, y, height(x, y)) as a triangle surface (the input) and as a working mesh
// whose triangles are merged into quads; its boundary is the initial front.
struct GridPatch {
    std::vector<D3> pts;
    std::vector<std::array<int, 3>> tris;
    vcg_ext::SurfaceProjector surface;
    qm::MixedMesh m;
    std::vector<int> home;

    static int Node(int x, int y) { return y * (kCells + 1) + x; }

    explicit GridPatch(const std::function<double(double, double)> &height)
    {
        for (int y = 0; y <= kCells; ++y)
            for (int x = 0; x <= kCells; ++x) pts.push_back(D3(x, y, height(x, y)));
        for (int y = 0; y < kCells; ++y)
            for (int x = 0; x < kCells; ++x) {
                tris.push_back({Node(x, y), Node(x + 1, y), Node(x + 1, y + 1)});
                tris.push_back({Node(x, y), Node(x + 1, y + 1), Node(x, y + 1)});
            }
        surface.Build(pts, tris);
        m.Build(pts, tris);
        for (int y = 0; y < kCells; ++y)
            for (int x = 0; x < kCells; ++x) m.MergeTriangles(m.FindHalfEdge(Node(x, y), Node(x + 1, y + 1)), 0);
        home.assign(pts.size(), 0);
        for (int t = 0; t < int(tris.size()); ++t)
            for (int v : tris[t]) home[v] = t;
    }

    // Turns the edge a-b between two quads to join the next pair of opposite corners of their
    // hexagon: a and b lose an edge, two nodes of the hexagon gain one (a 3-5 dipole pair).
    void TurnEdge(int a, int b)
    {
        const int h = m.FindHalfEdge(a, b), t = m.heTwin[h];
        ASSERT_GE(t, 0);
        const std::vector<int> loop{m.heNext[h], m.heNext[m.heNext[h]], m.hePrev[h], m.heNext[t], m.heNext[m.heNext[t]], m.hePrev[t]};
        m.ReplaceRegion(loop, {m.heFace[h], m.heFace[t]}, {}, {{1, 2, 3, 4}, {4, 5, 0, 1}}, 0);
    }

    int IrregularInnerNodes() const
    {
        int n = 0;
        for (int v = 0; v < m.VertexCount(); ++v) n += m.vertAlive[v] && !m.OnBoundary(v) && m.Valence(v) != 4;
        return n;
    }
};

// Every face a quad, twins consistent, a disk (Euler characteristic 1), every quad counter-
// clockwise seen from +z; returns the number of quads.
int ExpectConsistentQuadDisk(const qm::MixedMesh &m)
{
    int faces = 0, halfEdges = 0, boundary = 0, vertices = 0;
    for (int v = 0; v < m.VertexCount(); ++v) vertices += m.vertAlive[v];
    for (int f = 0; f < m.FaceCount(); ++f) {
        if (!m.FaceAlive(f)) continue;
        EXPECT_TRUE(m.IsQuad(f));
        EXPECT_GT(m.FaceNormal(f).Z(), 0) << "face " << f << " is upside down";
        ++faces;
    }
    for (int h = 0; h < m.HalfEdgeCount(); ++h) {
        if (!m.HeAlive(h)) continue;
        ++halfEdges;
        const int t = m.heTwin[h];
        if (t < 0) { ++boundary; continue; }
        EXPECT_EQ(m.heTwin[t], h);
        EXPECT_EQ(m.Org(t), m.Dst(h));
    }
    EXPECT_EQ(vertices - (halfEdges + boundary) / 2 + faces, 1) << "still a disk";
    return faces;
}

TEST(CavityPatterns, TwoTurnedEdgesInAGridBecomeARegularGridAgain)
{
    GridPatch g([](double, double) { return 0.0; });
    g.TurnEdge(GridPatch::Node(2, 2), GridPatch::Node(2, 3));
    g.TurnEdge(GridPatch::Node(4, 3), GridPatch::Node(4, 4));
    ASSERT_EQ(g.IrregularInnerNodes(), 8) << "each turn makes two nodes of valence 3 and two of valence 5";
    const qm::PatchParams params;
    qm::PatchContext context(g.m, g.surface, g.home, params);
    qm::CavityPatterns(context).Run();
    EXPECT_GE(context.stats.cavities, 1);
    EXPECT_EQ(g.IrregularInnerNodes(), 0);
    EXPECT_EQ(ExpectConsistentQuadDisk(g.m), kCells * kCells);
    for (int v = 0; v < g.m.VertexCount(); ++v) {
        if (!g.m.vertAlive[v]) continue;
        const D3 &p = g.m.pos[v];
        EXPECT_NEAR(p.X(), std::round(p.X()), 1e-9) << "the grid's nodes are the unit lattice's";
        EXPECT_NEAR(p.Y(), std::round(p.Y()), 1e-9);
        EXPECT_NEAR(p.Z(), 0, 1e-12);
    }
    for (int x = 0; x <= kCells; ++x)  // the initial front keeps its nodes and edges
        for (int y : {0, kCells}) {
            EXPECT_TRUE(g.m.vertFixed[GridPatch::Node(x, y)]);
            EXPECT_EQ(g.m.Valence(GridPatch::Node(x, y)), x == 0 || x == kCells ? 2 : 3);
        }
}

TEST(CavityPatterns, GridNodesLieOnACurvedInputSurface)
{
    auto height = [](double x, double y) { return 0.08 * (x - 3) * (x - 3) + 0.05 * (y - 3) * (y - 3); };
    GridPatch g(height);
    g.TurnEdge(GridPatch::Node(3, 2), GridPatch::Node(3, 3));
    const qm::PatchParams params;
    qm::PatchContext context(g.m, g.surface, g.home, params);
    qm::CavityPatterns(context).Run();
    EXPECT_EQ(g.IrregularInnerNodes(), 0);
    EXPECT_EQ(ExpectConsistentQuadDisk(g.m), kCells * kCells);
    for (int v = 0; v < g.m.VertexCount(); ++v) {
        if (!g.m.vertAlive[v]) continue;
        int from = g.home[v];
        const D3 onSurface = g.surface.Project(g.m.pos[v], from);
        EXPECT_LT((onSurface - g.m.pos[v]).Norm(), 1e-9) << "node " << v << " is off the input surface";
    }
}

// A grid is only laid where every new quad is fair: squeezed into a thin sliver of a cavity, the
// re-meshing is refused and the patch is left exactly as it was.
TEST(CavityPatterns, RefusesGridsThatWouldBeUnfair)
{
    GridPatch g([](double, double) { return 0.0; });
    g.TurnEdge(GridPatch::Node(2, 2), GridPatch::Node(2, 3));
    // squash the grid's rows into a strip 1e-3 high: every quad there is a needle, and would be
    for (int v = 0; v < g.m.VertexCount(); ++v) g.m.pos[v].Y() *= 1e-3;
    for (D3 &p : g.pts) p.Y() *= 1e-3;
    g.surface.Build(g.pts, g.tris);
    const std::vector<D3> before = g.m.pos;
    const int faces = g.m.FaceCount();
    const qm::PatchParams params;
    qm::PatchContext context(g.m, g.surface, g.home, params);
    qm::CavityPatterns(context).Run();
    EXPECT_EQ(context.stats.cavities, 0);
    EXPECT_EQ(g.m.FaceCount(), faces) << "no face made";
    for (size_t v = 0; v < before.size(); ++v) EXPECT_EQ(g.m.pos[v], before[v]);
}

// A triangle of side 4 meshed as a star: three 2 x 2 grids of quads around a centre of valence 3,
// the fewest irregular nodes a three-cornered disk can have. A turned edge adds four; the star
// comes back.
TEST(CavityPatterns, ATurnedEdgeInAThreeSidedStarBecomesAStarAgain)
{
    const D3 A(0, 0, 0), B(4, 0, 0), C(2, 2 * std::sqrt(3.0), 0), O = (A + B + C) / 3.0;
    const D3 corner[3] = {A, B, C}, mid[3] = {(A + B) / 2.0, (B + C) / 2.0, (C + A) / 2.0};
    std::vector<D3> pts;
    std::vector<std::array<int, 3>> tris;
    auto node = [&](const D3 &p) {
        for (size_t i = 0; i < pts.size(); ++i)
            if ((pts[i] - p).Norm() < 1e-9) return int(i);
        pts.push_back(p);
        return int(pts.size()) - 1;
    };
    std::vector<std::array<int, 2>> diagonals;
    for (int s = 0; s < 3; ++s) {  // the grid at corner s: corner, mid of side s, centre, mid of side s - 1
        const D3 q[4] = {corner[s], mid[s], O, mid[(s + 2) % 3]};
        auto at = [&](int i, int j) {
            const double u = i / 2.0, v = j / 2.0;
            return node(q[0] * ((1 - u) * (1 - v)) + q[1] * (u * (1 - v)) + q[2] * (u * v) + q[3] * ((1 - u) * v));
        };
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
                tris.push_back({a, b, c});
                tris.push_back({a, c, d});
                diagonals.push_back({a, c});
            }
    }
    vcg_ext::SurfaceProjector surface;
    surface.Build(pts, tris);
    qm::MixedMesh m;
    m.Build(pts, tris);
    for (const auto &d : diagonals) m.MergeTriangles(m.FindHalfEdge(d[0], d[1]), 0);
    auto inner = [&](int valence) {
        int n = 0;
        for (int v = 0; v < m.VertexCount(); ++v) n += m.vertAlive[v] && !m.OnBoundary(v) && (valence ? m.Valence(v) == valence : m.Valence(v) != 4);
        return n;
    };
    ASSERT_EQ(inner(0), 1);
    ASSERT_EQ(inner(3), 1);
    // turn the edge between two inner nodes of valence 4 in the grid at corner A
    const int x = node((mid[0] + O) / 2.0), y = node((A + mid[0] + O + mid[2]) / 4.0);
    ASSERT_TRUE(m.EdgeExists(x, y));
    const int h = m.FindHalfEdge(x, y), t = m.heTwin[h];
    m.ReplaceRegion({m.heNext[h], m.heNext[m.heNext[h]], m.hePrev[h], m.heNext[t], m.heNext[m.heNext[t]], m.hePrev[t]},
                    {m.heFace[h], m.heFace[t]}, {}, {{1, 2, 3, 4}, {4, 5, 0, 1}}, 0);
    ASSERT_GT(inner(0), 1);
    std::vector<int> home(m.VertexCount(), 0);
    const qm::PatchParams params;
    qm::PatchContext context(m, surface, home, params);
    qm::CavityPatterns(context).Run();
    EXPECT_GE(context.stats.cavities, 1);
    EXPECT_EQ(inner(0), 1) << "one irregular node left";
    EXPECT_EQ(inner(3), 1) << "... of valence 3";
    EXPECT_EQ(ExpectConsistentQuadDisk(m), 12);
}

}  // namespace
