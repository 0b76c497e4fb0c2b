// The engine of the geodesic straightening (see geodesic_straightening.h for the method): the paths
// as doubly linked point lists, every point registered at its site (a vertex or an edge) so the
// invariants are checked locally, the moves (edge point, vertex point, removal) and the final
// snapping onto vertices.
#ifndef VCG_EXT_BOUNDARY_STRAIGHTENING_ENGINE_H
#define VCG_EXT_BOUNDARY_STRAIGHTENING_ENGINE_H

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <vcg_ext/boundary/surface_path.h>

namespace vcg_ext {

struct StraighteningParams {
    static constexpr int kMaxIterations = 1000;
    // Edge points always keep at least this fraction of their edge from its ends, so that after
    // a float / 6-decimal round trip they are still told apart from the vertices.
    static constexpr double kMinSnapFraction = 0.001;
    static constexpr double kMaxSnapFraction = 0.45;

    int iterations = 3;          // passes over every point (the paper: "a few")
    double snapFraction = 0.10;  // edge points this close to a vertex (fraction of the edge length) snap to it

    std::string Validate() const
    {
        if (iterations < 0 || iterations > kMaxIterations)
            return "iterations must be between 0 and " + std::to_string(kMaxIterations);
        if (!(snapFraction >= kMinSnapFraction && snapFraction <= kMaxSnapFraction))
            return "the snap distance must be between 0.1% and 45% of the edge length";
        return "";
    }
};
struct StraighteningResult {
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

// The paths as doubly linked point lists, with every point registered at its site (a vertex,
// or an edge) so the constraints are checked locally.
template <class MeshType>
class StraighteningEngine
{
public:
    typedef StraighteningParams Params;
    typedef StraighteningResult Result;
    typedef SurfacePathGeometry<MeshType> Geometry;
    typedef typename Geometry::Topology Topology;
    typedef typename Geometry::Fan Fan;
    typedef typename Geometry::Vec Vec;
    typedef typename Geometry::Vec2 Vec2;

    StraighteningEngine(const Topology &topology, const Params &params)
        : t(topology), snap(Params::kMinSnapFraction), finalSnap(params.snapFraction), gap(params.snapFraction)
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
                        gap = Params::kMinSnapFraction;
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
    // The geometry of path points, under its own names.
    static Vec Position(const Topology &t, const SurfacePoint &p) { return Geometry::Position(t, p); }
    static bool InFace(const Topology &t, const SurfacePoint &p, int f) { return Geometry::InFace(t, p, f); }
    static int SharedFaces(const Topology &t, const SurfacePoint &a, const SurfacePoint &b, int *out, int cap)
    {
        return Geometry::SharedFaces(t, a, b, out, cap);
    }
    template <class... P>
    static bool ShareFace(const Topology &t, const P &...p) { return Geometry::ShareFace(t, p...); }
    static bool ParamOnEdge(const Topology &t, const SurfacePoint &p, int e, double &param) { return Geometry::ParamOnEdge(t, p, e, param); }
    static bool CommonEdge(const Topology &t, const SurfacePoint &a, const SurfacePoint &b, int &e, double &ta, double &tb)
    {
        return Geometry::CommonEdge(t, a, b, e, ta, tb);
    }
    static double Length(const Topology &t, const SurfacePath &path) { return Geometry::Length(t, path); }
    static double Wrap(double a, double period) { return Geometry::Wrap(a, period); }
    static double Cross2(const Vec2 &a, const Vec2 &b) { return Geometry::Cross2(a, b); }

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
        if (!Geometry::UnfoldAcrossEdge(t, e, P, N, p2, n2, len)) return false;
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
        if (!Geometry::PolarInFan(t, fan, v, P, aP, rP) || !Geometry::PolarInFan(t, fan, v, N, aN, rN)) return false;
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

}  // namespace vcg_ext

#endif
