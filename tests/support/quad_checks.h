// Checks of a quad-dominant result against its input, computed independently of the Q-Morph code:
// selected edges as position pairs (front nodes never move, so positions match bit for bit),
// Euler characteristic of the polygon mesh, enclosed volume, and a sampled two-sided Hausdorff
// distance (vertices, edge midpoints and face centroids of one surface to the other).
#ifndef QMF_TESTS_QUAD_CHECKS_H
#define QMF_TESTS_QUAD_CHECKS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

#include <vcg/complex/algorithms/closest.h>
#include <vcg/space/index/grid_static_ptr.h>

#include "test_mesh.h"
#include <vcg_ext/quad_quality.h>

namespace qmf_test {

typedef std::array<float, 6> PosEdge;  // endpoints' coordinates, smaller endpoint first

inline PosEdge MakePosEdge(const P3 &a, const P3 &b)
{
    std::array<float, 3> x{a[0], a[1], a[2]}, y{b[0], b[1], b[2]};
    if (y < x) std::swap(x, y);
    return {x[0], x[1], x[2], y[0], y[1], y[2]};
}

inline std::set<PosEdge> SelectedEdges(const TMesh &m)
{
    std::set<PosEdge> s;
    for (auto &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k)
                if (f.IsFaceEdgeS(k)) s.insert(MakePosEdge(f.cP(k), f.cP((k + 1) % 3)));
    return s;
}

inline std::set<PosEdge> AllEdges(const TMesh &m)
{
    std::set<PosEdge> s;
    for (auto &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k) s.insert(MakePosEdge(f.cP(k), f.cP((k + 1) % 3)));
    return s;
}

// V - E + F of the polygon mesh.
inline int EulerCharacteristic(const vcg_ext::PolygonMesh &pm)
{
    std::set<std::pair<int, int>> edges;
    std::set<int> verts;
    for (auto &f : pm.faces)
        for (size_t k = 0; k < f.size(); ++k) {
            int a = f[k], b = f[(k + 1) % f.size()];
            edges.insert({std::min(a, b), std::max(a, b)});
            verts.insert(a);
        }
    return int(verts.size()) - int(edges.size()) + int(pm.faces.size());
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

// Largest distance from the sample points of `from` to the surface of `to`.
inline double OneSidedDistance(TMesh &from, TMesh &to)
{
    typedef vcg::GridStaticPtr<TFace, float> Grid;
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(to);
    vcg::tri::UpdateBounding<TMesh>::Box(to);
    Grid grid;
    grid.Set(to.face.begin(), to.face.end());
    std::vector<P3> samples;
    for (auto &v : from.vert)
        if (!v.IsD()) samples.push_back(v.P());
    for (auto &f : from.face)
        if (!f.IsD()) {
            samples.push_back((f.P(0) + f.P(1) + f.P(2)) / 3.f);
            for (int k = 0; k < 3; ++k) samples.push_back((f.P(k) + f.P((k + 1) % 3)) / 2.f);
        }
    double worst = 0;
    const float maxDist = to.bbox.Diag();
    for (const P3 &s : samples) {
        float dist = maxDist;
        P3 closest;
        vcg::tri::GetClosestFaceBase(to, grid, s, maxDist, dist, closest);
        worst = std::max(worst, double(dist));
    }
    return worst;
}

inline double Hausdorff(TMesh &a, TMesh &b) { return std::max(OneSidedDistance(a, b), OneSidedDistance(b, a)); }

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
