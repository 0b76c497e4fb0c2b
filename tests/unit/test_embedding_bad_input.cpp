// Filter 3 core on bad input: an error saying why, and the mesh left exactly as it was.
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

namespace {
struct Snapshot {
    std::vector<P3> coords;
    std::vector<std::array<int, 3>> faces;
    std::vector<int> flags;
    std::vector<float> quality;
    static Snapshot Of(const TMesh &m)
    {
        Snapshot s;
        for (auto &v : m.vert) s.coords.push_back(v.cP());
        for (auto &f : m.face) {
            s.faces.push_back({int(vcg::tri::Index(m, f.cV(0))), int(vcg::tri::Index(m, f.cV(1))), int(vcg::tri::Index(m, f.cV(2)))});
            s.flags.push_back(f.cFlags());
            s.quality.push_back(f.cQ());
        }
        return s;
    }
    bool operator==(const Snapshot &o) const { return coords == o.coords && faces == o.faces && flags == o.flags && quality == o.quality; }
};

void ExpectRefused(TMesh &m, const TMesh &poly, const std::string &expected, double tolPercent = 1e-4)
{
    const Snapshot before = Snapshot::Of(m);
    Embedding::Result r = Embed(m, poly, tolPercent);
    EXPECT_NE(r.error.find(expected), std::string::npos) << "got: " << r.error;
    EXPECT_TRUE(Snapshot::Of(m) == before) << "the mesh changed";
}
}  // namespace

TEST(PolylineEmbedding, BadInputIsRefusedAndTheMeshUnchanged)
{
    TMesh m, poly;
    MakeCube(m, 4, 0.2f, 1);
    for (auto &f : m.face) f.Q() = 1;

    ExpectRefused(m, poly, "no edges");
    MakePolyline(poly, {P3(-1, 0.1f, 0.2f), P3(-1, -0.3f, 0.25f), P3(-1.01f, -0.5f, 0.5f)});
    ExpectRefused(m, poly, "from the surface");
    MakePolyline(poly, {P3(-1, 0.1f, 0.2f), P3(-1, -0.3f, 0.25f)});
    ExpectRefused(m, poly, "locate tolerance", 0);
    ExpectRefused(m, m, "the mesh itself");
    MakePolyline(poly, {P3(-1, 0.1f, 0.2f), P3(std::nanf(""), 0, 0)});
    ExpectRefused(m, poly, "NaN");

    // Two polylines crossing inside one face (each a chord between edge points).
    TMesh grid, more;
    MakeGrid(grid, 1);  // two triangles (0,0)(1,0)(1,1) and (0,0)(1,1)(0,1)
    MakePolyline(poly, {P3(0.3f, 0.f, 0), P3(1.f, 0.3f, 0)});
    MakePolyline(more, {P3(0.6f, 0.f, 0), P3(1.f, 0.9f, 0)});
    AppendPolyline(poly, more);
    ExpectRefused(grid, poly, "cross");
    // A polyline crossing itself (traced across several faces).
    MakeGrid(grid, 4, 1.f, 0.2f, 6);
    MakePolyline(poly, {P3(0.1f, 0.1f, 0), P3(0.9f, 0.9f, 0), P3(0.9f, 0.1f, 0), P3(0.1f, 0.9f, 0)});
    ExpectRefused(grid, poly, "cross");
}

TEST(PolylineEmbedding, NonManifoldAndBadlyOrientedMeshesAreRefused)
{
    TMesh fin, poly;
    Build(fin, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, -1, 0), P3(0, 0, 1)}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    MakePolyline(poly, {P3(0.2f, 0.1f, 0), P3(0.3f, 0.3f, 0)});
    ExpectRefused(fin, poly, "2-manifold");
    TMesh flipped;
    Build(flipped, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(1, 1, 0)}, {{0, 1, 2}, {1, 2, 3}});
    ExpectRefused(flipped, poly, "oriented");
    TMesh bowtie;  // two fans at vertex 0
    Build(bowtie, {P3(0, 0, 0), P3(1, 0, 0), P3(1, 1, 0), P3(-1, 0, 0), P3(-1, -1, 0)}, {{0, 1, 2}, {0, 3, 4}});
    MakePolyline(poly, {P3(0.5f, 0.1f, 0), P3(0.8f, 0.5f, 0)});
    ExpectRefused(bowtie, poly, "vertices are non-manifold");
}

TEST(PolylineEmbedding, UntraceableSegmentIsRefused)
{
    // Two disjoint cubes: a segment from one to the other has no surface path.
    TMesh m, other, poly;
    MakeCube(m, 3);
    MakeCube(other, 3);
    for (auto &v : other.vert) v.P() += P3(5, 0, 0);
    vcg::tri::Append<TMesh, TMesh>::Mesh(m, other);
    MakePolyline(poly, {P3(1, 0.1f, 0.2f), P3(4, 0.1f, 0.2f)});
    ExpectRefused(m, poly, "cannot be traced");
}
