// Filter 3 through the real meshlabserver: filters 1-3 in the shipped script; the saved PLY
// (-m fq ff) must carry the face-edge selection bits on exactly the front edges.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <queue>
#include <regex>
#include <set>
#include <sstream>

#include "meshlab_runner.h"
#include "obj_reader.h"
#include "ply_reader.h"

using namespace qmf_test;

namespace {

const int kFaceEdgeSel = 0x8000, kFaux = 0x40000;

double OffArea(const std::string &path, int &faces)
{
    std::ifstream in(path);
    std::string magic;
    int nv, ne;
    in >> magic >> nv >> faces >> ne;
    std::vector<V3> v(nv);
    for (auto &p : v) in >> p[0] >> p[1] >> p[2];
    double area = 0;
    for (int f = 0; f < faces; ++f) {
        int n, a, b, c;
        in >> n >> a >> b >> c;
        area += 0.5 * Norm(Cross(Sub(v[b], v[a]), Sub(v[c], v[a])));
    }
    return area;
}

std::array<int, 2> Key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }
}  // namespace

TEST(SplitFilter, PipelineScriptSelectsExactlyTheFrontEdgesInThePlyFlags)
{
    const std::string dir = WorkDir("split_fandisk");
    const std::string input = std::string(QMF_TEST_MESH_DIR) + "/fandisk.off";
    RunResult r = RunMeshLabServer(dir, "-i " + Quote(input) + " -o split.ply -m fq ff -o front.obj -l 1 -o edges.obj -l 2 -s " +
                                            Quote(Script("split_along_front.mlx")));
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char *f : {"split.ply", "front.obj", "edges.obj"})
        ASSERT_TRUE(FileExists(dir + "/" + f)) << f << ": meshlabserver exits 0 even when a save fails\n" << r.output;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.output, m, std::regex("(\\d+) vertices and (\\d+) faces added; (\\d+) front edges selected")))
        << r.output;
    const int facesAdded = std::stoi(m[2]), frontEdges = std::stoi(m[3]);
    EXPECT_TRUE(std::regex_search(r.output, std::regex("\\(0 traced"))) << "the smoothed front needs no tracing";

    int inputFaces = 0;
    const double inputArea = OffArea(input, inputFaces);
    PlyData d = ReadPly(dir + "/split.ply");
    ASSERT_EQ(d.error, "");
    ASSERT_EQ(int(d.faces.size()), inputFaces + facesAdded);
    ASSERT_EQ(d.faceProps["flags"].size(), d.faces.size());
    ASSERT_EQ(d.faceProps["quality"].size(), d.faces.size());

    // Edges: two faces each (closed 2-manifold), opposite directions (orientation), the selection
    // bit on both sides or neither, and selected exactly where the region ids differ.
    struct Side { int face, bit; bool forward; };
    std::map<std::array<int, 2>, std::vector<Side>> edges;
    double area = 0;
    int faux = 0, zeroArea = 0;
    for (size_t f = 0; f < d.faces.size(); ++f) {
        const auto &t = d.faces[f];
        ASSERT_EQ(t.size(), 3u);
        const int flags = int(d.faceProps["flags"][f]);
        if (flags & (kFaux | kFaux << 1 | kFaux << 2)) ++faux;
        const double a = 0.5 * Norm(Cross(Sub(d.vertices[t[1]], d.vertices[t[0]]), Sub(d.vertices[t[2]], d.vertices[t[0]])));
        area += a;
        if (!(a > 0)) ++zeroArea;
        for (int k = 0; k < 3; ++k)
            edges[Key(t[k], t[(k + 1) % 3])].push_back({int(f), (flags & (kFaceEdgeSel << k)) ? 1 : 0, t[k] < t[(k + 1) % 3]});
    }
    EXPECT_EQ(faux, 0);
    EXPECT_EQ(zeroArea, 0);
    EXPECT_NEAR(area, inputArea, 1e-6 * inputArea) << "total area";
    int notManifold = 0, misoriented = 0, oneSided = 0, selected = 0, wrong = 0;
    std::map<int, std::set<int>> graph;
    for (auto &e : edges) {
        if (e.second.size() != 2) { ++notManifold; continue; }
        const Side &a = e.second[0], &b = e.second[1];
        if (a.forward == b.forward) ++misoriented;
        if (a.bit != b.bit) ++oneSided;
        const bool idBoundary = d.faceProps["quality"][a.face] != d.faceProps["quality"][b.face];
        if (a.bit) {
            ++selected;
            graph[e.first[0]].insert(e.first[1]);
            graph[e.first[1]].insert(e.first[0]);
        }
        if (bool(a.bit) != idBoundary) ++wrong;
    }
    EXPECT_EQ(notManifold, 0);
    EXPECT_EQ(misoriented, 0);
    EXPECT_EQ(oneSided, 0) << "the selection bit must be on both faces of an edge";
    EXPECT_EQ(selected, frontEdges);
    EXPECT_EQ(wrong, 0) << "selected edges must be exactly the region-id boundaries";

    // Every segment of the saved front (6 decimals) is a chain of selected edges between its ends.
    ObjData front = ReadObj(dir + "/front.obj");
    ASSERT_GT(front.l.size(), 100u);
    auto nearest = [&](const V3 &p) {
        int best = -1;
        double bd = 1e30;
        for (size_t v = 0; v < d.vertices.size(); ++v) {
            const double dd = Norm(Sub(d.vertices[v], p));
            if (dd < bd) { bd = dd; best = int(v); }
        }
        return bd < 2e-6 ? best : -1;
    };
    int missing = 0;
    for (auto &s : front.l) {
        const int a = nearest(front.v[s[0]]), b = nearest(front.v[s[1]]);
        if (a < 0 || b < 0) { ++missing; continue; }
        std::set<int> seen{a};
        std::queue<int> q;
        q.push(a);
        const V3 pa = d.vertices[a], ab = Sub(d.vertices[b], pa);
        while (!q.empty() && !seen.count(b)) {
            const int v = q.front();
            q.pop();
            for (int w : graph[v]) {
                const V3 pw = Sub(d.vertices[w], pa);
                const double t = Dot(pw, ab) / Dot(ab, ab);
                const bool onSegment = t > -1e-9 && t < 1 + 1e-9 && Norm(Sub(pw, {ab[0] * t, ab[1] * t, ab[2] * t})) < 1e-5;
                if (!seen.count(w) && onSegment) { seen.insert(w); q.push(w); }
            }
        }
        if (!seen.count(b)) ++missing;
    }
    EXPECT_EQ(missing, 0) << "front segments that are not chains of selected edges";

    // The front-edges layer (layer 2) holds the selected edges.
    ObjData layer = ReadObj(dir + "/edges.obj");
    EXPECT_EQ(int(layer.l.size()), frontEdges);
}

TEST(SplitFilter, ErrorsGoToTheLogAndFailTheScript)
{
    const std::string dir = WorkDir("split_errors");
    std::ofstream(dir + "/split_self.mlx")
        << "<!DOCTYPE FilterScript>\n<FilterScript>\n <filter name=\"Split Triangles along Front\">\n"
           "  <Param type=\"RichMesh\" name=\"PolylineLayer\" value=\"0\"/>\n"
           "  <Param type=\"RichFloat\" name=\"LocateTolerance\" value=\"0.0001\"/>\n"
           "  <Param type=\"RichBool\" name=\"FrontEdgesLayer\" value=\"true\"/>\n </filter>\n</FilterScript>\n";
    RunResult r = RunMeshLabServer(dir, "-i " + Quote(std::string(QMF_TEST_MESH_DIR) + "/joint.off") +
                                            " -o out.ply -s split_self.mlx");
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.output.find("Split Triangles along Front: the polyline layer is the mesh itself"), std::string::npos)
        << r.output;
}
