// The output's final shape pass (qmorph/worst_element_smoothing.h): poor elements are raised by
// moving free corners on the input surface; front corners never move, nothing turns over, and no
// element that was fair is made poor.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "test_mesh.h"
#include <vcg/complex/append.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg_ext/qmorph/worst_element_smoothing.h>

using namespace qmf_test;

namespace {

typedef vcg_ext::qmorph::WorstElementSmoothing<TMesh> Smoothing;

// A 4 x 4 grid of unit quads in the z = 0 plane (two triangles sharing a faux diagonal per cell);
// the row y = 2 is a front (selected face-edges) when `front`.
void MakeQuadGrid(TMesh &m, bool front)
{
    MakeGrid(m, 4, 4.f, 0.f, 1, false);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k) {
            const P3 a = f.P0(k), b = f.P1(k);
            if (a[0] != b[0] && a[1] != b[1]) f.SetF(k);
            if (front && a[1] == 2 && b[1] == 2) f.SetFaceEdgeS(k);
        }
}

TVertex *At(TMesh &m, float x, float y)
{
    for (TVertex &v : m.vert)
        if (v.P()[0] == x && v.P()[1] == y) return &v;
    return nullptr;
}

// The scaled Jacobian of every quad against +z (the plane's normal), computed here.
std::vector<double> Jacobians(TMesh &m)
{
    std::vector<double> j;
    vcg_ext::QuadQuality::ForEachFauxPolygon(m, [&](TFace &, const std::array<int, 4> &c, int n) {
        if (n < 4) return;
        double worst = 1;
        for (int k = 0; k < 4; ++k) {
            const vcg::Point3d a = vcg::Point3d::Construct(m.vert[c[k]].P()), b = vcg::Point3d::Construct(m.vert[c[(k + 1) % 4]].P()),
                               d = vcg::Point3d::Construct(m.vert[c[(k + 3) % 4]].P());
            worst = std::min(worst, ((b - a) ^ (d - a))[2] / ((b - a).Norm() * (d - a).Norm()));
        }
        j.push_back(worst);
    });
    return j;
}

double Worst(const std::vector<double> &j) { return *std::min_element(j.begin(), j.end()); }

}  // namespace

TEST(WorstElementSmoothing, ASkewedGridVertexIsPutBackNearItsPlace)
{
    // vertex (1, 1) pushed almost to the middle of its cell: its quads are poor (scaled Jacobian below 0.3) but none
    // is inverted; the pass must raise them all above 0.9 and keep every vertex on the plane
    TMesh input, m;
    MakeQuadGrid(input, false);
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, input);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg_ext::InputSurface<TMesh> surface(input);
    At(m, 1, 1)->P() = P3(1.45f, 1.45f, 0);
    const std::vector<double> before = Jacobians(m);
    ASSERT_LT(Worst(before), 0.3);
    ASSERT_GT(Worst(before), 0);

    const Smoothing::Stats st = Smoothing::Do(m, surface, 60);
    EXPECT_GT(st.poorBefore, 0);
    EXPECT_EQ(st.poorAfter, 0);
    EXPECT_GE(st.moves, 1);
    EXPECT_GT(Worst(Jacobians(m)), 0.9);
    for (const TVertex &v : m.vert) EXPECT_EQ(v.cP()[2], 0.f) << "a vertex left the input plane";
}

TEST(WorstElementSmoothing, FrontCornersNeverMove)
{
    // (2, 2) on the front and (2, 3) off it both skewed: the poor quad between them is raised by
    // moving free corners only
    TMesh input, m;
    MakeQuadGrid(input, true);
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, input);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg_ext::InputSurface<TMesh> surface(input);
    TVertex *onFront = At(m, 2, 2), *free = At(m, 2, 3);
    const P3 frontPlace(2.7f, 2.f, 0);
    onFront->P() = frontPlace;
    free->P() = P3(2.2f, 2.5f, 0);
    const double worstBefore = Worst(Jacobians(m));

    ASSERT_LT(worstBefore, 0.5);

    const Smoothing::Stats st = Smoothing::Do(m, surface, 60);
    EXPECT_GE(st.moves, 1);
    EXPECT_EQ(onFront->P(), frontPlace) << "a front corner moved";
    for (const TVertex &v : m.vert) {
        if (v.cP()[1] == 2.f && &v != onFront) {
            EXPECT_EQ(v.cP()[0], std::round(v.cP()[0])) << "a front corner moved";
        }
    }
    EXPECT_GT(Worst(Jacobians(m)), worstBefore + 0.1);
}

TEST(WorstElementSmoothing, FairElementsStayFairAndNothingTurnsOver)
{
    // a jittered grid: every quad fair but a few (one vertex skewed); after the pass no quad is
    // below its own quality or 0.3, whichever is lower, and none is inverted
    TMesh input, m;
    MakeQuadGrid(input, false);
    for (TVertex &v : input.vert)  // bend the plane into a gentle bump: the input is curved
        v.P()[2] = 0.3f * std::sin(v.P()[0] * 0.7f) * std::sin(v.P()[1] * 0.7f);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(input);
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, input);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg_ext::InputSurface<TMesh> surface(input);
    TVertex *skewed = At(m, 2, 1);
    ASSERT_NE(skewed, nullptr);
    skewed->P() = P3(2.7f, 1.75f, skewed->P()[2]);
    const std::vector<double> before = Jacobians(m);

    Smoothing::Do(m, surface, 60);
    const std::vector<double> after = Jacobians(m);
    ASSERT_EQ(before.size(), after.size());
    EXPECT_GT(Worst(after), Worst(before));
    for (size_t i = 0; i < before.size(); ++i) EXPECT_GE(after[i], std::min(before[i], 0.3) - 0.01) << "quad " << i;
    for (TVertex &v : m.vert) {  // on the input surface
        TVertex::CoordType closest(0, 0, 0);
        ASSERT_NE(surface.Closest(v.cP(), closest), nullptr);
        EXPECT_LT(vcg::Distance(closest, v.cP()), 1e-5f);
    }
}
