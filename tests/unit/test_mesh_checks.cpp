#include <gtest/gtest.h>

#include <limits>

#include "test_mesh.h"
#include <vcg_ext/mesh_checks.h>

using namespace qmf_test;
typedef vcg_ext::MeshChecks<TMesh> Checks;

TEST(MeshChecks, ClosedCubeIsClosedOrientedManifold)
{
    TMesh m;
    MakeCube(m, 4, 0.3f);
    auto r = Checks::Inspect(m);
    EXPECT_EQ(r.faces, 6 * 4 * 4 * 2);
    EXPECT_EQ(r.vertices, 6 * 16 + 2);  // V - E + F = 2 with E = 3F/2
    EXPECT_TRUE(r.IsClosed());
    EXPECT_TRUE(r.IsTwoManifold());
    EXPECT_TRUE(r.IsOriented());
    EXPECT_EQ(r.components, 1);
    EXPECT_EQ(r.FirstProblem(true), "");
}

TEST(MeshChecks, GridHasItsBoundary)
{
    TMesh m;
    MakeGrid(m, 5);
    auto r = Checks::Inspect(m);
    EXPECT_EQ(r.boundaryEdges, 20);
    EXPECT_TRUE(r.IsTwoManifold());
    EXPECT_NE(r.FirstProblem(true).find("not closed"), std::string::npos);
    EXPECT_EQ(r.FirstProblem(false), "");
}

TEST(MeshChecks, NonManifoldEdgeAndVertex)
{
    TMesh fin;  // three triangles on one edge
    Build(fin, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, -1, 0), P3(0, 0, 1)}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    auto r = Checks::Inspect(fin);
    EXPECT_EQ(r.nonManifoldEdges, 1);
    EXPECT_FALSE(r.IsTwoManifold());

    TMesh bowtie;  // two triangles sharing only vertex 0
    Build(bowtie, {P3(0, 0, 0), P3(1, 0, 0), P3(1, 1, 0), P3(-1, 0, 0), P3(-1, -1, 0)}, {{0, 1, 2}, {0, 3, 4}});
    r = Checks::Inspect(bowtie);
    EXPECT_EQ(r.nonManifoldEdges, 0);
    EXPECT_EQ(r.nonManifoldVertices, 1);
    EXPECT_EQ(r.components, 2);
    EXPECT_NE(r.FirstProblem(true).find("vertices are non-manifold"), std::string::npos);
}

TEST(MeshChecks, DegenerateDuplicateAndNaN)
{
    TMesh m;
    Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(2, 0, 0)}, {{0, 1, 2}, {0, 1, 3}, {2, 1, 0}});
    auto r = Checks::Inspect(m);
    EXPECT_EQ(r.degenerateFaces, 1);  // 0,1,3 are collinear
    EXPECT_EQ(r.duplicateFaces, 1);   // {2,1,0} repeats {0,1,2}
    EXPECT_EQ(r.nonManifoldEdges, 1);  // edge 0-1 has three faces
    m.vert[3].P()[1] = std::numeric_limits<float>::quiet_NaN();
    r = Checks::Inspect(m, false);
    EXPECT_EQ(r.nonFiniteVertices, 1);
    EXPECT_NE(r.FirstProblem(false).find("NaN"), std::string::npos);
}

TEST(MeshChecks, EmptyAndPointCloud)
{
    TMesh m;
    EXPECT_EQ(Checks::Inspect(m).FirstProblem(false), "the mesh is empty");
    vcg::tri::Allocator<TMesh>::AddVertex(m, P3(0, 0, 0));
    EXPECT_NE(Checks::Inspect(m).FirstProblem(false).find("no faces"), std::string::npos);
}

TEST(MeshChecks, InconsistentOrientation)
{
    TMesh m;
    Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, -1, 0)}, {{0, 1, 2}, {0, 1, 3}});
    auto r = Checks::Inspect(m);
    EXPECT_EQ(r.inconsistentEdges, 1);
    EXPECT_FALSE(r.IsOriented());
}
