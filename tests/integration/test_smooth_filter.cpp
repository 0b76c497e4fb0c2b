// Filter 2 through the real meshlabserver: segmentation + smoothing from the shipped script, the
// front layer saved as OBJ (-l 1) and read back, checked against the input mesh with plain geometry.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "meshlab_runner.h"
#include "obj_reader.h"
#include "ply_reader.h"

using namespace qmf_test;

namespace {
double SegmentDistance(const V3 &p, const V3 &a, const V3 &b)
{
    V3 d = Sub(b, a);
    double l2 = Dot(d, d);
    double s = l2 > 0 ? std::max(0.0, std::min(1.0, Dot(Sub(p, a), d) / l2)) : 0.0;
    return Norm(Sub({a[0] + d[0] * s, a[1] + d[1] * s, a[2] + d[2] * s}, p));
}


double Diagonal(const std::vector<V3> &v)
{
    V3 lo = v[0], hi = v[0];
    for (auto &p : v)
        for (int k = 0; k < 3; ++k) { lo[k] = std::min(lo[k], p[k]); hi[k] = std::max(hi[k], p[k]); }
    return Norm(Sub(hi, lo));
}

// Where a front point lies on the mesh: the vertex it is on, else the edges it is on (within tol).
struct Location { int vertex = -1; std::set<std::pair<int, int>> edges; };

Location Locate(const ObjData &mesh, const V3 &p, double tol)
{
    Location loc;
    for (size_t i = 0; i < mesh.v.size(); ++i)
        if (Norm(Sub(mesh.v[i], p)) <= tol) { loc.vertex = int(i); return loc; }
    for (auto &t : mesh.f)
        for (int k = 0; k < 3; ++k) {
            int a = std::min(t[k], t[(k + 1) % 3]), b = std::max(t[k], t[(k + 1) % 3]);
            if (SegmentDistance(p, mesh.v[a], mesh.v[b]) <= tol) loc.edges.insert({a, b});
        }
    return loc;
}

bool InFace(const Location &l, const std::vector<int> &t)
{
    if (l.vertex >= 0) return l.vertex == t[0] || l.vertex == t[1] || l.vertex == t[2];
    for (int k = 0; k < 3; ++k)
        if (l.edges.count({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])})) return true;
    return false;
}
}  // namespace

TEST(SmoothFilter, FandiskSegmentedAndSmoothedThroughMeshlabserver)
{
    const std::string input = std::string(QMF_TEST_MESH_DIR) + "/fandisk.off";
    std::string dir = WorkDir("smooth_fandisk");
    RunResult r = RunMeshLabServer(dir, "-i " + Quote(input) + " -s " + Quote(Script("smooth_boundaries.mlx")) +
                                            " -o regions.ply -m fq -o front.obj -l 1");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ASSERT_TRUE(FileExists(dir + "/regions.ply")) << "meshlabserver exits 0 even when a save fails\n" << r.output;
    ASSERT_TRUE(FileExists(dir + "/front.obj")) << r.output;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.output, m, std::regex("Smooth Region Boundaries: (\\d+) curves \\((\\d+) closed loops\\), "
                                                          "(\\d+) corners, (\\d+) boundary edges between (\\d+) regions; "
                                                          "total length ([0-9.e+-]+) -> ([0-9.e+-]+)")))
        << r.output;
    const int curves = std::stoi(m[1]), loops = std::stoi(m[2]), corners = std::stoi(m[3]);
    const double before = std::stod(m[6]), after = std::stod(m[7]);
    EXPECT_GT(curves, 10);
    EXPECT_LT(after, before);
    ASSERT_TRUE(std::regex_search(r.output, m, std::regex("layer 'fandisk.off_front': (\\d+) vertices, (\\d+) edges"))) << r.output;
    const int vertices = std::stoi(m[1]), edges = std::stoi(m[2]);

    // The triangle mesh stayed the current layer (-o without -l saved it, with its region ids).
    PlyData regions = ReadPly(dir + "/regions.ply");
    ASSERT_EQ(regions.error, "");
    EXPECT_EQ(regions.faces.size(), 12946u);
    EXPECT_EQ(regions.faceProps["quality"].size(), 12946u);

    // The front: an edge-only OBJ with the logged counts; corners are the points not of degree 2.
    ObjData mesh = ReadObj(input), front = ReadObj(dir + "/front.obj");
    EXPECT_TRUE(front.f.empty());
    EXPECT_EQ(front.otherLines, 0);
    ASSERT_EQ(int(front.v.size()), vertices);
    ASSERT_EQ(int(front.l.size()), edges);
    std::vector<int> degree(front.v.size(), 0);
    double length = 0;
    for (auto &e : front.l) {
        ++degree[e[0]];
        ++degree[e[1]];
        length += Norm(Sub(front.v[e[0]], front.v[e[1]]));
    }
    int notTwo = 0;
    for (int d : degree) notTwo += d != 2;
    EXPECT_EQ(notTwo, corners);
    // Open curves have one edge less than points, loops as many, and a corner is one vertex for
    // all curves ending there: edges - vertices = open curves - corners.
    EXPECT_EQ(edges - vertices, (curves - loops) - corners);
    EXPECT_NEAR(length, after, 1e-4 * after);

    // Every point on a vertex or an edge of the input (6 decimals in OBJ), and every segment inside
    // one face: both ends on that face's vertices or edges.
    const double tol = 1e-5 * Diagonal(mesh.v);
    std::vector<Location> where;
    int onVertices = 0;
    for (auto &p : front.v) {
        where.push_back(Locate(mesh, p, tol));
        ASSERT_TRUE(where.back().vertex >= 0 || !where.back().edges.empty()) << "a point off the mesh edges";
        onVertices += where.back().vertex >= 0;
    }
    EXPECT_LT(onVertices, int(front.v.size())) << "smoothing moved points into edges";
    int withoutFace = 0;
    for (auto &e : front.l) {
        bool shared = false;
        for (auto &t : mesh.f)
            if (InFace(where[e[0]], t) && InFace(where[e[1]], t)) { shared = true; break; }
        withoutFace += !shared;
    }
    EXPECT_EQ(withoutFace, 0);

    // Read back by MeshLab itself (an edge-only OBJ imports; one with faces too would not).
    RunResult back = RunMeshLabServer(dir, "-i front.obj -o again.obj");
    ASSERT_EQ(back.exitCode, 0) << back.output;
    ObjData again = ReadObj(dir + "/again.obj");
    EXPECT_EQ(again.v.size(), front.v.size());
    EXPECT_EQ(again.l.size(), front.l.size());
}

TEST(SmoothFilter, BadInputIsRefusedWithAMessageInTheLog)
{
    std::string dir = WorkDir("smooth_bad_input");
    // Filter 2 alone, on meshes without region ids / with one region only.
    std::ifstream script(Script("smooth_boundaries.mlx"));
    std::stringstream ss;
    ss << script.rdbuf();
    std::string text = ss.str();
    const size_t from = text.find(" <filter name=\"Segment by Variational Shape Approximation\">");
    const size_t to = text.find(" <filter name=\"Smooth Region Boundaries\">");
    ASSERT_NE(from, std::string::npos);
    ASSERT_NE(to, std::string::npos);
    std::ofstream(dir + "/smooth_only.mlx") << text.substr(0, from) + text.substr(to);

    const std::string tetra = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                              "element face 4\nproperty list uchar int vertex_indices\n";
    std::ofstream(dir + "/plain.ply") << tetra << "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
    RunResult plain = RunMeshLabServer(dir, "-i plain.ply -o out.ply -s smooth_only.mlx");
    EXPECT_NE(plain.exitCode, 0);
    EXPECT_NE(plain.output.find("Smooth Region Boundaries: the mesh has no face quality"), std::string::npos) << plain.output;

    std::ofstream(dir + "/one.ply") << tetra << "property float quality\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                                "3 0 2 1 3\n3 0 1 3 3\n3 0 3 2 3\n3 1 2 3 3\n";
    RunResult one = RunMeshLabServer(dir, "-i one.ply -o out.ply -s smooth_only.mlx");
    EXPECT_NE(one.exitCode, 0);
    EXPECT_NE(one.output.find("Smooth Region Boundaries: the face quality holds a single region id"), std::string::npos)
        << one.output;

    // Two regions: accepted, the front is the closed loop between them (a triangle).
    std::ofstream(dir + "/two.ply") << tetra << "property float quality\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                                                "3 0 2 1 0\n3 0 1 3 1\n3 0 3 2 1\n3 1 2 3 1\n";
    RunResult two = RunMeshLabServer(dir, "-i two.ply -s smooth_only.mlx -o front.obj -l 1");
    EXPECT_EQ(two.exitCode, 0) << two.output;
    EXPECT_NE(two.output.find("Smooth Region Boundaries: 1 curves (1 closed loops), 0 corners, 3 boundary edges"),
              std::string::npos)
        << two.output;
    ObjData front = ReadObj(dir + "/front.obj");
    EXPECT_EQ(front.v.size(), 3u);
    EXPECT_EQ(front.l.size(), 3u);
}
