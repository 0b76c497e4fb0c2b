// Irregular, well-shaped triangulations of planar domains (disk, annulus, L-shape) for the Q-Morph
// tests: boundary samples plus jittered interior points, Bowyer-Watson Delaunay, triangles outside
// the domain dropped. Test-only code, small inputs (quadratic is fine here).
#ifndef QMF_TESTS_PLANAR_DOMAINS_H
#define QMF_TESTS_PLANAR_DOMAINS_H

#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "test_mesh.h"

namespace qmf_test {

struct P2 { double x, y; };

// Delaunay triangulation (counter-clockwise) of the points; triangles whose centroid fails
// `inside` are dropped.
inline std::vector<std::array<int, 3>> Delaunay(const std::vector<P2> &pts, const std::function<bool(P2)> &inside)
{
    // a tiny deterministic perturbation breaks the co-circular ties (points sampled on a circle)
    // that a plain Bowyer-Watson cannot handle
    std::vector<P2> p = pts;
    std::mt19937 jitter(12345);
    std::uniform_real_distribution<double> eps(-1e-9, 1e-9);
    for (P2 &q : p) { q.x += eps(jitter); q.y += eps(jitter); }
    const int n = int(p.size());
    p.push_back({-60, -60});  // super-triangle: domains lie in [-3, 3]^2
    p.push_back({60, -60});
    p.push_back({0, 60});
    struct T { int a, b, c; };
    std::vector<T> tris{{n, n + 1, n + 2}};
    auto inCircle = [&](const T &t, const P2 &d) {
        const P2 &a = p[t.a], &b = p[t.b], &c = p[t.c];
        double ax = a.x - d.x, ay = a.y - d.y, bx = b.x - d.x, by = b.y - d.y, cx = c.x - d.x, cy = c.y - d.y;
        return (ax * ax + ay * ay) * (bx * cy - cx * by) - (bx * bx + by * by) * (ax * cy - cx * ay) +
                   (cx * cx + cy * cy) * (ax * by - bx * ay) > 0;
    };
    for (int i = 0; i < n; ++i) {
        std::vector<std::array<int, 2>> edges;
        std::vector<T> keep;
        for (const T &t : tris) {
            if (inCircle(t, p[i])) {
                edges.push_back({t.a, t.b});
                edges.push_back({t.b, t.c});
                edges.push_back({t.c, t.a});
            } else keep.push_back(t);
        }
        for (size_t e = 0; e < edges.size(); ++e) {
            bool shared = false;
            for (size_t g = 0; g < edges.size() && !shared; ++g)
                shared = g != e && edges[g][0] == edges[e][1] && edges[g][1] == edges[e][0];
            if (!shared) keep.push_back({edges[e][0], edges[e][1], i});
        }
        tris.swap(keep);
    }
    std::vector<std::array<int, 3>> out;
    for (const T &t : tris) {
        if (t.a >= n || t.b >= n || t.c >= n) continue;
        P2 c{(p[t.a].x + p[t.b].x + p[t.c].x) / 3, (p[t.a].y + p[t.b].y + p[t.c].y) / 3};
        if (inside(c)) out.push_back({t.a, t.b, t.c});
    }
    return out;
}

// A planar domain mesh: `boundary` polygons (sampled), interior points on a jittered lattice of
// spacing h kept at least h/2 from the boundary samples.
inline void MakeDomain(TMesh &m, const std::vector<P2> &boundary, const std::function<bool(P2)> &inside, double h,
                       unsigned seed = 1)
{
    std::vector<P2> pts = boundary;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.25, 0.25);
    double lo = -3, hi = 3;
    for (double y = lo; y <= hi; y += h * 0.87)
        for (double x = lo + (int(std::round((y - lo) / (h * 0.87))) % 2) * h / 2; x <= hi; x += h) {
            P2 q{x + u(rng) * h, y + u(rng) * h};
            if (!inside(q)) continue;
            bool far = true;
            for (const P2 &b : boundary) far = far && (b.x - q.x) * (b.x - q.x) + (b.y - q.y) * (b.y - q.y) > 0.36 * h * h;
            if (far) pts.push_back(q);
        }
    std::vector<P3> v;
    for (const P2 &q : pts) v.push_back(P3(float(q.x), float(q.y), 0.f));
    Build(m, v, Delaunay(pts, inside));
    vcg::tri::Clean<TMesh>::RemoveUnreferencedVertex(m);
    vcg::tri::Allocator<TMesh>::CompactEveryVector(m);
}

inline std::vector<P2> Circle(double r, int n, bool clockwise = false)
{
    std::vector<P2> c;
    for (int i = 0; i < n; ++i) {
        double t = 2 * M_PI * i / n * (clockwise ? -1 : 1);
        c.push_back({r * std::cos(t), r * std::sin(t)});
    }
    return c;
}

inline void MakeDisk(TMesh &m, int boundaryEdges, double h, unsigned seed = 1)
{
    MakeDomain(m, Circle(1, boundaryEdges), [](P2 q) { return q.x * q.x + q.y * q.y < 1 - 1e-9; }, h, seed);
}

inline void MakeAnnulus(TMesh &m, int outerEdges, int innerEdges, double h, unsigned seed = 1)
{
    std::vector<P2> b = Circle(1, outerEdges), in = Circle(0.45, innerEdges);
    b.insert(b.end(), in.begin(), in.end());
    MakeDomain(m, b, [](P2 q) { double r2 = q.x * q.x + q.y * q.y; return r2 < 1 - 1e-9 && r2 > 0.45 * 0.45 + 1e-9; }, h, seed);
}

// Strip [0,4] x [0,1] with `bottomEdges` boundary edges below and `topEdges` above (3 on each
// end): fronts of very different edge lengths meet in the middle (Owen's transitions).
inline void MakeGradedStrip(TMesh &m, int bottomEdges, int topEdges, double h, unsigned seed = 1)
{
    std::vector<P2> b;
    auto side = [&](P2 a, P2 c, int n) {
        for (int i = 0; i < n; ++i) b.push_back({a.x + (c.x - a.x) * i / n, a.y + (c.y - a.y) * i / n});
    };
    side({0, 0}, {4, 0}, bottomEdges);
    side({4, 0}, {4, 1}, 3);
    side({4, 1}, {0, 1}, topEdges);
    side({0, 1}, {0, 0}, 3);
    MakeDomain(m, b, [](P2 q) { return q.x > 1e-9 && q.x < 4 - 1e-9 && q.y > 1e-9 && q.y < 1 - 1e-9; }, h, seed);
}

// L-shape [0,2]^2 minus [1,2]^2, `perUnit` boundary edges per unit length (+ `extra` points on
// the long bottom side to change the parity).
inline void MakeLShape(TMesh &m, int perUnit, double h, int extra = 0, unsigned seed = 1)
{
    std::vector<P2> b;
    auto side = [&](P2 a, P2 c, int n) {
        for (int i = 0; i < n; ++i) b.push_back({a.x + (c.x - a.x) * i / n, a.y + (c.y - a.y) * i / n});
    };
    side({0, 0}, {2, 0}, 2 * perUnit + extra);
    side({2, 0}, {2, 1}, perUnit);
    side({2, 1}, {1, 1}, perUnit);
    side({1, 1}, {1, 2}, perUnit);
    side({1, 2}, {0, 2}, perUnit);
    side({0, 2}, {0, 0}, 2 * perUnit);
    MakeDomain(m, b, [](P2 q) { return q.x > 1e-9 && q.y > 1e-9 && q.x < 2 - 1e-9 && q.y < 2 - 1e-9 && !(q.x > 1 - 1e-9 && q.y > 1 - 1e-9); }, h, seed);
}

}  // namespace qmf_test

#endif
