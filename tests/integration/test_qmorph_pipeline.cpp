// The whole pipeline (closed_mesh_to_quads.mlx: filters 1-4 with default parameters) through the
// real meshlabserver on Debian-package meshes. The PLY (-m ff fq) and the exported OBJ are read
// back with independent readers and checked: real quads, the same quads in both files, closed
// 2-manifold, genus, no inverted quad, front edges selected and never a diagonal, Hausdorff.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "meshlab_runner.h"
#include "obj_reader.h"
#include "ply_reader.h"
#include "quad_checks.h"
#include "test_mesh.h"

using namespace qmf_test;

namespace {

// Quads of a PLY in MeshLab's polygonal form: triangle pairs sharing an edge flagged faux on both.
ObjData QuadsFromFauxPly(const PlyData &d, int &selectedFaceEdges, int &diagonalsOnFront)
{
    const int FAUX0 = 0x40000, SEL0 = 0x8000;
    std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> edgeFaces;  // edge -> (face, k)
    for (size_t i = 0; i < d.faces.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            int a = d.faces[i][k], b = d.faces[i][(k + 1) % 3];
            edgeFaces[{std::min(a, b), std::max(a, b)}].push_back({int(i), k});
        }
    ObjData p;
    for (auto &x : d.vertices) p.v.push_back(x);
    std::vector<char> used(d.faces.size(), 0);
    selectedFaceEdges = diagonalsOnFront = 0;
    for (size_t i = 0; i < d.faces.size(); ++i) {
        int flags = int(d.faceProps.at("flags")[i]);
        for (int k = 0; k < 3; ++k) {
            selectedFaceEdges += (flags & (SEL0 << k)) ? 1 : 0;
            diagonalsOnFront += (flags & (SEL0 << k)) && (flags & (FAUX0 << k)) ? 1 : 0;
        }
        if (used[i]) continue;
        used[i] = 1;
        int faux = -1;
        for (int k = 0; k < 3; ++k)
            if (flags & (FAUX0 << k)) faux = k;
        const auto &t = d.faces[i];
        if (faux >= 0) {
            int a = t[faux], b = t[(faux + 1) % 3];
            for (auto &o : edgeFaces[{std::min(a, b), std::max(a, b)}]) {
                if (o.first == int(i) || used[o.first]) continue;
                const auto &u = d.faces[o.first];
                used[o.first] = 1;
                p.f.push_back({t[(faux + 1) % 3], t[(faux + 2) % 3], t[faux], u[(o.second + 2) % 3]});
                break;
            }
            if (used[i] && p.f.size() && p.f.back().size() == 4 && p.f.back()[2] == t[faux]) continue;
        }
        p.f.push_back({t[0], t[1], t[2]});
    }
    return p;
}

// Quads as sorted vertex-index quadruples: the export writes MeshLab's live vertices in order, as
// meshlabserver's PLY does, so both files share the numbering (positions are checked separately).
std::multiset<std::vector<int>> QuadKeys(const ObjData &p)
{
    std::multiset<std::vector<int>> keys;
    for (auto &f : p.f)
        if (f.size() == 4) {
            std::vector<int> k(f);
            std::sort(k.begin(), k.end());
            keys.insert(k);
        }
    return keys;
}

double ScaledJacobian(const ObjData &p, const std::vector<int> &f)
{
    V3 n{0, 0, 0};
    for (int k = 0; k < 4; ++k) {
        V3 c = Cross(p.v[f[k]], p.v[f[(k + 1) % 4]]);
        n = {n[0] + c[0], n[1] + c[1], n[2] + c[2]};
    }
    double nl = std::sqrt(Dot(n, n)), worst = 1;
    for (int k = 0; k < 4; ++k) {
        V3 e1 = Sub(p.v[f[(k + 1) % 4]], p.v[f[k]]), e2 = Sub(p.v[f[(k + 3) % 4]], p.v[f[k]]);
        double l = std::sqrt(Dot(e1, e1) * Dot(e2, e2));
        worst = std::min(worst, Dot(Cross(e1, e2), n) / (l * nl));
    }
    return worst;
}

void ToTMesh(const ObjData &p, TMesh &m)
{
    std::vector<P3> v;
    for (auto &x : p.v) v.push_back(P3(float(x[0]), float(x[1]), float(x[2])));
    std::vector<std::array<int, 3>> t;
    for (auto &f : p.f)
        for (size_t k = 1; k + 1 < f.size(); ++k) t.push_back({f[0], f[k], f[k + 1]});
    Build(m, v, t);
}

// A triangle whose apex is nearer its longest side than this fraction of it is a needle (as the
// last check of Q-Morph defines it).
constexpr double kNeedleHeight = 1e-3;

// remeshFraction > 0: Q-Morph re-meshes first, to that fraction of the bounding box diagonal;
// allQuads: Q-Morph's All quads on (no triangle may be left); mustLog: a text the log must hold.
void RunPipeline(const std::string &mesh, double hausdorffBound, double remeshFraction = 0, bool allQuads = false,
                 const std::string &mustLog = std::string())
{
    std::string dir = WorkDir("pipeline_" + mesh + (remeshFraction > 0 ? "_remeshed" : "") + (allQuads ? "_all_quads" : ""));
    const std::string input = std::string(QMF_TEST_MESH_DIR) + "/" + mesh + ".off";
    // the shipped script, with the export path of Q-Morph set
    std::string script = ReadText(Script("closed_mesh_to_quads.mlx"));
    auto setParam = [&](const std::string &from, const std::string &to) {
        ASSERT_NE(script.find(from), std::string::npos) << from;
        script.replace(script.find(from), from.size(), to);
    };
    setParam("name=\"ExportPath\" value=\"\"", "name=\"ExportPath\" value=\"" + dir + "/quads.obj\"");
    std::string length;
    if (remeshFraction > 0) {
        TMesh in;
        ASSERT_TRUE(LoadOff(in, input));
        length = std::to_string(remeshFraction * in.bbox.Diag());
        setParam("name=\"TargetEdgeLength\" value=\"0\"", "name=\"TargetEdgeLength\" value=\"" + length + "\"");
    }
    if (allQuads) setParam("name=\"AllQuads\" value=\"false\"", "name=\"AllQuads\" value=\"true\"");
    std::ofstream(dir + "/pipeline.mlx") << script;
    RunResult r = RunMeshLabServer(dir, "-i " + Quote(input) + " -o out.ply -m ff fq sa -s pipeline.mlx");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    ASSERT_TRUE(FileExists(dir + "/out.ply")) << r.output;
    ASSERT_TRUE(FileExists(dir + "/quads.obj")) << r.output;
    std::smatch mq;
    ASSERT_TRUE(std::regex_search(r.output, mq, std::regex("Q-Morph: (\\d+) patches .*?; (\\d+) quads, (\\d+) triangles left"))) << r.output;
    const int quads = std::stoi(mq[2]), tris = std::stoi(mq[3]);
    EXPECT_NE(r.output.find("flipped faces: 0, folded quads: 0"), std::string::npos);
    if (!mustLog.empty()) {
        EXPECT_NE(r.output.find(mustLog), std::string::npos) << r.output;
    }
    if (remeshFraction > 0) {
        EXPECT_TRUE(std::regex_search(r.output, std::regex("re-meshing to edge length [0-9.e-]+: [1-9]\\d* front edges became [1-9]\\d*")))
            << r.output;
    }

    // the exported OBJ: real quads, as many as logged, a closed 2-manifold with the input's genus
    ObjData obj = ReadObj(dir + "/quads.obj");
    int objQuads = 0, objTris = 0;
    for (auto &f : obj.f) (f.size() == 4 ? objQuads : objTris)++;
    EXPECT_EQ(objQuads, quads);
    EXPECT_EQ(objTris, tris);
    if (allQuads) {
        EXPECT_EQ(objTris, 0) << "All quads on";
    }
    EXPECT_GT(double(quads) / (quads + tris), 0.9);
    std::map<std::pair<int, int>, int> uses;
    for (auto &f : obj.f)
        for (size_t k = 0; k < f.size(); ++k) uses[{std::min(f[k], f[(k + 1) % f.size()]), std::max(f[k], f[(k + 1) % f.size()])}]++;
    int notTwice = 0;
    for (auto &u : uses) notTwice += u.second != 2;
    EXPECT_EQ(notTwice, 0) << "every edge of a closed 2-manifold has two faces";
    TMesh in;
    ASSERT_TRUE(LoadOff(in, input));
    const int eulerIn = int(EulerCharacteristic(in));  // by vertex index: diplodocus has vertices at one place
    EXPECT_EQ(int(obj.v.size()) - int(uses.size()) + int(obj.f.size()), eulerIn) << "genus changed";
    int inverted = 0, poor = 0;
    for (auto &f : obj.f)
        if (f.size() == 4) {
            const double sj = ScaledJacobian(obj, f);
            inverted += sj <= 0;
            poor += sj < 0.3;
        }
    EXPECT_EQ(inverted, 0);
    // a needle (apex on its longest side, up to float noise) faces either way: evalquad counted
    // man's last one flipped when the last check ran one round only
    int needles = 0;
    for (auto &f : obj.f)
        if (f.size() == 3) {
            const V3 &a = obj.v[f[0]], &b = obj.v[f[1]], &c = obj.v[f[2]];
            const double longest = std::max(Norm(Sub(b, a)), std::max(Norm(Sub(c, b)), Norm(Sub(a, c))));
            needles += Norm(Cross(Sub(b, a), Sub(c, a))) / longest < kNeedleHeight * longest;
        }
    EXPECT_EQ(needles, 0) << "needle triangles";
    EXPECT_LE(poor, 0.005 * objQuads) << "issue 11's bar: at most 0.5% of the quads below 0.3 (on their own normal, as evalquad)";

    // the PLY holds the same quads as faux pairs, the front selected and never a diagonal
    PlyData ply = ReadPly(dir + "/out.ply");
    ASSERT_EQ(ply.error, "");
    ASSERT_EQ(ply.faceProps.count("flags"), 1u);
    int selected = 0, diagonalsOnFront = 0;
    ObjData fromPly = QuadsFromFauxPly(ply, selected, diagonalsOnFront);
    ASSERT_EQ(fromPly.v.size(), obj.v.size());
    double farthest = 0;
    for (size_t i = 0; i < obj.v.size(); ++i)
        for (int c = 0; c < 3; ++c) farthest = std::max(farthest, std::fabs(obj.v[i][c] - fromPly.v[i][c]));
    EXPECT_LT(farthest, 1e-5) << "the two files number the vertices differently";
    EXPECT_TRUE(QuadKeys(fromPly) == QuadKeys(obj)) << "the export and MeshLab's polygonal form disagree";
    EXPECT_GT(selected, 0);
    EXPECT_EQ(diagonalsOnFront, 0);

    // close to the input surface
    TMesh out;
    ToTMesh(obj, out);
    EXPECT_LT(Hausdorff(out, in), hausdorffBound * in.bbox.Diag());
}
}  // namespace

// The quality bar (0.5% of the diagonal) holds on the CAD part; the organic elephant cut into 136
// small regions measures about 0.48% at the defaults (0.57% on its own triangles: thin ear rims),
// bounded here at 1%.
TEST(QMorphPipeline, FandiskThroughMeshlabserver) { RunPipeline("fandisk", 0.005); }

TEST(QMorphPipeline, ElephantThroughMeshlabserver) { RunPipeline("elephant", 0.01); }

// Re-meshing at a given length (1% of the diagonal) through the shipped script: same invariants.
TEST(QMorphPipeline, FandiskRemeshedThroughMeshlabserver) { RunPipeline("fandisk", 0.005, 0.01); }

// All quads on, the rest at the script's defaults (re-meshed first at twice the automatic length).
TEST(QMorphPipeline, FandiskAllQuadsThroughMeshlabserver) { RunPipeline("fandisk", 0.005, 0, true); }

// CGAL's diplodocus: a straightened boundary segment crosses the rim of a flap thinner than its
// triangles, its ends on sheets facing apart, so no plane section joins them and the split lays it
// along mesh edges (SurfaceTracer::EdgePath); the pipeline used to stop there. On that flap the
// last check also splits triangles whose centroid lies nearer the sheet behind.
// CGAL's man (kept aside by the benchmark, extracted by set-up): thin fins and fingers, whose last
// needles and flipped triangles need the last check's second round (its first collapses change
// their neighbourhood). With one round a needle along a fin is left, which evalquad counts flipped.
TEST(QMorphPipeline, ManFinsThroughMeshlabserver) { RunPipeline("man", 0.005); }

TEST(QMorphPipeline, DiplodocusThinFlapThroughMeshlabserver)
{
    RunPipeline("diplodocus", 0.005, 0, false, "of them along mesh edges (no plane section joins their ends)");
}
