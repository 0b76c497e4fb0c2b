// Projection of points onto a fixed triangle surface (the input surface of one patch) by walking
// over its triangles from a "home" triangle each tracked point remembers. Smoothing moves nodes a
// little at a time, so the walk is a few steps: O(1) per query, no spatial index.
#ifndef VCG_EXT_QMORPH_SURFACE_PROJECTOR_H
#define VCG_EXT_QMORPH_SURFACE_PROJECTOR_H

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <vcg/space/point3.h>

#include <vcg_ext/common/edge_pairing.h>
#include <vcg_ext/common/polygon_geometry.h>

namespace vcg_ext {

class SurfaceProjector
{
public:
    typedef vcg::Point3<double> P3;

    void Build(const std::vector<P3> &points, const std::vector<std::array<int, 3>> &tris)
    {
        pts = points;
        tri = tris;
        normal.resize(tri.size());
        for (size_t t = 0; t < tri.size(); ++t) {
            const P3 n = (pts[tri[t][1]] - pts[tri[t][0]]) ^ (pts[tri[t][2]] - pts[tri[t][0]]);
            const double l = n.Norm();
            normal[t] = l > 0 ? n / l : P3(0, 0, 0);
        }
        nb.assign(tri.size(), {-1, -1, -1});
        const std::vector<int> twin = EdgePairing::Twins(tri);
        for (size_t h = 0; h < twin.size(); ++h)
            if (twin[h] >= 0) nb[h / 3][h % 3] = twin[h] / 3;
    }

    // Unit normal of triangle t (zero for a degenerate one or no triangle): the input surface's
    // orientation, the reference every flip test of the working mesh is made against.
    P3 Normal(int t) const { return t >= 0 && t < int(normal.size()) ? normal[t] : P3(0, 0, 0); }
    // Unit normal of the surface at `point`: of the triangle nearest it found by walking from each
    // of `homes` (one walk can stop short on a strongly curved surface); (0, 0, 0) when none is valid.
    P3 NormalAt(const P3 &point, const int *homes, int count, double *distance = nullptr) const
    {
        double best = -1;
        int bestT = -1;
        for (int i = 0; i < count; ++i) {
            int t = homes[i];
            if (t < 0 || t >= TriangleCount()) continue;
            const double d = (Project(point, t) - point).SquaredNorm();
            if (bestT < 0 || d < best) { best = d; bestT = t; }
            if (i == 0 && FacesAllHomes(t, homes, count)) break;  // no bend in between: one walk is enough
        }
        if (distance) *distance = bestT < 0 ? -1 : std::sqrt(best);
        return Normal(bestT);
    }
    int TriangleCount() const { return int(tri.size()); }
    // Triangle t faces the same way (within 90 degrees) as every one of `homes`.
    bool FacesAllHomes(int t, const int *homes, int count) const
    {
        for (int i = 0; i < count; ++i)
            if (Normal(t) * Normal(homes[i]) <= 0) return false;
        return true;
    }

    // Closest point to p found by walking from `home` (updated to the triangle of the result).
    P3 Project(const P3 &p, int &home) const
    {
        if (tri.empty()) return p;
        if (home < 0 || home >= int(tri.size())) home = 0;
        int t = home, prev = -1;
        P3 best = p;
        double bestD = -1;
        for (int step = 0; step < 64; ++step) {
            int exitEdge = -1;
            P3 q = ClosestOnTriangle(p, t, exitEdge);
            double d = (q - p).SquaredNorm();
            if (bestD < 0 || d < bestD) { bestD = d; best = q; home = t; }
            if (exitEdge < 0) break;            // inside: the local closest point
            int next = nb[t][exitEdge];
            if (next < 0 || next == prev) break;  // surface boundary, or walking back and forth
            prev = t;
            t = next;
        }
        return best;
    }

    // Closest point on triangle t; exitEdge = the edge (k: v[k]->v[k+1]) to walk across when the
    // closest point is on the triangle's border and p lies outside that edge (the most violated
    // one), else -1.
    P3 ClosestOnTriangle(const P3 &p, int t, int &exitEdge) const
    {
        const P3 &a = pts[tri[t][0]], &b = pts[tri[t][1]], &c = pts[tri[t][2]];
        exitEdge = -1;
        TriangleFeature on;
        const P3 q = ClosestPointOnTriangle(p, a, b, c, &on);
        if (on == InsideTriangle) return q;
        const P3 n = (b - a) ^ (c - a);
        const P3 *v[3] = {&a, &b, &c};
        double worst = 0;
        for (int k = 0; k < 3; ++k) {
            const double s = ((*v[(k + 1) % 3] - *v[k]) ^ (p - *v[k])) * n;
            if (s < worst) { worst = s; exitEdge = k; }
        }
        return q;
    }

private:
    std::vector<P3> pts;
    std::vector<std::array<int, 3>> tri;
    std::vector<std::array<int, 3>> nb;
    std::vector<P3> normal;
};

}  // namespace vcg_ext

#endif
