// Geodesic straightening of region boundaries (vcg_ext/geodesic_straightening.h).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "boundary_test_meshes.h"
#include "test_mesh.h"
#include <vcg_ext/geodesic_straightening.h>
#include <vcg_ext/vsa_segmentation.h>

using namespace qmf_test;
using namespace qmf_test::boundary;
typedef vcg_ext::SurfacePoint SP;

namespace {

// A 40 x 40 jittered grid of the unit square; cells with j < 10 + i/2 are region 0, the rest
// region 1: a staircase of grid edges from (0, 0.25) to (1, 0.725) (slope 1/2, steps of one cell).
const int kGrid = 40;
std::vector<int> MakeStaircase(TMesh &m)
{
    MakeGrid(m, kGrid, 1.f, 0.25f, 11);
    return SetRegions(m, [](int f) {
        int i, j;
        GridCell(kGrid, f, i, j);
        return j < 10 + i / 2 ? 0 : 1;
    });
}
const D3 kStairStart(0, 0.25, 0), kStairEnd(1, 29.0 / 40, 0);

Smoothing::Result RunSmoothing(const TMesh &m, const std::vector<int> &region, int iterations, double snapPercent = 10)
{
    Smoothing::Params p;
    p.iterations = iterations;
    p.snapPercent = snapPercent;
    return Smoothing::Smooth(m, region, p);
}

std::set<int> CornerSet(const Smoothing::Result &r) { return std::set<int>(r.corners.begin(), r.corners.end()); }

void ExpectInvariants(const TMesh &m, const Smoothing::Result &r, double snapFraction)
{
    CurveCheck c = CheckCurves(m, r.topology, r.curves, snapFraction, CornerSet(r));
    EXPECT_EQ(c.pointsOffEdges, 0) << c.firstProblem;
    EXPECT_EQ(c.segmentsWithoutFace, 0) << c.firstProblem;
    EXPECT_EQ(c.crossings, 0) << c.firstProblem;
    EXPECT_EQ(c.pointsNearVertex, 0);
    EXPECT_EQ(c.sharedPoints, 0);
    EXPECT_EQ(r.unsnapped, 0);
}

// The ends of every open curve are corners, the same before and after.
void ExpectSameEnds(const Smoothing::Result &before, const Smoothing::Result &after)
{
    ASSERT_EQ(before.curves.size(), after.curves.size());
    for (size_t i = 0; i < before.curves.size(); ++i) {
        const auto &a = before.curves[i].path, &b = after.curves[i].path;
        ASSERT_EQ(a.closed, b.closed);
        EXPECT_EQ(before.curves[i].regionLeft, after.curves[i].regionLeft);
        EXPECT_EQ(before.curves[i].regionRight, after.curves[i].regionRight);
        if (a.closed) continue;
        EXPECT_TRUE(a.points.front() == b.points.front());
        EXPECT_TRUE(a.points.back() == b.points.back());
    }
}

}  // namespace

TEST(GeodesicStraightening, StaircaseOnAFlatSquareBecomesStraight)
{
    TMesh m;
    auto region = MakeStaircase(m);
    Smoothing::Result raw = RunSmoothing(m, region, 0);
    ASSERT_EQ(raw.error, "");
    ASSERT_EQ(raw.curves.size(), 1u);
    // Hand count: 40 cells along x plus 19 one-cell steps up, each of length 1/40.
    EXPECT_NEAR(raw.lengthBefore, 59.0 / 40, 0.05) << "jittered grid edges";
    const double straight = (kStairEnd - kStairStart).Norm();
    Smoothing::Result r = RunSmoothing(m, region, 1000);
    ASSERT_EQ(r.error, "");
    EXPECT_GT(r.passes, 100);
    const auto &path = r.curves[0].path;
    EXPECT_NEAR(Straight::Position(r.topology, path.points.front())[1], 0.25, 1e-6);
    EXPECT_NEAR(Straight::Position(r.topology, path.points.back())[1], 29.0 / 40, 1e-6);
    EXPECT_LT(r.lengthAfter, straight * 1.005) << "straight within 0.5%";
    EXPECT_GE(r.lengthAfter, straight * (1 - 1e-9));
    // Every point close to the segment between the ends: within a few tenths of a cell (the last
    // snapping moves points by up to 10% of an edge; the convergence is slow, like diffusion).
    for (const SP &q : path.points)
        EXPECT_LT(SegmentDistance(Straight::Position(r.topology, q), kStairStart, kStairEnd), 0.3 / kGrid);
    EXPECT_LT(r.jaggednessAfter, 0.1 * r.jaggednessBefore);
    ExpectSameEnds(raw, r);
    ExpectInvariants(m, r, 0.1);
}

TEST(GeodesicStraightening, ThreeIterationsShortenTheStaircaseAndKeepItsEnds)
{
    TMesh m;
    auto region = MakeStaircase(m);
    Smoothing::Result raw = RunSmoothing(m, region, 0);
    Smoothing::Result r = RunSmoothing(m, region, 3);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.passes, 3);
    EXPECT_DOUBLE_EQ(r.lengthBefore, raw.lengthAfter);
    EXPECT_LT(r.lengthAfter, r.lengthBefore * 0.95);
    EXPECT_LT(r.jaggednessAfter, r.jaggednessBefore);
    EXPECT_GT(r.moves, 0);
    ExpectSameEnds(raw, r);
    ExpectInvariants(m, r, 0.1);
    // More iterations never lengthen it.
    Smoothing::Result r10 = RunSmoothing(m, region, 10);
    EXPECT_LE(r10.lengthAfter, r.lengthAfter);
}

TEST(GeodesicStraightening, SnappingKeepsEdgePointsAwayFromVertices)
{
    TMesh m;
    auto region = MakeStaircase(m);
    for (double snap : {0.1, 5.0, 25.0}) {
        Smoothing::Result r = RunSmoothing(m, region, 20, snap);
        ASSERT_EQ(r.error, "");
        int edgePoints = 0;
        for (const SP &q : r.curves[0].path.points) {
            if (q.IsVertex()) continue;
            ++edgePoints;
            EXPECT_GE(std::min(q.t, 1 - q.t), snap / 100);
        }
        EXPECT_GT(edgePoints, 0);
        ExpectInvariants(m, r, snap / 100);
    }
}

TEST(GeodesicStraightening, CubeFromVsaHasTwelveCurvesThatStayOnTheCubeEdges)
{
    TMesh m;
    MakeCube(m, 6, 0.35f, 7);
    vcg_ext::VSASegmentation<TMesh>::Params vp;
    vp.mode = vcg_ext::VSASegmentation<TMesh>::FixedRegionCount;
    vp.maxRegions = 6;
    auto seg = vcg_ext::VSASegmentation<TMesh>::Segment(m, vp);
    ASSERT_EQ(seg.error, "");
    ASSERT_EQ(seg.regions, 6);
    Smoothing::Result r = RunSmoothing(m, seg.faceRegion, 3);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.curves.size(), 12u);
    EXPECT_EQ(r.corners.size(), 8u);
    EXPECT_EQ(r.closedLoops, 0);
    EXPECT_NEAR(r.lengthBefore, 24.0, 1e-5);
    EXPECT_NEAR(r.lengthAfter, 24.0, 1e-5) << "cube edges are already geodesic";
    EXPECT_NEAR(r.jaggednessAfter, 0.0, 1e-4);
    for (const auto &c : r.curves)
        for (const SP &q : c.path.points) {
            D3 p = Straight::Position(r.topology, q);
            int onFace = 0;
            for (int k = 0; k < 3; ++k) onFace += std::fabs(std::fabs(p[k]) - 1) < 1e-6;
            EXPECT_GE(onFace, 2) << "point off the cube edges: " << p[0] << " " << p[1] << " " << p[2];
        }
    ExpectInvariants(m, r, 0.1);
}

TEST(GeodesicStraightening, CylinderCapsAndBandKeepInvariantsAndRegionPairs)
{
    TMesh m;
    MakeCylinder(m, 24, 8, 1.f, 2.f, 4);
    // Caps, a helical-ish band split into sectors: corners on the rims and between sectors.
    auto region = SetRegions(m, [&](int f) {
        D3 c = Centroid(m, f);
        if (c[2] > 0.999) return 0;
        if (c[2] < -0.999) return 1;
        double a = std::atan2(c[1], c[0]) + c[2] * 0.8;  // twisted sector borders: jagged on the grid
        int sector = int(std::floor((a + M_PI) / (2 * M_PI / 3) + 3)) % 3;
        return 2 + sector;
    });
    Smoothing::Result raw = RunSmoothing(m, region, 0);
    Smoothing::Result r = RunSmoothing(m, region, 3);
    ASSERT_EQ(r.error, "");
    EXPECT_EQ(r.curves.size(), raw.curves.size());
    EXPECT_LT(r.lengthAfter, r.lengthBefore);
    ExpectSameEnds(raw, r);
    ExpectInvariants(m, r, 0.1);
    Smoothing::Result many = RunSmoothing(m, region, 200);
    ExpectSameEnds(raw, many);
    ExpectInvariants(m, many, 0.1);
    EXPECT_LE(many.lengthAfter, r.lengthAfter);
    // Region pairs kept: the vertex patches left and right of each curve carry its two regions.
    for (const Smoothing::Result *res : {&r, &many}) {
        VertexPatches patches = ComputePatches(m, res->topology, res->curves, region);
        for (const auto &c : res->curves) {
            std::map<int, int> left, right;
            SideLabels(m, res->topology, c.path, patches, 3, left, right);
            ASSERT_FALSE(left.empty() || right.empty());
            EXPECT_EQ(Majority(left), c.regionLeft);
            EXPECT_EQ(Majority(right), c.regionRight);
        }
    }
}

TEST(GeodesicStraightening, ClosedLoopsAreAnchoredAndDoNotVanish)
{
    TMesh m;
    MakeSphere(m, 4);
    // A cap of the sphere: its boundary is a jagged closed loop that shortening would shrink.
    auto region = SetRegions(m, [&](int f) { return Centroid(m, f)[2] > 0.5 ? 1 : 0; });
    Smoothing::Result r = RunSmoothing(m, region, 500);
    ASSERT_EQ(r.error, "");
    ASSERT_EQ(r.curves.size(), 1u);
    EXPECT_EQ(r.closedLoops, 1);
    const auto &path = r.curves[0].path;
    EXPECT_TRUE(path.closed);
    int fixed = 0;
    for (char f : path.fixed) fixed += f;
    EXPECT_EQ(fixed, 3);
    EXPECT_GE(path.points.size(), 3u);
    EXPECT_LT(r.lengthAfter, r.lengthBefore);
    EXPECT_GT(r.lengthAfter, 0.5 * r.lengthBefore) << "a geodesic triangle through the anchors, not a point";
    ExpectInvariants(m, r, 0.1);
}

TEST(GeodesicStraightening, TwoCurvesBetweenTheSameCornersNeverCross)
{
    // An eye-shaped region 2 between regions 0 (above) and 1 (below) on a flat grid: both of its
    // curves run from tip to tip, and straightening pulls both onto the same straight chord.
    const int n = 30;
    TMesh m;
    MakeGrid(m, n, 1.f, 0.2f, 5);
    auto region = SetRegions(m, [&](int f) {
        D3 c = Centroid(m, f);
        double x = (c[0] - 0.5) / 0.3;
        if (std::fabs(x) < 1 && std::fabs(c[1] - 0.5) < 0.15 * (1 - x * x)) return 2;
        return c[1] > 0.5 ? 0 : 1;
    });
    Smoothing::Result raw = RunSmoothing(m, region, 0);
    Smoothing::Result r = RunSmoothing(m, region, 1000);
    ASSERT_EQ(r.error, "");
    ExpectSameEnds(raw, r);
    ExpectInvariants(m, r, 0.1);
    EXPECT_GT(r.rejectedMoves, 0) << "the two curves of the eye met";
    // The eye keeps mesh vertices of its own between its curves.
    VertexPatches vp = ComputePatches(m, r.topology, r.curves, region);
    std::set<int> labels(vp.label.begin(), vp.label.end());
    EXPECT_TRUE(labels.count(0) && labels.count(1));
}

TEST(GeodesicStraightening, RealMeshInvariants)
{
    TMesh m;
    ASSERT_TRUE(LoadOff(m, MeshDir() + "/fandisk.off"));
    vcg_ext::VSASegmentation<TMesh>::Params vp;
    auto seg = vcg_ext::VSASegmentation<TMesh>::Segment(m, vp);
    ASSERT_EQ(seg.error, "");
    Smoothing::Result raw = RunSmoothing(m, seg.faceRegion, 0);
    Smoothing::Result r = RunSmoothing(m, seg.faceRegion, 3);
    ASSERT_EQ(r.error, "");
    EXPECT_GT(r.curves.size(), 10u);
    EXPECT_LT(r.lengthAfter, r.lengthBefore);
    EXPECT_LT(r.jaggednessAfter, r.jaggednessBefore);
    ExpectSameEnds(raw, r);
    ExpectInvariants(m, r, 0.1);
    // Region pairs kept: the vertex patches left and right of each curve carry its two regions.
    VertexPatches patches = ComputePatches(m, r.topology, r.curves, seg.faceRegion);
    int checked = 0;
    for (const auto &c : r.curves) {
        std::map<int, int> left, right;
        SideLabels(m, r.topology, c.path, patches, 3, left, right);
        if (left.empty() || right.empty()) continue;
        ++checked;
        EXPECT_EQ(Majority(left), c.regionLeft);
        EXPECT_EQ(Majority(right), c.regionRight);
    }
    EXPECT_GT(checked, int(r.curves.size()) * 3 / 4);
}

// Two paths from c1 to c2 across the edge a-b of two triangles, A at 0.3 and B at 0.6 along it;
// both want to go to 0.8. A may not pass B: their segments only meet at the shared ends, so only
// the order along the edge tells that A would jump over B (and swap the regions between them).
TEST(GeodesicStraightening, TwoPathsThroughOneEdgeKeepTheirOrder)
{
    TMesh m;
    Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0.8f, 1, 0), P3(0.8f, -1, 0)}, {{0, 1, 2}, {1, 0, 3}});
    Topo t;
    t.Build(m);
    const int e = t.EdgeBetween(0, 1);
    ASSERT_GE(e, 0);
    auto along = [&](double s) { return SP::OnEdge(e, t.edgeVerts[e][0] == 0 ? s : 1 - s); };  // s from vertex 0
    auto param = [&](const SP &q) { return t.edgeVerts[e][0] == 0 ? q.t : 1 - q.t; };
    std::vector<vcg_ext::SurfacePath> paths(2);
    paths[0].points = {SP::AtVertex(2), along(0.3), SP::AtVertex(3)};
    paths[1].points = {SP::AtVertex(2), along(0.6), SP::AtVertex(3)};
    for (auto &p : paths) p.fixed = {1, 0, 1};
    Straight::Params p;
    p.iterations = 10;
    Straight::Result r = Straight::Straighten(t, paths, p);
    ASSERT_EQ(r.error, "");
    ASSERT_EQ(paths[0].points.size(), 3u);
    ASSERT_EQ(paths[1].points.size(), 3u);
    EXPECT_NEAR(param(paths[1].points[1]), 0.8, 1e-6) << "B reaches the straight line (float coordinates)";
    EXPECT_LT(param(paths[0].points[1]), param(paths[1].points[1])) << "A stays on its side of B";
    EXPECT_GE(param(paths[1].points[1]) - param(paths[0].points[1]), 0.1 - 1e-12) << "the gap: the snap distance";
    EXPECT_GT(r.rejected, 0);
}

// Random Voronoi-like labellings (ids modulo 3: regions touching themselves, ids on several
// patches) on a closed and an open mesh: every run keeps every invariant and never lengthens.
TEST(GeodesicStraightening, RandomLabellingsKeepTheInvariants)
{
    TMesh sphere, grid;
    MakeSphere(sphere, 3);
    MakeGrid(grid, 16, 1.f, 0.3f, 4);
    std::mt19937 rng(7);
    for (TMesh *m : {&sphere, &grid})
        for (int trial = 0; trial < 3; ++trial) {
            const int k = 5 + int(rng() % 25);
            std::vector<int> seeds;
            for (int i = 0; i < k; ++i) seeds.push_back(int(rng() % m->face.size()));
            auto region = SetRegions(*m, [&](int f) {
                int best = 0;
                double bd = 1e30;
                for (int i = 0; i < k; ++i) {
                    double d = (Centroid(*m, f) - Centroid(*m, seeds[i])).SquaredNorm();
                    if (d < bd) { bd = d; best = i; }
                }
                return trial == 2 ? best % 3 : best;
            });
            for (int iterations : {3, 100})
                for (double snap : {10.0, 30.0}) {
                    SCOPED_TRACE(std::to_string(trial) + " " + std::to_string(iterations) + " " + std::to_string(snap));
                    Smoothing::Result r = RunSmoothing(*m, region, iterations, snap);
                    ASSERT_EQ(r.error, "");
                    EXPECT_LE(r.lengthAfter, r.lengthBefore);
                    ExpectInvariants(*m, r, snap / 100);
                }
        }
}

TEST(GeodesicStraightening, RefusesBadInput)
{
    TMesh m;
    MakeCube(m, 2);
    std::vector<int> one(m.face.size(), 4);
    EXPECT_NE(RunSmoothing(m, one, 3).error.find("single region"), std::string::npos);
    std::vector<int> two(m.face.size(), 0);
    two[0] = 1;
    EXPECT_NE(RunSmoothing(m, two, -1).error.find("iterations"), std::string::npos);
    EXPECT_NE(RunSmoothing(m, two, 1001).error.find("iterations"), std::string::npos);
    EXPECT_NE(RunSmoothing(m, two, 3, 50).error.find("snap"), std::string::npos);
    EXPECT_NE(RunSmoothing(m, two, 3, -1).error.find("snap"), std::string::npos);
    EXPECT_EQ(RunSmoothing(m, two, 3).error, "");
    // Two components, one region each: regions but no boundary.
    TMesh pair;
    Build(pair, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(5, 0, 0), P3(6, 0, 0), P3(5, 1, 0)}, {{0, 1, 2}, {3, 4, 5}});
    EXPECT_NE(RunSmoothing(pair, {0, 1}, 3).error.find("no boundary edge"), std::string::npos);
    m.vert[3].P()[1] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_NE(RunSmoothing(m, two, 3).error.find("NaN"), std::string::npos);
}

TEST(GeodesicStraightening, BoundariesAlongACreaseStayOnIt)
{
    // Caps and side of a cylinder as three regions: the two boundaries are the rims, closed loops of
    // 90-degree creases. Shortened, each would cut across its cap toward the triangle of its three
    // anchors; held, every point stays on a rim vertex and the length stays the same.
    const int slices = 24;
    TMesh m;
    MakeCylinder(m, slices, 4, 1.f, 2.f, 3);
    auto region = SetRegions(m, [&](int f) {
        const D3 c = Centroid(m, f);
        return c[2] > 0.999 ? 0 : (c[2] < -0.999 ? 1 : 2);
    });
    Smoothing::Result r = RunSmoothing(m, region, 50);
    ASSERT_EQ(r.error, "");
    ASSERT_EQ(r.curves.size(), 2u);
    EXPECT_EQ(r.closedLoops, 2);
    EXPECT_EQ(r.heldCreasePoints, 2 * (slices - 3)) << "every rim point but the three anchors of each loop";
    EXPECT_NEAR(r.lengthAfter, r.lengthBefore, 1e-9 * r.lengthBefore);
    for (const auto &c : r.curves) {
        ASSERT_EQ(c.path.points.size(), size_t(slices));
        for (const SP &p : c.path.points) {
            ASSERT_TRUE(p.IsVertex());
            const D3 q = D3::Construct(m.vert[p.vertex].cP());
            EXPECT_NEAR(std::fabs(q[2]), 1.0, 1e-6);
            EXPECT_NEAR(std::hypot(q[0], q[1]), 1.0, 1e-6);
        }
    }
    ExpectInvariants(m, r, 0.1);
}
