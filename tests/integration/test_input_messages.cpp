// Bad input through the real meshlabserver and the shipped whole-pipeline script: the first filter
// (VSA) names the MeshLab filter that fixes the input, refusing what it cannot segment (unmerged
// vertices, inconsistent orientation) and warning about what only the later filters refuse
// (non-manifold edges and vertices, zero-area and duplicate faces). Needle faces of tiny but
// non-zero area and an inward-oriented mesh are valid input and go through the whole pipeline.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <regex>
#include <vector>

#include "meshlab_runner.h"
#include "ply_reader.h"
#include "test_mesh.h"

using namespace qmf_test;

namespace {

const std::string kVsaName = "Segment by Variational Shape Approximation: ";

struct Soup {
    std::vector<std::array<float, 3>> v;
    std::vector<std::array<int, 3>> f;
};

// The closed cube [-1,1]^3 with 4 x 4 cells per side (outward oriented).
Soup Cube()
{
    TMesh m;
    MakeCube(m, 4);
    Soup s;
    for (auto &x : m.vert) s.v.push_back({x.P()[0], x.P()[1], x.P()[2]});
    for (auto &x : m.face)
        s.f.push_back({int(vcg::tri::Index(m, x.V(0))), int(vcg::tri::Index(m, x.V(1))), int(vcg::tri::Index(m, x.V(2)))});
    return s;
}

void WritePly(const std::string &path, const Soup &s)
{
    std::ofstream out(path);
    out << "ply\nformat ascii 1.0\nelement vertex " << s.v.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << s.f.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    char buf[128];
    for (auto &p : s.v) {
        std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g\n", p[0], p[1], p[2]);
        out << buf;
    }
    for (auto &t : s.f) out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
}

RunResult RunPipeline(const std::string &name, const Soup &s)
{
    const std::string dir = WorkDir("input_" + name);
    WritePly(dir + "/in.ply", s);
    return RunMeshLabServer(dir, "-i in.ply -o out.ply -m ff fq -s " + Quote(Script("closed_mesh_to_quads.mlx")));
}

// An interior edge a-b of the side z = 1 and the third vertices c, d of its faces (a, b, c) and (b, a, d).
struct EdgeFan { int a, b, c, d, abc, bad; };
EdgeFan InteriorEdge(const Soup &s)
{
    std::map<std::pair<int, int>, int> half;  // directed edge -> face
    for (size_t i = 0; i < s.f.size(); ++i)
        for (int k = 0; k < 3; ++k) half[{s.f[i][k], s.f[i][(k + 1) % 3]}] = int(i);
    auto interior = [&](int v) { return s.v[v][2] == 1.f && std::abs(s.v[v][0]) < 1 && std::abs(s.v[v][1]) < 1; };
    for (auto &h : half) {
        const int a = h.first.first, b = h.first.second;
        if (!interior(a) || !interior(b)) continue;
        const int f = h.second, g = half.at({b, a});
        auto third = [&](int face) {
            for (int k = 0; k < 3; ++k)
                if (s.f[face][k] != a && s.f[face][k] != b) return s.f[face][k];
            return -1;
        };
        return {a, b, third(f), third(g), f, g};
    }
    return {-1, -1, -1, -1, -1, -1};
}

// Edge a-b split at a new vertex m, (a, b, c) replaced by (a, m, c), (m, b, c) and the sliver
// (m, a, b) between m and the edge: m on the edge (t = 0) makes a zero-area face, m moved a
// fraction t of the way towards c a needle of tiny but non-zero area. Closed, 2-manifold, oriented.
Soup WithSliver(double t)
{
    Soup s = Cube();
    const EdgeFan e = InteriorEdge(s);
    std::array<float, 3> m;
    for (int k = 0; k < 3; ++k) {
        const double mid = (double(s.v[e.a][k]) + s.v[e.b][k]) / 2;
        m[k] = float(mid + t * (s.v[e.c][k] - mid));
    }
    const int mi = int(s.v.size());
    s.v.push_back(m);
    s.f[e.abc] = {e.a, mi, e.c};
    s.f.push_back({mi, e.b, e.c});
    s.f.push_back({mi, e.a, e.b});
    return s;
}

void ExpectRefusedAtTheFirstFilter(const RunResult &r, const std::string &message, const std::string &fix)
{
    EXPECT_NE(r.exitCode, 0) << r.output;
    const size_t at = r.output.find(kVsaName + message);
    ASSERT_NE(at, std::string::npos) << r.output;
    EXPECT_NE(r.output.find("run '" + fix + "' first", at), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("Smooth Region Boundaries:"), std::string::npos) << "the script must stop at filter 1\n"
                                                                             << r.output;
}

// VSA segments it but warns, naming the fix; a later filter refuses it.
void ExpectWarnedAtTheFirstFilter(const RunResult &r, const std::string &message, const std::string &fix)
{
    EXPECT_NE(r.exitCode, 0) << r.output;
    const size_t at = r.output.find(kVsaName + "warning: " + message);
    ASSERT_NE(at, std::string::npos) << r.output;
    EXPECT_NE(r.output.find("run '" + fix + "' first", at), std::string::npos) << r.output;
    const size_t split = r.output.find("Split Triangles along Front:");
    EXPECT_TRUE(split == std::string::npos || split > at) << r.output;
    EXPECT_NE(r.output.find("run '", r.output.find("\n", at)), std::string::npos)
        << "the later refusal names a fix too\n" << r.output;
}

double SignedVolume(const PlyData &d)
{
    double vol = 0;
    for (auto &f : d.faces)
        for (size_t k = 1; k + 1 < f.size(); ++k) {
            const auto &a = d.vertices[f[0]], &b = d.vertices[f[k]], &c = d.vertices[f[k + 1]];
            vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                    a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
        }
    return vol;
}

}  // namespace

TEST(InputMessages, TriangleSoupNamesMergeCloseVertices)
{
    const Soup cube = Cube();
    Soup soup;
    for (auto &t : cube.f) {
        soup.f.push_back({int(soup.v.size()), int(soup.v.size()) + 1, int(soup.v.size()) + 2});
        for (int k = 0; k < 3; ++k) soup.v.push_back(cube.v[t[k]]);
    }
    ExpectRefusedAtTheFirstFilter(RunPipeline("soup", soup), "the mesh is a triangle soup", "Merge Close Vertices");
}

TEST(InputMessages, DuplicateVerticesNameMergeCloseVertices)
{
    Soup s = Cube();  // the side z = 1 gets its own copies of its vertices: cut open along its border
    std::map<int, int> copy;
    for (auto &t : s.f) {
        if (!(s.v[t[0]][2] == 1.f && s.v[t[1]][2] == 1.f && s.v[t[2]][2] == 1.f)) continue;
        for (int &i : t) {
            if (!copy.count(i)) { copy[i] = int(s.v.size()); s.v.push_back(s.v[i]); }
            i = copy[i];
        }
    }
    ExpectRefusedAtTheFirstFilter(RunPipeline("duplicate_vertices", s), "the mesh has 32 duplicate vertices",
                                  "Merge Close Vertices");
}

TEST(InputMessages, InconsistentOrientationNamesReOrient)
{
    Soup s = Cube();
    std::swap(s.f[7][1], s.f[7][2]);
    ExpectRefusedAtTheFirstFilter(RunPipeline("flipped_face", s), "the mesh is not consistently oriented (3 edges",
                                  "Re-Orient all faces coherentely");
}

TEST(InputMessages, NonManifoldEdgeNamesItsRepair)
{
    Soup s = Cube();  // a fin: a third face on an edge of the cube, outside it
    const auto t = s.f[0];
    s.v.push_back({3, 3, 3});
    s.f.push_back({t[0], t[1], int(s.v.size()) - 1});
    ExpectWarnedAtTheFirstFilter(RunPipeline("fin", s), "the mesh is not 2-manifold: 1 edges",
                                 "Repair non Manifold Edges by removing faces");
}

TEST(InputMessages, NonManifoldVertexNamesItsRepair)
{
    Soup s = Cube();  // a triangle hanging on one corner of the cube
    const int corner = s.f[0][0];
    const auto c = s.v[corner];
    s.v.push_back({2 * c[0], 2 * c[1], 2 * c[2]});
    s.v.push_back({2 * c[0] + 0.5f, 2 * c[1], 2 * c[2]});
    s.f.push_back({corner, int(s.v.size()) - 2, int(s.v.size()) - 1});
    ExpectWarnedAtTheFirstFilter(RunPipeline("bowtie", s), "the mesh is not 2-manifold: 1 vertices",
                                 "Repair non Manifold Vertices by splitting");
}

TEST(InputMessages, ZeroAreaFaceNamesRemoveZeroAreaFaces)
{
    ExpectWarnedAtTheFirstFilter(RunPipeline("zero_area", WithSliver(0)), "1 faces are degenerate",
                                 "Remove Zero Area Faces");
}

TEST(InputMessages, DuplicateFaceNamesRemoveDuplicateFaces)
{
    Soup s = Cube();
    s.f.push_back(s.f[10]);
    ExpectWarnedAtTheFirstFilter(RunPipeline("duplicate_face", s), "1 faces are duplicates", "Remove Duplicate Faces");
}

// Only exact degeneracy is refused: needles of tiny but non-zero area go through the pipeline.
TEST(InputMessages, NeedleFacesRunThroughThePipeline)
{
    for (double t : {1e-3, 1e-5}) {
        const std::string name = "needle_" + std::to_string(int(-std::log10(t)));
        const RunResult r = RunPipeline(name, WithSliver(t));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        EXPECT_EQ(r.output.find(kVsaName + "warning"), std::string::npos) << r.output;
        EXPECT_TRUE(std::regex_search(r.output, std::regex("Q-Morph: \\d+ patches .*?; [1-9]\\d* quads"))) << r.output;
        const PlyData d = ReadPly(std::string(QMF_TEST_WORK_DIR) + "/input_" + name + "/out.ply");
        ASSERT_EQ(d.error, "");
        EXPECT_NEAR(SignedVolume(d), 8.0, 0.08) << "the cube, outward";
    }
}

// A closed mesh whose faces all point inward is valid input, and its orientation is kept.
TEST(InputMessages, InwardOrientedMeshRunsAndStaysInward)
{
    Soup s = Cube();
    for (auto &t : s.f) std::swap(t[1], t[2]);
    const RunResult r = RunPipeline("inward", s);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(r.output.find(kVsaName + "warning"), std::string::npos) << r.output;
    const PlyData d = ReadPly(std::string(QMF_TEST_WORK_DIR) + "/input_inward/out.ply");
    ASSERT_EQ(d.error, "");
    ASSERT_GT(d.faces.size(), 0u);
    EXPECT_NEAR(SignedVolume(d), -8.0, 0.08) << "the cube, every face pointing inward";
}
