// Checks of a quad-dominant result against its input, computed independently of the Q-Morph code
// (tests and benchmark): selected edges as position pairs (front nodes never move, so positions
// match bit for bit) and as chains when the front was cut into pieces, Euler characteristics,
// non-manifold edges, enclosed volume, and a sampled two-sided Hausdorff distance (vertices, edge
// midpoints and face centroids of one surface to the other).
#ifndef QMF_TESTS_QUAD_CHECKS_H
#define QMF_TESTS_QUAD_CHECKS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <vcg/complex/algorithms/closest.h>
#include <vcg/space/index/grid_static_ptr.h>

#include "test_mesh.h"
#include <vcg_ext/common/edge_key.h>
#include <vcg_ext/common/point_face_distance.h>
#include <vcg_ext/quad_quality.h>

namespace qmf_test {

typedef std::array<float, 6> PosEdge;  // endpoints' coordinates, smaller endpoint first

inline PosEdge MakePosEdge(const P3 &a, const P3 &b)
{
    std::array<float, 3> x{a[0], a[1], a[2]}, y{b[0], b[1], b[2]};
    if (y < x) std::swap(x, y);
    return {x[0], x[1], x[2], y[0], y[1], y[2]};
}

// Signed volume enclosed by a closed oriented triangle mesh.
inline double Volume(const TMesh &m)
{
    double v = 0;
    for (auto &f : m.face)
        if (!f.IsD()) {
            vcg::Point3d a = vcg::Point3d::Construct(f.cP(0)), b = vcg::Point3d::Construct(f.cP(1)), c = vcg::Point3d::Construct(f.cP(2));
            v += a * (b ^ c) / 6.0;
        }
    return v;
}

// Largest distance from the samples of `from` (vertices, edge midpoints, face centroids) to the
// surface of `to` (the exact closest point on a triangle, vcg's static grid).
inline double OneSidedDistance(const TMesh &from, TMesh &to)
{
    typedef vcg::GridStaticPtr<TFace, float> Grid;
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(to);
    vcg::tri::UpdateBounding<TMesh>::Box(to);
    Grid grid;
    grid.Set(to.face.begin(), to.face.end());
    const float maxDist = to.bbox.Diag();
    vcg_ext::PointFaceDistance<TFace> exactDistance;
    vcg::tri::EmptyTMark<TMesh> noMarks;
    double worst = 0;
    auto probe = [&](const P3 &s) {
        float dist = maxDist;
        P3 closest;
        grid.GetClosest(exactDistance, noMarks, s, maxDist, dist, closest);
        worst = std::max(worst, double(dist));
    };
    for (const auto &v : from.vert)
        if (!v.IsD()) probe(v.cP());
    for (const auto &f : from.face)
        if (!f.IsD()) {
            probe((f.cP(0) + f.cP(1) + f.cP(2)) / 3.f);
            for (int k = 0; k < 3; ++k) probe((f.cP(k) + f.cP((k + 1) % 3)) / 2.f);
        }
    return worst;
}

// Faces of a polygon mesh flipped against the input surface: their vector area (Newell) points
// away from the normal of the input triangle closest to their corner centroid (vcg's static grid;
// the measure of evalquad, independent of the core's surface walk). As evalquad documents, at a
// crease sharper than 90 degrees the closest input triangle can lie on the other side: a face whose
// closest triangle is next to such a crease is counted apart (`ambiguous`), not as flipped.
// Folded quads too: their two triangles meet at more than 60 degrees whichever diagonal splits them.
struct FlipCount {
    int flipped = 0, folded = 0, ambiguous = 0;
};
inline FlipCount FlippedFaces(const vcg_ext::PolygonMesh &pm, TMesh &input)
{
    typedef vcg::GridStaticPtr<TFace, float> Grid;
    typedef vcg::Point3d D3;
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(input);
    vcg::tri::UpdateBounding<TMesh>::Box(input);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(input);
    auto besideSharpCrease = [](const TFace &f) {
        for (int k = 0; k < 3; ++k)
            if (f.cFFp(k) != &f && f.cN() * f.cFFp(k)->cN() < 0) return true;
        return false;
    };
    Grid grid;
    grid.Set(input.face.begin(), input.face.end());
    vcg_ext::PointFaceDistance<TFace> exactDistance;
    vcg::tri::EmptyTMark<TMesh> noMarks;
    FlipCount c;
    for (const auto &f : pm.faces) {
        D3 centroid(0, 0, 0), area(0, 0, 0);
        for (int v : f) centroid += pm.points[v];
        centroid /= double(f.size());
        for (size_t k = 1; k + 1 < f.size(); ++k)
            area += (pm.points[f[k]] - pm.points[f[0]]) ^ (pm.points[f[k + 1]] - pm.points[f[0]]);
        float dist = input.bbox.Diag();
        P3 closest;
        const TFace *near = grid.GetClosest(exactDistance, noMarks, P3::Construct(centroid), input.bbox.Diag(), dist, closest);
        if (near && area * D3::Construct(near->cN()) < 0) ++(besideSharpCrease(*near) ? c.ambiguous : c.flipped);
        if (f.size() == 4) {
            auto bent = [&](int i) {
                const D3 &a = pm.points[f[i]], &b = pm.points[f[(i + 1) % 4]], &d = pm.points[f[(i + 2) % 4]], &e = pm.points[f[(i + 3) % 4]];
                const D3 n1 = (b - a) ^ (d - a), n2 = (d - a) ^ (e - a);
                return n1.Norm() > 0 && n2.Norm() > 0 && n1 * n2 < std::cos(M_PI / 3) * n1.Norm() * n2.Norm();
            };
            c.folded += bent(0) && bent(1);
        }
    }
    return c;
}

inline double Hausdorff(TMesh &a, TMesh &b) { return std::max(OneSidedDistance(a, b), OneSidedDistance(b, a)); }

// V - E + F of a triangle mesh (referenced vertices only).
inline long EulerCharacteristic(const TMesh &m)
{
    std::vector<uint64_t> edges;
    std::vector<char> used(m.vert.size(), 0);
    long faces = 0;
    for (const auto &f : m.face) {
        if (f.IsD()) continue;
        ++faces;
        for (int k = 0; k < 3; ++k) {
            int a = int(vcg::tri::Index(m, f.cV(k))), b = int(vcg::tri::Index(m, f.cV((k + 1) % 3)));
            edges.push_back(vcg_ext::EdgeKey(a, b));
            used[a] = 1;
        }
    }
    std::sort(edges.begin(), edges.end());
    long e = long(std::unique(edges.begin(), edges.end()) - edges.begin());
    long v = long(std::count(used.begin(), used.end(), 1));
    return v - e + faces;
}

// V - E + F of a polygon mesh (quads counted once: their diagonal is no edge).
inline long EulerCharacteristic(const vcg_ext::PolygonMesh &pm)
{
    std::vector<uint64_t> edges;
    std::vector<char> used(pm.points.size(), 0);
    for (const auto &f : pm.faces)
        for (size_t k = 0; k < f.size(); ++k) {
            edges.push_back(vcg_ext::EdgeKey(f[k], f[(k + 1) % f.size()]));
            used[f[k]] = 1;
        }
    std::sort(edges.begin(), edges.end());
    long e = long(std::unique(edges.begin(), edges.end()) - edges.begin());
    long v = long(std::count(used.begin(), used.end(), 1));
    return v - e + long(pm.faces.size());
}

// Where the edges used by more than two faces are (up to `max`): "(x y z)-(x y z) n faces".
inline std::vector<std::string> NonManifoldEdges(const TMesh &m, size_t max)
{
    std::vector<std::pair<uint64_t, int>> he;
    for (const auto &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k)
                he.push_back({vcg_ext::EdgeKey(int(vcg::tri::Index(m, f.cV(k))), int(vcg::tri::Index(m, f.cV((k + 1) % 3)))), 0});
    std::sort(he.begin(), he.end());
    std::vector<std::string> out;
    for (size_t i = 0; i < he.size() && out.size() < max;) {
        size_t j = i;
        while (j < he.size() && he[j].first == he[i].first) ++j;
        if (j - i > 2) {
            const P3 &a = m.vert[he[i].first >> 32].cP(), &b = m.vert[he[i].first & 0xffffffffu].cP();
            char buf[200];
            std::snprintf(buf, sizeof buf, "(%g %g %g)-(%g %g %g) %d faces", a[0], a[1], a[2], b[0], b[1], b[2], int(j - i));
            out.push_back(buf);
        }
        i = j;
    }
    return out;
}

// ---------------------------------------------------------------- front as position pairs
// Sorted, unique: the selected face-edges (selectedOnly) or all edges.
inline std::vector<PosEdge> EdgesByPosition(const TMesh &m, bool selectedOnly)
{
    std::vector<PosEdge> s;
    for (const auto &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k)
                if (!selectedOnly || f.IsFaceEdgeS(k)) s.push_back(MakePosEdge(f.cP(k), f.cP((k + 1) % 3)));
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
    return s;
}

inline std::set<PosEdge> SelectedEdges(const TMesh &m)
{
    const std::vector<PosEdge> e = EdgesByPosition(m, true);
    return std::set<PosEdge>(e.begin(), e.end());
}
inline std::set<PosEdge> AllEdges(const TMesh &m)
{
    const std::vector<PosEdge> e = EdgesByPosition(m, false);
    return std::set<PosEdge>(e.begin(), e.end());
}

// Distance from points to a set of segments (PosEdge), through a hash grid of the segments'
// midpoints with the longest segment (or `reach`, if larger) as cell: linear in the sizes.
class SegmentDistance
{
public:
    typedef vcg::Point3d D3;
    SegmentDistance(const std::vector<PosEdge> &segments, double reach) : seg(segments), cell(reach)
    {
        for (const PosEdge &e : seg) cell = std::max(cell, (End(e, 1) - End(e, 0)).Norm());
        if (!(cell > 0)) cell = 1;
        for (size_t i = 0; i < seg.size(); ++i) grid[Key((End(seg[i], 0) + End(seg[i], 1)) * 0.5)].push_back(int(i));
    }
    // Distance from q to the nearest segment, if within `reach` (else a larger value).
    double operator()(const D3 &q) const
    {
        double best = std::numeric_limits<double>::max();
        const std::array<long, 3> c = Key(q);
        for (long dx = -2; dx <= 2; ++dx)
            for (long dy = -2; dy <= 2; ++dy)
                for (long dz = -2; dz <= 2; ++dz) {
                    auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
                    if (it == grid.end()) continue;
                    for (int i : it->second) {
                        const D3 p = End(seg[i], 0), d = End(seg[i], 1) - p;
                        const double t = std::max(0.0, std::min(1.0, d.SquaredNorm() > 0 ? ((q - p) * d) / d.SquaredNorm() : 0.0));
                        best = std::min(best, (p + d * t - q).Norm());
                    }
                }
        return best;
    }
    static D3 End(const PosEdge &e, int k) { return D3(e[3 * k], e[3 * k + 1], e[3 * k + 2]); }

private:
    const std::vector<PosEdge> &seg;
    double cell;
    std::map<std::array<long, 3>, std::vector<int>> grid;
    std::array<long, 3> Key(const D3 &p) const
    {
        return {long(std::floor(p[0] / cell)), long(std::floor(p[1] / cell)), long(std::floor(p[2] / cell))};
    }
};

// The front as curves, where re-meshing may coarsen a front over smooth surface into chords: every
// selected output edge has its endpoints on the input front (within `onCurve`) and its midpoint
// within `chord` of it, and every input front edge's midpoint lies within `chord` of the output
// front. Returns the edges that fail (0: every front curve is a chain of selected output edges
// along the input's).
inline long FrontCurveMismatches(const std::vector<PosEdge> &input, const std::vector<PosEdge> &output, double onCurve,
                                 double chord)
{
    const SegmentDistance toInput(input, chord), toOutput(output, chord);
    long bad = 0;
    for (const PosEdge &o : output) {
        const auto a = SegmentDistance::End(o, 0), b = SegmentDistance::End(o, 1);
        bad += toInput(a) > onCurve || toInput(b) > onCurve || toInput((a + b) * 0.5) > chord;
    }
    for (const PosEdge &e : input)
        bad += toOutput((SegmentDistance::End(e, 0) + SegmentDistance::End(e, 1)) * 0.5) > chord;
    return bad;
}

// With re-meshing the front edges are cut into pieces: the selected output edges must lie on the
// selected input edges and cover each exactly. Returns the input edges not covered exactly plus the
// output edges lying on none (0: every front curve is a chain of selected output edges). A hash
// grid over the input edges' midpoints keeps it linear.
inline long FrontChainMismatches(const std::vector<PosEdge> &input, const std::vector<PosEdge> &output)
{
    typedef vcg::Point3d D3;
    auto end = [](const PosEdge &e, int k) { return D3(e[3 * k], e[3 * k + 1], e[3 * k + 2]); };
    double cell = 0;
    for (const PosEdge &e : input) cell = std::max(cell, (end(e, 1) - end(e, 0)).Norm());
    if (input.empty() || !(cell > 0)) return long(input.size() + output.size());
    auto key = [&](const D3 &p) {
        return std::array<long, 3>{long(std::floor(p[0] / cell)), long(std::floor(p[1] / cell)), long(std::floor(p[2] / cell))};
    };
    std::map<std::array<long, 3>, std::vector<int>> grid;
    for (size_t i = 0; i < input.size(); ++i) grid[key((end(input[i], 0) + end(input[i], 1)) * 0.5)].push_back(int(i));
    std::vector<double> covered(input.size(), 0);
    long stray = 0;
    for (const PosEdge &o : output) {
        const D3 a = end(o, 0), b = end(o, 1), mid = (a + b) * 0.5;
        const std::array<long, 3> c = key(mid);
        int found = -1;
        for (long dx = -1; dx <= 1 && found < 0; ++dx)
            for (long dy = -1; dy <= 1 && found < 0; ++dy)
                for (long dz = -1; dz <= 1 && found < 0; ++dz) {
                    auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
                    if (it == grid.end()) continue;
                    for (int i : it->second) {
                        const D3 p = end(input[i], 0), d = end(input[i], 1) - p;
                        auto on = [&](const D3 &q) {
                            const double t = ((q - p) * d) / d.SquaredNorm();
                            return t > -1e-6 && t < 1 + 1e-6 && (p + d * t - q).Norm() < 1e-5 * d.Norm();
                        };
                        if (on(a) && on(b)) { found = i; break; }
                    }
                }
        if (found < 0) ++stray;
        else covered[found] += (b - a).Norm();
    }
    long uncovered = 0;
    for (size_t i = 0; i < input.size(); ++i) {
        const double len = (end(input[i], 1) - end(input[i], 0)).Norm();
        uncovered += std::fabs(covered[i] - len) > 1e-4 * len;
    }
    return uncovered + stray;
}

// Selects (both sides) the edges whose two faces' normals differ by more than `deg` degrees.
inline int SelectCreases(TMesh &m, double deg)
{
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
    int n = 0;
    for (auto &f : m.face)
        for (int k = 0; k < 3; ++k) {
            TFace *g = f.FFp(k);
            if (g != &f && vcg::Angle(f.N(), g->N()) > deg * M_PI / 180) { f.SetFaceEdgeS(k); ++n; }
        }
    return n / 2;
}

// Selects the edges between faces of different face quality (region ids).
inline int SelectRegionBoundaries(TMesh &m)
{
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    int n = 0;
    for (auto &f : m.face)
        for (int k = 0; k < 3; ++k)
            if (f.FFp(k)->Q() != f.Q()) { f.SetFaceEdgeS(k); ++n; }
    return n / 2;
}

}  // namespace qmf_test

#endif
