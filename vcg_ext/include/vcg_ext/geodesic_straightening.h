// Geodesic straightening of paths on a triangle mesh (Martinez, Velho, Carvalho, "Computing
// geodesics on triangular meshes", Computers & Graphics 29(5), 2005), as the seed paper uses it to
// smooth region boundaries, with the constraints that keep the result usable for splitting.
//
// A path is a sequence of surface points, each at a mesh vertex or inside a mesh edge, where
// consecutive points share a face (so each segment is straight inside one face). One pass visits
// every movable point p_i once, with its neighbours P = p_(i-1), N = p_(i+1):
//   - P, p_i and N share a face: p_i is redundant and is removed;
//   - p_i inside edge e: the two faces of e are unfolded into one plane and p_i moves to where
//     the segment PN crosses e (clamped to e: at an end it becomes a vertex point);
//   - p_i at vertex v: the fan of v is unfolded by polar angle; the path splits the angle sum
//     into two sides. When one side is below pi the path is shortened on that side: p_i is
//     replaced by the crossings of segment PN with the spokes (edges at v) of that side.
// A move is kept only when it shortens the path (so passes converge to a locally shortest path)
// and keeps every invariant:
//   - a mesh vertex holds at most one path point, except the fixed points (corners) where paths
//     end; two points on one edge stay at least the snap fraction of its length apart;
//   - points never change order along an edge (a move sweeps no other point);
//   - no two segments cross inside a face (in a triangle, two chords with distinct ends cross
//     exactly when their ends interleave along its boundary) or overlap along an edge.
// The region a move sweeps (between the old and the new path) lies in the faces around p_i and
// holds no mesh vertex except on the new path, so with these checks no path can jump over a
// corner or another path: the arrangement of the paths on the surface (which region lies
// between which curves) is kept.
// Snapping: while straightening, new points closer than 0.1% of their edge to an end go to that
// vertex. At the end, edge points closer than the user's snap fraction move onto the vertex (or,
// when that would break an invariant, to the snap distance on their edge), so splitting the mesh
// along the paths later makes no slivers. Snapping at every move instead pins curves at vertices
// and at the snap distance: local minima of the length far from the shortest path.
//
// Also here: RegionBoundarySmoothing, the whole of filter 2 (boundary graph + straightening).
#ifndef VCG_EXT_GEODESIC_STRAIGHTENING_H
#define VCG_EXT_GEODESIC_STRAIGHTENING_H

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/boundary/region_boundary.h>
#include <vcg_ext/common/edge_layer.h>
#include <vcg_ext/mesh_checks.h>

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
class GeodesicStraightening
{
public:
    typedef MeshEdgeTopology<MeshType> Topology;
    typedef typename Topology::Fan Fan;
    typedef vcg::Point3<double> Vec;
    typedef vcg::Point2<double> Vec2;

    struct Params {
        int iterations = 3;          // passes over every point (the paper: "a few")
        double snapFraction = 0.10;  // edge points this close to a vertex (fraction of the edge length) snap to it

        std::string Validate() const
        {
            if (iterations < 0 || iterations > kMaxIterations)
                return "iterations must be between 0 and " + std::to_string(kMaxIterations);
            if (!(snapFraction >= kMinSnapFraction && snapFraction <= 0.45))
                return "the snap distance must be between 0.1% and 45% of the edge length";
            return "";
        }
    };
    static constexpr int kMaxIterations = 1000;
    // Edge points always keep at least this fraction of their edge from its ends, so that after
    // a float / 6-decimal round trip they are still told apart from the vertices.
    static constexpr double kMinSnapFraction = 0.001;

    struct Result {
        std::string error;
        int passes = 0;          // passes run (stops early once a pass shortens the paths by < 1e-9 of their length)
        bool converged = false;  // stopped early: locally shortest within the moves and constraints
        int moves = 0;           // accepted moves (removals included)
        int removals = 0;        // redundant points removed
        int rejected = 0;        // shortening moves refused because they would break an invariant
        int snapped = 0;         // final snapping: edge points moved onto a vertex ...
        int held = 0;            // ... or, that vertex being taken, to the snap distance on their edge
        int unsnapped = 0;       // ... or left closer to a vertex than the snap distance (neither was possible)
        double seconds = 0;
    };

    // Straightens the paths in place; `cb` gets percentages from `progressFrom` to `progressTo`.
    // The paths must be valid: consecutive points share a face, no point shared by two paths
    // except fixed ones at vertices, no crossings (boundary chains of mesh edges are). The ends of
    // open paths never move; a closed path without a fixed point gets its first point fixed.
    static Result Straighten(const Topology &t, std::vector<SurfacePath> &paths, const Params &p,
                             vcg::CallBackPos *cb = nullptr, int progressFrom = 0, int progressTo = 100)
    {
        auto t0 = std::chrono::steady_clock::now();
        Result res;
        res.error = p.Validate();
        if (!res.error.empty()) return res;
        Engine engine(t, p);
        engine.Load(paths);
        for (int pass = 0; pass < p.iterations; ++pass) {
            if (cb) cb(progressFrom + (progressTo - progressFrom) * pass / std::max(1, p.iterations), "Straightening region boundaries");
            const double gain = engine.Pass(res);
            ++res.passes;
            if (!(gain > 1e-9 * engine.InitialLength())) { res.converged = true; break; }
        }
        if (p.iterations > 0) engine.SnapToVertices(res);  // 0 iterations: the paths as given
        engine.Store(paths);
        res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return res;
    }

    // ---- Geometry of surface points (static: also used by the measures and the tests) ----

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

private:
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

    // The paths as doubly linked point lists, with every point registered at its site (a vertex,
    // or an edge) so the constraints are checked locally.
    class Engine
    {
    public:
        Engine(const Topology &topology, const Params &params)
            : t(topology), snap(kMinSnapFraction), finalSnap(params.snapFraction), gap(params.snapFraction)
        {
        }

        void Load(const std::vector<SurfacePath> &paths)
        {
            siteHead.assign(size_t(t.vertexCount) + t.EdgeCount(), -1);
            heads.clear();
            nodes.clear();
            for (size_t i = 0; i < paths.size(); ++i) {
                const SurfacePath &path = paths[i];
                const int n = int(path.points.size());
                int first = -1, last = -1, anchor = -1;
                for (int k = 0; k < n; ++k) {
                    int id = NewNode(path.points[k], int(i), k < int(path.fixed.size()) && path.fixed[k]);
                    if (last >= 0) { nodes[last].next = id; nodes[id].prev = last; }
                    if (first < 0) first = id;
                    if (anchor < 0 && nodes[id].fixed) anchor = id;
                    last = id;
                }
                const bool loop = path.closed && n >= 3;
                initialLength += Length(t, path);
                if (loop) {
                    nodes[last].next = first;
                    nodes[first].prev = last;
                    if (anchor < 0) {  // a loop needs a fixed start: its first point
                        anchor = first;
                        nodes[first].fixed = true;
                    }
                    heads.push_back(anchor);
                } else {
                    if (n > 0) { nodes[first].fixed = true; nodes[last].fixed = true; }  // ends never move
                    heads.push_back(first);
                }
            }
        }

        void Store(std::vector<SurfacePath> &paths) const
        {
            for (size_t i = 0; i < paths.size(); ++i) {
                SurfacePath &path = paths[i];
                path.points.clear();
                path.fixed.clear();
                int s = heads[i];
                if (s < 0) continue;
                int n = s;
                do {
                    path.points.push_back(nodes[n].p);
                    path.fixed.push_back(nodes[n].fixed);
                    n = nodes[n].next;
                } while (n >= 0 && n != s);
            }
        }

        double InitialLength() const { return initialLength; }

        // One pass over the movable points; returns how much its shortening moves gained.
        double Pass(Result &res)
        {
            gain = 0;
            for (size_t i = 0; i < heads.size(); ++i) {
                int s = heads[i];
                if (s < 0) continue;
                int n = nodes[s].next;
                while (n >= 0 && n != s) {
                    int after = nodes[n].next;
                    if (!nodes[n].fixed && nodes[n].prev >= 0 && after >= 0) TryMove(n, res);
                    n = after;
                }
            }
            return gain;
        }

        // Edge points closer to an end than the snap distance move onto that vertex or, when that
        // would break an invariant (the vertex is taken, a crossing), to the snap distance on their
        // edge; then points made redundant are removed. Straightening runs with a tiny snap
        // distance and snaps only here: snapping while straightening pins curves at vertices and
        // at the snap distance (local minima of the length far from the shortest path).
        void SnapToVertices(Result &res)
        {
            std::vector<SurfacePoint> q;
            snap = finalSnap;
            for (size_t i = 0; i < heads.size(); ++i) {
                int s = heads[i];
                if (s < 0) continue;
                for (int n = nodes[s].next; n >= 0 && n != s;) {
                    const int after = nodes[n].next;
                    const SurfacePoint X = nodes[n].p;
                    if (!X.IsVertex() && !nodes[n].fixed && after >= 0 && (X.t < snap || X.t > 1 - snap)) {
                        // Onto the vertex; or, when a neighbour is already there, into that neighbour.
                        const SurfacePoint v = SnapOnEdge(X.edge, X.t);
                        q.assign(1, v);
                        if (nodes[nodes[n].prev].p == v || nodes[after].p == v) q.clear();
                        if (Acceptable(n, q)) {
                            Apply(n, q);
                            ++res.snapped;
                        } else {
                            // Held at the snap distance, closer to other points than the usual gap if need be.
                            q.assign(1, SnapOnEdge(X.edge, X.t, true));
                            const double usualGap = gap;
                            gap = kMinSnapFraction;
                            const bool ok = Acceptable(n, q);
                            gap = usualGap;
                            if (ok) { Apply(n, q); ++res.held; }
                            else ++res.unsnapped;
                        }
                    }
                    n = after;
                }
            }
            q.clear();
            for (size_t i = 0; i < heads.size(); ++i) {  // redundant points
                int s = heads[i];
                if (s < 0) continue;
                for (int n = nodes[s].next; n >= 0 && n != s;) {
                    const int after = nodes[n].next;
                    if (!nodes[n].fixed && after >= 0) {
                        const SurfacePoint &X = nodes[n].p, &P = nodes[nodes[n].prev].p, &N = nodes[after].p;
                        if (P != N && ShareFace(t, P, X, N) && Acceptable(n, q)) { Apply(n, q); ++res.removals; }
                    }
                    n = after;
                }
            }
        }

    private:
        struct Node {
            SurfacePoint p;
            int path = -1;
            int prev = -1, next = -1;
            int siteNext = -1;  // next node at the same site
            bool fixed = false;
        };

        const Topology &t;
        double snap;             // while straightening: new points closer than this fraction of their edge to an end snap to it
        const double finalSnap;  // at the end: the user's snap distance (fraction of the edge length)
        double gap;              // least distance of two points on one edge, as a fraction of its length
        std::vector<Node> nodes;
        std::vector<int> siteHead;  // first node per site: vertices, then edges
        std::vector<int> heads;     // per path: its first node (open) or a fixed node (closed)
        double initialLength = 0, gain = 0;
        // Scratch.
        Fan fan;
        std::vector<SurfacePoint> candidate, sequence;
        std::vector<std::pair<int, int>> chords;
        std::vector<std::pair<double, int>> crossed;  // (unfolded angle, spoke)

        int Site(const SurfacePoint &p) const { return p.IsVertex() ? p.vertex : t.vertexCount + p.edge; }

        int NewNode(const SurfacePoint &p, int path, bool fixed)
        {
            Node n;
            n.p = p;
            n.path = path;
            n.fixed = fixed;
            int id = int(nodes.size());
            nodes.push_back(n);
            int s = Site(p);
            nodes[id].siteNext = siteHead[s];
            siteHead[s] = id;
            return id;
        }

        void Unregister(int id)
        {
            int s = Site(nodes[id].p);
            if (siteHead[s] == id) { siteHead[s] = nodes[id].siteNext; return; }
            for (int n = siteHead[s]; n >= 0; n = nodes[n].siteNext)
                if (nodes[n].siteNext == id) { nodes[n].siteNext = nodes[id].siteNext; return; }
        }

        // ---- Moves ----

        void TryMove(int x, Result &res)
        {
            const SurfacePoint X = nodes[x].p, P = nodes[nodes[x].prev].p, N = nodes[nodes[x].next].p;
            if (P == N) return;
            const Vec p = Position(t, P), n = Position(t, N);
            const double before = (Position(t, X) - p).Norm() + (n - Position(t, X)).Norm();
            if (ShareFace(t, P, X, N)) {  // redundant: removing it may keep the length (collinear) but never adds
                candidate.clear();
                const double after = PathLength(p, candidate, n);
                if (after <= before * (1 + 1e-12)) {
                    if (Acceptable(x, candidate)) {
                        gain += before - after;
                        Apply(x, candidate);
                        ++res.moves;
                        ++res.removals;
                    } else {
                        ++res.rejected;
                    }
                }
                return;
            }
            candidate.clear();
            double slack = 0;
            bool ok = X.IsVertex() ? VertexMove(X.vertex, P, N, candidate) : EdgeMove(X.edge, X, P, N, candidate, slack);
            if (!ok || (candidate.size() == 1 && candidate[0] == X)) return;
            // Moves must shorten the path (passes converge), except a snap onto a vertex that the
            // straight line passes within the snap distance of: the path may then need to pass
            // over that vertex, which a point hugging it cannot do by shortening moves alone.
            const double after = PathLength(p, candidate, n);
            if (!(after < before * (1 - 1e-9)) && !(slack > 0 && after < before + slack)) return;
            if (!Acceptable(x, candidate)) { ++res.rejected; return; }
            gain += std::max(0.0, before - after);  // snaps may lengthen a little: not progress
            Apply(x, candidate);
            ++res.moves;
        }

        double PathLength(const Vec &from, const std::vector<SurfacePoint> &via, const Vec &to) const
        {
            double len = 0;
            Vec last = from;
            for (const SurfacePoint &q : via) { Vec c = Position(t, q); len += (c - last).Norm(); last = c; }
            return len + (to - last).Norm();
        }

        // A point at `param` on edge e: snapped to an end closer than the snap fraction, or, when
        // `hold`, kept on the edge at the snap distance from that end.
        SurfacePoint SnapOnEdge(int e, double param, bool hold = false) const
        {
            const double s = snap;
            if (hold) {
                const double lo = std::nextafter(s, 1.0), hi = std::nextafter(1 - s, 0.0);
                if (lo < hi) return SurfacePoint::OnEdge(e, std::min(hi, std::max(lo, param)));
            }
            if (param <= s) return SurfacePoint::AtVertex(t.edgeVerts[e][0]);
            if (param >= 1 - s) return SurfacePoint::AtVertex(t.edgeVerts[e][1]);
            return SurfacePoint::OnEdge(e, param);
        }

        // p inside edge e moves to the crossing of the unfolded segment PN with e.
        bool EdgeMove(int e, const SurfacePoint &X, const SurfacePoint &P, const SurfacePoint &N, std::vector<SurfacePoint> &out,
                      double &slack)
        {
            Vec2 p2, n2;
            double len;
            if (!UnfoldAcrossEdge(t, e, P, N, p2, n2, len)) return false;
            const double s = p2[1] / (p2[1] - n2[1]);
            const double param = (p2[0] + s * (n2[0] - p2[0])) / len;
            if (!std::isfinite(param)) return false;
            SurfacePoint q = SnapOnEdge(e, std::min(1.0, std::max(0.0, param)));
            if (!q.IsVertex() && std::fabs(q.t - X.t) < 1e-12) return false;
            if (q.IsVertex() && param > 0 && param < 1) slack = snap * len;  // snapped, not clamped
            out.push_back(q);
            return true;
        }

        // p at vertex v: when one side of the path around v has an angle sum below pi, p is
        // replaced by the crossings of the unfolded segment PN with the spokes of that side.
        bool VertexMove(int v, const SurfacePoint &P, const SurfacePoint &N, std::vector<SurfacePoint> &out)
        {
            if (!t.VertexFan(v, fan)) return false;
            double aP, rP, aN, rN;
            if (!PolarInFan(t, fan, v, P, aP, rP) || !PolarInFan(t, fan, v, N, aN, rN)) return false;
            double side, dir;
            if (fan.closed) {
                double d = Wrap(aN - aP, fan.total);
                if (d <= fan.total - d) { side = d; dir = 1; }
                else { side = fan.total - d; dir = -1; }
            } else {
                side = std::fabs(aN - aP);
                dir = aN >= aP ? 1 : -1;
            }
            if (!(side < M_PI - 1e-6) || !(side > 0)) return false;
            // Spokes strictly inside the side, by unfolded angle from P.
            crossed.clear();
            for (int j = 0; j < fan.Spokes(); ++j) {
                double b = dir * (fan.SpokeAngle(j) - aP);
                if (fan.closed) b = Wrap(b, fan.total);
                if (b > 0 && b < side) crossed.push_back({b, j});
            }
            std::sort(crossed.begin(), crossed.end());
            const Vec2 p2(rP, 0), n2(rN * std::cos(side), rN * std::sin(side));
            const Vec2 d = n2 - p2;
            const Vec V = t.Position(v);
            for (auto &c : crossed) {
                const Vec2 ray(std::cos(c.first), std::sin(c.first));
                const double denom = Cross2(ray, d);
                if (!(std::fabs(denom) > 0)) return false;
                const double rho = Cross2(p2, d) / denom;
                const int j = c.second, w = fan.ring[j], e = fan.spokeEdge[j];
                const double spoke = (t.Position(w) - V).Norm();
                if (!(rho > 0) || !(spoke > 0) || e < 0) return false;
                const double s = std::min(1.0, rho / spoke);  // from v along the spoke
                SurfacePoint q = SnapOnEdge(e, t.edgeVerts[e][0] == v ? s : 1 - s);
                if (out.empty() || out.back() != q) out.push_back(q);
            }
            return !out.empty();  // no spoke inside: nothing to do here
        }

        // ---- Invariants ----

        bool Acceptable(int x, const std::vector<SurfacePoint> &Q)
        {
            const SurfacePoint &X = nodes[x].p;
            sequence.clear();
            sequence.push_back(nodes[nodes[x].prev].p);
            sequence.insert(sequence.end(), Q.begin(), Q.end());
            sequence.push_back(nodes[nodes[x].next].p);
            for (size_t i = 0; i < Q.size(); ++i) {
                const SurfacePoint &q = Q[i];
                for (size_t j = 0; j < i; ++j)
                    if (Q[j] == q) return false;
                if (q.IsVertex()) {
                    for (int n = siteHead[q.vertex]; n >= 0; n = nodes[n].siteNext)
                        if (n != x) return false;  // a vertex holds one point
                } else {
                    if (!t.IsManifoldEdge(q.edge)) return false;
                    for (int n = siteHead[Site(q)]; n >= 0; n = nodes[n].siteNext)
                        if (n != x && std::fabs(nodes[n].p.t - q.t) < gap) return false;
                    if (EdgeChordCovers(q.edge, q.t, x)) return false;
                }
                int e;
                double tx, tq;  // the move must not sweep a point along an edge
                if (CommonEdge(t, X, q, e, tx, tq) && PointBetween(e, tx, tq, x, Q)) return false;
            }
            for (size_t i = 0; i + 1 < sequence.size(); ++i) {
                const SurfacePoint &a = sequence[i], &b = sequence[i + 1];
                if (a == b) return false;
                int faces[3];
                int nf = SharedFaces(t, a, b, faces, 3);
                if (nf == 0 || nf > 2) return false;
                int e;
                double ta, tb;
                if (CommonEdge(t, a, b, e, ta, tb)) {
                    if (!t.IsManifoldEdge(e)) return false;
                    if (PointBetween(e, ta, tb, x, Q)) return false;
                }
                for (int k = 0; k < nf; ++k) {
                    const int f = faces[k];
                    const double ka = Key(a, f), kb = Key(b, f);
                    ChordsIn(f, x);
                    for (auto &c : chords)
                        if (Conflict(ka, kb, Key(nodes[c.first].p, f), Key(nodes[c.second].p, f))) return false;
                    for (size_t j = 0; j + 1 < sequence.size(); ++j) {
                        if (j == i || !InFace(t, sequence[j], f) || !InFace(t, sequence[j + 1], f)) continue;
                        if (Conflict(ka, kb, Key(sequence[j], f), Key(sequence[j + 1], f))) return false;
                    }
                }
            }
            return true;
        }

        // Position of a point along the boundary of face f: corner k at k, points of side k in (k, k+1).
        double Key(const SurfacePoint &p, int f) const
        {
            if (p.IsVertex()) return t.CornerOf(f, p.vertex);
            int k = t.SideOf(f, p.edge);
            return k + (t.faceVerts[f][k] == t.edgeVerts[p.edge][0] ? p.t : 1 - p.t);
        }

        // Chords (a, b) and (c, d) of one triangle, given by boundary keys: identical, or crossing
        // with four distinct ends. Chords sharing one end only meet there (overlaps along an edge
        // are found by PointBetween / EdgeChordCovers).
        static bool Conflict(double a, double b, double c, double d)
        {
            if (a > b) std::swap(a, b);
            const bool sharedA = c == a || d == a, sharedB = c == b || d == b;
            if (sharedA || sharedB) return sharedA && sharedB;
            return (a < c && c < b) != (a < d && d < b);
        }

        // Existing segments in face f, except those of node x.
        void ChordsIn(int f, int x)
        {
            chords.clear();
            int sites[6] = {t.faceVerts[f][0], t.faceVerts[f][1], t.faceVerts[f][2], t.vertexCount + t.edgeOf[3 * f],
                            t.vertexCount + t.edgeOf[3 * f + 1], t.vertexCount + t.edgeOf[3 * f + 2]};
            for (int s : sites)
                for (int n = siteHead[s]; n >= 0; n = nodes[n].siteNext) {
                    if (n == x) continue;
                    for (int nb : {nodes[n].prev, nodes[n].next})
                        if (nb > n && nb != x && InFace(t, nodes[nb].p, f)) chords.push_back({n, nb});
                }
        }

        // A point of the paths (other than x) or of Q strictly between parameters a and b on edge e.
        bool PointBetween(int e, double a, double b, int x, const std::vector<SurfacePoint> &Q) const
        {
            if (a > b) std::swap(a, b);
            for (int n = siteHead[t.vertexCount + e]; n >= 0; n = nodes[n].siteNext)
                if (n != x && nodes[n].p.t > a && nodes[n].p.t < b) return true;
            for (const SurfacePoint &q : Q)
                if (!q.IsVertex() && q.edge == e && q.t > a && q.t < b) return true;
            return false;
        }

        // A segment (not of x) running along edge e over parameter tq.
        bool EdgeChordCovers(int e, double tq, int x) const
        {
            for (int n = siteHead[t.vertexCount + e]; n >= 0; n = nodes[n].siteNext) {
                if (n == x) continue;
                for (int nb : {nodes[n].prev, nodes[n].next}) {
                    double tb;
                    if (nb < 0 || nb == x || !ParamOnEdge(t, nodes[nb].p, e, tb)) continue;
                    if (std::min(tb, nodes[n].p.t) < tq && tq < std::max(tb, nodes[n].p.t)) return true;
                }
            }
            const int a = t.edgeVerts[e][0], b = t.edgeVerts[e][1];
            for (int n = siteHead[a]; n >= 0; n = nodes[n].siteNext) {
                if (n == x) continue;
                for (int nb : {nodes[n].prev, nodes[n].next})
                    if (nb >= 0 && nb != x && nodes[nb].p.IsVertex() && nodes[nb].p.vertex == b) return true;
            }
            return false;
        }

        void Apply(int x, const std::vector<SurfacePoint> &Q)
        {
            const int prev = nodes[x].prev, next = nodes[x].next, path = nodes[x].path;
            Unregister(x);
            nodes[x].prev = nodes[x].next = -1;
            int last = prev;
            for (const SurfacePoint &q : Q) {
                int id = NewNode(q, path, false);
                nodes[last].next = id;
                nodes[id].prev = last;
                last = id;
            }
            nodes[last].next = next;
            nodes[next].prev = last;
        }
    };
};

// Filter 2 as one call: region ids per face -> boundary graph -> straightened curves.
template <class MeshType>
class RegionBoundarySmoothing
{
public:
    typedef MeshEdgeTopology<MeshType> Topology;
    typedef RegionBoundaryGraph<MeshType> Graph;
    typedef GeodesicStraightening<MeshType> Straightening;
    typedef vcg::Point3<double> Vec;

    struct Params {
        int iterations = 3;        // straightening passes (0: the raw boundary, chains of mesh edges)
        double snapPercent = 25;   // % of an edge's length: closer edge points snap to its vertex
        int minRegionFaces = 0;    // regions with fewer faces join their longest-boundary neighbour (0: off)

        std::string Validate() const
        {
            typename Straightening::Params s;
            s.iterations = iterations;
            s.snapFraction = snapPercent / 100;
            std::string e = s.Validate();
            if (!e.empty()) return e;
            if (minRegionFaces < 0) return "the minimum region size must be >= 0 faces";
            return "";
        }
    };

    struct Curve {
        SurfacePath path;
        int regionLeft = -1, regionRight = -1;  // as in BoundaryCurve
    };

    struct Result {
        std::string error;                 // empty on success
        Topology topology;                 // edge ids of the surface points refer to it
        std::vector<Curve> curves;
        std::vector<int> corners;          // corner vertices
        int regions = 0;                   // distinct region ids in the input
        int mergedRegions = 0;             // regions merged away (minRegionFaces)
        int boundaryEdges = 0;
        int closedLoops = 0;
        int pointsBefore = 0, pointsAfter = 0;
        double lengthBefore = 0, lengthAfter = 0;
        double jaggednessBefore = 0, jaggednessAfter = 0;  // total |geodesic turning| / total length (rad per unit length)
        int passes = 0, moves = 0, rejectedMoves = 0;
        int snapped = 0, held = 0, unsnapped = 0;  // final snapping (see GeodesicStraightening::Result)
        bool converged = false;
        double topologySeconds = 0, graphSeconds = 0, straightenSeconds = 0, seconds = 0;
    };

    // faceRegion: region id per face index (deleted faces ignored). The mesh is not modified.
    static Result Smooth(const MeshType &m, const std::vector<int> &faceRegion, const Params &p, vcg::CallBackPos *cb = nullptr)
    {
        typedef std::chrono::steady_clock Clock;
        auto t0 = Clock::now();
        Result r;
        r.error = p.Validate();
        if (!r.error.empty()) return r;
        if (faceRegion.size() != m.face.size()) { r.error = "one region id per face is needed"; return r; }
        if (m.fn == 0) { r.error = "the mesh has no faces"; return r; }
        if (MeshChecks<MeshType>::CountNonFiniteVertices(m)) {
            r.error = "the mesh has vertices with NaN or infinite coordinates";
            return r;
        }
        if (cb) cb(0, "Region boundaries: mesh topology");
        r.topology.Build(m);
        auto t1 = Clock::now();
        r.topologySeconds = std::chrono::duration<double>(t1 - t0).count();

        r.regions = Graph::CountRegions(r.topology, faceRegion);
        if (r.regions < 2) {
            r.error = "the face quality holds a single region id: there is no region boundary to smooth";
            return r;
        }
        std::vector<int> merged;
        const std::vector<int> *labels = &faceRegion;
        if (p.minRegionFaces > 1) {
            merged = MergeSmallRegions(r.topology, faceRegion, p.minRegionFaces, &r.mergedRegions);
            labels = &merged;
        }
        if (cb) cb(10, "Region boundaries: curves and corners");
        Graph g = Graph::Build(r.topology, *labels);
        if (!g.error.empty()) { r.error = g.error; return r; }
        if (g.boundaryEdges == 0) {
            r.error = std::to_string(r.regions) + " regions but no boundary edge between two of them (" +
                      (r.mergedRegions ? "small regions were merged away" : "each region is a whole connected component") +
                      "): nothing to smooth";
            return r;
        }
        r.boundaryEdges = g.boundaryEdges;
        r.corners = g.corners;
        r.closedLoops = g.closedLoops;
        std::vector<SurfacePath> paths;
        for (const BoundaryCurve &c : g.curves) paths.push_back(InitialPath(r.topology, c));
        auto t2 = Clock::now();
        r.graphSeconds = std::chrono::duration<double>(t2 - t1).count();

        Measure(r.topology, paths, r.pointsBefore, r.lengthBefore, r.jaggednessBefore);
        typename Straightening::Params sp;
        sp.iterations = p.iterations;
        sp.snapFraction = p.snapPercent / 100;
        typename Straightening::Result sr = Straightening::Straighten(r.topology, paths, sp, cb, 20, 95);
        if (!sr.error.empty()) { r.error = sr.error; return r; }
        r.passes = sr.passes;
        r.moves = sr.moves;
        r.rejectedMoves = sr.rejected;
        r.snapped = sr.snapped;
        r.held = sr.held;
        r.unsnapped = sr.unsnapped;
        r.converged = sr.converged;
        Measure(r.topology, paths, r.pointsAfter, r.lengthAfter, r.jaggednessAfter);
        for (size_t i = 0; i < paths.size(); ++i) {
            Curve c;
            c.path = std::move(paths[i]);
            c.regionLeft = g.curves[i].regionLeft;
            c.regionRight = g.curves[i].regionRight;
            r.curves.push_back(std::move(c));
        }
        auto t3 = Clock::now();
        r.straightenSeconds = std::chrono::duration<double>(t3 - t2).count();
        r.seconds = std::chrono::duration<double>(t3 - t0).count();
        return r;
    }

    // The output polylines: one vertex per distinct point (a corner shared by several curves is
    // one vertex), one segment per pair of consecutive points, loops closed back to their start.
    struct Polylines {
        std::vector<Vec> points;
        std::vector<SurfacePoint> where;          // per point: its vertex or edge on the source mesh
        std::vector<std::array<int, 2>> segments;
        std::vector<int> segmentCurve;             // per segment: its curve index
    };

    static Polylines ToPolylines(const Topology &t, const std::vector<Curve> &curves)
    {
        Polylines out;
        std::unordered_map<int, int> atVertex;
        for (size_t c = 0; c < curves.size(); ++c) {
            const SurfacePath &path = curves[c].path;
            int first = -1, last = -1;
            for (const SurfacePoint &q : path.points) {
                int id = -1;
                if (q.IsVertex()) {
                    auto it = atVertex.find(q.vertex);
                    if (it != atVertex.end()) id = it->second;
                }
                if (id < 0) {
                    id = int(out.points.size());
                    out.points.push_back(Straightening::Position(t, q));
                    out.where.push_back(q);
                    if (q.IsVertex()) atVertex[q.vertex] = id;
                }
                if (last >= 0) { out.segments.push_back({last, id}); out.segmentCurve.push_back(int(c)); }
                if (first < 0) first = id;
                last = id;
            }
            if (path.closed && path.points.size() > 2) { out.segments.push_back({last, first}); out.segmentCurve.push_back(int(c)); }
        }
        return out;
    }

    // Fills an (empty) vcg mesh with the polylines as vertices and edges (an edge-only mesh).
    template <class EdgeMeshType>
    static void BuildEdgeMesh(const Polylines &pl, EdgeMeshType &out) { WriteEdgeLayer(pl.points, pl.segments, out); }

private:
    // The boundary chain as vertex points. Corners are fixed; a closed loop is pinned at three
    // vertices a third of its length apart and a curve that starts and ends at the same corner
    // at two more, so shortening cannot shrink either to nothing.
    static SurfacePath InitialPath(const Topology &t, const BoundaryCurve &c)
    {
        SurfacePath path;
        path.closed = c.closed;
        for (int v : c.vertices) path.points.push_back(SurfacePoint::AtVertex(v));
        const int n = int(path.points.size());
        path.fixed.assign(n, 0);
        if (!c.closed) { path.fixed[0] = path.fixed[n - 1] = 1; }
        const bool lasso = !c.closed && c.vertices.front() == c.vertices.back();
        if (c.closed || lasso) {
            std::vector<double> at(n + 1, 0.0);  // arc length at each point (and back at the start for loops)
            for (int i = 0; i < n; ++i) {
                if (i + 1 == n && !c.closed) { at[n] = at[n - 1]; break; }
                at[i + 1] = at[i] + (t.Position(c.vertices[(i + 1) % n]) - t.Position(c.vertices[i])).Norm();
            }
            const double total = c.closed ? at[n] : at[n - 1];
            for (int k = c.closed ? 0 : 1; k < 3; ++k) {
                const double target = total * k / 3;
                int best = 0;
                for (int i = 0; i < n; ++i)
                    if (std::fabs(at[i] - target) < std::fabs(at[best] - target)) best = i;
                path.fixed[best] = 1;
            }
        }
        return path;
    }

    static void Measure(const Topology &t, const std::vector<SurfacePath> &paths, int &points, double &length, double &jaggedness)
    {
        points = 0;
        length = 0;
        double turning = 0;
        for (const SurfacePath &p : paths) {
            points += int(p.points.size());
            length += Straightening::Length(t, p);
            turning += Straightening::TotalTurning(t, p);
        }
        jaggedness = length > 0 ? turning / length : 0;
    }
};

}  // namespace vcg_ext

#endif
