// Filter 3's step on one triangle (embedding/face_split.h): the paper's looped vertex list cut by
// chords, the max-min-angle triangulation, interior points and their segments.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <set>

#include "split_test_meshes.h"
#include "test_mesh.h"
#include <vcg/complex/append.h>
#include <vcg_ext/polyline_embedding.h>
#include <vcg_ext/vsa_segmentation.h>

using namespace qmf_test;
using namespace qmf_test::split;
typedef vcg_ext::embedding::FaceSplitter Splitter;
typedef Splitter::P2 P2;

namespace {

// Every triangulation of a convex polygon (indices 0..n-1), as triangle lists.
void AllTriangulations(int i, int j, std::vector<std::vector<std::array<int, 3>>> &out)
{
    out.clear();
    if (j - i < 2) { out.push_back({}); return; }
    for (int k = i + 1; k < j; ++k) {
        std::vector<std::vector<std::array<int, 3>>> left, right;
        AllTriangulations(i, k, left);
        AllTriangulations(k, j, right);
        for (auto &l : left)
            for (auto &r : right) {
                auto t = l;
                t.insert(t.end(), r.begin(), r.end());
                t.push_back({i, k, j});
                out.push_back(t);
            }
    }
}

double Orient(const P2 &a, const P2 &b, const P2 &c) { return (b - a) ^ (c - a); }

// Checks a splitter output: CCW triangles covering the area, segments as edges.
void ExpectValidSplit(const Splitter::Input &in, const Splitter::Output &out, double area)
{
    ASSERT_EQ(out.error, "");
    double sum = 0;
    std::set<std::pair<int, int>> edges;
    for (auto &t : out.triangles) {
        const double o = Orient(in.xy[t[0]], in.xy[t[1]], in.xy[t[2]]);
        EXPECT_GT(o, 0) << "triangle not counter-clockwise";
        sum += o / 2;
        for (int k = 0; k < 3; ++k) edges.insert(vcg_ext::UndirectedPair(t[k], t[(k + 1) % 3]));
    }
    EXPECT_NEAR(sum, area, 1e-12 * std::max(1.0, area));
    for (auto &s : out.segmentEdges) EXPECT_TRUE(edges.count(vcg_ext::UndirectedPair(s.first, s.second))) << "segment is no edge";
}

}  // namespace

// Fig. 7 of the paper: LS_ab and LS_cd traverse (v0 v1 v2); LVL = (v0 a d v1 c v2 b).
TEST(FaceSplitter, PaperFigure7TwoSegmentsGiveTwoTrianglesAndATriangulatedPentagon)
{
    Splitter::Input in;
    const P2 v0(0, 0), v1(4, 0), v2(1, 3);
    auto onEdge = [](P2 a, P2 b, double t) { return a + (b - a) * t; };
    // local indices: 0 v0, 1 a, 2 d, 3 v1, 4 c, 5 v2, 6 b
    in.xy = {v0, onEdge(v0, v1, 0.25), onEdge(v0, v1, 0.7), v1, onEdge(v1, v2, 0.5), v2, onEdge(v2, v0, 0.6)};
    in.edgeMask = {5, 1, 1, 3, 2, 6, 4};
    in.loop = {0, 1, 2, 3, 4, 5, 6};
    in.segments = {{1, 6}, {4, 2}};
    in.tolerance = 1e-9;
    Splitter::Output out = Splitter::Split(in);
    ExpectValidSplit(in, out, 6.0);
    ASSERT_EQ(out.triangles.size(), 5u) << "(b v0 a), (d v1 c) and three triangles for (c v2 b a d)";
    std::set<std::set<int>> tris;
    for (auto &t : out.triangles) tris.insert({t[0], t[1], t[2]});
    EXPECT_TRUE(tris.count({6, 0, 1})) << "triangle (b, v0, a)";
    EXPECT_TRUE(tris.count({2, 3, 4})) << "triangle (d, v1, c)";
    EXPECT_EQ(out.segmentEdges.size(), 2u);
    // The pentagon (c v2 b a d) is triangulated with the best smallest angle of its 5 triangulations.
    const std::vector<int> penta = {4, 5, 6, 1, 2};
    std::vector<std::vector<std::array<int, 3>>> all;
    AllTriangulations(0, 4, all);
    ASSERT_EQ(all.size(), 5u);
    double bestPossible = 0;
    for (auto &t : all) {
        double mn = M_PI;
        for (auto &tri : t) mn = std::min(mn, Splitter::MinAngle(in.xy[penta[tri[0]]], in.xy[penta[tri[1]]], in.xy[penta[tri[2]]]));
        bestPossible = std::max(bestPossible, mn);
    }
    double got = M_PI;
    for (auto &t : out.triangles) {
        std::set<int> s{t[0], t[1], t[2]};
        if (s == std::set<int>{6, 0, 1} || s == std::set<int>{2, 3, 4}) continue;
        got = std::min(got, Splitter::MinAngle(in.xy[t[0]], in.xy[t[1]], in.xy[t[2]]));
    }
    EXPECT_NEAR(got, bestPossible, 1e-12);
}

TEST(FaceSplitter, ConvexLoopsGetTheMaxMinAngleTriangulation)
{
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.05, 0.95);
    for (int trial = 0; trial < 40; ++trial) {
        // A triangle with 1-3 random points per edge and no segment: one convex loop.
        const P2 c[3] = {P2(0, 0), P2(2 + u(rng), 0.3 * u(rng)), P2(0.5 + u(rng), 1 + 2 * u(rng))};
        Splitter::Input in;
        for (int k = 0; k < 3; ++k) {
            in.loop.push_back(int(in.xy.size()));
            in.xy.push_back(c[k]);
            in.edgeMask.push_back((unsigned char)((1 << k) | (1 << ((k + 2) % 3))));
            std::vector<double> ts;
            for (int i = 0, n = 1 + trial % 3; i < n; ++i) ts.push_back(u(rng));
            std::sort(ts.begin(), ts.end());
            for (double t : ts) {
                in.loop.push_back(int(in.xy.size()));
                in.xy.push_back(c[k] + (c[(k + 1) % 3] - c[k]) * t);
                in.edgeMask.push_back((unsigned char)(1 << k));
            }
        }
        Splitter::Output out = Splitter::Split(in);
        const double area = Orient(c[0], c[1], c[2]) / 2;
        ExpectValidSplit(in, out, area);
        const int n = int(in.loop.size());
        EXPECT_EQ(int(out.triangles.size()), n - 2);
        double got = M_PI;
        for (auto &t : out.triangles) got = std::min(got, Splitter::MinAngle(in.xy[t[0]], in.xy[t[1]], in.xy[t[2]]));
        std::vector<std::vector<std::array<int, 3>>> all;
        AllTriangulations(0, n - 1, all);
        double best = 0;
        for (auto &tr : all) {
            double mn = M_PI;
            for (auto &t : tr) {
                if ((in.edgeMask[t[0]] & in.edgeMask[t[1]] & in.edgeMask[t[2]]) != 0) { mn = -1; break; }
                mn = std::min(mn, Splitter::MinAngle(in.xy[t[0]], in.xy[t[1]], in.xy[t[2]]));
            }
            best = std::max(best, mn);
        }
        EXPECT_NEAR(got, best, 1e-12) << "trial " << trial;
    }
}

TEST(FaceSplitter, CrossingChordsAreRefused)
{
    Splitter::Input in;
    in.xy = {P2(0, 0), P2(0.5, 0), P2(1, 0), P2(0.5, 0.5), P2(0, 1), P2(0, 0.5)};
    in.edgeMask = {5, 1, 3, 2, 6, 4};
    in.loop = {0, 1, 2, 3, 4, 5};
    in.segments = {{1, 4}, {2, 5}};  // (0.5,0)-(0,1) crosses (1,0)-(0,0.5)
    Splitter::Output out = Splitter::Split(in);
    EXPECT_NE(out.error.find("cross"), std::string::npos) << out.error;
}

TEST(FaceSplitter, InteriorPointsAndTheirSegmentsAreEdges)
{
    Splitter::Input in;
    // Triangle with a point on each edge, two interior points joined to each other and to the boundary.
    in.xy = {P2(0, 0), P2(0.5, 0), P2(1, 0), P2(0.5, 0.5), P2(0, 1), P2(0, 0.5), P2(0.2, 0.2), P2(0.35, 0.25)};
    in.edgeMask = {5, 1, 3, 2, 6, 4, 0, 0};
    in.loop = {0, 1, 2, 3, 4, 5};
    in.segments = {{5, 6}, {6, 7}, {7, 3}, {1, 4}};
    in.tolerance = 1e-9;
    Splitter::Output out = Splitter::Split(in);
    // Chord (0.5,0)-(0,1) is x + y/2 = 0.5: both interior points are below it, (0.5,0.5) above, so
    // the path's last piece crosses the chord.
    EXPECT_NE(out.error.find("cross"), std::string::npos) << out.error;

    in.segments = {{5, 6}, {6, 7}, {7, 3}, {1, 3}};
    out = Splitter::Split(in);
    ExpectValidSplit(in, out, 0.5);
    EXPECT_EQ(out.segmentEdges.size(), 4u);
    EXPECT_EQ(out.triangles.size(), 8u) << "6 loop points + 2 interior points: 6 - 2 + 2 * 2 triangles";
}

TEST(FaceSplitter, SegmentThroughAnInteriorPointIsSplitThere)
{
    Splitter::Input in;
    in.xy = {P2(0, 0), P2(1, 0), P2(0, 1), P2(0.25, 0.25), P2(0.1, 0.1)};
    in.edgeMask = {5, 3, 6, 0, 0};
    in.loop = {0, 1, 2};
    in.segments = {{0, 3}};  // from corner 0 through (0.1, 0.1) to (0.25, 0.25)
    in.tolerance = 1e-9;
    Splitter::Output out = Splitter::Split(in);
    ExpectValidSplit(in, out, 0.5);
    std::set<std::pair<int, int>> segs(out.segmentEdges.begin(), out.segmentEdges.end());
    EXPECT_EQ(segs, (std::set<std::pair<int, int>>{{0, 4}, {3, 4}}));
}
