#include <gtest/gtest.h>

#include <limits>
#include <map>
#include <random>

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

TEST(MeshChecks, DuplicateFacesCountedWhateverTheirCornerOrderAndCopies)
{
    TMesh cube;
    MakeCube(cube, 2);  // 48 faces, closed
    std::vector<P3> v;
    for (const auto &x : cube.vert) v.push_back(x.cP());
    std::vector<std::array<int, 3>> f;
    for (const auto &face : cube.face)
        f.push_back({int(vcg::tri::Index(cube, face.cV(0))), int(vcg::tri::Index(cube, face.cV(1))), int(vcg::tri::Index(cube, face.cV(2)))});
    const std::array<int, 3> a = f[0], b = f[5], c = f[7];
    f.push_back({a[2], a[1], a[0]});  // reversed: 1
    f.push_back(b);                   // twice more: 2
    f.push_back({b[1], b[2], b[0]});
    f.push_back({c[1], c[2], c[0]});  // turned: 1
    TMesh m;
    Build(m, v, f);
    auto r = Checks::Inspect(m);
    EXPECT_EQ(r.duplicateFaces, 4);
    EXPECT_EQ(r.degenerateFaces, 0);
    EXPECT_EQ(r.First(vcg_ext::MeshCheckReport::Basic), vcg_ext::MeshCheckReport::DuplicateFaces);
    EXPECT_NE(r.FirstProblem(false).find("4 faces are duplicates"), std::string::npos) << r.FirstProblem(false);
    // a face with a repeated vertex has no lowest edge: the same count by sorting every triple
    f.push_back({a[0], a[0], a[1]});
    Build(m, v, f);
    r = Checks::Inspect(m);
    EXPECT_EQ(r.duplicateFaces, 4);
    EXPECT_EQ(r.degenerateFaces, 1);
    EXPECT_EQ(Checks::Inspect(cube).duplicateFaces, 0);
}

TEST(MeshChecks, DuplicateFacesAsSortingEveryTripleCountsThem)
{
    // random faces over 8 vertices: many duplicates, edges with many faces; 3 of 24 with a
    // repeated vertex in the second half of the trials
    std::mt19937 rng(7);
    std::vector<P3> v;
    for (int i = 0; i < 8; ++i) v.push_back(P3(float(i % 2), float(i / 2 % 2), float(i / 4)));
    for (int trial = 0; trial < 200; ++trial) {
        std::vector<std::array<int, 3>> f;
        for (int k = 0; k < 24; ++k) {
            std::array<int, 3> t;
            do {
                for (int &x : t) x = int(rng() % 8);
            } while (trial < 100 && (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]));
            f.push_back(t);
        }
        std::vector<std::array<int, 3>> sorted(f);
        for (auto &t : sorted) std::sort(t.begin(), t.end());
        std::sort(sorted.begin(), sorted.end());
        int expected = 0;
        for (size_t i = 1; i < sorted.size(); ++i) expected += sorted[i] == sorted[i - 1] ? 1 : 0;
        TMesh m;
        Build(m, v, f);
        EXPECT_EQ(Checks::Inspect(m).duplicateFaces, expected) << "trial " << trial;
    }
}

TEST(MeshChecks, DuplicateFacesOnAFanOfManyFacesAroundOneEdge)
{
    // 20,000 faces on the edge 0-1 (a bad input the filters must refuse with a message, quickly:
    // faces on one edge are compared by their sorted third vertices, not pair by pair)
    const int fan = 20000;
    std::vector<P3> v{P3(0, 0, 0), P3(1, 0, 0)};
    std::vector<std::array<int, 3>> f;
    for (int i = 0; i < fan; ++i) {
        const float a = 6.2831853f * float(i) / float(fan);
        v.push_back(P3(0.5f, std::cos(a), std::sin(a)));
        f.push_back({0, 1, i + 2});
    }
    f.push_back({1, 0, 7});  // reversed copy
    f.push_back({7, 0, 1});  // turned copy of the same face: 2 more duplicates of face 5
    f.push_back({0, 1, fan + 1});
    TMesh m;
    Build(m, v, f);
    const auto r = Checks::Inspect(m);
    EXPECT_EQ(r.duplicateFaces, 3);
    EXPECT_EQ(r.nonManifoldEdges, 3);  // 0-1, and 0-7 and 1-7 of the three copies of face 5
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

namespace {
// Every face with its own three vertices (positions kept): what an STL reader leaves unmerged.
void MakeSoup(const TMesh &in, TMesh &out)
{
    std::vector<P3> v;
    std::vector<std::array<int, 3>> f;
    for (const auto &face : in.face) {
        f.push_back({int(v.size()), int(v.size()) + 1, int(v.size()) + 2});
        for (int k = 0; k < 3; ++k) v.push_back(face.cV(k)->cP());
    }
    Build(out, v, f);
}
bool Names(const std::string &message, const std::string &fix) { return message.find("'" + fix + "'") != std::string::npos; }
}  // namespace

TEST(MeshChecks, TriangleSoupNamesMergeCloseVertices)
{
    TMesh cube, soup;
    MakeCube(cube, 2);
    MakeSoup(cube, soup);
    auto r = Checks::Inspect(soup);
    EXPECT_TRUE(r.IsTriangleSoup());
    EXPECT_EQ(r.duplicateVertices, 3 * r.faces);
    EXPECT_EQ(r.First(vcg_ext::MeshCheckReport::Basic), vcg_ext::MeshCheckReport::DuplicateVertices);
    EXPECT_NE(r.FirstProblem(false).find("triangle soup"), std::string::npos) << r.FirstProblem(false);
    EXPECT_TRUE(Names(r.PipelineProblem(), "Merge Close Vertices")) << r.PipelineProblem();
    EXPECT_FALSE(Checks::Inspect(cube).IsTriangleSoup());
    EXPECT_EQ(Checks::Inspect(cube).duplicateVertices, 0);
}

TEST(MeshChecks, SurfaceCutOpenAlongDuplicateVertices)
{
    TMesh m;  // a 4 x 4 grid whose right half has its own copies of the vertices on x = 0.5
    MakeGrid(m, 4);
    std::vector<P3> v;
    for (auto &x : m.vert) v.push_back(x.P());
    std::vector<std::array<int, 3>> f;
    std::map<int, int> copy;
    for (auto &face : m.face) {
        std::array<int, 3> t;
        const float cx = (face.V(0)->P()[0] + face.V(1)->P()[0] + face.V(2)->P()[0]) / 3;
        for (int k = 0; k < 3; ++k) {
            int i = int(vcg::tri::Index(m, face.V(k)));
            if (cx > 0.5f && v[i][0] == 0.5f) {
                if (!copy.count(i)) { copy[i] = int(v.size()); v.push_back(v[i]); }
                i = copy[i];
            }
            t[k] = i;
        }
        f.push_back(t);
    }
    TMesh cut;
    Build(cut, v, f);
    auto r = Checks::Inspect(cut);
    EXPECT_EQ(r.duplicateVertices, 10);  // 5 vertices on the cut, twice
    EXPECT_FALSE(r.IsTriangleSoup());
    EXPECT_NE(r.PipelineProblem().find("10 duplicate vertices"), std::string::npos) << r.PipelineProblem();
    EXPECT_TRUE(Names(r.PipelineProblem(), "Merge Close Vertices"));
}

TEST(MeshChecks, ClosedPartsTouchingAtAPointAreNotDuplicates)
{
    TMesh a, b;
    MakeCube(a, 2);
    MakeCube(b, 2);
    for (auto &v : b.vert) v.P() += P3(2, 2, 2);  // corner (1,1,1) of both
    vcg::tri::Append<TMesh, TMesh>::Mesh(a, b);
    auto r = Checks::Inspect(a);
    EXPECT_EQ(r.duplicateVertices, 0);
    EXPECT_EQ(r.PipelineProblem(), "");
}

TEST(MeshChecks, EveryProblemNamesItsMeshLabFix)
{
    TMesh fin;  // a non-manifold edge also makes boundary edges: the fin is reported, not the border
    Build(fin, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, -1, 0), P3(0, 0, 1)}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    auto r = Checks::Inspect(fin);
    EXPECT_TRUE(Names(r.FirstProblem(true), "Repair non Manifold Edges by removing faces")) << r.FirstProblem(true);
    EXPECT_TRUE(Names(r.PipelineProblem(), "Repair non Manifold Edges by removing faces"));

    TMesh bowtie;
    Build(bowtie, {P3(0, 0, 0), P3(1, 0, 0), P3(1, 1, 0), P3(-1, 0, 0), P3(-1, -1, 0)}, {{0, 1, 2}, {0, 3, 4}});
    r = Checks::Inspect(bowtie);
    EXPECT_TRUE(Names(r.FirstProblem(true), "Repair non Manifold Vertices by splitting")) << r.FirstProblem(true);

    TMesh twisted;
    Build(twisted, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, -1, 0)}, {{0, 1, 2}, {0, 1, 3}});
    r = Checks::Inspect(twisted);
    EXPECT_TRUE(Names(r.PipelineProblem(), "Re-Orient all faces coherentely")) << r.PipelineProblem();
    EXPECT_EQ(r.FirstProblem(false), "") << "orientation is not a basic requirement";

    TMesh m;
    Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(2, 0, 0)}, {{0, 1, 2}, {0, 1, 3}});
    EXPECT_TRUE(Names(Checks::Inspect(m).PipelineProblem(), "Remove Zero Area Faces"));
    Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0)}, {{0, 1, 2}, {1, 2, 0}});
    EXPECT_TRUE(Names(Checks::Inspect(m).PipelineProblem(), "Remove Duplicate Faces"));
}

// Only exact degeneracy is a problem: a needle of tiny but non-zero area is a face like any other.
TEST(MeshChecks, NeedleFacesAreNotDegenerate)
{
    TMesh m;
    for (float h : {1e-3f, 1e-5f, 1e-6f}) {
        Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0.5f, h, 0)}, {{0, 1, 2}});
        EXPECT_EQ(Checks::Inspect(m).degenerateFaces, 0) << h;
    }
    Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0.5f, 0, 0)}, {{0, 1, 2}});
    EXPECT_EQ(Checks::Inspect(m).degenerateFaces, 1);
}

// A closed mesh whose faces all point inward is consistently oriented: valid input.
TEST(MeshChecks, InwardOrientedMeshIsValid)
{
    TMesh m;
    MakeCube(m, 3);
    for (auto &f : m.face) std::swap(f.V(1), f.V(2));
    auto r = Checks::Inspect(m);
    EXPECT_TRUE(r.IsOriented());
    EXPECT_EQ(r.FirstProblem(true), "");
}
