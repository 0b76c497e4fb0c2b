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
// --resolution: of the final pictures (default 1200x900); the f3d options ask for --supersample
// times that (default 2), tube widths are in final pixels: scaling the render down smooths edges
// thinner than a pixel, which f3d's FXAA alone leaves broken.
// --view: the overall pictures' direction in degrees (azimuth about +Y from +Z, elevation); by
// default the one of 36 that shows most of the regions.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <vcg_ext/front_edges.h>
#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/quad_quality.h>
#include <vcg_ext/region_ids.h>

#include "render_scene.h"
#include "report_mesh.h"
#include "report_tables.h"

using namespace qmf_report;

namespace {

struct Options {
    std::string input, split, quads, quadsObj, regions, front, renderDir, jacobians;
    int width = 1200, height = 900;
    int supersample = 2;  // scenes framed for a picture this many times larger, to be scaled down
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
    t.euler = EulerCharacteristic(m);
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
std::string CheckObj(const std::string &path, const vcg_ext::QuadQualityReport &ref)
{
    if (path.empty()) return "not given";
    vcg_ext::PolygonMesh pm;
    std::string err = ReadObj(path, pm);
    if (!err.empty()) return err;
    vcg_ext::QuadQualityReport r = vcg_ext::QuadQuality::Measure(pm);
    std::string counts = Int(r.quads) + " quads, " + Int(r.triangles) + " triangles, " + Int(r.others) + " other";
    bool same = r.quads == ref.quads && r.triangles == ref.triangles && r.others == ref.others &&
                r.irregularVertices == ref.irregularVertices && std::fabs(r.meanJacobian - ref.meanJacobian) < 1e-4;
    return (same ? "agrees: " : "DIFFERS: ") + counts + Fmt(", mean scaled Jacobian %.3f", r.meanJacobian);
}

// ------------------------------------------------------------------ pictures
const Colour kEdge(45, 45, 50, 255), kFront(205, 25, 30, 255), kQuad(246, 246, 240, 255), kBadQuad(250, 205, 50, 255),
    kTriangle(245, 130, 30, 255), kJagged(70, 100, 170, 255), kRegionLine(40, 40, 40, 255);

Colour Pale(Colour c, double keep)
{
    return Colour((unsigned char)(255 - keep * (255 - c[0])), (unsigned char)(255 - keep * (255 - c[1])),
                  (unsigned char)(255 - keep * (255 - c[2])), 255);
}

double MeanEdge(const RMesh &m, bool skipFaux)
{
    double sum = 0;
    long n = 0;
    for (const RFace &f : m.face) {
        if (f.IsD()) continue;
        for (int k = 0; k < 3; ++k)
            if (!(skipFaux && f.IsF(k))) { sum += (PosOf(f.cV(k)) - PosOf(f.cV((k + 1) % 3))).Norm(); ++n; }
    }
    return n ? sum / n : 1;
}

// Each edge between two faces once (FF adjacency), with a predicate on (face, edge index).
template <class Pred, class Emit>
void ForEachEdge(const RMesh &m, Pred keep, Emit emit)
{
    for (const RFace &f : m.face) {
        if (f.IsD()) continue;
        for (int k = 0; k < 3; ++k) {
            const RFace *g = f.cFFp(k);
            if (g != &f && g < &f) continue;  // the other side emits it
            if (keep(f, k)) emit(PosOf(f.cV(k)), PosOf(f.cV((k + 1) % 3)));
        }
    }
}

void SaveScene(const Scene &s, const Camera &cam, const std::string &dir, const std::string &name)
{
    std::string err = s.Save(dir + "/" + name + ".ply");
    if (err.empty()) err = WriteF3dArgs(dir + "/" + name + ".args", cam);
    if (!err.empty()) Fail(err);
}

// Möller-Trumbore: does the ray o + t d (t > 0) hit triangle abc?
bool RayHits(const P3d &o, const P3d &d, const P3d &a, const P3d &b, const P3d &c)
{
    P3d e1 = b - a, e2 = c - a, p = d ^ e2;
    double det = e1 * p;
    if (std::fabs(det) < 1e-30) return false;
    P3d s = o - a;
    double u = (s * p) / det;
    if (u < 0 || u > 1) return false;
    P3d q = s ^ e1;
    double v = (d * q) / det;
    if (v < 0 || u + v > 1) return false;
    return (e2 * q) / det > 0;
}

// Close-up where the front meets the rows of quads: the front vertex whose neighbourhood (faces
// within R, connected) is flattest and can be seen along its mean normal.
Camera CloseUpCamera(const RMesh &m, double radius, int w, int h, P3d &centre)
{
    std::vector<std::vector<int>> vf(m.vert.size());
    std::vector<char> onFront(m.vert.size(), 0);
    for (size_t i = 0; i < m.face.size(); ++i) {
        const RFace &f = m.face[i];
        if (f.IsD()) continue;
        for (int k = 0; k < 3; ++k) {
            vf[vcg::tri::Index(m, f.cV(k))].push_back(int(i));
            if (f.IsFaceEdgeS(k)) onFront[vcg::tri::Index(m, f.cV(k))] = onFront[vcg::tri::Index(m, f.cV((k + 1) % 3))] = 1;
        }
    }
    std::vector<int> cand;
    for (size_t v = 0; v < m.vert.size(); ++v)
        if (onFront[v] && !vf[v].empty()) cand.push_back(int(v));
    if (cand.empty())
        for (size_t v = 0; v < m.vert.size(); ++v)
            if (!vf[v].empty()) cand.push_back(int(v));
    const size_t maxCand = std::max<size_t>(24, std::min<size_t>(300, 20000000 / std::max(1, m.fn)));
    if (cand.size() > maxCand) {
        std::vector<int> sub;
        for (size_t i = 0; i < maxCand; ++i) sub.push_back(cand[i * cand.size() / maxCand]);
        cand.swap(sub);
    }
    struct Scored { double flat; int v; P3d dir; };
    std::vector<Scored> scored;
    std::vector<int> mark(m.face.size(), -1);
    for (int v : cand) {
        const P3d p = PosOf(&m.vert[v]);
        std::vector<int> stack(vf[v]), region;
        for (int f : stack) mark[f] = v;
        while (!stack.empty()) {
            int f = stack.back();
            stack.pop_back();
            region.push_back(f);
            for (int k = 0; k < 3; ++k) {
                const RFace *g = m.face[f].cFFp(k);
                int gi = int(vcg::tri::Index(m, g));
                if (mark[gi] == v || g->IsD()) continue;
                P3d c = (PosOf(g->cV(0)) + PosOf(g->cV(1)) + PosOf(g->cV(2))) / 3.0;
                if ((c - p).Norm() > radius) continue;
                mark[gi] = v;
                stack.push_back(gi);
            }
        }
        P3d n(0, 0, 0);
        double area = 0;
        for (int f : region) {
            const RFace &F = m.face[f];
            P3d a = (PosOf(F.cV(1)) - PosOf(F.cV(0))) ^ (PosOf(F.cV(2)) - PosOf(F.cV(0)));
            n += a * 0.5;
            area += 0.5 * a.Norm();
        }
        if (area > 0 && n.Norm() > 0) scored.push_back({n.Norm() / area, v, n / n.Norm()});
    }
    std::stable_sort(scored.begin(), scored.end(), [](const Scored &a, const Scored &b) { return a.flat > b.flat; });
    const double eps = 1e-4 * m.bbox.Diag();
    const Scored *pick = scored.empty() ? nullptr : &scored.front();
    for (const Scored &s : scored) {  // the flattest one not hidden behind another part
        const P3d o = PosOf(&m.vert[s.v]) + s.dir * eps;
        bool hidden = false;
        for (const RFace &f : m.face) {
            if (f.IsD() || f.cV(0) == &m.vert[s.v] || f.cV(1) == &m.vert[s.v] || f.cV(2) == &m.vert[s.v]) continue;
            if (RayHits(o, s.dir, PosOf(f.cV(0)), PosOf(f.cV(1)), PosOf(f.cV(2)))) { hidden = true; break; }
        }
        if (!hidden) { pick = &s; break; }
    }
    Camera cam;
    cam.width = w;
    cam.height = h;
    centre = pick ? PosOf(&m.vert[pick->v]) : P3d::Construct(m.bbox.Center());
    P3d dir = pick ? pick->dir : P3d(0, 0, 1);
    P3d up(0, 1, 0);
    if (std::fabs(up * dir) > 0.9) up = P3d(0, 0, -1);
    up = (up - dir * (up * dir)).Normalize();
    cam.focal = centre;
    cam.position = centre + dir * (radius / std::tan(cam.viewAngleDeg * M_PI / 360));
    cam.up = up;
    return cam;
}

// Light colours (ColorBrewer Set3 without its grey), given to regions largest first so that
// neighbouring regions differ: the picture's own palette, readable under f3d's lights.
std::vector<Colour> RegionPalette(const RMesh &m, const std::vector<int> &region, int regions)
{
    static const unsigned char set3[11][3] = {{141, 211, 199}, {255, 255, 179}, {190, 186, 218}, {251, 128, 114},
                                              {128, 177, 211}, {253, 180, 98},  {179, 222, 105}, {252, 205, 229},
                                              {188, 128, 189}, {204, 235, 197}, {255, 237, 111}};
    std::vector<double> area(regions, 0);
    std::vector<std::set<int>> next(regions);
    for (size_t i = 0; i < m.face.size(); ++i) {
        const RFace &f = m.face[i];
        if (f.IsD()) continue;
        area[region[i]] += FaceArea(f);
        for (int k = 0; k < 3; ++k) {
            int g = region[vcg::tri::Index(m, f.cFFp(k))];
            if (g != region[i]) next[region[i]].insert(g);
        }
    }
    std::vector<int> order(regions), colour(regions, -1);
    for (int r = 0; r < regions; ++r) order[r] = r;
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return area[x] > area[y]; });
    std::vector<double> total(11, 0);  // area per colour so far: spread the colours over the part
    for (int r : order) {
        int best = 0;
        for (int c = 1; c < 11; ++c) {
            auto clash = [&](int col) { int n = 0; for (int g : next[r]) n += colour[g] == col; return n; };
            int a = clash(c), b = clash(best);
            if (a < b || (a == b && total[c] < total[best])) best = c;
        }
        colour[r] = best;
        total[best] += area[r];
    }
    std::vector<Colour> out;
    for (int r = 0; r < regions; ++r) out.push_back(Colour(set3[colour[r]][0], set3[colour[r]][1], set3[colour[r]][2], 255));
    return out;
}

void QuadScene(Scene &s, const RMesh &q, const std::vector<std::array<P3d, 3>> &normals, const std::vector<double> &faceJacobian,
               double edgeR, double frontR, const P3d *clipCentre, double clipRadius)
{
    auto inside = [&](const RFace &f) {
        if (!clipCentre) return true;
        P3d c = (PosOf(f.cV(0)) + PosOf(f.cV(1)) + PosOf(f.cV(2))) / 3.0;
        return (c - *clipCentre).Norm() < clipRadius;
    };
    for (size_t i = 0; i < q.face.size(); ++i) {
        const RFace &f = q.face[i];
        if (f.IsD() || !inside(f)) continue;
        int faux = f.IsF(0) + f.IsF(1) + f.IsF(2);
        Colour c = faux == 0 ? kTriangle : (faceJacobian[i] < 0.3 ? kBadQuad : kQuad);
        s.AddTriangle(PosOf(f.cV(0)), PosOf(f.cV(1)), PosOf(f.cV(2)), normals[i], c);
    }
    ForEachEdge(q, [&](const RFace &f, int k) { return !f.IsF(k) && !f.IsFaceEdgeS(k) && inside(f); },
                [&](const P3d &a, const P3d &b) { s.AddTube(a, b, edgeR, kEdge); });
    ForEachEdge(q, [&](const RFace &f, int k) { return f.IsFaceEdgeS(k) && inside(f); },
                [&](const P3d &a, const P3d &b) { s.AddTube(a, b, frontR, kFront); });
}

void RenderScenes(const Options &o, RMesh &quads)
{
    RMesh regions, front;
    LoadOrFail(regions, o.regions);
    LoadOrFail(front, o.front);
    vcg::tri::UpdateTopology<RMesh>::FaceFace(regions);
    // region ids (face quality of step 1) as indices 0..K-1
    std::vector<int> ids;
    std::string bad = vcg_ext::RegionIds<RMesh>::Read(regions, ids);
    if (!bad.empty()) Fail(o.regions + ": " + bad);
    std::map<int, int> index;
    for (size_t i = 0; i < ids.size(); ++i)
        if (ids[i] >= 0) index.emplace(ids[i], 0);
    int k = 0;
    for (auto &e : index) e.second = k++;
    for (int &id : ids)
        if (id >= 0) id = index[id];
    const int regionCount = int(index.size());
    const std::vector<Colour> palette = RegionPalette(regions, ids, regionCount);

    const P3d viewDir = ViewDirection(o.azimuth, o.elevation);
    const int W = o.width * o.supersample, H = o.height * o.supersample;
    const Camera overall = OverallCamera(regions, ids, regionCount, W, H, o.fixedView ? &viewDir : nullptr);
    const double px = overall.PixelSize() * o.supersample;  // one pixel of the final picture
    const double inEdge = MeanEdge(regions, false), quadEdge = MeanEdge(quads, true);
    const auto inNormals = CornerNormals(regions), quadNormals = CornerNormals(quads);
    auto regionEdge = [&](const RFace &f, int e) { return ids[vcg::tri::Index(regions, f.cFFp(e))] != ids[vcg::tri::Index(regions, &f)]; };

    // 1. regions, thin dark lines where the region changes
    {
        Scene s;
        for (size_t i = 0; i < regions.face.size(); ++i) {
            const RFace &f = regions.face[i];
            if (!f.IsD()) s.AddTriangle(PosOf(f.cV(0)), PosOf(f.cV(1)), PosOf(f.cV(2)), inNormals[i], palette[ids[i]]);
        }
        ForEachEdge(regions, regionEdge, [&](const P3d &a, const P3d &b) { s.AddTube(a, b, std::min(0.8 * px, 0.08 * inEdge), kRegionLine); });
        SaveScene(s, overall, o.renderDir, "regions");
    }
    // 2. front: the smoothed curves (red) over the pale regions, with the jagged region boundaries
    //    they replace (blue)
    {
        Scene s;
        for (size_t i = 0; i < regions.face.size(); ++i) {
            const RFace &f = regions.face[i];
            if (!f.IsD()) s.AddTriangle(PosOf(f.cV(0)), PosOf(f.cV(1)), PosOf(f.cV(2)), inNormals[i], Pale(palette[ids[i]], 0.45));
        }
        ForEachEdge(regions, regionEdge, [&](const P3d &a, const P3d &b) { s.AddTube(a, b, std::min(0.7 * px, 0.06 * inEdge), kJagged); });
        for (const REdge &e : front.edge)
            if (!e.IsD()) s.AddTube(PosOf(e.cV(0)), PosOf(e.cV(1)), std::min(1.6 * px, 0.2 * inEdge), kFront);
        SaveScene(s, overall, o.renderDir, "front");
    }
    // per triangle of the faux form: the scaled Jacobian of its quad (1 for a triangle)
    std::vector<double> faceJ(quads.face.size(), 1.0);
    for (size_t i = 0; i < quads.face.size(); ++i) {
        const RFace &f = quads.face[i];
        if (f.IsD()) continue;
        for (int e = 0; e < 3; ++e)
            if (f.IsF(e)) {
                const RFace *g = f.cFFp(e);
                faceJ[i] = vcg_ext::QuadQuality::ScaledJacobian(PosOf(f.cV((e + 1) % 3)), PosOf(f.cV((e + 2) % 3)), PosOf(f.cV(e)),
                                                                PosOf(g->cV((f.cFFi(e) + 2) % 3)));
            }
    }
    // 3. quads: edges dark, the front red, quads below 0.3 yellow, triangles orange
    {
        Scene s;
        QuadScene(s, quads, quadNormals, faceJ, std::min(0.6 * px, 0.07 * quadEdge), std::min(1.3 * px, 0.2 * quadEdge), nullptr, 0);
        SaveScene(s, overall, o.renderDir, "quads");
    }
    // 4. close-up: about a dozen rows of quads across the picture's height
    {
        P3d centre;
        const double radius = 6 * quadEdge;
        Camera cam = CloseUpCamera(quads, radius, W, H, centre);
        const double cpx = cam.PixelSize() * o.supersample;
        Scene s;
        QuadScene(s, quads, quadNormals, faceJ, std::min(1.2 * cpx, 0.05 * quadEdge), std::min(2.8 * cpx, 0.12 * quadEdge), &centre,
                  3 * radius);
        SaveScene(s, cam, o.renderDir, "closeup");
    }
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
    qf.q = vcg_ext::QuadQuality::Measure(pm);
    std::vector<double> jac = QuadJacobians(pm);
    if (!o.jacobians.empty()) WriteJacobians(o.jacobians, jac);
    std::sort(jac.begin(), jac.end());
    qf.jacobianP5 = Percentile(jac, 0.05);
    qf.vertices = long(pm.points.size());
    qf.topo = MeasureTopology(quads);
    qf.inputGenus = in.topo.Valid() ? in.topo.Genus() : -1;
    qf.objCheck = CheckObj(o.quadsObj, qf.q);

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

    if (!o.renderDir.empty()) RenderScenes(o, quads);
    return 0;
}
