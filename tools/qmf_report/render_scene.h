// Scenes for the demo's pictures, rendered by f3d (one file per scene, no line widths of its own):
// one PLY per picture holding the surface and its curves as thin square tubes, coloured per face,
// plus the f3d options (camera, resolution) that frame it. Tube radii are given in pixels of the
// picture's camera, so edges stay readable whatever the mesh's size.
#ifndef QMF_REPORT_RENDER_SCENE_H
#define QMF_REPORT_RENDER_SCENE_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <wrap/io_trimesh/export_ply.h>

#include "report_mesh.h"

namespace qmf_report {

typedef vcg::Color4b Colour;

struct Camera {
    P3d position, focal, up;
    double viewAngleDeg = 30;  // vertical, f3d's default
    int width = 1200, height = 900;

    double Distance() const { return (position - focal).Norm(); }
    // World length of one pixel at the focal point.
    double PixelSize() const { return 2 * Distance() * std::tan(viewAngleDeg * M_PI / 360) / height; }
};

inline P3d Orthogonal(const P3d &d)
{
    P3d a = std::fabs(d[0]) < 0.6 ? P3d(1, 0, 0) : P3d(0, 1, 0);
    return (a ^ d).Normalize();
}

// Camera looking along -dir (dir points from the part to the camera), `up` projected to the image
// plane, framing `points` so that their bounding rectangle fills `fill` of the frame.
inline Camera FitCamera(const std::vector<P3d> &points, P3d dir, P3d up, int width, int height, double fill = 0.9)
{
    Camera cam;
    cam.width = width;
    cam.height = height;
    dir.Normalize();
    up = up - dir * (up * dir);
    if (up.Norm() < 1e-6) up = Orthogonal(dir);
    up.Normalize();
    P3d right = up ^ dir;
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const P3d &p : points) {
        x0 = std::min(x0, p * right); x1 = std::max(x1, p * right);
        y0 = std::min(y0, p * up);    y1 = std::max(y1, p * up);
    }
    double zc = 0;
    for (const P3d &p : points) zc += p * dir;
    zc = points.empty() ? 0 : zc / points.size();
    const P3d focal = right * (0.5 * (x0 + x1)) + up * (0.5 * (y0 + y1)) + dir * zc;
    const double tv = std::tan(cam.viewAngleDeg * M_PI / 360) * fill, th = tv * width / height;
    double dist = 0;
    for (const P3d &p : points) {  // perspective: every point inside the frustum
        P3d q = p - focal;
        dist = std::max(dist, q * dir + std::max(std::fabs(q * right) / th, std::fabs(q * up) / tv));
    }
    if (!(dist > 0)) dist = 1;
    cam.focal = focal;
    cam.position = focal + dir * dist;
    cam.up = up;
    return cam;
}

// How well a view shows the part: the front-facing projected area of each region (the faces'
// `group`), summed as square roots so that seeing many regions counts more than one large one,
// over the frame the fitted camera sees (both at the focal plane).
inline double ViewScore(const RMesh &m, const std::vector<int> &group, int groups, const std::vector<P3d> &points,
                        const P3d &dir, const P3d &up, int w, int h)
{
    Camera cam = FitCamera(points, dir, up, w, h);
    std::vector<double> seen(std::max(1, groups), 0.0);
    for (size_t i = 0; i < m.face.size(); ++i) {
        const RFace &f = m.face[i];
        if (f.IsD()) continue;
        P3d n = (PosOf(f.cV(1)) - PosOf(f.cV(0))) ^ (PosOf(f.cV(2)) - PosOf(f.cV(0)));
        seen[group.empty() ? 0 : group[i]] += std::max(0.0, 0.5 * (n * dir));
    }
    double px = cam.PixelSize(), frame = px * px * w * h, score = 0;
    for (double a : seen) score += std::sqrt(a / frame);
    return score;
}

// Direction from the part to the camera: azimuth about +Y from +Z (f3d's default view), elevation.
inline P3d ViewDirection(double azimuthDeg, double elevationDeg)
{
    double a = azimuthDeg * M_PI / 180, e = elevationDeg * M_PI / 180;
    return P3d(std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e));
}

// The overall view: +Y up (f3d's default), looking down at 15-45 degrees from the azimuth that
// shows the regions best (`group`: region index 0..groups-1 per face, or empty); `fixed` (not
// null) sets the direction instead.
inline Camera OverallCamera(const RMesh &m, const std::vector<int> &group, int groups, int w, int h, const P3d *fixed = nullptr)
{
    std::vector<P3d> pts;
    for (const RVertex &v : m.vert)
        if (!v.IsD()) pts.push_back(PosOf(&v));
    const P3d up(0, 1, 0);
    double best = -1;
    P3d bestDir(0, 0, 1);
    if (fixed) return FitCamera(pts, *fixed, up, w, h);
    for (int el = 15; el <= 45; el += 15)
        for (int az = 0; az < 360; az += 30) {
            P3d d = ViewDirection(az, el);
            double s = ViewScore(m, group, groups, pts, d, up, w, h);
            if (s > best * 1.02) { best = s; bestDir = d; }  // a clearly better view only: stable choice
        }
    return FitCamera(pts, bestDir, up, w, h);
}

// Per face corner: the area-weighted normal of the faces around the corner's vertex that lie
// within `creaseDeg` of the face (smooth surfaces shade smooth, creases stay sharp).
inline std::vector<std::array<P3d, 3>> CornerNormals(const RMesh &m, double creaseDeg = 35)
{
    std::vector<P3d> fn(m.face.size(), P3d(0, 0, 0));  // area-weighted (twice the area)
    std::vector<std::vector<int>> vf(m.vert.size());
    for (size_t i = 0; i < m.face.size(); ++i) {
        const RFace &f = m.face[i];
        if (f.IsD()) continue;
        fn[i] = (PosOf(f.cV(1)) - PosOf(f.cV(0))) ^ (PosOf(f.cV(2)) - PosOf(f.cV(0)));
        for (int k = 0; k < 3; ++k) vf[vcg::tri::Index(m, f.cV(k))].push_back(int(i));
    }
    const double cosCrease = std::cos(creaseDeg * M_PI / 180);
    std::vector<std::array<P3d, 3>> out(m.face.size());
    for (size_t i = 0; i < m.face.size(); ++i) {
        const RFace &f = m.face[i];
        if (f.IsD()) continue;
        P3d own = fn[i];
        double l = own.Norm();
        if (l > 0) own /= l;
        for (int k = 0; k < 3; ++k) {
            P3d sum(0, 0, 0);
            for (int g : vf[vcg::tri::Index(m, f.cV(k))]) {
                double lg = fn[g].Norm();
                if (lg > 0 && (fn[g] / lg) * own >= cosCrease) sum += fn[g];
            }
            out[i][k] = sum.Norm() > 0 ? sum / sum.Norm() : own;
        }
    }
    return out;
}

// A scene: triangles with a colour each, written as a binary PLY (face colours as RGBA).
class Scene
{
public:
    // A surface triangle with its corner normals (smooth shading within a crease angle).
    void AddTriangle(const P3d &a, const P3d &b, const P3d &c, const std::array<P3d, 3> &n, Colour col)
    {
        int i = int(points_.size());
        points_.push_back(a); points_.push_back(b); points_.push_back(c);
        for (int k = 0; k < 3; ++k) normals_.push_back(n[k]);
        tris_.push_back({i, i + 1, i + 2});
        colours_.push_back(col);
    }
    // A square tube of half-width r around segment a-b, lengthened by r at both ends so
    // consecutive tubes close their joints.
    void AddTube(P3d a, P3d b, double r, Colour col)
    {
        P3d t = b - a;
        double len = t.Norm();
        if (!(len > 0) || !(r > 0)) return;
        t /= len;
        a -= t * r;
        b += t * r;
        P3d u = Orthogonal(t), w = t ^ u;
        P3d ring[4] = {u * r, w * r, -u * r, -w * r};
        int base = int(points_.size());
        for (int end = 0; end < 2; ++end)
            for (int k = 0; k < 4; ++k) {  // radial normals: the tube shades round
                points_.push_back((end ? b : a) + ring[k]);
                normals_.push_back(ring[k] / r);
            }
        for (int k = 0; k < 4; ++k) {
            int a0 = base + k, a1 = base + (k + 1) % 4, b0 = a0 + 4, b1 = a1 + 4;
            tris_.push_back({a0, a1, b1}); colours_.push_back(col);
            tris_.push_back({a0, b1, b0}); colours_.push_back(col);
        }
        for (int cap = 0; cap < 2; ++cap) {
            int o = base + 4 * cap;
            tris_.push_back({o, o + 1, o + 2}); colours_.push_back(col);
            tris_.push_back({o, o + 2, o + 3}); colours_.push_back(col);
        }
    }
    size_t Triangles() const { return tris_.size(); }

    std::string Save(const std::string &path) const
    {
        RMesh m;
        if (!points_.empty()) vcg::tri::Allocator<RMesh>::AddVertices(m, points_.size());
        for (size_t i = 0; i < points_.size(); ++i) {
            m.vert[i].P() = vcg::Point3f::Construct(points_[i]);
            m.vert[i].N() = vcg::Point3f::Construct(normals_[i]);
        }
        if (!tris_.empty()) vcg::tri::Allocator<RMesh>::AddFaces(m, tris_.size());
        for (size_t i = 0; i < tris_.size(); ++i) {
            for (int k = 0; k < 3; ++k) m.face[i].V(k) = &m.vert[tris_[i][k]];
            m.face[i].C() = colours_[i];
        }
        int err = vcg::tri::io::ExporterPLY<RMesh>::Save(m, path.c_str(), vcg::tri::io::Mask::IOM_FACECOLOR | vcg::tri::io::Mask::IOM_VERTNORMAL, true);
        return err ? "cannot write " + path + ": " + vcg::tri::io::ExporterPLY<RMesh>::ErrorMsg(err) : "";
    }

private:
    std::vector<P3d> points_, normals_;
    std::vector<std::array<int, 3>> tris_;
    std::vector<Colour> colours_;
};

// f3d options for a scene: the camera, the size, colours from the face RGBA array, light background.
inline std::string WriteF3dArgs(const std::string &path, const Camera &c)
{
    FILE *out = std::fopen(path.c_str(), "w");
    if (!out) return "cannot write " + path;
    std::fprintf(out, "--resolution=%d,%d\n", c.width, c.height);
    std::fprintf(out, "--camera-position=%.9g,%.9g,%.9g\n", c.position[0], c.position[1], c.position[2]);
    std::fprintf(out, "--camera-focal-point=%.9g,%.9g,%.9g\n", c.focal[0], c.focal[1], c.focal[2]);
    std::fprintf(out, "--camera-view-up=%.9g,%.9g,%.9g\n", c.up[0], c.up[1], c.up[2]);
    std::fprintf(out, "--camera-view-angle=%g\n", c.viewAngleDeg);
    std::fprintf(out, "--scalars=RGBA\n--comp=-2\n--cells\n--bg-color=1,1,1\n--roughness=0.6\n--fxaa\n");
    return std::fclose(out) == 0 ? "" : "cannot write " + path;
}

}  // namespace qmf_report

#endif
