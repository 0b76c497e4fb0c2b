// Thin strips between two feature chains (qmorph/facing_features.h and the ladder cells of
// PatchStage::QuadShape): CAD micro-steps, two creases a few thousandths of the target length apart
// (lever's plate rings), must become ladders of thin rectangles, not needle triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "test_mesh.h"
#include <vcg_ext/qmorph/facing_features.h>
#include <vcg_ext/qmorph/patch_stage.h>

using namespace qmf_test;

namespace {

constexpr float kWidth = 0.002f;  // the strip, times the target length L = 1

// Three rows in the z = 0 plane: y = -0.5 (outer), y = 0 (chain A, vertices at x = 0, 0.1, ..,
// 1), y = width (chain B, staggered: 0, 0.05, 0.15, .., 0.95, 1), y = 0.5 (outer); each band
// triangulated by merging its two rows by x. The two chains are selected face-edges.
void MakeStrip(TMesh &m, std::vector<int> &chainA, std::vector<int> &chainB, float width = kWidth)
{
    std::vector<P3> v;
    std::vector<std::vector<int>> rows(4);
    const float ys[4] = {-0.5f, 0.f, width, 0.5f};
    for (int r = 0; r < 4; ++r) {
        std::vector<float> xs;
        if (r == 2) {
            xs.push_back(0);
            for (int i = 0; i < 10; ++i) xs.push_back(0.05f + 0.1f * i);
            xs.push_back(1);
        } else {
            for (int i = 0; i <= 10; ++i) xs.push_back(0.1f * i);
        }
        for (float x : xs) {
            rows[r].push_back(int(v.size()));
            v.push_back(P3(x, ys[r], 0));
        }
    }
    std::vector<std::array<int, 3>> f;
    for (int r = 0; r < 3; ++r) {  // zigzag between rows r (below) and r + 1 (above), counter-clockwise
        const std::vector<int> &lo = rows[r], &hi = rows[r + 1];
        size_t i = 0, j = 0;
        while (i + 1 < lo.size() || j + 1 < hi.size()) {
            const bool advanceLow = j + 1 >= hi.size() || (i + 1 < lo.size() && v[lo[i + 1]][0] <= v[hi[j + 1]][0]);
            if (advanceLow) { f.push_back({lo[i], lo[i + 1], hi[j]}); ++i; }
            else { f.push_back({lo[i], hi[j + 1], hi[j]}); ++j; }
        }
    }
    Build(m, v, f);
    chainA = rows[1];
    chainB = rows[2];
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg::tri::UpdateTopology<TMesh>::VertexFace(m);
    auto onChain = [&](const TVertex *a, const TVertex *b) {
        return std::abs(a->cP()[1] - b->cP()[1]) < 1e-7f && (std::abs(a->cP()[1]) < 1e-7f || std::abs(a->cP()[1] - width) < 1e-7f);
    };
    for (TFace &face : m.face)
        for (int k = 0; k < 3; ++k)
            if (onChain(face.V0(k), face.V1(k))) face.SetFaceEdgeS(k);
}

// Positions along x of the vertices at height y.
std::vector<float> XsAt(const TMesh &m, float y)
{
    std::vector<float> xs;
    for (const TVertex &v : m.vert)
        if (!v.IsD() && std::abs(v.cP()[1] - y) < 1e-6f) xs.push_back(v.cP()[0]);
    std::sort(xs.begin(), xs.end());
    return xs;
}

struct QuadProbe : vcg_ext::qmorph::PatchStage
{
    using vcg_ext::qmorph::PatchStage::QuadShape;
};

}  // namespace

TEST(FacingFeatures, StaggeredChainsAcrossAThinStripFaceEachOther)
{
    TMesh m;
    std::vector<int> a, b;
    MakeStrip(m, a, b);
    const int facesBefore = m.fn;
    const int added = vcg_ext::qmorph::FacingFeatures<TMesh>::Do(m, 1.0);

    // B's 10 staggered inner vertices each split an edge of A, A's 9 inner ones each one of B
    EXPECT_EQ(added, 19);
    const std::vector<float> xa = XsAt(m, 0), xb = XsAt(m, kWidth);
    ASSERT_EQ(xa.size(), xb.size());
    for (size_t i = 0; i < xa.size(); ++i) EXPECT_NEAR(xa[i], xb[i], 1e-6) << "vertex " << i << " of the chains does not face its partner";
    // the outer rows are untouched, every split turned two faces into four, none turned over
    EXPECT_EQ(XsAt(m, -0.5f).size(), 11u);
    EXPECT_EQ(XsAt(m, 0.5f).size(), 11u);
    EXPECT_EQ(m.fn, facesBefore + 2 * added);
    for (const TFace &f : m.face)
        if (!f.IsD()) { EXPECT_GT(vcg::TriangleNormal(f)[2], 0.f); }
    // the chains are still chains of selected edges, and nothing else is selected
    int selectedOnA = 0, selectedOnB = 0, selectedElsewhere = 0;
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    for (const TFace &f : m.face)
        for (int k = 0; k < 3; ++k) {
            if (f.IsD() || !f.IsFaceEdgeS(k)) continue;
            const float y0 = f.cV0(k)->cP()[1], y1 = f.cV1(k)->cP()[1];
            if (y0 == 0 && y1 == 0) ++selectedOnA;
            else if (y0 == kWidth && y1 == kWidth) ++selectedOnB;
            else ++selectedElsewhere;
        }
    EXPECT_EQ(selectedOnA, 2 * int(xa.size() - 1));  // both sides of each edge
    EXPECT_EQ(selectedOnB, 2 * int(xb.size() - 1));
    EXPECT_EQ(selectedElsewhere, 0);
}

TEST(FacingFeatures, AFoldedRingAFewHundredthsOfLWideIsAStripToo)
{
    // block's boss meets its plate through a ring 0.02-0.1 of L wide: still a ladder's width
    constexpr float kRing = 0.03f;
    TMesh m;
    std::vector<int> a, b;
    MakeStrip(m, a, b, kRing);
    EXPECT_EQ(vcg_ext::qmorph::FacingFeatures<TMesh>::Do(m, 1.0), 19);
    const std::vector<float> xa = XsAt(m, 0), xb = XsAt(m, kRing);
    ASSERT_EQ(xa.size(), xb.size());
    for (size_t i = 0; i < xa.size(); ++i) EXPECT_NEAR(xa[i], xb[i], 1e-6) << "vertex " << i << " of the chains does not face its partner";
}

TEST(FacingFeatures, StripsOverATenthOfLAreLeftToTheRemesher)
{
    // a tenth of L: staggered rims there make quads of fair shape, and matching them would only
    // put short edges into the fronts of the patches beside
    TMesh m;
    std::vector<int> a, b;
    MakeStrip(m, a, b, 0.1f);
    const int vertsBefore = m.vn;
    EXPECT_EQ(vcg_ext::qmorph::FacingFeatures<TMesh>::Do(m, 1.0), 0);
    EXPECT_EQ(m.vn, vertsBefore);
}

TEST(FacingFeatures, WideBandsAreLeftAlone)
{
    // the two bands beside the strip are half L wide: fair triangles, nothing to match
    TMesh m;
    std::vector<int> a, b;
    MakeStrip(m, a, b);
    for (TVertex &v : m.vert)  // chain B moved to 0.4 L: the strip is a band now
        if (std::abs(v.P()[1] - kWidth) < 1e-7f) v.P()[1] = 0.4f;
    const int vertsBefore = m.vn;
    EXPECT_EQ(vcg_ext::qmorph::FacingFeatures<TMesh>::Do(m, 1.0), 0);
    EXPECT_EQ(m.vn, vertsBefore);
}

TEST(FacingFeatures, LadderCellsAreQuadsOnlyWhenAskedForAndRectangular)
{
    typedef vcg_ext::qmorph::P3 Q3;
    const Q3 up(0, 0, 1);
    // a ladder cell: sides 0.3 along x, rungs 0.002 and 0.004 (a tapering strip)
    const std::array<Q3, 4> cell{Q3(0, 0, 0), Q3(0.3, 0, 0), Q3(0.3, 0.002, 0), Q3(0, 0.004, 0)};
    EXPECT_EQ(QuadProbe::QuadShape(cell, up), -1) << "a needle, when not asked for ladder cells";
    EXPECT_GT(QuadProbe::QuadShape(cell, up, true), 0.99);
    // rungs slanted by twice the width (66 degrees off square): a needle after all
    const std::array<Q3, 4> slanted{Q3(0, 0, 0), Q3(0.3, 0, 0), Q3(0.3045, 0.002, 0), Q3(0.0045, 0.002, 0)};
    EXPECT_EQ(QuadProbe::QuadShape(slanted, up, true), -1);
    // a triangle with a fourth corner next to another (one short side only): never a ladder cell
    const std::array<Q3, 4> triangleLike{Q3(0, 0, 0), Q3(0.3, 0, 0), Q3(0.3, 0.002, 0), Q3(0, 0.3, 0)};
    EXPECT_EQ(QuadProbe::QuadShape(triangleLike, up, true), -1);
    // upside down against the surface: refused whatever its shape
    EXPECT_EQ(QuadProbe::QuadShape(cell, Q3(0, 0, -1), true), -1);
}
