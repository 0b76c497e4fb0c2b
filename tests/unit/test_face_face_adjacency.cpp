// FaceFaceAdjacency (common/face_face_adjacency.h): vcglib's UpdateTopology::FaceFace in linear
// time. The same adjacency, pointer for pointer and index for index, on a closed mesh with deleted
// faces (so with border edges); a non-manifold edge and a degenerate face go to vcglib itself.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "test_mesh.h"
#include <vcg_ext/common/face_face_adjacency.h>

using namespace qmf_test;

namespace {

typedef std::vector<std::pair<TFace *, int>> Adjacency;

Adjacency Read(TMesh &m)
{
    Adjacency a;
    for (TFace &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k) a.push_back({f.FFp(k), f.FFi(k)});
    return a;
}

void Clear(TMesh &m)
{
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k) {
            f.FFp(k) = nullptr;
            f.FFi(k) = -1;
        }
}

// vcglib's adjacency of m, then ours from scratch: they must be the same.
void ExpectVcglibs(TMesh &m)
{
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    const Adjacency expected = Read(m);
    Clear(m);
    vcg_ext::FaceFaceAdjacency<TMesh>::Update(m);
    const Adjacency got = Read(m);
    ASSERT_EQ(got.size(), expected.size());
    for (size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].first, expected[i].first) << "face-edge " << i;
        EXPECT_EQ(got[i].second, expected[i].second) << "face-edge " << i;
    }
}

}  // namespace

TEST(FaceFaceAdjacency, IsVcglibsOnAClosedMeshWithDeletedFaces)
{
    TMesh m;
    MakeCube(m, 6, 0.3f);
    for (size_t i = 0; i < m.face.size(); i += 17) vcg::tri::Allocator<TMesh>::DeleteFace(m, m.face[i]);
    ExpectVcglibs(m);
    int borders = 0;
    for (TFace &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k) borders += f.FFp(k) == &f && f.FFi(k) == k;
    EXPECT_GT(borders, 0) << "the deleted faces leave holes";
}

// Three triangles on one edge (vcglib links them in a ring) and a triangle with a repeated vertex.
TEST(FaceFaceAdjacency, NonManifoldAndDegenerateMeshesAreVcglibs)
{
    const std::vector<P3> v = {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, -1, 0), P3(0, 0, 1), P3(2, 2, 2)};
    {
        TMesh fin;
        Build(fin, v, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
        ExpectVcglibs(fin);
        EXPECT_NE(fin.face[0].FFp(0), &fin.face[0]);
        EXPECT_NE(fin.face[2].FFp(0), &fin.face[2]) << "each of the three faces on the edge is in the ring";
    }
    {
        TMesh degenerate;
        Build(degenerate, v, {{0, 1, 2}, {1, 0, 3}, {2, 5, 2}});
        ExpectVcglibs(degenerate);
    }
}
