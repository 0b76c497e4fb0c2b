// The input surface as the judge of flipped faces (common/input_surface.h): next to a crease sharper
// than 90 degrees (a thin fin), the closest triangle decides, and only a point as close to both
// sides (on the crease) is left to the caller's own normal.
#include <gtest/gtest.h>

#include "test_mesh.h"
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg_ext/common/input_surface.h>

using namespace qmf_test;

namespace {

typedef vcg::Point3d D3;

// A knife: a lower sheet (z = 0, facing down) and an upper sheet rising to kOpening at x = 0
// (facing up) that meet at the edge x = 1, their normals almost opposite (about 178 degrees).
const float kOpening = 0.04f;

void MakeKnife(TMesh &m)
{
    Build(m,
          {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, kOpening}, {0, 1, kOpening}},
          {{0, 2, 1}, {0, 3, 2}, {4, 1, 2}, {4, 2, 5}});
}

}  // namespace

TEST(InputSurface, ThinFinSideUnderAFaceLyingOnItDecides)
{
    TMesh m;
    MakeKnife(m);
    vcg_ext::InputSurface<TMesh> input(m);
    const D3 down(0, 0, -1), up(0, 0, 1);
    // On the lower sheet, its normal whatever the caller's: a face there facing up is flipped.
    EXPECT_LT(input.NormalUnder(D3(0.5, 0.5, 0), up)[2], -0.99);
    EXPECT_LT(input.NormalUnder(D3(0.3, 0.7, 0), down)[2], -0.99);
    // On the upper sheet (z = 0.02 at x = 0.5), its normal.
    EXPECT_GT(input.NormalUnder(D3(0.5, 0.5, kOpening / 2), down)[2], 0.99);
}

TEST(InputSurface, ThinFinNearerSideDecidesAndItsEdgeKeepsTheCallersNormal)
{
    TMesh m;
    MakeKnife(m);
    vcg_ext::InputSurface<TMesh> input(m);
    const D3 own(0.6, 0, 0.8);
    // Between the sheets at x = 0.5, a quarter of the opening up: nearer the lower sheet.
    EXPECT_LT(input.NormalUnder(D3(0.5, 0.5, kOpening / 8), own)[2], -0.99);
    // On the fin's edge (x = 1) both sheets are as close: neither decides.
    const D3 n = input.NormalUnder(D3(1, 0.5, 0), own);
    EXPECT_DOUBLE_EQ(n[0], own[0]);
    EXPECT_DOUBLE_EQ(n[2], own[2]);
}

TEST(InputSurface, FlatSurfaceAlwaysDecides)
{
    TMesh m;
    MakeGrid(m, 4);  // z = 0, facing up: no sharp crease
    vcg_ext::InputSurface<TMesh> input(m);
    EXPECT_GT(input.NormalUnder(D3(0.4, 0.4, 0.3), D3(0, 0, -1))[2], 0.99);
}

// A roof: two sheets meeting at a ridge (y = 0.5) at 40 degrees from the horizontal. Above the ridge
// both are as close; a direction facing one and not the other (a face standing on edge over the
// ridge) faces not every closest triangle, whichever of them the closest-point search returns.
TEST(InputSurface, OnEdgeOverARidgeFacesNotEveryClosestTriangle)
{
    TMesh m;
    const float rise = 0.5f * std::tan(float(40 * M_PI / 180));
    Build(m, {{0, 0, 0}, {1, 0, 0}, {1, 0.5f, rise}, {0, 0.5f, rise}, {1, 1, 0}, {0, 1, 0}},
          {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}, {3, 4, 5}});
    vcg_ext::InputSurface<TMesh> input(m);
    const D3 aboveRidge(0.5, 0.5, rise + 0.1), tiltedToOneSide(0, 0.8, 0.6), up(0, 0, 1);
    EXPECT_TRUE(input.FacesEveryClosest(aboveRidge, up));
    EXPECT_FALSE(input.FacesEveryClosest(aboveRidge, tiltedToOneSide));
    EXPECT_FALSE(input.FacesEveryClosest(aboveRidge, D3(0, -0.8, 0.6)));
    // Above one sheet only that sheet decides.
    EXPECT_TRUE(input.FacesEveryClosest(D3(0.5, 0.8, 0.3), tiltedToOneSide));
}

// An obtuse triangle (0,0,0) (10,0,0) (5,1,0) and the point (2,3,1): its projection lies outside
// the edges b-c and c-a, and the nearest point is inside edge c-a, at (2.5, 0.5, 0): distance
// sqrt(0.5^2 + 2.5^2 + 1) = sqrt(7.5). vcglib 2020.09's PointDistanceBase measures to the first
// edge whose side test fails (b-c, nearest at its end c): sqrt(13 + 1).
TEST(InputSurface, ExactDistanceToAnObtuseTriangle)
{
    TMesh m;
    Build(m, {{0, 0, 0}, {10, 0, 0}, {5, 1, 0}}, {{0, 1, 2}});
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
    const P3 p(2, 3, 1);
    P3 closest;
    float dist = 100;
    ASSERT_TRUE(vcg_ext::PointFaceDistance<TFace>()(m.face[0], p, dist, closest));
    EXPECT_NEAR(dist, std::sqrt(7.5), 1e-5);
    EXPECT_NEAR(closest[0], 2.5, 1e-5);
    EXPECT_NEAR(closest[1], 0.5, 1e-5);
    EXPECT_NEAR(closest[2], 0.0, 1e-5);
    float vcgDist = 100;
    P3 vcgClosest;
    vcg::face::PointDistanceBase(m.face[0], p, vcgDist, vcgClosest);
    EXPECT_NEAR(vcgDist, std::sqrt(14.0), 1e-5);  // why vcglib's functor is not used
    // a face farther than the bound is not taken, and the bound is kept
    float bound = 2.5f;
    EXPECT_FALSE(vcg_ext::PointFaceDistance<TFace>()(m.face[0], p, bound, closest));
    EXPECT_EQ(bound, 2.5f);
}

// The same triangle next to a second one facing the other way, 3 from the point: the input
// surface finds the obtuse triangle (sqrt(7.5) = 2.74 away) as the closest, so the normal under
// the point is its normal (up), not the farther triangle's (down).
TEST(InputSurface, ClosestTriangleOfAnObtuseNeighbourhoodIsTheNearest)
{
    TMesh m;
    Build(m, {{0, 0, 0}, {10, 0, 0}, {5, 1, 0}, {-5, 3, 4}, {9, 3, 4}, {2, 10, 4}}, {{0, 1, 2}, {3, 5, 4}});
    vcg_ext::InputSurface<TMesh> input(m);
    P3 closest;
    const TFace *f = input.Closest(P3(2, 3, 1), closest);
    ASSERT_NE(f, nullptr);
    EXPECT_EQ(vcg::tri::Index(input.mesh, f), 0u);
    EXPECT_GT(input.NormalUnder(D3(2, 3, 1), D3(0, 0, -1))[2], 0.99);
}

// The grid's answers against every triangle tested one by one, on a scan with thin fins and sharp
// creases (CGAL's man, extracted by set-up): the closest triangle's distance is the least of all,
// and whether a direction faces every closest triangle (those within the tie slack of the closest,
// on its side of a crease) is what the whole list says. Points near face centres, and just above
// vertices, where the closest point is a corner that several triangles share (ties).
TEST(InputSurface, SearchesAgreeWithEveryTriangleTestedOnAScan)
{
    TMesh m;
    ASSERT_TRUE(LoadOff(m, MeshDir() + "/man.off"));
    vcg_ext::InputSurface<TMesh> input(m);
    const TMesh &s = input.mesh;
    const double diagonal = s.bbox.Diag();
    std::vector<D3> points;
    for (size_t f = 0; f < s.face.size(); f += 97) {
        const D3 a = D3::Construct(s.face[f].cP(0)), b = D3::Construct(s.face[f].cP(1)), c = D3::Construct(s.face[f].cP(2));
        const D3 n = D3::Construct(s.face[f].cN());
        const double edge = (b - a).Norm();
        points.push_back((a + b + c) / 3.0 + n * (0.3 * edge) + (b - a) * 0.2);
        points.push_back(a + n * (1e-3 * edge));
    }
    const D3 directions[3] = {D3(0, 0, 1), D3(0.6, -0.8, 0), D3(-0.48, 0.6, 0.64)};
    int ties = 0;
    for (const D3 &p : points) {
        const P3 q = P3::Construct(p);
        P3 closest;
        const TFace *near = input.Closest(q, closest);
        ASSERT_NE(near, nullptr);
        double least = 1e300;
        for (const TFace &f : s.face) {
            float d = float(diagonal);
            P3 at;
            if (vcg_ext::PointFaceDistance<TFace>()(f, q, d, at)) least = std::min(least, double(d));
        }
        EXPECT_NEAR(vcg::Distance(q, closest), least, 1e-6 * diagonal);
        // the triangles tied with the closest, as the input surface defines them
        const float radius = float(vcg::Distance(q, closest) + vcg_ext::InputSurface<TMesh>::kTieDiagonal * diagonal);
        std::vector<const TFace *> tied;
        for (const TFace &f : s.face) {
            float d = radius;
            P3 at;
            if (vcg_ext::PointFaceDistance<TFace>()(f, q, d, at)) tied.push_back(&f);
        }
        ties += tied.size() > 1;
        for (const D3 &direction : directions) {
            bool every = D3::Construct(input.Normal(near)) * direction > 0;
            for (const TFace *f : tied)
                if (f->cN() * near->cN() >= 0 && !(D3::Construct(input.Normal(f)) * direction > 0)) every = false;
            EXPECT_EQ(input.FacesEveryClosest(p, direction), every);
        }
    }
    EXPECT_GT(ties, int(points.size()) / 4);  // the points above vertices have several closest triangles
}
