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

    // What the test reads of a face before its exact distance: its first corner and its normal
    // (b - a) x (c - a), unnormalised, with that normal's length, in double. Kept per face by a
    // caller that tests the same faces again and again (InputSurface): the same numbers, so the
    // same answers, without reading the other two corners of the many faces the plane rejects.
    struct Plane {
        Vec3d n;
        double len;
        CoordType a;
    };
    static Plane PlaneOf(const FaceType &f)
    {
        const Vec3d a = Vec3d::Construct(f.cP(0));
        const Vec3d n = (Vec3d::Construct(f.cP(1)) - a) ^ (Vec3d::Construct(f.cP(2)) - a);
        return {n, n.Norm(), f.cP(0)};
    }

    // As vcglib's functors: true (with `minDist` and `closest` updated) when f is nearer than
    // minDist.
    bool operator()(const FaceType &f, const CoordType &p, ScalarType &minDist, CoordType &closest) const
    {
        return Nearer(f, PlaneOf(f), p, minDist, closest);
    }

    // The same with f's plane given. The distance to the plane bounds the distance from below: most
    // faces stop there.
    static bool Nearer(const FaceType &f, const Plane &plane, const CoordType &p, ScalarType &minDist, CoordType &closest)
    {
        const Vec3d q = Vec3d::Construct(p), a = Vec3d::Construct(plane.a);
        if (plane.len > 0 && std::abs((q - a) * plane.n) > double(minDist) * plane.len) return false;
        const Vec3d at = ClosestPointOnTriangle(q, a, Vec3d::Construct(f.cP(1)), Vec3d::Construct(f.cP(2)));
        const double d = (at - q).Norm();
        if (!(d < double(minDist))) return false;
        minDist = ScalarType(d);
        closest = CoordType::Construct(at);
        return true;
    }
};

}  // namespace vcg_ext

#endif
