// Paths on a triangle mesh for the geodesic straightening: points at a mesh vertex or inside a mesh
// edge (of MeshEdgeTopology), consecutive points sharing a face, and their geometry: positions,
// shared faces, lengths, turning angles, the unfolding of the two faces of an edge and the polar
// position of a point in the unfolded fan of a vertex.
#ifndef VCG_EXT_BOUNDARY_SURFACE_PATH_H
#define VCG_EXT_BOUNDARY_SURFACE_PATH_H

#include <algorithm>
#include <cmath>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/boundary/region_boundary.h>

namespace vcg_ext {

// A point on the surface: at a mesh vertex, or inside a mesh edge.
struct SurfacePoint {
    int vertex = -1;  // >= 0: the point is this vertex
    int edge = -1;    // else: inside this edge (MeshEdgeTopology id) ...
    double t = 0;     // ... at this parameter, 0 at edgeVerts[edge][0], 1 at edgeVerts[edge][1]

    static SurfacePoint AtVertex(int v) { SurfacePoint p; p.vertex = v; return p; }
    static SurfacePoint OnEdge(int e, double t) { SurfacePoint p; p.edge = e; p.t = t; return p; }
    bool IsVertex() const { return vertex >= 0; }
    bool operator==(const SurfacePoint &o) const
    {
        return IsVertex() ? o.vertex == vertex : (!o.IsVertex() && o.edge == edge && o.t == t);
    }
    bool operator!=(const SurfacePoint &o) const { return !(*this == o); }
};

struct SurfacePath {
    std::vector<SurfacePoint> points;
    std::vector<char> fixed;  // per point: never moves (corners, anchors of loops)
    bool closed = false;      // the last point joins the first one
};

template <class MeshType>
class SurfacePathGeometry
{
public:
    typedef MeshEdgeTopology<MeshType> Topology;
    typedef typename Topology::Fan Fan;
    typedef vcg::Point3<double> Vec;
    typedef vcg::Point2<double> Vec2;

    static Vec Position(const Topology &t, const SurfacePoint &p)
    {
        if (p.IsVertex()) return t.Position(p.vertex);
        return t.Position(t.edgeVerts[p.edge][0]) * (1 - p.t) + t.Position(t.edgeVerts[p.edge][1]) * p.t;
    }

    static bool InFace(const Topology &t, const SurfacePoint &p, int f)
    {
        return p.IsVertex() ? t.FaceHasVertex(f, p.vertex) : t.SideOf(f, p.edge) >= 0;
    }

    // Faces whose closure holds both points (at most `cap` written, the count is returned up to cap).
    static int SharedFaces(const Topology &t, const SurfacePoint &a, const SurfacePoint &b, int *out, int cap)
    {
        int n = 0;
        if (a.IsVertex()) {
            for (const int *it = t.FacesBegin(a.vertex); it != t.FacesEnd(a.vertex) && n < cap; ++it)
                if (InFace(t, b, *it)) out[n++] = *it;
        } else {
            int faces[2];
            int k = t.EdgeFaces(a.edge, faces);
            for (int i = 0; i < k && n < cap; ++i)
                if (InFace(t, b, faces[i])) out[n++] = faces[i];
        }
        return n;
    }
    static bool ShareFace(const Topology &t, const SurfacePoint &a, const SurfacePoint &b)
    {
        int f;
        return SharedFaces(t, a, b, &f, 1) > 0;
    }
    static bool ShareFace(const Topology &t, const SurfacePoint &a, const SurfacePoint &b, const SurfacePoint &c)
    {
        int faces[3];
        int n = SharedFaces(t, a, b, faces, 3);
        for (int i = 0; i < n; ++i)
            if (InFace(t, c, faces[i])) return true;
        return false;
    }

    // The parameter of p on edge e (vertex ends: 0 or 1); false when p is not on the closed edge.
    static bool ParamOnEdge(const Topology &t, const SurfacePoint &p, int e, double &param)
    {
        if (!p.IsVertex()) { param = p.t; return p.edge == e; }
        if (p.vertex == t.edgeVerts[e][0]) { param = 0; return true; }
        if (p.vertex == t.edgeVerts[e][1]) { param = 1; return true; }
        return false;
    }
    // The mesh edge whose closure holds both (distinct) points, with their parameters on it.
    static bool CommonEdge(const Topology &t, const SurfacePoint &a, const SurfacePoint &b, int &e, double &ta, double &tb)
    {
        if (!a.IsVertex()) e = a.edge;
        else if (!b.IsVertex()) e = b.edge;
        else e = a.vertex == b.vertex ? -1 : t.EdgeBetween(a.vertex, b.vertex);
        return e >= 0 && ParamOnEdge(t, a, e, ta) && ParamOnEdge(t, b, e, tb);
    }

    // Length of a path (segments are straight inside faces).
    static double Length(const Topology &t, const SurfacePath &path)
    {
        double len = 0;
        const size_t n = path.points.size();
        for (size_t i = 0; i + 1 < n; ++i) len += (Position(t, path.points[i + 1]) - Position(t, path.points[i])).Norm();
        if (path.closed && n > 1) len += (Position(t, path.points[0]) - Position(t, path.points[n - 1])).Norm();
        return len;
    }

    // Sum over the interior points of the absolute geodesic turning angle (radians): at an edge
    // point, the angle between the incoming and outgoing directions with the two faces unfolded;
    // at an interior vertex with angle sum theta split into sides theta_1 + theta_2, the
    // discrete geodesic curvature |theta_1 - theta_2| / 2 (0 for a straight path through a flat
    // vertex, pi/2 for a right-angle turn). Divided by the length this is the jaggedness.
    static double TotalTurning(const Topology &t, const SurfacePath &path)
    {
        const int n = int(path.points.size());
        double sum = 0;
        Fan fan;
        for (int i = 0; i < n; ++i) {
            if (!path.closed && (i == 0 || i == n - 1)) continue;
            if (n < 3) continue;
            sum += Turning(t, path.points[(i + n - 1) % n], path.points[i], path.points[(i + 1) % n], fan);
        }
        return sum;
    }

    static double Turning(const Topology &t, const SurfacePoint &P, const SurfacePoint &X, const SurfacePoint &N)
    {
        Fan fan;
        return Turning(t, P, X, N, fan);
    }
    static double Turning(const Topology &t, const SurfacePoint &P, const SurfacePoint &X, const SurfacePoint &N, Fan &fan)
    {
        if (!X.IsVertex() && !ShareFace(t, P, X, N)) {
            Vec2 p2, n2;
            double len;
            if (UnfoldAcrossEdge(t, X.edge, P, N, p2, n2, len)) {
                Vec2 x2(X.t * len, 0);
                return Angle2(x2 - p2, n2 - x2);
            }
        } else if (X.IsVertex()) {
            double aP, rP, aN, rN;
            if (t.VertexFan(X.vertex, fan) && fan.closed && PolarInFan(t, fan, X.vertex, P, aP, rP) &&
                PolarInFan(t, fan, X.vertex, N, aN, rN)) {
                double d = Wrap(aN - aP, fan.total);
                return std::fabs(2 * d - fan.total) / 2;
            }
        }
        Vec a = Position(t, X) - Position(t, P), b = Position(t, N) - Position(t, X);
        if (a.SquaredNorm() == 0 || b.SquaredNorm() == 0) return 0;
        return Topology::Angle(a, b);
    }

    // Unfolds the two faces of edge e into the plane (edge end 0 at the origin, end 1 at (len, 0)):
    // P (in one face, not on e) above the axis, N (in the other face) below. False when P and N
    // are not in different faces of e or a face is degenerate.
    static bool UnfoldAcrossEdge(const Topology &t, int e, const SurfacePoint &P, const SurfacePoint &N, Vec2 &p2, Vec2 &n2,
                                 double &len)
    {
        int faces[2];
        if (t.EdgeFaces(e, faces) != 2) return false;
        bool across = false;  // P in one face, N in the other
        for (int i = 0; i < 2; ++i) across = across || (InFace(t, P, faces[i]) && InFace(t, N, faces[1 - i]));
        if (!across) return false;
        const Vec A = t.Position(t.edgeVerts[e][0]), B = t.Position(t.edgeVerts[e][1]);
        len = (B - A).Norm();
        if (!(len > 0)) return false;
        const Vec u = (B - A) / len;
        auto flat = [&](int w, double sign) {
            Vec d = t.Position(w) - A;
            return Vec2(d * u, sign * (d ^ u).Norm());
        };
        auto flatPoint = [&](const SurfacePoint &q, double sign) {
            if (q.IsVertex()) return flat(q.vertex, sign);
            return flat(t.edgeVerts[q.edge][0], sign) * (1 - q.t) + flat(t.edgeVerts[q.edge][1], sign) * q.t;
        };
        p2 = flatPoint(P, 1);
        n2 = flatPoint(N, -1);
        const double eps = 1e-12 * len;
        return p2[1] > eps && n2[1] < -eps;
    }

    // Polar coordinates of q around v in the unfolded fan (angle measured from spoke 0).
    static bool PolarInFan(const Topology &t, const Fan &fan, int v, const SurfacePoint &q, double &angle, double &radius)
    {
        const Vec V = t.Position(v), Q = Position(t, q);
        radius = (Q - V).Norm();
        if (q.IsVertex()) {
            for (int j = 0; j < fan.Spokes(); ++j)
                if (fan.ring[j] == q.vertex) { angle = fan.SpokeAngle(j); return true; }
            return false;
        }
        for (int j = 0; j < fan.Spokes(); ++j)
            if (fan.spokeEdge[j] == q.edge) { angle = fan.SpokeAngle(j); return true; }
        for (size_t j = 0; j < fan.faces.size(); ++j) {
            if (t.SideOf(fan.faces[j], q.edge) < 0) continue;
            double a = Topology::Angle(t.Position(fan.ring[j]) - V, Q - V);
            angle = fan.start[j] + std::min(std::max(a, 0.0), fan.angle[j]);
            return true;
        }
        return false;
    }

    static double Wrap(double a, double period)
    {
        a = std::fmod(a, period);
        return a < 0 ? a + period : a;
    }
    static double Angle2(const Vec2 &a, const Vec2 &b)
    {
        if (a.SquaredNorm() == 0 || b.SquaredNorm() == 0) return 0;
        return std::atan2(std::fabs(a[0] * b[1] - a[1] * b[0]), a * b);
    }
    static double Cross2(const Vec2 &a, const Vec2 &b) { return a[0] * b[1] - a[1] * b[0]; }
};

}  // namespace vcg_ext

#endif
