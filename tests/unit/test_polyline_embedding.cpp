// Filter 3 core: locating, tracing, splitting, max-min-angle triangulation, relabelling.
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
typedef vcg_ext::PolylineEmbedding<TMesh> Embedding;
typedef vcg_ext::embedding::FaceSplitter Splitter;
typedef Splitter::P2 P2;

namespace {

void Copy(TMesh &dst, const TMesh &src) { vcg::tri::Append<TMesh, TMesh>::MeshCopy(dst, const_cast<TMesh &>(src)); }

Embedding::Result Embed(TMesh &m, const TMesh &poly, double tolPercent = 1e-4)
{
    Embedding::Params p;
    p.locateTolerancePercent = tolPercent;
    return Embedding::Embed(m, poly, p);
}

// Regular tetrahedron-like closed mesh, outward oriented.
void MakeTetra(TMesh &m)
{
    Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, 0, 1)}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
}

P3 Lerp(const P3 &a, const P3 &b, float t) { return a + (b - a) * t; }

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
        for (int k = 0; k < 3; ++k) edges.insert(Ordered(t[k], t[(k + 1) % 3]));
    }
    EXPECT_NEAR(sum, area, 1e-12 * std::max(1.0, area));
    for (auto &s : out.segmentEdges) EXPECT_TRUE(edges.count(Ordered(s.first, s.second))) << "segment is no edge";
}

int CountSelectedEdges(const TMesh &m) { return int(vcg_ext::FrontEdges<TMesh>::Collect(m).size()); }

}  // namespace

// ------------------------------------------------------------------ FaceSplitter (the paper's step)

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

// ------------------------------------------------------------------ whole meshes

TEST(PolylineEmbedding, PaperFigure7OnATetrahedronFace)
{
    TMesh m, before, poly;
    MakeTetra(m);
    Copy(before, m);
    // Face 2 = (v1 v2 v3): a, d on v1-v2, c on v2-v3, b on v3-v1; segments a-b and c-d.
    const P3 v1 = m.vert[1].P(), v2 = m.vert[2].P(), v3 = m.vert[3].P();
    const P3 a = Lerp(v1, v2, 0.25f), d = Lerp(v1, v2, 0.7f), c = Lerp(v2, v3, 0.5f), b = Lerp(v3, v1, 0.6f);
    MakePolyline(poly, {a, b});
    TMesh second;
    MakePolyline(second, {c, d});
    AppendPolyline(poly, second);
    Embedding::Result r = Embed(m, poly);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.pointsOnEdges, 4);
    EXPECT_EQ(r.verticesAdded, 4);
    EXPECT_EQ(r.facesCrossed, 1);
    EXPECT_EQ(r.facesSplit, 4) << "the crossed face and its three neighbours (new vertices on their edges)";
    EXPECT_EQ(m.fn, 12) << "crossed face -> 5 triangles; neighbours get 2, 1, 1 more";
    EXPECT_EQ(r.facesAdded, 8);
    EXPECT_EQ(r.frontEdges, 2);
    EXPECT_EQ(CountSelectedEdges(m), 2);
    EXPECT_EQ(r.patches, 1) << "two open chords cut nothing off the closed surface";
    EXPECT_EQ(r.danglingFrontEdges, 2);
    EXPECT_GT(r.minAngleDeg, 5.0);
    SplitExpectations x;
    x.closedFront = false;
    ExpectSplitInvariants(before, m, poly, x);
}

TEST(PolylineEmbedding, PlaneSectionWithPointsInsideEdgesOnAJitteredCube)
{
    TMesh m, before, poly;
    MakeCube(m, 7, 0.35f, 5);
    Copy(before, m);
    ASSERT_TRUE(PlaneSectionPolyline(m, D3(0.3, 0.2, 1).Normalize(), 0.137, poly));
    for (size_t f = 0; f < m.face.size(); f += 7) m.face[f].Flags() |= TFace::FAUX0 | TFace::FACEEDGESEL1;  // cleared
    ASSERT_GT(poly.en, 20);
    Embedding::Result r = Embed(m, poly);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.tracedSegments, 0) << "consecutive points share a face";
    EXPECT_EQ(r.pointsOnEdges, poly.vn);
    EXPECT_EQ(r.pointsAtVertices, 0);
    EXPECT_EQ(r.verticesAdded, poly.vn) << "one new vertex per crossing point";
    EXPECT_EQ(r.frontEdges, poly.en);
    EXPECT_EQ(r.facesCrossed, poly.en) << "one face per segment";
    EXPECT_EQ(r.patches, 2) << "the loop cuts the cube in two";
    EXPECT_EQ(r.danglingFrontEdges, 0);
    EXPECT_EQ(r.missingFrontEdges, 0);
    std::set<int> ids(r.faceRegion.begin(), r.faceRegion.end());
    EXPECT_EQ(ids.size(), 2u);
    ExpectSplitInvariants(before, m, poly);
}

TEST(PolylineEmbedding, RegionBoundariesThroughVerticesSelectExactlyThoseEdges)
{
    TMesh m, poly;
    MakeCube(m, 6, 0.3f, 2);
    typedef vcg_ext::VSASegmentation<TMesh> VSA;
    VSA::Params vp;
    vp.mode = VSA::FixedRegionCount;
    vp.maxRegions = 6;
    ASSERT_EQ(VSA::Segment(m, vp).error, "");
    TMesh before;
    Copy(before, m);
    RegionBoundaryPolyline(m, poly);
    ASSERT_GT(poly.en, 0);
    Embedding::Result r = Embed(m, poly);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.verticesAdded, 0);
    EXPECT_EQ(r.facesSplit, 0) << "a front along mesh edges splits nothing";
    EXPECT_EQ(m.fn, before.fn);
    EXPECT_EQ(r.frontEdges, poly.en);
    EXPECT_EQ(r.patches, 6);
    for (size_t f = 0; f < m.face.size(); ++f) EXPECT_EQ(m.face[f].Q(), before.face[f].Q()) << "ids stay stable";
    ExpectSplitInvariants(before, m, poly);
}

TEST(PolylineEmbedding, PointsReadBackFromObjWithSixDecimalsAreRecovered)
{
    TMesh m, before, exact, poly;
    ASSERT_TRUE(LoadOff(m, MeshDir() + "/elephant.off"));
    Copy(before, m);
    ASSERT_TRUE(PlaneSectionPolyline(m, D3(0, 1, 0.2).Normalize(), 0.0123, exact));
    RoundTripObj6(exact, poly);
    Embedding::Result r = Embed(m, poly);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.tracedSegments, 0);
    EXPECT_EQ(r.pointsOnEdges + r.pointsAtVertices, exact.vn);
    EXPECT_EQ(r.frontEdges, exact.en);
    EXPECT_EQ(r.danglingFrontEdges, 0);
    EXPECT_GE(r.patches, 2);
    ExpectSplitInvariants(before, m, exact);
}

TEST(PolylineEmbedding, FandiskAndElephantSectionsKeepEveryInvariant)
{
    for (const char *name : {"fandisk", "elephant"}) {
        SCOPED_TRACE(name);
        TMesh m, before, poly, more;
        ASSERT_TRUE(LoadOff(m, MeshDir() + "/" + name + ".off"));
        // Region ids by VSA, then three parallel plane sections (closed loops that never cross).
        typedef vcg_ext::VSASegmentation<TMesh> VSA;
        VSA::Params vp;
        ASSERT_EQ(VSA::Segment(m, vp).error, "");
        Copy(before, m);
        const D3 n = D3(0.1, 1, 0.3).Normalize();
        ASSERT_TRUE(PlaneSectionPolyline(m, n, 0.0171, poly));
        for (double d : {-0.1913, 0.1377}) {
            ASSERT_TRUE(PlaneSectionPolyline(m, n, d, more));
            AppendPolyline(poly, more);
        }
        Embedding::Result r = Embed(m, poly);
        ASSERT_EQ(r.error, "");
        EXPECT_EQ(r.verticesAdded, poly.vn) << "one new vertex per section point";
        EXPECT_EQ(r.frontEdges, poly.en);
        EXPECT_GT(r.facesCrossed, 100);
        EXPECT_GT(r.minAngleDeg, 0.0);
        EXPECT_EQ(r.missingFrontEdges, 0);
        EXPECT_EQ(r.danglingFrontEdges, 0);
        EXPECT_GE(r.patches, 4);
        SplitExpectations x;
        x.segmentsAreEdges = true;
        ExpectSplitInvariants(before, m, poly, x);
    }
}

TEST(PolylineEmbedding, UserPolylineAcrossSeveralFacesIsTracedStraightOnAPlane)
{
    TMesh m, before, poly;
    MakeGrid(m, 8, 1.f, 0.3f, 4);
    Copy(before, m);
    MakePolyline(poly, {P3(0.07f, 0.11f, 0), P3(0.93f, 0.71f, 0), P3(0.41f, 0.96f, 0)});
    Embedding::Result r = Embed(m, poly);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.tracedSegments, 2);
    EXPECT_EQ(r.pointsInFaces, 3);
    EXPECT_GT(r.tracedCrossings, 10);
    EXPECT_EQ(r.patches, 1) << "an open polyline cuts nothing off";
    EXPECT_EQ(r.danglingFrontEdges, r.frontEdges);
    SplitExpectations x;
    x.closedFront = false;
    x.pointsInFaces = true;
    ExpectSplitInvariants(before, m, poly, x);  // straight chains on the plane
}

TEST(PolylineEmbedding, UserLoopOnASphereFollowsThePlaneSections)
{
    TMesh m, before, poly;
    MakeSphere(m, 3);
    Copy(before, m);
    // Four points on the sphere around its equator (slightly tilted), inside faces.
    std::vector<P3> pts;
    for (int i = 0; i < 4; ++i) {
        const double a = 2 * M_PI * (i + 0.13) / 4;
        D3 p(std::cos(a), std::sin(a), 0.17 + 0.05 * i);
        pts.push_back(P3::Construct(p.Normalize()));
    }
    // Project the points on the mesh (the sphere's facets are inside the unit sphere).
    ClosestOnInput input(m);
    std::vector<D3> normals;
    for (P3 &p : pts) {
        float d;
        P3 q;
        normals.push_back(D3::Construct(input.Closest(p, d, q)->cN()));
        p = q;
    }
    MakePolyline(poly, pts, true);
    Embedding::Result r = Embed(m, poly);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.tracedSegments, 4);
    EXPECT_EQ(r.patches, 2) << "a closed loop around the sphere";
    EXPECT_EQ(r.danglingFrontEdges, 0);
    SplitExpectations x;
    x.pointsInFaces = true;
    x.straightSegments = false;
    ExpectSplitInvariants(before, m, poly, x);
    // Each traced chain lies in the plane through its ends containing their averaged face normals.
    std::vector<vcg_ext::FrontEdges<TMesh>::Edge> front = vcg_ext::FrontEdges<TMesh>::Collect(m);
    int offPlanes = 0;
    for (auto &e : front)
        for (int v : {e.first, e.second}) {
            const D3 p = D3::Construct(m.vert[v].P());
            double best = 1e30;
            for (int i = 0; i < 4; ++i) {
                const D3 a = D3::Construct(pts[i]), b = D3::Construct(pts[(i + 1) % 4]);
                const D3 n = ((b - a) ^ (normals[i] + normals[(i + 1) % 4])).Normalize();
                best = std::min(best, std::fabs(n * (p - a)));
            }
            if (best > 1e-5) ++offPlanes;
        }
    EXPECT_EQ(offPlanes, 0);
}

TEST(PolylineEmbedding, JunctionsOnEdgesAndInsideFaces)
{
    TMesh m, before, poly, more;
    MakeGrid(m, 6, 1.f, 0.2f, 9);
    Copy(before, m);
    // A Y: three polylines from the borders meeting at one interior point (inside a face).
    const P3 centre(0.512f, 0.487f, 0);
    MakePolyline(poly, {P3(0.f, 0.31f, 0), centre});
    MakePolyline(more, {P3(1.f, 0.22f, 0), centre});
    AppendPolyline(poly, more);
    MakePolyline(more, {P3(0.55f, 1.f, 0), centre});
    AppendPolyline(poly, more);
    Embedding::Result r = Embed(m, poly);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.patches, 3) << "the Y cuts the square in three";
    EXPECT_EQ(r.mergedPoints, 2) << "the centre is one point";
    SplitExpectations x;
    x.pointsInFaces = true;
    ExpectSplitInvariants(before, m, poly, x);
}

TEST(PolylineEmbedding, RunningTwiceChangesNothing)
{
    TMesh m, poly;
    MakeCube(m, 5, 0.3f, 8);
    for (auto &f : m.face) f.Q() = 0;
    ASSERT_TRUE(PlaneSectionPolyline(m, D3(0.1, 1, 0.2).Normalize(), -0.2113, poly));
    ASSERT_EQ(Embed(m, poly).error, "");
    TMesh once;
    Copy(once, m);
    Embedding::Result r = Embed(m, poly);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.verticesAdded, 0);
    EXPECT_EQ(r.facesSplit, 0);
    EXPECT_EQ(r.pointsAtVertices, poly.vn);
    ASSERT_EQ(m.fn, once.fn);
    for (size_t f = 0; f < m.face.size(); ++f) {
        EXPECT_EQ(m.face[f].Flags(), once.face[f].Flags());
        EXPECT_EQ(m.face[f].Q(), once.face[f].Q());
    }
}

TEST(PolylineEmbedding, OpenMeshAndPolylineEndingOnTheBoundary)
{
    TMesh m, before, poly;
    MakeGrid(m, 5, 1.f, 0.25f, 3);
    Copy(before, m);
    MakePolyline(poly, {P3(0.f, 0.43f, 0), P3(0.5f, 0.51f, 0), P3(1.f, 0.47f, 0)});
    Embedding::Result r = Embed(m, poly);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.patches, 2) << "a cut from border to border";
    EXPECT_EQ(r.pointsOnEdges, 2);
    EXPECT_EQ(r.pointsInFaces, 1);
    SplitExpectations x;
    x.pointsInFaces = true;
    ExpectSplitInvariants(before, m, poly, x);
}

TEST(PolylineEmbedding, SplittingARegionGivesTheSmallerPieceANewId)
{
    TMesh m, poly;
    MakeGrid(m, 6);
    for (auto &f : m.face) f.Q() = 4;
    MakePolyline(poly, {P3(0.f, 0.3f, 0), P3(1.f, 0.3f, 0)});
    Embedding::Result r = Embed(m, poly);
    ASSERT_EQ(r.error, "");
    ASSERT_EQ(r.patches, 2);
    double above4 = 0, below5 = 0;
    for (auto &f : m.face) {
        const double cy = (f.P(0)[1] + f.P(1)[1] + f.P(2)[1]) / 3;
        EXPECT_TRUE(f.Q() == 4 || f.Q() == 5) << f.Q();
        if (cy > 0.3 && f.Q() == 4) above4 += Area(f);
        if (cy < 0.3 && f.Q() == 5) below5 += Area(f);
    }
    EXPECT_NEAR(above4, 0.7, 1e-6) << "the larger patch keeps the id";
    EXPECT_NEAR(below5, 0.3, 1e-6) << "the smaller one gets the next free id";
}

// ------------------------------------------------------------------ locating rules

TEST(PolylineEmbedding, LocateRulesVertexEdgeFace)
{
    TMesh m;
    MakeGrid(m, 2);  // vertices on a 0.5 lattice
    vcg_ext::embedding::EmbeddingAdjacency adj;
    ASSERT_EQ(adj.Build(m), "");
    const double tol = 1e-3;
    vcg_ext::embedding::SurfaceLocator<TMesh> loc(m, adj, tol);
    vcg_ext::embedding::LocatedPoint s;
    ASSERT_TRUE(loc.Locate(vcg_ext::embedding::EmbedVec(0.5 + 0.0007, 0.5, 0.0005), s));
    EXPECT_EQ(s.kind, vcg_ext::embedding::LocatedPoint::AtVertex) << "within tol of a vertex";
    EXPECT_EQ(s.pos, vcg_ext::embedding::EmbedVec(0.5, 0.5, 0)) << "re-projected onto the vertex";
    ASSERT_TRUE(loc.Locate(vcg_ext::embedding::EmbedVec(0.25, 0.0008, -0.0002), s));
    EXPECT_EQ(s.kind, vcg_ext::embedding::LocatedPoint::OnEdge);
    EXPECT_NEAR(s.pos[1], 0.0, 1e-15) << "re-projected onto the edge";
    EXPECT_NEAR(s.pos[0], 0.25, 1e-12);
    ASSERT_TRUE(loc.Locate(vcg_ext::embedding::EmbedVec(0.5009, 0.0006, 0), s));
    EXPECT_EQ(s.kind, vcg_ext::embedding::LocatedPoint::AtVertex) << "1.08e-3 from the vertex, but its projection on the edge is within tol";
    EXPECT_EQ(s.vertex, 1);
    ASSERT_TRUE(loc.Locate(vcg_ext::embedding::EmbedVec(0.5015, 0.0002, 0), s));
    EXPECT_EQ(s.kind, vcg_ext::embedding::LocatedPoint::OnEdge);
    // Near the diagonal from (0,0): the nearest edge wins, its foot is 1.06e-3 from (0,0).
    ASSERT_TRUE(loc.Locate(vcg_ext::embedding::EmbedVec(0.0009, 0.0006, 0), s));
    EXPECT_EQ(s.kind, vcg_ext::embedding::LocatedPoint::OnEdge);
    EXPECT_NEAR(s.pos[0], 0.00075, 1e-12);
    EXPECT_NEAR(s.pos[1], 0.00075, 1e-12);
    ASSERT_TRUE(loc.Locate(vcg_ext::embedding::EmbedVec(0.3, 0.1, 0.0009), s));
    EXPECT_EQ(s.kind, vcg_ext::embedding::LocatedPoint::InFace);
    EXPECT_NEAR(s.pos[2], 0.0, 1e-15);
    EXPECT_FALSE(loc.Locate(vcg_ext::embedding::EmbedVec(0.3, 0.1, 0.0011), s)) << "off the surface";
    EXPECT_FALSE(loc.Locate(vcg_ext::embedding::EmbedVec(1.2, 0.1, 0), s));
}

TEST(PolylineEmbedding, LocateAllFindsTheGeneratingVertexEdgeOrFace)
{
    TMesh m;
    MakeSphere(m, 4);
    vcg_ext::embedding::EmbeddingAdjacency adj;
    ASSERT_EQ(adj.Build(m), "");
    typedef vcg_ext::embedding::EmbedVec V;
    typedef vcg_ext::embedding::LocatedPoint SP;
    const double tol = 1e-6 * BoxDiag(m);
    vcg_ext::embedding::SurfaceLocator<TMesh> loc(m, adj, tol);
    std::mt19937 rng(12);
    std::uniform_real_distribution<double> u(0.05, 0.95), noise(-0.3 * tol, 0.3 * tol);
    std::vector<V> pts;
    std::vector<int> kind, face, edge, vert;
    for (int i = 0; i < 3000; ++i) {
        const int f = int(rng() % m.face.size());
        const V a = V::Construct(m.face[f].P(0)), b = V::Construct(m.face[f].P(1)), c = V::Construct(m.face[f].P(2));
        const V n = ((b - a) ^ (c - a)).Normalize();
        V p;
        const int k = i % 3;
        if (k == 0) { double x = u(rng), y = u(rng) * (1 - x); p = a + (b - a) * x * 0.9 + (c - a) * y * 0.9 + (b - a + c - a) * 0.02; }
        if (k == 1) p = a + (b - a) * u(rng);
        if (k == 2) p = a;
        pts.push_back(p + n * noise(rng));
        kind.push_back(k);
        face.push_back(f);
        vert.push_back(int(vcg::tri::Index(m, m.face[f].V(0))));
        edge.push_back(int(vcg::tri::Index(m, m.face[f].V(1))));
    }
    std::vector<SP> out;
    std::vector<char> found;
    loc.LocateAll(pts, out, found);
    int wrong = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        if (!found[i]) { ++wrong; continue; }
        const SP &s = out[i];
        if ((s.pos - pts[i]).Norm() > tol) ++wrong;
        if (kind[i] == 0 && (s.kind != SP::InFace || s.face != face[i])) ++wrong;
        if (kind[i] == 1) {
            if (s.kind != SP::OnEdge) { ++wrong; continue; }
            std::set<int> e{adj.fv[s.face][s.edge], adj.fv[s.face][(s.edge + 1) % 3]};
            if (e != std::set<int>{vert[i], edge[i]}) ++wrong;
        }
        if (kind[i] == 2 && (s.kind != SP::AtVertex || s.vertex != vert[i])) ++wrong;
    }
    EXPECT_EQ(wrong, 0);
}

// ------------------------------------------------------------------ bad input: error, mesh unchanged

namespace {
struct Snapshot {
    std::vector<P3> coords;
    std::vector<std::array<int, 3>> faces;
    std::vector<int> flags;
    std::vector<float> quality;
    static Snapshot Of(const TMesh &m)
    {
        Snapshot s;
        for (auto &v : m.vert) s.coords.push_back(v.cP());
        for (auto &f : m.face) {
            s.faces.push_back({int(vcg::tri::Index(m, f.cV(0))), int(vcg::tri::Index(m, f.cV(1))), int(vcg::tri::Index(m, f.cV(2)))});
            s.flags.push_back(f.cFlags());
            s.quality.push_back(f.cQ());
        }
        return s;
    }
    bool operator==(const Snapshot &o) const { return coords == o.coords && faces == o.faces && flags == o.flags && quality == o.quality; }
};

void ExpectRefused(TMesh &m, const TMesh &poly, const std::string &expected, double tolPercent = 1e-4)
{
    const Snapshot before = Snapshot::Of(m);
    Embedding::Result r = Embed(m, poly, tolPercent);
    EXPECT_NE(r.error.find(expected), std::string::npos) << "got: " << r.error;
    EXPECT_TRUE(Snapshot::Of(m) == before) << "the mesh changed";
}
}  // namespace

TEST(PolylineEmbedding, BadInputIsRefusedAndTheMeshUnchanged)
{
    TMesh m, poly;
    MakeCube(m, 4, 0.2f, 1);
    for (auto &f : m.face) f.Q() = 1;

    ExpectRefused(m, poly, "no edges");
    MakePolyline(poly, {P3(-1, 0.1f, 0.2f), P3(-1, -0.3f, 0.25f), P3(-1.01f, -0.5f, 0.5f)});
    ExpectRefused(m, poly, "from the surface");
    MakePolyline(poly, {P3(-1, 0.1f, 0.2f), P3(-1, -0.3f, 0.25f)});
    ExpectRefused(m, poly, "locate tolerance", 0);
    ExpectRefused(m, m, "the mesh itself");
    MakePolyline(poly, {P3(-1, 0.1f, 0.2f), P3(std::nanf(""), 0, 0)});
    ExpectRefused(m, poly, "NaN");

    // Two polylines crossing inside one face (each a chord between edge points).
    TMesh grid, more;
    MakeGrid(grid, 1);  // two triangles (0,0)(1,0)(1,1) and (0,0)(1,1)(0,1)
    MakePolyline(poly, {P3(0.3f, 0.f, 0), P3(1.f, 0.3f, 0)});
    MakePolyline(more, {P3(0.6f, 0.f, 0), P3(1.f, 0.9f, 0)});
    AppendPolyline(poly, more);
    ExpectRefused(grid, poly, "cross");
    // A polyline crossing itself (traced across several faces).
    MakeGrid(grid, 4, 1.f, 0.2f, 6);
    MakePolyline(poly, {P3(0.1f, 0.1f, 0), P3(0.9f, 0.9f, 0), P3(0.9f, 0.1f, 0), P3(0.1f, 0.9f, 0)});
    ExpectRefused(grid, poly, "cross");
}

TEST(PolylineEmbedding, NonManifoldAndBadlyOrientedMeshesAreRefused)
{
    TMesh fin, poly;
    Build(fin, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, -1, 0), P3(0, 0, 1)}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    MakePolyline(poly, {P3(0.2f, 0.1f, 0), P3(0.3f, 0.3f, 0)});
    ExpectRefused(fin, poly, "2-manifold");
    TMesh flipped;
    Build(flipped, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(1, 1, 0)}, {{0, 1, 2}, {1, 2, 3}});
    ExpectRefused(flipped, poly, "oriented");
    TMesh bowtie;  // two fans at vertex 0
    Build(bowtie, {P3(0, 0, 0), P3(1, 0, 0), P3(1, 1, 0), P3(-1, 0, 0), P3(-1, -1, 0)}, {{0, 1, 2}, {0, 3, 4}});
    MakePolyline(poly, {P3(0.5f, 0.1f, 0), P3(0.8f, 0.5f, 0)});
    ExpectRefused(bowtie, poly, "vertices are non-manifold");
}

TEST(PolylineEmbedding, UntraceableSegmentIsRefused)
{
    // Two disjoint cubes: a segment from one to the other has no surface path.
    TMesh m, other, poly;
    MakeCube(m, 3);
    MakeCube(other, 3);
    for (auto &v : other.vert) v.P() += P3(5, 0, 0);
    vcg::tri::Append<TMesh, TMesh>::Mesh(m, other);
    MakePolyline(poly, {P3(1, 0.1f, 0.2f), P3(4, 0.1f, 0.2f)});
    ExpectRefused(m, poly, "cannot be traced");
}

// ------------------------------------------------------------------ front-edge helpers (shared with Q-Morph)

TEST(FrontEdges, SelectCollectAndEdgeMesh)
{
    TMesh m, edges;
    MakeCube(m, 2);
    typedef vcg_ext::FrontEdges<TMesh> FE;
    std::vector<FE::Edge> want;
    for (auto &f : m.face)
        if (f.P(0)[2] == 1 && f.P(1)[2] == 1) want.push_back(FE::EdgeOf(m, f, 0));
    std::sort(want.begin(), want.end());
    want.erase(std::unique(want.begin(), want.end()), want.end());
    ASSERT_FALSE(want.empty());
    EXPECT_EQ(FE::Select(m, want), int(want.size()));
    EXPECT_EQ(FE::Collect(m), want);
    EXPECT_EQ(FE::CountOneSided(m), 0);
    // Find a selected face-edge and clear one side of it.
    int f0 = 0, e0 = -1;
    for (; f0 < int(m.face.size()) && e0 < 0; ++f0)
        for (int k = 0; k < 3 && e0 < 0; ++k)
            if (m.face[f0].IsFaceEdgeS(k)) e0 = k;
    ASSERT_GE(e0, 0);
    m.face[f0 - 1].ClearFaceEdgeS(e0);
    EXPECT_EQ(FE::CountOneSided(m), 1);
    EXPECT_EQ(FE::Collect(m), want) << "still selected on the other side";
    FE::BuildEdgeMesh(m, want, edges);
    EXPECT_EQ(edges.en, int(want.size()));
    EXPECT_EQ(edges.fn, 0);
    for (size_t i = 0; i < want.size(); ++i) {
        EXPECT_EQ(edges.edge[i].V(0)->P(), m.vert[want[i].first].P());
        EXPECT_EQ(edges.edge[i].V(1)->P(), m.vert[want[i].second].P());
    }
    FE::Clear(m);
    EXPECT_TRUE(FE::Collect(m).empty());
}
