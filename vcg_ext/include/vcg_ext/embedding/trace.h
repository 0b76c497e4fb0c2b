// Tracing a polyline segment whose end points share no face (user-drawn or loaded polylines)
// across the faces between them, along the section of the surface by the plane through both
// points that contains the average of their normals (seed paper, section 3.3 input; as user
// polylines need it).
//
// Every mesh vertex gets a signed distance to the plane (zero when within the tolerance: the
// plane passes through that vertex). From the start point the walk takes the exit of the section
// curve that heads most toward the end point; then, face after face, the edge whose end points lie
// on opposite sides (or the vertex on the plane), never re-entering a face. It stops as soon as
// the current point shares a face with the end point. If that direction fails (boundary, loop,
// step limit) the other exits are tried. Each step costs O(1) (O(valence) at vertices).
#ifndef VCG_EXT_EMBEDDING_TRACE_H
#define VCG_EXT_EMBEDDING_TRACE_H

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>
#include <vector>

#include <vcg_ext/embedding/adjacency.h>
#include <vcg_ext/embedding/locate.h>

namespace vcg_ext {
namespace embedding {

template <class MeshType>
class SurfaceTracer
{
public:
    SurfaceTracer(const MeshType &mesh, const EmbeddingAdjacency &adjacency, double tolerance)
        : m(mesh), adj(adjacency), tol(tolerance)
    {
    }

    EmbedVec P(int v) const { return EmbedVec::Construct(m.vert[v].cP()); }

    // Calls fn(face) for every face containing p.
    template <class Fn>
    void ForEachFaceOf(const LocatedPoint &p, Fn fn) const
    {
        if (p.kind == LocatedPoint::AtVertex) {
            adj.ForEachFaceAround(p.face, p.vertex, [&](int g, int) { fn(g); });
        } else {
            fn(p.face);
            if (p.kind == LocatedPoint::OnEdge) {
                const int h = adj.twin[3 * p.face + p.edge];
                if (h >= 0) fn(h / 3);
            }
        }
    }

    bool FaceContains(int f, const LocatedPoint &p) const
    {
        switch (p.kind) {
        case LocatedPoint::AtVertex: return adj.CornerOf(f, p.vertex) >= 0;
        case LocatedPoint::OnEdge: {
            const int h = adj.twin[3 * p.face + p.edge];
            return f == p.face || (h >= 0 && f == h / 3);
        }
        default: return f == p.face;
        }
    }

    // A face containing both points, or -1.
    int CommonFace(const LocatedPoint &a, const LocatedPoint &b) const
    {
        int found = -1;
        ForEachFaceOf(a, [&](int f) {
            if (found < 0 && FaceContains(f, b)) found = f;
        });
        return found;
    }

    // Fills `path` with the points between a and b (crossings of edges, or vertices), each
    // consecutive pair of a, path..., b sharing a face. False when the section curve from a does
    // not reach b within `maxSteps` faces.
    bool Trace(const LocatedPoint &a, const LocatedPoint &b, int maxSteps, std::vector<LocatedPoint> &path)
    {
        path.clear();
        EmbedVec chord = b.pos - a.pos;
        if (!(chord.Norm() > 0)) return false;
        // Plane normal: chord x average normal, then chord x either normal alone: across the rim
        // of a part thinner than its triangles the two ends lie on sheets facing apart, their
        // average normal is about nothing and its plane misses the rim.
        const EmbedVec na = Normal(a), nb = Normal(b);
        const EmbedVec candidates[3] = {na + nb, na, nb};
        origin = a.pos;
        for (const EmbedVec &n : candidates) {
            EmbedVec pn = chord ^ n;
            if (!(pn.Norm() > 1e-9 * chord.Norm() * std::max(1e-300, n.Norm()))) continue;
            plane = pn.Normalize();
            std::vector<Step> first = Exits(a, nullptr, -1);
            std::sort(first.begin(), first.end(), [&](const Step &x, const Step &y) {
                return (x.point.pos - a.pos) * chord > (y.point.pos - a.pos) * chord;
            });
            for (const Step &s : first)
                if (Walk(a, s, b, maxSteps, path)) return true;
        }
        path.clear();
        return false;
    }

    // The last resort where no plane section joins a and b (across the rim of a part thinner than
    // its triangles, where the section curves of both sheets miss each other): the shortest chain
    // of mesh edges from a corner of a face holding a to a corner of a face holding b (Dijkstra,
    // lengths straight, ties by vertex index), as vertex points. False when none joins them.
    bool EdgePath(const LocatedPoint &a, const LocatedPoint &b, std::vector<LocatedPoint> &path) const
    {
        path.clear();
        struct Reached {
            double dist;
            int previous, face;  // the vertex it was reached from (-1: a corner of a's faces), a face holding it
        };
        std::unordered_map<int, Reached> reached;
        std::unordered_map<int, double> toB;  // corners of b's faces -> their distance to b
        typedef std::pair<double, int> Entry;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
        auto relax = [&](int v, double d, int previous, int face) {
            auto it = reached.find(v);
            if (it != reached.end() && it->second.dist <= d) return;
            reached[v] = {d, previous, face};
            heap.push({d, v});
        };
        ForEachFaceOf(b, [&](int f) {
            for (int k = 0; k < 3; ++k) toB[adj.fv[f][k]] = (P(adj.fv[f][k]) - b.pos).Norm();
        });
        ForEachFaceOf(a, [&](int f) {
            for (int k = 0; k < 3; ++k) relax(adj.fv[f][k], (P(adj.fv[f][k]) - a.pos).Norm(), -1, f);
        });
        double best = std::numeric_limits<double>::infinity();
        int last = -1;
        while (!heap.empty()) {
            const Entry e = heap.top();
            heap.pop();
            const int v = e.second;
            const Reached here = reached.at(v);
            if (e.first > here.dist) continue;  // reached shorter since
            if (here.dist >= best) break;
            auto target = toB.find(v);
            if (target != toB.end() && here.dist + target->second < best) {
                best = here.dist + target->second;
                last = v;
            }
            adj.ForEachFaceAround(here.face, v, [&](int g, int corner) {
                for (int w : {adj.fv[g][EmbeddingAdjacency::Next(corner)], adj.fv[g][EmbeddingAdjacency::Prev(corner)]})
                    relax(w, here.dist + (P(w) - P(v)).Norm(), v, g);
            });
        }
        if (last < 0) return false;
        for (int v = last; v >= 0; v = reached.at(v).previous) {
            const int f = reached.at(v).face;
            path.push_back(VertexPoint(f, adj.CornerOf(f, v)));
        }
        std::reverse(path.begin(), path.end());
        return true;
    }

private:
    struct Step {
        LocatedPoint point;
        int face;  // the face holding the sub-segment from the current point to `point`
    };

    const MeshType &m;
    const EmbeddingAdjacency &adj;
    double tol;
    EmbedVec plane, origin;
    std::vector<unsigned> visitStamp;
    unsigned stamp = 0;

    double Side(int v) const
    {
        const double s = plane * (P(v) - origin);
        return std::fabs(s) <= tol ? 0.0 : s;
    }

    EmbedVec FaceNormal(int f) const
    {
        const EmbedVec a = P(adj.fv[f][0]), b = P(adj.fv[f][1]), c = P(adj.fv[f][2]);
        return (b - a) ^ (c - a);
    }

    EmbedVec Normal(const LocatedPoint &p) const
    {
        EmbedVec n(0, 0, 0);
        ForEachFaceOf(p, [&](int f) {
            EmbedVec fn = FaceNormal(f);
            double l = fn.Norm();
            if (l > 0) n += (p.kind == LocatedPoint::AtVertex ? fn : fn / l);  // vertex: area weighted
        });
        double l = n.Norm();
        return l > 0 ? n / l : n;
    }

    LocatedPoint VertexPoint(int f, int corner) const
    {
        LocatedPoint s;
        s.kind = LocatedPoint::AtVertex;
        s.face = f;
        s.vertex = adj.fv[f][corner];
        s.pos = P(s.vertex);
        return s;
    }

    // The crossing of half-edge k of face f (its ends on opposite sides).
    LocatedPoint EdgePoint(int f, int k, double su, double sw) const
    {
        LocatedPoint s;
        s.kind = LocatedPoint::OnEdge;
        s.face = f;
        s.edge = k;
        s.t = su / (su - sw);
        const EmbedVec a = P(adj.fv[f][k]), b = P(adj.fv[f][EmbeddingAdjacency::Next(k)]);
        s.pos = a + (b - a) * s.t;
        return s;
    }

    // Exits of the section curve inside face f from a point on corner `from` (-1: from an edge
    // or the face interior): crossings of edges whose ends are on opposite sides, vertices on the plane.
    void FaceExits(int f, int fromCorner, int fromEdge, std::vector<Step> &out) const
    {
        double s[3];
        for (int k = 0; k < 3; ++k) s[k] = Side(adj.fv[f][k]);
        for (int k = 0; k < 3; ++k) {
            const int n = EmbeddingAdjacency::Next(k);
            if (k == fromEdge) continue;
            if (k == fromCorner || n == fromCorner) {  // edges at the start corner: only their far vertex
                continue;
            }
            if (s[k] * s[n] < 0) out.push_back({EdgePoint(f, k, s[k], s[n]), f});
        }
        for (int k = 0; k < 3; ++k)
            if (s[k] == 0 && k != fromCorner) {
                // A vertex on the plane; on the entry edge only when the plane contains that edge.
                if (fromEdge >= 0 && (k == fromEdge || k == EmbeddingAdjacency::Next(fromEdge)) &&
                    !(s[fromEdge] == 0 && s[EmbeddingAdjacency::Next(fromEdge)] == 0))
                    continue;
                out.push_back({VertexPoint(f, k), f});
            }
    }

    // Every way the section curve leaves `p`; faces containing `prev` are not taken (no going back).
    std::vector<Step> Exits(const LocatedPoint &p, const LocatedPoint *prev, int arrivedThrough) const
    {
        std::vector<Step> out;
        auto blocked = [&](int f) { return prev != nullptr && FaceContains(f, *prev); };
        if (p.kind == LocatedPoint::AtVertex) {
            adj.ForEachFaceAround(p.face, p.vertex, [&](int f, int corner) {
                if (!blocked(f)) FaceExits(f, corner, -1, out);
            });
        } else if (p.kind == LocatedPoint::OnEdge) {
            const int h = adj.twin[3 * p.face + p.edge];
            if (arrivedThrough < 0 && !blocked(p.face)) FaceExits(p.face, -1, p.edge, out);  // start point: both sides
            if (h >= 0 && h / 3 != arrivedThrough && !blocked(h / 3)) FaceExits(h / 3, -1, h % 3, out);
        } else {
            FaceExits(p.face, -1, -1, out);
        }
        return out;
    }

    bool Walk(const LocatedPoint &a, const Step &firstStep, const LocatedPoint &b, int maxSteps, std::vector<LocatedPoint> &path)
    {
        path.clear();
        if (visitStamp.empty()) visitStamp.assign(adj.fv.size(), 0);  // only when something needs tracing
        if (++stamp == 0) { std::fill(visitStamp.begin(), visitStamp.end(), 0); stamp = 1; }
        LocatedPoint prev = a;
        Step cur = firstStep;
        for (int steps = 0; steps < maxSteps; ++steps) {
            if (visitStamp[cur.face] == stamp) return false;  // the section curve closed without meeting b
            visitStamp[cur.face] = stamp;
            path.push_back(cur.point);
            if (CommonFace(cur.point, b) >= 0) return true;
            // Edge crossing: continue in the face across that edge.
            const int arrived = cur.point.kind == LocatedPoint::OnEdge ? cur.face : -1;
            std::vector<Step> next = Exits(cur.point, &prev, arrived);
            if (next.empty()) return false;
            const EmbedVec dir = cur.point.pos - prev.pos;
            const Step *best = &next[0];
            for (const Step &s : next)
                if ((s.point.pos - cur.point.pos) * dir > (best->point.pos - cur.point.pos) * dir) best = &s;
            prev = cur.point;
            cur = *best;
        }
        return false;
    }
};

}  // namespace embedding
}  // namespace vcg_ext

#endif
