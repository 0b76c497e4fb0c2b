// Filter 3's locating rules (embedding/locate.h): a polyline point at a vertex, inside an edge or
// inside a face, within the locate tolerance.
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
