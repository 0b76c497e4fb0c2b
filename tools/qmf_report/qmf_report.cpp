// qmf_report: the quality report of one demo run, computed with the product's own code
// (vcg_ext/quad_quality.h, vcg_ext/mesh_checks.h, vcg_ext/front_edges.h) on the files the real
// meshlabserver wrote. Prints the input and quad-mesh tables as Markdown, writes the per-quad
// scaled Jacobians for a histogram and, with --render-dir, the scenes of the demo's pictures.
//
//   qmf_report --input IN --split split.ply --quads quads_polygonal.ply [--quads-obj quads.obj]
//              [--regions regions.ply --front front.obj --render-dir DIR [--view AZ,EL] [--resolution WxH]]
//              [--jacobians FILE]
//   qmf_report --convert IN OUT.ply     (the mesh as a binary PLY: Debian's meshlabserver 2020.09
//                                        aborts on OBJ files with faces, Debian bug #1054006)
// --resolution: of the final pictures (default 1200x900); for the overall quads picture the f3d
// options ask for --supersample times that (default 2): scaling it down smooths quad edges thinner
// than a pixel, which f3d's FXAA alone leaves broken. Tube widths are in final pixels.
// --view: the overall pictures' direction in degrees (azimuth about +Y from +Z, elevation); by
// default the one of 36 that shows most of the regions.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <vcg_ext/common/front_edges.h>
#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/quad_quality.h>

#include "pictures.h"
#include <vcg_ext/common/input_surface.h>

#include "report_mesh.h"
#include "report_tables.h"

using namespace qmf_report;

namespace {

struct Options {
    std::string input, split, quads, quadsObj, regions, front, renderDir, jacobians;
    int width = 1200, height = 900;
    int supersample = 2;  // the overall quads picture is rendered this many times larger
    bool fixedView = false;
    double azimuth = 0, elevation = 0;
};

[[noreturn]] void Fail(const std::string &msg)
{
    std::fprintf(stderr, "qmf_report: %s\n", msg.c_str());
    std::exit(1);
}

void LoadOrFail(RMesh &m, const std::string &path)
{
    std::string err = Load(m, path);
    if (!err.empty()) Fail(err);
}

Topology MeasureTopology(const RMesh &m)
{
    Topology t;
    t.checks = vcg_ext::MeshChecks<RMesh>::Inspect(m);
    t.euler = t.checks.EulerCharacteristic();
    return t;
}

InputFigures MeasureInput(const RMesh &m, const std::string &path)
{
    InputFigures in;
    in.path = path;
    in.topo = MeasureTopology(m);
    in.area = TotalArea(m);
    in.bboxDiagonal = m.bbox.Diag();
    std::vector<double> angles;
    for (const RFace &f : m.face)
        if (!f.IsD()) angles.push_back(SmallestAngleDeg(f));
    std::sort(angles.begin(), angles.end());
    in.angleBucketEdges = {0, 5, 10, 20, 30, 40, 50, 60};
    in.angleBucketCounts.assign(in.angleBucketEdges.size() - 1, 0);
    double sum = 0;
    for (double a : angles) {
        sum += a;
        size_t k = 0;
        while (k + 2 < in.angleBucketEdges.size() && a >= in.angleBucketEdges[k + 1]) ++k;
        in.angleBucketCounts[k]++;
    }
    if (!angles.empty()) {
        in.angleMin = angles.front();
        in.angleP5 = Percentile(angles, 0.05);
        in.angleMedian = Percentile(angles, 0.5);
        in.angleMean = sum / angles.size();
    }
    return in;
}

// An edge by the float coordinates of its two end points (vertex indices differ between files;
// Q-Morph never moves a front node, so the coordinates match exactly).
typedef std::array<float, 6> EdgeKey;
EdgeKey KeyOf(const RVertex *a, const RVertex *b)
{
    std::array<float, 3> p = {a->cP()[0], a->cP()[1], a->cP()[2]}, q = {b->cP()[0], b->cP()[1], b->cP()[2]};
    if (q < p) std::swap(p, q);
    return {p[0], p[1], p[2], q[0], q[1], q[2]};
}

std::vector<double> QuadJacobians(const vcg_ext::PolygonMesh &pm)
{
    std::vector<double> j;
    for (const auto &f : pm.faces)
        if (f.size() == 4)
            j.push_back(vcg_ext::QuadQuality::ScaledJacobian(pm.points[f[0]], pm.points[f[1]], pm.points[f[2]], pm.points[f[3]]));
    return j;
}

void WriteJacobians(const std::string &path, const std::vector<double> &j)
{
    FILE *out = std::fopen(path.c_str(), "w");
    if (!out) Fail("cannot write " + path);
    std::fprintf(out, "# scaled Jacobian of each quad (vcg_ext::QuadQuality::ScaledJacobian), in the face order of quads.obj\n");
    for (double v : j) std::fprintf(out, "%.6f\n", v);
    if (std::fclose(out) != 0) Fail("cannot write " + path);
}

// Quads read back from the real-quad export: the same counts and quality as the polygonal PLY?
std::string CheckObj(const std::string &path, const vcg_ext::QuadQualityReport &ref, vcg_ext::InputSurface<RMesh> &surface)
{
    if (path.empty()) return "not given";
    vcg_ext::PolygonMesh pm;
    std::string err = ReadObj(path, pm);
    if (!err.empty()) return err;
    vcg_ext::QuadQualityReport r = vcg_ext::QuadQuality::Measure(pm, surface.NormalsUnder(pm));
    std::string counts = Int(r.quads) + " quads, " + Int(r.triangles) + " triangles, " + Int(r.others) + " other";
    bool same = r.quads == ref.quads && r.triangles == ref.triangles && r.others == ref.others &&
                r.irregularVertices == ref.irregularVertices && std::fabs(r.meanJacobian - ref.meanJacobian) < 1e-4;
    return (same ? "agrees: " : "DIFFERS: ") + counts + Fmt(", mean scaled Jacobian %.3f", r.meanJacobian);
}

}  // namespace

int main(int argc, char **argv)
{
    if (argc == 4 && std::string(argv[1]) == "--convert") {  // any input mesh to a binary PLY meshlabserver can read
        RMesh m;
        LoadOrFail(m, argv[2]);
        int err = vcg::tri::io::ExporterPLY<RMesh>::Save(m, argv[3], 0, true);
        if (err) Fail(std::string("cannot write ") + argv[3] + ": " + vcg::tri::io::ExporterPLY<RMesh>::ErrorMsg(err));
        return 0;
    }
    Options o;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto next = [&]() -> std::string {
            if (i + 1 >= argc) Fail("missing value after " + a);
            return argv[++i];
        };
        if (a == "--input") o.input = next();
        else if (a == "--split") o.split = next();
        else if (a == "--quads") o.quads = next();
        else if (a == "--quads-obj") o.quadsObj = next();
        else if (a == "--regions") o.regions = next();
        else if (a == "--front") o.front = next();
        else if (a == "--render-dir") o.renderDir = next();
        else if (a == "--jacobians") o.jacobians = next();
        else if (a == "--view") {
            if (std::sscanf(next().c_str(), "%lf,%lf", &o.azimuth, &o.elevation) != 2) Fail("--view AZIMUTH,ELEVATION (degrees)");
            o.fixedView = true;
        } else if (a == "--supersample") {
            o.supersample = std::atoi(next().c_str());
            if (o.supersample < 1 || o.supersample > 4) Fail("--supersample 1..4");
        } else if (a == "--resolution") {
            if (std::sscanf(next().c_str(), "%dx%d", &o.width, &o.height) != 2 || o.width < 16 || o.height < 16)
                Fail("--resolution WIDTHxHEIGHT");
        } else Fail("unknown argument " + a + " (see the comment at the top of qmf_report.cpp)");
    }
    if (o.input.empty() || o.split.empty() || o.quads.empty()) Fail("--input, --split and --quads are required");
    if (!o.renderDir.empty() && (o.regions.empty() || o.front.empty())) Fail("--render-dir needs --regions and --front");

    RMesh input, split, quads;
    LoadOrFail(input, o.input);
    LoadOrFail(split, o.split);
    LoadOrFail(quads, o.quads);
    const InputFigures in = MeasureInput(input, o.input);

    vcg::tri::UpdateTopology<RMesh>::FaceFace(quads);
    const vcg_ext::PolygonMesh pm = vcg_ext::QuadQuality::FromFauxMesh(quads);
    QuadFigures qf;
    vcg_ext::InputSurface<RMesh> surface(input);
    qf.q = vcg_ext::QuadQuality::Measure(pm, surface.NormalsUnder(pm));  // against the input surface
    std::vector<double> jac = QuadJacobians(pm);
    if (!o.jacobians.empty()) WriteJacobians(o.jacobians, jac);
    qf.vertices = long(pm.points.size());
    qf.topo = MeasureTopology(quads);
    qf.inputGenus = in.topo.Valid() ? in.topo.Genus() : -1;
    qf.objCheck = CheckObj(o.quadsObj, qf.q, surface);

    // the initial front: selected face-edges of the split mesh, looked up among the output's edges
    std::map<EdgeKey, bool> outEdges;  // non-faux output edge -> still selected
    for (const RFace &f : quads.face) {
        if (f.IsD()) continue;
        for (int k = 0; k < 3; ++k)
            if (!f.IsF(k)) {
                bool &sel = outEdges[KeyOf(f.cV(k), f.cV((k + 1) % 3))];
                sel = sel || f.IsFaceEdgeS(k);
            }
    }
    for (const auto &e : vcg_ext::FrontEdges<RMesh>::Collect(split)) {
        ++qf.frontEdges;
        auto it = outEdges.find(KeyOf(&split.vert[e.first], &split.vert[e.second]));
        if (it != outEdges.end()) {
            ++qf.frontKept;
            qf.frontStillSelected += it->second;
        }
    }

    std::printf("## Input mesh\n\n");
    PrintTable(stdout, "input", "", InputRows(in));
    std::printf("\nSmallest angle of each triangle:\n\n");
    PrintTable(stdout, "smallest angle", "triangles", AngleRows(in));
    std::printf("\n## Quad mesh\n\n");
    std::printf("Measured on `quads_polygonal.ply` (MeshLab's polygonal form read back) with the core's "
                "`QuadQuality::Measure` and `MeshChecks::Inspect`.\n\n");
    PrintTable(stdout, "quad mesh", "", QuadRows(qf));

    if (!o.renderDir.empty()) {
        PictureOptions p;
        p.regions = o.regions;
        p.front = o.front;
        p.dir = o.renderDir;
        p.width = o.width;
        p.height = o.height;
        p.supersample = o.supersample;
        p.fixedView = o.fixedView;
        p.azimuth = o.azimuth;
        p.elevation = o.elevation;
        std::string err = RenderScenes(p, quads);
        if (!err.empty()) Fail(err);
    }
    return 0;
}
