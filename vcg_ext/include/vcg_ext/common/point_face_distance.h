// The exact distance from a point to a triangle face, as a functor for vcglib's spatial indices
// (in place of vcg::face::PointDistanceBaseFunctor).
//
// vcglib 2020.09's PointDistanceBase, once the point's projection falls outside the triangle,
// measures to the first edge whose side test fails; for an obtuse triangle whose projection is
// outside two edges that need not be the nearest one, so the distance comes out too large (on the
// man scan kept aside: 5.8e-5 instead of 3.6e-5 for a triangle of a sharp ridge, and the closest
// triangle found was the one across the ridge). Closest-point answers decide which way the input
// faces under an output face, so they must be exact: ClosestPointOnTriangle, in double.
#ifndef VCG_EXT_COMMON_POINT_FACE_DISTANCE_H
#define VCG_EXT_COMMON_POINT_FACE_DISTANCE_H

#include <cmath>

#include <vcg_ext/common/polygon_geometry.h>

namespace vcg_ext {

template <class FaceType>
struct PointFaceDistance {
    typedef typename FaceType::ScalarType ScalarType;
    typedef typename FaceType::CoordType CoordType;
    typedef CoordType QueryType;
    static const CoordType &Pos(const CoordType &q) { return q; }

    // As vcglib's functors: true (with `minDist` and `closest` updated) when f is nearer than
    // minDist.
    bool operator()(const FaceType &f, const CoordType &p, ScalarType &minDist, CoordType &closest) const
    {
        const CoordType corners[3] = {f.cP(0), f.cP(1), f.cP(2)};
        return Nearer(corners, p, minDist, closest);
    }

    // The same for the triangle of the three corners given (a caller keeping them itself:
    // TriangleGrid). The distance to the plane bounds the distance from below: most triangles stop
    // there.
    static bool Nearer(const CoordType *corner, const CoordType &p, ScalarType &minDist, CoordType &closest)
    {
        const Vec3d q = Vec3d::Construct(p), a = Vec3d::Construct(corner[0]), b = Vec3d::Construct(corner[1]),
                    c = Vec3d::Construct(corner[2]);
        const Vec3d n = (b - a) ^ (c - a);
        const double len = n.Norm();
        if (len > 0 && std::abs((q - a) * n) > double(minDist) * len) return false;
        const Vec3d at = ClosestPointOnTriangle(q, a, b, c);
        const double d = (at - q).Norm();
        if (!(d < double(minDist))) return false;
        minDist = ScalarType(d);
        closest = CoordType::Construct(at);
        return true;
    }
};

}  // namespace vcg_ext

#endif
