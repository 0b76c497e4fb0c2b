// Front edges as selected face-edges (common/front_edges.h), shared by filters 3 and 4.
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
