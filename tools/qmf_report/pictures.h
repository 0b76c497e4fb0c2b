// The demo's picture scenes: regions, front curves, quads and a close-up, each a PLY with colours
// per face and the f3d options that frame it (render_scene.h), from the files of steps 1, 2 and 4.
#ifndef QMF_REPORT_PICTURES_H
#define QMF_REPORT_PICTURES_H

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <vcg_ext/quad_quality.h>
#include <vcg_ext/common/region_ids.h>

#include "render_scene.h"
#include "report_mesh.h"

namespace qmf_report {

const Colour kEdge(45, 45, 50, 255), kFront(205, 25, 30, 255), kQuad(246, 246, 240, 255), kBadQuad(250, 205, 50, 255),
    kTriangle(245, 130, 30, 255), kJagged(70, 100, 170, 255), kRegionLine(40, 40, 40, 255);

inline Colour Pale(Colour c, double keep)
{
    return Colour((unsigned char)(255 - keep * (255 - c[0])), (unsigned char)(255 - keep * (255 - c[1])),
                  (unsigned char)(255 - keep * (255 - c[2])), 255);
}

inline double MeanEdge(const RMesh &m, bool skipFaux)
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
inline void ForEachEdge(const RMesh &m, Pred keep, Emit emit)
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

inline std::string SaveScene(const Scene &s, const Camera &cam, const std::string &dir, const std::string &name)
{
    std::string err = s.Save(dir + "/" + name + ".ply");
    return err.empty() ? WriteF3dArgs(dir + "/" + name + ".args", cam) : err;
}

// Möller-Trumbore: does the ray o + t d (t > 0) hit triangle abc?
inline bool RayHits(const P3d &o, const P3d &d, const P3d &a, const P3d &b, const P3d &c)
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
inline Camera CloseUpCamera(const RMesh &m, double radius, int w, int h, P3d &centre)
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
inline std::vector<Colour> RegionPalette(const RMesh &m, const std::vector<int> &region, int regions)
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

inline void QuadScene(Scene &s, const RMesh &q, const std::vector<std::array<P3d, 3>> &normals, const std::vector<double> &faceJacobian,
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

struct PictureOptions {
    std::string regions, front, dir;  // step 1's and step 2's files, the folder for the scenes
    int width = 1200, height = 900;   // of the final pictures
    int supersample = 2;              // the overall quads picture (dense edges, often thinner than a pixel)
                                      // is framed this many times larger, to be scaled down
    bool fixedView = false;
    double azimuth = 0, elevation = 0;
};

// Writes <dir>/{regions,front,quads,closeup}.{ply,args}: the scene and its f3d options. `quads`:
// the output in MeshLab's polygonal form with FF adjacency. Empty string, or what went wrong.
inline std::string RenderScenes(const PictureOptions &o, RMesh &quads)
{
    RMesh regions, front;
    std::string err = Load(regions, o.regions);
    if (err.empty()) err = Load(front, o.front);
    if (!err.empty()) return err;
    vcg::tri::UpdateTopology<RMesh>::FaceFace(regions);
    // region ids (face quality of step 1) as indices 0..K-1
    std::vector<int> ids;
    std::string bad = vcg_ext::RegionIds<RMesh>::Read(regions, ids);
    if (!bad.empty()) return o.regions + ": " + bad;
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
    const Camera overall = OverallCamera(regions, ids, regionCount, o.width, o.height, o.fixedView ? &viewDir : nullptr);
    const double px = overall.PixelSize();  // one pixel of the final pictures
    Camera overallLarge = overall;          // the same view, more pixels
    overallLarge.width *= o.supersample;
    overallLarge.height *= o.supersample;
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
        if (!(err = SaveScene(s, overall, o.dir, "regions")).empty()) return err;
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
        if (!(err = SaveScene(s, overall, o.dir, "front")).empty()) return err;
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
        if (!(err = SaveScene(s, overallLarge, o.dir, "quads")).empty()) return err;
    }
    // 4. close-up: about a dozen rows of quads across the picture's height
    {
        P3d centre;
        const double radius = 6 * quadEdge;
        Camera cam = CloseUpCamera(quads, radius, o.width, o.height, centre);
        const double cpx = cam.PixelSize();
        Scene s;
        QuadScene(s, quads, quadNormals, faceJ, std::min(1.2 * cpx, 0.05 * quadEdge), std::min(2.8 * cpx, 0.12 * quadEdge), &centre,
                  3 * radius);
        if (!(err = SaveScene(s, cam, o.dir, "closeup")).empty()) return err;
    }
    return "";
}

}  // namespace qmf_report

#endif
