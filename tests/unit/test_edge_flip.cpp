// common/edge_flip.h: an edge flip moves the selection and faux bits with the edges they mark.
#include <gtest/gtest.h>

#include <map>
#include <utility>

#include "test_mesh.h"
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg_ext/common/edge_flip.h>
#include <vcg_ext/common/edge_key.h>

using namespace qmf_test;

namespace {

// Every face-edge's bits by its vertex pair: 1 selected, 2 faux, per side (the pair is met twice).
std::multimap<vcg_ext::VertexPair, int> FlagsByEdge(TMesh &m)
{
    std::multimap<vcg_ext::VertexPair, int> flags;
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k)
            flags.emplace(vcg_ext::UndirectedPair(int(vcg::tri::Index(m, f.V0(k))), int(vcg::tri::Index(m, f.V1(k)))),
                          (f.IsFaceEdgeS(k) ? 1 : 0) | (f.IsF(k) ? 2 : 0));
    return flags;
}

}  // namespace

TEST(EdgeFlip, SelectedAndFauxEdgesBesideTheFlipKeepTheirFlags)
{
    // a 3 x 3 grid: every axis-parallel edge selected (a front around each cell), the middle
    // cell's bottom side faux as well; its diagonal is flipped
    TMesh m;
    MakeGrid(m, 3, 3.f, 0.f, 1, false);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    TFace *middle = nullptr;
    int diagonal = -1;
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k) {
            const P3 a = f.P0(k), b = f.P1(k);
            const bool axisParallel = a[0] == b[0] || a[1] == b[1];
            if (axisParallel) f.SetFaceEdgeS(k);
            if (axisParallel && a[1] == 1 && b[1] == 1 && a[0] + b[0] == 3) f.SetF(k);  // middle cell's bottom
            const P3 mid = (a + b) / 2;
            if (!axisParallel && mid[0] == 1.5f && mid[1] == 1.5f) { middle = &f; diagonal = k; }
        }
    ASSERT_NE(middle, nullptr);
    ASSERT_TRUE(vcg::face::CheckFlipEdge(*middle, diagonal));
    const vcg_ext::VertexPair before = vcg_ext::UndirectedPair(int(vcg::tri::Index(m, middle->V0(diagonal))),
                                                               int(vcg::tri::Index(m, middle->V1(diagonal))));
    // the new diagonal joins the two corners of the cell off the old one
    const vcg_ext::VertexPair after = vcg_ext::UndirectedPair(
        int(vcg::tri::Index(m, middle->V2(diagonal))),
        int(vcg::tri::Index(m, middle->FFp(diagonal)->V2(middle->FFi(diagonal)))));
    std::multimap<vcg_ext::VertexPair, int> want = FlagsByEdge(m);
    want.erase(before);

    vcg_ext::FlipEdgeKeepingFlags(*middle, diagonal);

    std::multimap<vcg_ext::VertexPair, int> got = FlagsByEdge(m);
    // the new diagonal is an edge now, flagged on neither side
    EXPECT_EQ(got.count(before), 0u);
    ASSERT_EQ(got.count(after), 2u);
    auto range = got.equal_range(after);
    for (auto it = range.first; it != range.second; ++it) EXPECT_EQ(it->second, 0) << "the new diagonal carries a flag";
    got.erase(after);
    // every other edge has the flags it had, on both sides
    EXPECT_EQ(got, want);
    // and the adjacency is still consistent
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k) {
            if (f.FFp(k) == &f) continue;
            EXPECT_EQ(f.FFp(k)->FFp(f.FFi(k)), &f);
        }
}
