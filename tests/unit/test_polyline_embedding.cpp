// Filter 3 core on whole meshes: locating, tracing, splitting, relabelling, and its invariants.
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

// Across the rim of a part thinner than its triangles (a plate 0.002 thick, triangles 0.5 wide; a
// scan's thin flap, diplodocus from CGAL's data): a segment from the top sheet straight down to
// the bottom one has ends whose normals are opposite and parallel to it, so no plane section
// joins them. It is laid along the shortest chain of mesh edges over the rim instead, a chain of
// selected edges from end to end, and the split keeps every other invariant.
TEST(PolylineEmbedding, SegmentAcrossAThinRimFollowsMeshEdges)
{
    TMesh m, before, poly;
    MakeCube(m, 4);
    for (TVertex &v : m.vert) v.P()[2] *= 0.001f;
    Copy(before, m);
    MakePolyline(poly, {P3(0.7f, 0.1f, 0.001f), P3(0.7f, 0.1f, -0.001f)});
    Embedding::Result r = Embed(m, poly);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.tracedSegments, 1);
    EXPECT_EQ(r.edgePathSegments, 1);
    EXPECT_EQ(r.pointsInFaces, 2);
    EXPECT_GE(r.frontEdges, 4) << "in to the top sheet's corner, over the rim (two edges), out to the end";
    SplitExpectations x;
    x.closedFront = false;
    x.pointsInFaces = true;
    x.straightSegments = false;
    ExpectSplitInvariants(before, m, poly, x);
}
