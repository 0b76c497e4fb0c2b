// The geometry of one polygon (3 or 4 corners, counter-clockwise), one implementation for every
// module: its vector area (normal times area, right for non-planar quads too), the side of an
// equilateral tiling, the angle between two vectors, a triangle's smallest angle, the scaled
// Jacobian of a quad, and the closest point of a triangle.
#ifndef VCG_EXT_COMMON_POLYGON_GEOMETRY_H
#define VCG_EXT_COMMON_POLYGON_GEOMETRY_H

#include <algorithm>
#include <cmath>

#include <vcg/space/point3.h>

namespace vcg_ext {

typedef vcg::Point3<double> Vec3d;

// Vector area of the polygon p[0..n-1]: half the sum of the fan's cross products from p[0]
// (Newell's vector area; relative to a corner, so rounding does not grow with the distance from
// the origin). Its direction is the polygon's normal, its length the area of a planar polygon.
inline Vec3d VectorArea(const Vec3d *p, int n)
{
    Vec3d a(0, 0, 0);
    for (int k = 1; k + 1 < n; ++k) a += (p[k] - p[0]) ^ (p[k + 1] - p[0]);
    return a * 0.5;
}

// Area of the equilateral triangle of unit side (sqrt(3) / 4).
constexpr double kEquilateralArea = 0.43301270189221932;

// The side of `triangles` equilateral triangles that tile `area`: a mesh's resolution whatever the
// shapes of its triangles.
inline double EquilateralSide(double area, double triangles) { return std::sqrt(area / (kEquilateralArea * triangles)); }

// Angle between two vectors in [0, pi]; 0 when one of them is zero.
inline double AngleBetween(const Vec3d &u, const Vec3d &v)
{
    const double nu = u.Norm(), nv = v.Norm();
    if (!(nu > 0 && nv > 0)) return 0;
    const double c = (u * v) / (nu * nv);
    return std::acos(std::max(-1.0, std::min(1.0, c)));
}

// Smallest corner angle (radians) of the triangle a b c.
inline double TriangleMinAngle(const Vec3d &a, const Vec3d &b, const Vec3d &c)
{
    return std::min({AngleBetween(b - a, c - a), AngleBetween(a - b, c - b), AngleBetween(a - c, b - c)});
}

// Scaled Jacobian of corner k of the quad q[0..3] against the unit normal n: ((e1 x e2) . n) /
// (|e1| |e2|), e1 and e2 the corner's two sides; <= 0 for a reflex, folded or (against n) flipped
// corner, -1 when a side has zero length (`degenerate`, optional, then set).
inline double CornerJacobian(const Vec3d *q, int k, const Vec3d &n, bool *degenerate = nullptr)
{
    const Vec3d e1 = q[(k + 1) % 4] - q[k], e2 = q[(k + 3) % 4] - q[k];
    const double d = e1.Norm() * e2.Norm();
    if (degenerate) *degenerate = !(d > 0);
    return d > 0 ? ((e1 ^ e2) * n) / d : -1.0;
}

// Scaled Jacobian of the quad q[0..3] against the unit normal n: the least of its corners'
// (CornerJacobian); 1 for a square.
inline double ScaledJacobian(const Vec3d *q, const Vec3d &n)
{
    double worst = 1;
    for (int k = 0; k < 4; ++k) worst = std::min(worst, CornerJacobian(q, k, n));
    return worst;
}

// Scaled Jacobian against the quad's own normal (its vector area); -1 for a zero-area quad.
inline double ScaledJacobian(const Vec3d *q)
{
    const Vec3d a = VectorArea(q, 4);
    const double l = a.Norm();
    return l > 0 ? ScaledJacobian(q, a / l) : -1.0;
}

// A quad is folded when its two triangles meet at more than this angle (between their normals)
// whichever diagonal splits it: no flat writing of it follows the surface.
constexpr double kFoldAngleDeg = 60;

inline bool IsFolded(const Vec3d *q)
{
    const double limit = std::cos(kFoldAngleDeg * M_PI / 180);
    auto bent = [&](int i) {  // the split along the diagonal q[i] - q[i+2]
        const Vec3d a = (q[(i + 1) % 4] - q[i]) ^ (q[(i + 2) % 4] - q[i]), b = (q[(i + 2) % 4] - q[i]) ^ (q[(i + 3) % 4] - q[i]);
        const double la = a.Norm(), lb = b.Norm();
        return la > 0 && lb > 0 && (a * b) < limit * la * lb;
    };
    return bent(0) && bent(1);
}

// Which feature of a triangle (a, b, c) a closest point lies on.
enum TriangleFeature { OnVertexA, OnVertexB, OnVertexC, OnEdgeAB, OnEdgeBC, OnEdgeCA, InsideTriangle };

// Closest point of triangle (a, b, c) to p and the feature it lies on (Ericson, Real-Time
// Collision Detection, 5.1.5: Voronoi regions of the vertices, then the edges, then the face).
inline Vec3d ClosestPointOnTriangle(const Vec3d &p, const Vec3d &a, const Vec3d &b, const Vec3d &c,
                                    TriangleFeature *feature = nullptr)
{
    TriangleFeature dummy;
    TriangleFeature &on = feature ? *feature : dummy;
    const Vec3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab * ap, d2 = ac * ap;
    if (d1 <= 0 && d2 <= 0) { on = OnVertexA; return a; }
    const Vec3d bp = p - b;
    const double d3 = ab * bp, d4 = ac * bp;
    if (d3 >= 0 && d4 <= d3) { on = OnVertexB; return b; }
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) { on = OnEdgeAB; return a + ab * (d1 / (d1 - d3)); }
    const Vec3d cp = p - c;
    const double d5 = ab * cp, d6 = ac * cp;
    if (d6 >= 0 && d5 <= d6) { on = OnVertexC; return c; }
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) { on = OnEdgeCA; return a + ac * (d2 / (d2 - d6)); }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) { on = OnEdgeBC; return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))); }
    const double denom = 1.0 / (va + vb + vc);
    on = InsideTriangle;
    return a + ab * (vb * denom) + ac * (vc * denom);
}

inline double PointTriangleDistance(const Vec3d &p, const Vec3d &a, const Vec3d &b, const Vec3d &c)
{
    return (ClosestPointOnTriangle(p, a, b, c) - p).Norm();
}

}  // namespace vcg_ext

#endif
