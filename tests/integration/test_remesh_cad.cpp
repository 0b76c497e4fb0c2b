// The whole pipeline with Q-Morph's re-meshing on (closed_mesh_to_quads.mlx, TargetEdgeLength at 1%
// of the diagonal) through the real meshlabserver on Debian's anchor, a coarse CAD mesh of genus 4.
// The exported quads are read back with the independent OBJ reader and checked: a closed 2-manifold
// (every edge on two faces, every vertex one fan) with the input's Euler characteristic, and no
// face flipped against the input surface (quad_checks.h's grid-based test, not the product's);
// the product's own log must say "flipped faces: 0" too.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <numeric>
#include <regex>
#include <set>
#include <string>

#include "meshlab_runner.h"
#include "obj_reader.h"
#include "quad_checks.h"
#include "test_mesh.h"

using namespace qmf_test;

namespace {

// Vertices whose faces do not form one fan (the wedges around the vertex, prev-next pairs of
// neighbours, are not one connected cycle).
int NonManifoldVertices(const ObjData &p)
{
    std::vector<std::vector<std::pair<int, int>>> wedges(p.v.size());
    for (auto &f : p.f)
        for (size_t k = 0; k < f.size(); ++k)
            wedges[f[k]].push_back({f[(k + f.size() - 1) % f.size()], f[(k + 1) % f.size()]});
    int bad = 0;
    for (auto &w : wedges) {
        if (w.empty()) continue;
        std::map<int, int> parent, degree;
        std::function<int(int)> find = [&](int x) { return parent[x] == x ? x : parent[x] = find(parent[x]); };
        for (auto &e : w) {
            for (int x : {e.first, e.second})
                if (!parent.count(x)) parent[x] = x;
            parent[find(e.first)] = find(e.second);
            ++degree[e.first];
            ++degree[e.second];
        }
        std::set<int> roots;
        bool cycle = true;
        for (auto &d : degree) {
            roots.insert(find(d.first));
            cycle = cycle && d.second == 2;
        }
        bad += !(cycle && roots.size() == 1);
    }
    return bad;
}

}  // namespace

TEST(RemeshCad, AnchorRemeshedThroughMeshlabserverStaysClosedAndUnflipped)
{
    const std::string dir = WorkDir("remesh_cad_anchor");
    const std::string input = std::string(QMF_TEST_MESH_DIR) + "/anchor.off";
    TMesh in;
    ASSERT_TRUE(LoadOff(in, input));
    const double length = 0.01 * in.bbox.Diag();

    std::string script = ReadText(Script("closed_mesh_to_quads.mlx"));
    auto setParam = [&](const std::string &from, const std::string &to) {
        ASSERT_NE(script.find(from), std::string::npos) << from;
        script.replace(script.find(from), from.size(), to);
    };
    setParam("name=\"ExportPath\" value=\"\"", "name=\"ExportPath\" value=\"" + dir + "/quads.obj\"");
    char value[64];
    std::snprintf(value, sizeof value, "%.9g", length);
    setParam("name=\"TargetEdgeLength\" value=\"0\"", std::string("name=\"TargetEdgeLength\" value=\"") + value + "\"");
    std::ofstream(dir + "/pipeline.mlx") << script;

    RunResult r = RunMeshLabServer(dir, "-i " + Quote(input) + " -o out.ply -m ff fq -s pipeline.mlx");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ASSERT_TRUE(FileExists(dir + "/quads.obj")) << r.output;
    std::smatch mq;
    ASSERT_TRUE(std::regex_search(r.output, mq, std::regex("Q-Morph: (\\d+) patches .*?; (\\d+) quads, (\\d+) triangles left"))) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex("re-meshing to edge length [0-9.e+-]+: [1-9]\\d* front edges became [1-9]\\d*")))
        << r.output;
    EXPECT_NE(r.output.find("flipped faces: 0,"), std::string::npos) << "the filter's own count:\n" << r.output;

    // the exported quads, read back independently
    const ObjData obj = ReadObj(dir + "/quads.obj");
    ASSERT_FALSE(obj.f.empty());
    int quads = 0, tris = 0;
    for (auto &f : obj.f) (f.size() == 4 ? quads : tris)++;
    EXPECT_EQ(quads, std::stoi(mq[2]));
    EXPECT_EQ(tris, std::stoi(mq[3]));
    std::map<std::pair<int, int>, int> uses;
    for (auto &f : obj.f)
        for (size_t k = 0; k < f.size(); ++k) uses[{std::min(f[k], f[(k + 1) % f.size()]), std::max(f[k], f[(k + 1) % f.size()])}]++;
    int boundary = 0, nonManifold = 0;
    for (auto &u : uses) {
        boundary += u.second == 1;
        nonManifold += u.second > 2;
    }
    EXPECT_EQ(boundary, 0) << "closed: no edge with one face";
    EXPECT_EQ(nonManifold, 0) << "no edge with three or more faces";
    EXPECT_EQ(NonManifoldVertices(obj), 0) << "every vertex has one fan of faces";
    std::set<int> used;
    for (auto &f : obj.f) used.insert(f.begin(), f.end());
    const int eulerIn = in.vn - int(AllEdges(in).size()) + in.fn;
    const int eulerOut = int(used.size()) - int(uses.size()) + int(obj.f.size());
    EXPECT_EQ(eulerIn, -6) << "anchor is a closed surface of genus 4";
    EXPECT_EQ(eulerOut, eulerIn) << "the Euler characteristic changed";

    vcg_ext::PolygonMesh pm;
    for (auto &v : obj.v) pm.points.push_back(vcg::Point3d(v[0], v[1], v[2]));
    pm.faces = obj.f;
    const FlipCount flips = FlippedFaces(pm, in);
    std::printf("anchor through meshlabserver, L %g: %d quads, %d triangles (%.2f%%), elements %.1f against area / L^2 %.1f; "
                "flipped %d (ambiguous %d), folded %d; Euler %d (input %d)\n",
                length, quads, tris, 100.0 * tris / (quads + tris), quads + 0.5 * tris, TotalArea(in) / (length * length),
                flips.flipped, flips.ambiguous, flips.folded, eulerOut, eulerIn);
    EXPECT_EQ(flips.flipped, 0) << "faces upside down on the input surface (independent check)";
    EXPECT_EQ(flips.folded, 0) << "quads folded across both diagonals";
}
