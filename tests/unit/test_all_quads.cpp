// The all-quads split (qmorph/all_quads.h) on hand-made meshes in the z = 0 plane: a quad becomes
// four quads and a triangle three, unless the triangle is a sliver beside a quad, which is first
// merged with it into a pentagon (five quads).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "test_mesh.h"
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/qmorph/all_quads.h>
#include <vcg_ext/quad_quality.h>

using namespace qmf_test;

namespace {

typedef vcg_ext::qmorph::AllQuads<TMesh> AllQuads;
typedef vcg::Point3d D3;

// The input: a square of two triangles covering the work area, z = 0, facing +z.
void MakeInputPlane(TMesh &input)
{
    auto v = vcg::tri::Allocator<TMesh>::AddVertices(input, 4);
    v[0].P() = P3(-2, -2, 0);
    v[1].P() = P3(6, -2, 0);
    v[2].P() = P3(6, 6, 0);
    v[3].P() = P3(-2, 6, 0);
    vcg::tri::Allocator<TMesh>::AddFace(input, &v[0], &v[1], &v[2]);
    vcg::tri::Allocator<TMesh>::AddFace(input, &v[0], &v[2], &v[3]);
}

// The quad A(1,1) B(3,1) C(3,3) D(1,3) (two triangles with a faux diagonal A-C) and the
// triangle A, apex, B below its edge A-B, all counter-clockwise seen from +z.
void MakeQuadAndTriangle(TMesh &m, const P3 &apex)
{
    auto v = vcg::tri::Allocator<TMesh>::AddVertices(m, 5);
    v[0].P() = P3(1, 1, 0);
    v[1].P() = P3(3, 1, 0);
    v[2].P() = P3(3, 3, 0);
    v[3].P() = P3(1, 3, 0);
    v[4].P() = apex;
    auto f = vcg::tri::Allocator<TMesh>::AddFaces(m, 3);
    f[0].V(0) = &v[0]; f[0].V(1) = &v[1]; f[0].V(2) = &v[2];
    f[1].V(0) = &v[0]; f[1].V(1) = &v[2]; f[1].V(2) = &v[3];
    f[2].V(0) = &v[0]; f[2].V(1) = &v[4]; f[2].V(2) = &v[1];
    f[0].SetF(2);  // C-A
    f[1].SetF(0);  // A-C
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
}

// The worst scaled Jacobian (against +z, the input's normal) of m's faces read as polygons, and
// their count by size.
double WorstJacobian(TMesh &m, int &quads, int &others)
{
    const vcg_ext::PolygonMesh pm = vcg_ext::QuadQuality::FromFauxMesh(m);
    quads = others = 0;
    double worst = 1;
    for (const std::vector<int> &f : pm.faces) {
        if (f.size() != 4) { ++others; continue; }
        ++quads;
        const D3 q[4] = {pm.points[f[0]], pm.points[f[1]], pm.points[f[2]], pm.points[f[3]]};
        worst = std::min(worst, vcg_ext::ScaledJacobian(q, D3(0, 0, 1)));
    }
    return worst;
}

// The quad and the triangle with that apex split; `frontBetween`: their shared edge A-B selected
// on both sides (a front edge).
struct SplitOutcome {
    AllQuads::Stats stats;
    int quads = 0, others = 0;  // read back from the mesh
    double worst = 0;           // WorstJacobian
    int selectedHalves = 0;     // selected face-edges after the split
};
SplitOutcome SplitBesideQuad(const P3 &apex, bool frontBetween = false)
{
    TMesh input, m;
    MakeInputPlane(input);
    vcg_ext::InputSurface<TMesh> surface(input);
    MakeQuadAndTriangle(m, apex);
    if (frontBetween) {
        m.face[0].SetFaceEdgeS(0);  // A-B on the quad's side
        m.face[2].SetFaceEdgeS(2);  // B-A on the triangle's side
    }
    SplitOutcome r;
    r.stats = AllQuads::Split(m, surface, 60);
    r.worst = WorstJacobian(m, r.quads, r.others);
    for (const TFace &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k) r.selectedHalves += f.IsFaceEdgeS(k);
    return r;
}

}  // namespace

// A sliver (base 2, height 0.05) against the quad's edge: its own child at the apex would be flat,
// all four corners within 0.05 of the base line; merged with the quad, the pentagon's five
// children all turn the right way (the one at the apex, whose angle is nearly straight, is the
// worst: about 0.1, left to the final shape pass).
TEST(AllQuads, ASliverBesideAQuadIsMergedIntoAPentagon)
{
    const D3 a(1, 1, 0), b(3, 1, 0), apex(2, 0.95, 0);
    const SplitOutcome r = SplitBesideQuad(P3::Construct(apex));
    EXPECT_EQ(r.stats.pentagons, 1);
    EXPECT_EQ(r.stats.quads, 5);
    EXPECT_EQ(r.quads, 5);
    EXPECT_EQ(r.others, 0);
    // the triangle's own child at the apex: apex, midpoint to b, centroid, midpoint from a
    const D3 apexChild[4] = {apex, (apex + b) / 2, (a + b + apex) / 3, (a + apex) / 2};
    const double alone = vcg_ext::ScaledJacobian(apexChild, D3(0, 0, 1));
    EXPECT_LT(alone, 0.05);
    EXPECT_GT(r.worst, alone + 0.05);
    EXPECT_GT(r.worst, 0.05) << "no flat or flipped child";
}

// A fair triangle (base 2, height 1.7) is split on its own: three quads, next to the quad's four.
TEST(AllQuads, AFairTriangleIsSplitOnItsOwn)
{
    const SplitOutcome r = SplitBesideQuad(P3(2, -0.7f, 0));
    EXPECT_EQ(r.stats.pentagons, 0);
    EXPECT_EQ(r.stats.quads, 7);
    EXPECT_EQ(r.quads, 7);
    EXPECT_EQ(r.others, 0);
    EXPECT_GT(r.worst, 0.5);
}

// A sliver whose edge with the quad is a front edge (selected) is never merged across it: the front
// must stay a chain of edges.
TEST(AllQuads, NoMergeAcrossAFrontEdge)
{
    const SplitOutcome r = SplitBesideQuad(P3(2, 0.95f, 0), true);
    EXPECT_EQ(r.stats.pentagons, 0);
    EXPECT_EQ(r.stats.quads, 7);
    EXPECT_EQ(r.selectedHalves, 4) << "A-B cut in two, each half selected on both sides";
}

// A quad turned the other way than the input at one corner (a dart: A(0,0) B(4,0) C(1,1) D(0,4),
// facing +z, its corner C bent in past the diagonal B-D), as a thin quad bent over a fillet is seen
// from the input under one of its corners (rocker_arm_20k with All quads): split at its centroid
// (1.25, 1.25), which lies outside it, the quarter at C turns over. The centre, a point of its own,
// is moved instead: no quarter turned over.
TEST(AllQuads, AQuarterTurnedOverByTheCentroidGetsAnotherCentre)
{
    TMesh input, m;
    MakeInputPlane(input);
    vcg_ext::InputSurface<TMesh> surface(input);
    const D3 a(0, 0, 0), b(4, 0, 0), c(1, 1, 0), d(0, 4, 0);
    Build(m, {P3::Construct(a), P3::Construct(b), P3::Construct(c), P3::Construct(d)}, {{0, 1, 2}, {0, 2, 3}});
    m.face[0].SetF(2);  // C-A, the dart's inner diagonal
    m.face[1].SetF(0);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    // the straight split's quarter at C: C, midpoint to D, centroid, midpoint from B
    const D3 centroid = (a + b + c + d) / 4;
    const D3 quarterAtC[4] = {c, (c + d) / 2, centroid, (b + c) / 2};
    ASSERT_LT(vcg_ext::VectorArea(quarterAtC, 4)[2], 0) << "the centroid's quarter at C is turned over";

    const AllQuads::Stats st = AllQuads::Split(m, surface, 60);
    EXPECT_EQ(st.quads, 4);
    const vcg_ext::PolygonMesh pm = vcg_ext::QuadQuality::FromFauxMesh(m);
    ASSERT_EQ(pm.faces.size(), 4u);
    for (const std::vector<int> &f : pm.faces) {
        ASSERT_EQ(f.size(), 4u);
        const D3 q[4] = {pm.points[f[0]], pm.points[f[1]], pm.points[f[2]], pm.points[f[3]]};
        EXPECT_GT(vcg_ext::VectorArea(q, 4)[2], 0) << "a quarter turned over";
        EXPECT_FALSE(vcg_ext::IsFolded(q));
    }
    // the centre stays on the input (the plane) and inside the dart (on the inner side of B-D)
    const int centre = int(m.vert.size()) - 1;
    EXPECT_EQ(m.vert[centre].P()[2], 0);
    EXPECT_LT(m.vert[centre].P()[0] + m.vert[centre].P()[1], 4);
}

// A part thinner than the face: the quad A(0,0) B(2,0) C(2,2) D(0,2) at z = 0 (facing +z) lies on the
// eaves of a roof (the input facing up: z = 0.3 (1 - |x - 1|)) whose underside, a strip at z = 0.25
// facing down, is nearer the quad's straight centre (1, 1, 0) than the roof is (0.25 against
// 0.287). The centre goes onto the roof, the sheet the quad faces, not left between the sheets.
TEST(AllQuads, ACentreNearerTheSheetBehindGoesOntoTheSheetTheFaceFaces)
{
    TMesh input, m;
    const double kRidge = 0.3, kUnderside = 0.25, kStrip = 0.15;
    Build(input,
          {P3(0, -1, 0), P3(1, -1, kRidge), P3(2, -1, 0), P3(0, 3, 0), P3(1, 3, kRidge), P3(2, 3, 0),  // the roof
           P3(1 - kStrip, -1, kUnderside), P3(1 + kStrip, -1, kUnderside), P3(1 + kStrip, 3, kUnderside),
           P3(1 - kStrip, 3, kUnderside)},  // its underside
          {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {6, 8, 7}, {6, 9, 8}});
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(input);
    ASSERT_GT(input.face[0].N()[2], 0);
    ASSERT_LT(input.face[4].N()[2], 0);
    vcg_ext::InputSurface<TMesh> surface(input);
    Build(m, {P3(0, 0, 0), P3(2, 0, 0), P3(2, 2, 0), P3(0, 2, 0)}, {{0, 1, 2}, {0, 2, 3}});
    m.face[0].SetF(2);
    m.face[1].SetF(0);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);

    EXPECT_EQ(AllQuads::Split(m, surface, 60).quads, 4);
    const P3 centre = m.vert.back().P();  // the last new point
    EXPECT_NEAR(centre[1], 1, 1e-6);
    EXPECT_NEAR(centre[2], kRidge * (1 - std::abs(centre[0] - 1)), 1e-5) << "the centre is not on the roof";
    EXPECT_GT(centre[2], kUnderside);
}
