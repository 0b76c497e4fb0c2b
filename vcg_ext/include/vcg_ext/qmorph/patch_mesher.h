// Q-Morph (Owen, Staten, Canann, Saigal 1999) on one patch: a triangulated surface piece whose
// boundary is the initial front. Every geometric decision is made on the surface itself: front
// angles are sums of triangle corner angles, side directions are rotations inside a triangle,
// orientation tests use the node's normal from the patch's own faces, and smoothing moves nodes
// in their tangent plane and projects them back onto the patch's input surface (no shrinkage).
//
// Per front edge A->B (highest state, lowest level first):
//   1. side edges at A and B: the adjacent front edge when the front angle is closed (< 3pi/4),
//      else an existing edge within pi/6 of the ideal direction, else a swap creating one, else
//      a split of the edge the ideal direction crosses; long sides are split to the base length;
//   2. the top edge between the side tips, recovered by swaps;
//   3. the triangles enclosed by base, sides and top merged into one quad (inner nodes removed);
//   4. local smoothing of the new front nodes and their triangle neighbours.
// Loops of <= 6 edges are closed by templates (a quad; a quad and a triangle; two quads). The
// initial front (the patch boundary) is never swapped, split or moved.
// Afterwards: leftover triangle pairs merged where the quad is good, doublets dissolved, and a
// final tangent-plane smoothing.
#ifndef VCG_EXT_QMORPH_PATCH_MESHER_H
#define VCG_EXT_QMORPH_PATCH_MESHER_H

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

#include <vcg_ext/qmorph/front.h>
#include <vcg_ext/qmorph/mixed_mesh.h>
#include <vcg_ext/qmorph/surface_projector.h>

namespace vcg_ext {
namespace qmorph {

struct PatchParams {
    double closedAngle = 3 * M_PI / 4;  // a front angle below this closes that end (Owen: 3pi/4)
    double sideTolerance = M_PI / 6;    // existing edges within this of the ideal side are used
    double longSideFactor = std::sqrt(3.0);  // sides longer than this times the base are split
    double minQuadJacobian = 0.05;      // a quad is formed only when its scaled Jacobian exceeds this
    double pairMinJacobian = 0.3;       // leftover triangle pairs are merged above this quality
    double migrationMinJacobian = 0.02; // quads made while bringing distant triangles together
    bool seams = true;                  // Owen's seam away from the initial front
    double seamAngle = M_PI / 6;        // front edges meeting at a smaller angle are sewn together
    bool transitions = true;            // Owen's transition seam and transition split
    double transitionRatio = 2.5;       // front edges differing more than this in length need a transition
    double transitionMinLength = 1.5;   // ... when the longer one is also this long (times the patch's mean
                                        // input edge): short edges get plain seams, no cascade of splits
    bool preserveInitialFront = true;   // false: a seam may also close onto an initial front edge
                                        // (its nodes never move: the other node joins them)
    bool cleanup = true;                // topological clean-up: valence turns and diagonal collapses
    bool rescueBadQuads = true;         // nodes of quads below 0.3 moved to raise their worst quality
    int finalSmoothing = 5;             // tangent-plane smoothing sweeps at the end
    bool smoothing = true;              // local smoothing after each quad + final sweeps
};

struct PatchStats {
    int quadsFormed = 0, templates = 0, swaps = 0, splits = 0, failures = 0;
    int pairedTriangles = 0, doublets = 0, iterations = 0, valenceTurns = 0, seams = 0;
    int transitionSeams = 0, transitionSplits = 0, diagonalCollapses = 0, quadsOpened = 0;
};

class PatchMesher
{
public:
    PatchMesher(MixedMesh &mesh, const SurfaceProjector &surface, std::vector<int> &homeTriangle, const PatchParams &params)
        : m(mesh), front(mesh), proj(surface), home(homeTriangle), p(params)
    {
        home.resize(m.VertexCount(), 0);
        vertexCap = 4 * m.VertexCount() + 64;
        double sum = 0;
        int n = 0;
        for (int h = 0; h < m.HalfEdgeCount(); ++h)
            if (m.HeAlive(h)) { sum += m.Length(h); ++n; }
        meanLength = n ? sum / n : 0;
        minLength = 0.02 * meanLength;
    }

    PatchStats Run()
    {
        ImproveTriangulation();
        int triangles = 0;
        for (int f = 0; f < m.FaceCount(); ++f) triangles += m.FaceAlive(f) && m.IsTri(f);
        const long cap = 40L * triangles + 1000;
        failedAt.assign(m.HalfEdgeCount(), -1);
        for (int sweep = 0; sweep < 4; ++sweep) {
            int before = successes;
            PushAllFront();
            while (!queue.Empty() && stats.iterations < cap) {
                ++stats.iterations;
                FrontEntry e = queue.Pop();
                int h = e.he;
                if (!front.IsFront(h)) continue;
                int state = front.State(h, p.closedAngle), level = front.Level(h);
                if (FrontQueue::Rank(state) != e.rank || level != e.level) { queue.Push(h, state, level); continue; }
                if (h < int(failedAt.size()) && failedAt[h] == successes) continue;
                int len = front.LoopLength(h, 6);
                bool ok = (len < 0 && p.seams && Seam(h)) || (len > 0 && CloseSmallLoop(h, len)) ||
                          (len < 0 && p.transitions && SplitLongFrontEdge(h)) || (len != 3 && FormQuad(h, state));
                if (ok) ++successes;
                else {
                    if (int(failedAt.size()) < m.HalfEdgeCount()) failedAt.resize(m.HalfEdgeCount(), -1);
                    failedAt[h] = successes;
                    ++stats.failures;
                }
            }
            if (successes == before) break;
        }
        // Leftover triangles: smooth first (their shapes improve), then merge good adjacent pairs,
        // then bring distant ones together through the quads.
        if (p.smoothing)
            for (int it = 0; it < 2; ++it) SmoothAll();
        PairLeftoverTriangles(p.pairMinJacobian);
        PairLeftoverTriangles(p.migrationMinJacobian);
        MigrateTrianglesIntoPairs();
        DissolveDoublets();
        if (p.cleanup)
            for (int round = 0; round < 2; ++round) {  // a smoothing sweep between rounds: better shapes let more operations pass
                ImproveValences();
                CollapseQuadDiagonals();
                OpenQuads();
                DissolveDoublets();
                ImproveValences();
                if (p.smoothing) SmoothAll(true);
            }
        if (p.smoothing) {
            for (int it = 0; it < p.finalSmoothing; ++it) SmoothAll();
            if (p.rescueBadQuads) ImproveBadQuads();
        }
        return stats;
    }

private:
    MixedMesh &m;
    Front front;
    const SurfaceProjector &proj;
    std::vector<int> &home;
    const PatchParams &p;
    FrontQueue queue;
    PatchStats stats;
    std::vector<int> failedAt;  // per half-edge: success count when it last failed
    std::vector<char> transitioned;  // per node: part of a transition split already
    int successes = 0;

    int vertexCap;
    double meanLength = 0;  // mean input edge length of the patch
    double minLength = 0;   // no split makes edges shorter than this (2% of the mean input edge)

    // Intrinsic Delaunay flips of the near-flat interior edges next to thin triangles, before the
    // front starts: slivers (from splitting) make poor side edges. Well-shaped triangulations
    // (grids, isotropic meshes) are left alone: their structure pairs into good quads. Only edges
    // whose two triangles are within 15 degrees of coplanar are flipped: the surface barely changes.
    void ImproveTriangulation()
    {
        const double maxDihedral = std::cos(15 * M_PI / 180);
        for (int pass = 0; pass < 8; ++pass) {
            int flips = 0;
            for (int h = 0; h < m.HalfEdgeCount(); ++h) {
                int t = m.heTwin[h];
                if (t < h || !m.HeAlive(h) || !m.IsTri(m.heFace[h]) || !m.IsTri(m.heFace[t])) continue;
                double opposite = m.CornerAngle(m.hePrev[h]) + m.CornerAngle(m.hePrev[t]);
                if (opposite <= M_PI + 0.1) continue;
                if (std::min(MinCorner(m.heFace[h]), MinCorner(m.heFace[t])) > 15 * M_PI / 180) continue;
                P3 n1 = m.FaceNormal(m.heFace[h]), n2 = m.FaceNormal(m.heFace[t]);
                double l = n1.Norm() * n2.Norm();
                if (!(l > 0) || (n1 * n2) / l < maxDihedral || !m.CanFlip(h)) continue;
                m.Flip(h);
                ++flips;
            }
            stats.swaps += flips;
            if (!flips) break;
        }
    }

    double MinCorner(int f) const
    {
        int g = m.faceHe[f];
        return std::min({m.CornerAngle(g), m.CornerAngle(m.heNext[g]), m.CornerAngle(m.hePrev[g])});
    }

    // ---- queue ----------------------------------------------------------------------------------
    void PushAllFront()
    {
        for (int h = 0; h < m.HalfEdgeCount(); ++h)
            if (front.IsFront(h)) queue.Push(h, front.State(h, p.closedAngle), front.Level(h));
    }
    void PushIfFront(int h)
    {
        if (h >= 0 && front.IsFront(h)) queue.Push(h, front.State(h, p.closedAngle), front.Level(h));
    }
    // Front edges whose state may have changed around node v.
    void PushAround(int v)
    {
        if (!m.vertAlive[v]) return;
        m.ForEachOutgoing(v, [&](int g) {
            PushIfFront(g);
            PushIfFront(m.hePrev[g]);
            if (m.heTwin[g] >= 0) PushIfFront(m.heTwin[g]);
        });
    }

    // ---- geometry helpers -----------------------------------------------------------------------
    // Scaled Jacobian of the quad (a b c d) against reference normal n (<= 0: inverted).
    double QuadQuality(int a, int b, int c, int d, const P3 &n) const
    {
        if (!m.DistinctNodes({a, b, c, d})) return -1;
        return QuadQuality({m.pos[a], m.pos[b], m.pos[c], m.pos[d]}, n);
    }
    static double QuadQuality(const std::array<P3, 4> &pos, const P3 &n)
    {
        double shortest = 1e300, longest = 0;  // a needle (aspect above 50) is as bad as a fold
        for (int k = 0; k < 4; ++k) {
            double l = (pos[(k + 1) % 4] - pos[k]).Norm();
            shortest = std::min(shortest, l);
            longest = std::max(longest, l);
        }
        if (!(shortest > 0.02 * longest)) return -1;
        P3 N(0, 0, 0);
        for (int k = 0; k < 4; ++k) N += pos[k] ^ pos[(k + 1) % 4];
        double l = N.Norm();
        if (!(l > 0) || N * n <= 0) return -1;
        N /= l;
        double worst = 1;
        for (int k = 0; k < 4; ++k) {
            P3 e1 = pos[(k + 1) % 4] - pos[k], e2 = pos[(k + 3) % 4] - pos[k];
            double d = e1.Norm() * e2.Norm();
            worst = std::min(worst, d > 0 ? ((e1 ^ e2) * N) / d : -1.0);
        }
        return worst;
    }
    bool TriPositive(int a, int b, int c, const P3 &n) const
    {
        P3 u = m.pos[b] - m.pos[a], v = m.pos[c] - m.pos[a], w = m.pos[c] - m.pos[b];
        double l2 = std::max({u.SquaredNorm(), v.SquaredNorm(), w.SquaredNorm()});
        double nl = n.Norm();
        return m.DistinctNodes({a, b, c}) && nl > 0 && (u ^ v) * n > 1e-3 * l2 * nl && ((m.pos[b] - m.pos[a]) ^ (m.pos[c] - m.pos[a])) * n > 0;
    }

    int NewVertexOnEdge(int h, const P3 &point)
    {
        int from = m.Org(h);
        int v = m.SplitEdge(h, point);
        home.resize(m.VertexCount(), 0);
        home[v] = home[from];
        TryMove(v, proj.Project(m.pos[v], home[v]));  // a point of a current edge: back onto the input surface
        ++stats.splits;
        return v;
    }

    bool Splittable(int h) const
    {
        int t = m.heTwin[h];
        return t >= 0 && !m.heInitial[h] && m.IsTri(m.heFace[h]) && m.IsTri(m.heFace[t]) && m.VertexCount() < vertexCap &&
               m.Length(h) > 5 * minLength;
    }

    // ---- side edges -----------------------------------------------------------------------------
    // Chooses (creating it if needed) the side edge at the open end of front edge h; returns its
    // far node or -1. `exclude` is a node the side must not reach; `keepA/keepB` an edge that must
    // not be swapped or split. Owen's order: an existing edge close to the ideal direction, else a
    // swap of the edge the direction crosses, else a split of it; a split that would make a side
    // much shorter than the front edge (a sliver triangle at the node) swaps first and splits the
    // farther edge the direction then crosses.
    int ChooseSide(int h, bool leftEnd, int exclude, int keepA, int keepB)
    {
        auto isKept = [&](int e) {
            int a = m.Org(e), b = m.Dst(e);
            return (a == keepA && b == keepB) || (a == keepB && b == keepA);
        };
        const double base = m.Length(h);
        int tip = -1;
        for (int attempt = 0; attempt < 4 && tip < 0; ++attempt) {
            Fan fan;
            if (!(leftEnd ? front.LeftFan(h, fan) : front.RightFan(h, fan))) return -1;
            const int node = fan.node;
            const double ideal = std::min(fan.Total() / 2, M_PI / 2);
            int best = -1;
            for (int i = 1; i + 1 < int(fan.edges.size()); ++i) {
                if (fan.edges[i].vertex == exclude || ClosesOddLoop(h, leftEnd, fan.edges[i].vertex)) continue;
                if (best < 0 || std::fabs(fan.edges[i].angle - ideal) < std::fabs(fan.edges[best].angle - ideal)) best = i;
            }
            if (best >= 0 && std::fabs(fan.edges[best].angle - ideal) < p.sideTolerance) {
                tip = fan.edges[best].vertex;
                break;
            }
            int k = 0;
            while (k + 1 < int(fan.gaps.size()) && fan.gaps[k].angleEnd < ideal) ++k;
            const FanGap gap = fan.gaps[k];
            const int e = gap.opposite;
            const int x = fan.edges[k].vertex, y = fan.edges[k + 1].vertex;
            P3 point;
            bool canSplit = !isKept(e) && Splittable(e) && SplitPoint(node, x, y, ideal - gap.angleStart, point);
            if (canSplit && (point - m.pos[node]).Norm() >= 0.5 * base) {
                tip = NewVertexOnEdge(e, point);
                break;
            }
            if (isKept(e) || !m.CanFlip(e)) {
                if (canSplit && (point - m.pos[node]).Norm() >= 0.2 * base) tip = NewVertexOnEdge(e, point);
                else if (best >= 0 && std::fabs(fan.edges[best].angle - ideal) < 2 * p.sideTolerance) tip = fan.edges[best].vertex;
                break;
            }
            m.Flip(e);  // the new edge may be the side; else the direction now crosses a farther edge
            ++stats.swaps;
        }
        if (tip < 0 || tip == exclude) return -1;
        // long side: split it to the base length
        const int node = leftEnd ? m.Org(h) : m.Dst(h);
        int hs = m.FindHalfEdge(node, tip);
        if (hs >= 0 && m.Length(hs) > p.longSideFactor * base && base > minLength && !isKept(hs) && Splittable(hs)) {
            P3 point = m.pos[node] + (m.pos[tip] - m.pos[node]) * (base / m.Length(hs));
            tip = NewVertexOnEdge(hs, point);
        }
        return tip;
    }

    // A side from an end of h to a node a few front edges away along the loop (walking away from
    // h) cuts that stretch off as a loop of its own: with an odd number of edges it would end as a
    // triangle. Such tips are avoided (Q-Morph keeps loops even wherever it can).
    bool ClosesOddLoop(int h, bool leftEnd, int tip) const
    {
        int e = h;
        for (int d = 1; d <= 7; ++d) {
            e = leftEnd ? front.PrevFront(e) : front.NextFront(e);
            if (e < 0 || e == h) return false;
            if ((leftEnd ? m.Org(e) : m.Dst(e)) == tip) return (d + 1) % 2 == 1;
        }
        return false;
    }

    // Where the direction at `delta` from node->x, turning towards node->y inside the triangle
    // (node x y), crosses the side x-y; false when it does not (well inside the side).
    bool SplitPoint(int node, int x, int y, double delta, P3 &point) const
    {
        P3 o = m.pos[node], u = m.pos[x] - o, w = m.pos[y] - o;
        double ul = u.Norm();
        if (!(ul > 0)) return false;
        P3 uh = u / ul;
        P3 wp = w - uh * (w * uh);
        double wl = wp.Norm();
        if (!(wl > 0)) return false;
        P3 vh = wp / wl;
        delta = std::max(0.0, delta);
        double dx = std::cos(delta), dy = std::sin(delta);
        double ex = w * uh - ul, ey = w * vh;  // x->y in the (uh, vh) frame, x at (ul, 0)
        double den = ex * dy - ey * dx;        // cross(x->y, direction)
        if (std::fabs(den) < 1e-300) return false;
        double t = -dy * ul / den;             // cross(direction, x) / cross(x->y, direction)
        if (!(t > 0.15 && t < 0.85)) t = std::max(0.15, std::min(0.85, t));
        point = m.pos[x] + (m.pos[y] - m.pos[x]) * t;
        return true;
    }

    // ---- top edge recovery ----------------------------------------------------------------------
    // Swaps edges crossing the segment d-c (seen in the tangent plane at d, then at c) until the
    // edge exists. Edges in `kept` (vertex pairs) are never swapped.
    bool RecoverEdge(int d, int c, const std::vector<std::pair<int, int>> &kept)
    {
        auto isKept = [&](int e) {
            int a = m.Org(e), b = m.Dst(e);
            for (auto &k : kept)
                if ((a == k.first && b == k.second) || (a == k.second && b == k.first)) return true;
            return false;
        };
        for (int iter = 0; iter < 24; ++iter) {
            if (m.EdgeExists(d, c)) return true;
            bool flipped = false;
            for (int side = 0; side < 2 && !flipped; ++side) {
                int from = side ? c : d, to = side ? d : c;
                int e = CrossedEdge(from, to);
                if (e >= 0 && !isKept(e) && m.CanFlip(e)) { m.Flip(e); ++stats.swaps; flipped = true; }
            }
            if (!flipped) return false;
        }
        return m.EdgeExists(d, c);
    }

    // The side, opposite `from`, of the triangle at `from` that the direction to `to` passes through.
    int CrossedEdge(int from, int to) const
    {
        P3 n = m.VertexNormal(from);
        auto tangent = [&](const P3 &v) { return v - n * (v * n); };
        P3 c = tangent(m.pos[to] - m.pos[from]);
        int found = -1;
        m.ForEachOutgoing(from, [&](int g) {
            if (found >= 0 || !m.IsTri(m.heFace[g])) return;
            P3 x = tangent(m.pos[m.Dst(g)] - m.pos[from]), y = tangent(m.pos[m.Org(m.hePrev[g])] - m.pos[from]);
            if ((x ^ c) * n > 0 && (c ^ y) * n > 0) found = m.heNext[g];
        });
        return found;
    }

    // ---- quad formation -------------------------------------------------------------------------
    bool FormQuad(int h, int state)
    {
        const int a = m.Org(h), b = m.Dst(h);
        Fan fan;
        int d = -1, c = -1;
        if (state & 1) {
            if (!front.LeftFan(h, fan)) return false;
            d = fan.edges.back().vertex;
        }
        if (state & 2) {
            if (!front.RightFan(h, fan)) return false;
            c = fan.edges.back().vertex;
        }
        if (d < 0) d = ChooseSide(h, true, c >= 0 ? c : b, b, c);
        if (d < 0) return false;
        if (c < 0) c = ChooseSide(h, false, d, a, d);
        if (c < 0 || c == d || c == a || d == b) return false;
        if (!m.EdgeExists(a, d) || !m.EdgeExists(b, c)) return false;
        if (!RecoverEdge(d, c, {{a, b}, {a, d}, {b, c}})) return false;
        std::array<int, 4> loop{h, m.FindHalfEdge(b, c), m.FindHalfEdge(c, d), m.FindHalfEdge(d, a)};
        for (int e : loop)
            if (e < 0 || !m.IsTri(m.heFace[e])) return false;
        P3 n = m.VertexNormal(a) + m.VertexNormal(b);
        if (QuadQuality(a, b, c, d, n) <= p.minQuadJacobian) return false;
        std::vector<int> faces, inner;
        if (!m.EnclosedTriangles(loop, faces, inner)) return false;
        if (!m.QuadHasFreeDiagonal(a, b, c, d, faces) || !InnerNodesNearQuad(inner, {a, b, c, d})) return false;
        int q = m.MakeQuad(loop, faces, inner, front.Level(h) + 1);
        ++stats.quadsFormed;
        AfterNewFaces({q}, {c, d});
        return true;
    }

    // Smooths the new front nodes and their triangle neighbours; re-queues the front nearby.
    void AfterNewFaces(const std::vector<int> &faces, const std::vector<int> &nodes)
    {
        if (p.smoothing) {
            std::vector<int> moved;
            for (int v : nodes)
                if (m.vertAlive[v] && !m.vertFixed[v]) moved.push_back(v);
            for (int v : nodes)
                if (m.vertAlive[v])
                    m.ForEachOutgoing(v, [&](int g) {
                        int w = m.Dst(g);
                        if (!m.vertFixed[w] && AllTriangles(w) && std::find(moved.begin(), moved.end(), w) == moved.end())
                            moved.push_back(w);
                    });
            for (int pass = 0; pass < 2; ++pass)
                for (int v : moved) SmoothNode(v);
        }
        for (int f : faces) {
            int g = m.faceHe[f];
            for (int k = 0; k < m.faceSize[f]; ++k, g = m.heNext[g]) {
                if (m.heTwin[g] >= 0) PushIfFront(m.heTwin[g]);
                PushAround(m.Org(g));
            }
        }
    }

    bool AllTriangles(int v) const
    {
        bool all = true;
        m.ForEachOutgoing(v, [&](int g) { all = all && m.IsTri(m.heFace[g]); });
        return all;
    }

    // Removing inner nodes must not flatten the surface: each removed node must lie close to the
    // new polygon (its fan of triangles from the first corner; for a quad, the better of its two
    // diagonals), within a fifth of the polygon's shortest side and a tenth of the mean input edge.
    bool InnerNodesNearQuad(const std::vector<int> &inner, const std::vector<int> &corners) const
    {
        if (inner.empty()) return true;
        double shortest = 1e300;
        for (size_t k = 0; k < corners.size(); ++k)
            shortest = std::min(shortest, (m.pos[corners[(k + 1) % corners.size()]] - m.pos[corners[k]]).Norm());
        const double tolerance = std::min(0.2 * shortest, 0.1 * meanLength);
        auto worstDistance = [&](size_t first) {  // fan from corner `first`
            double worst = 0;
            for (int v : inner) {
                double best = 1e300;
                for (size_t k = 1; k + 1 < corners.size(); ++k)
                    best = std::min(best, PointTriangleDistance(m.pos[v], m.pos[corners[first]],
                                                                m.pos[corners[(first + k) % corners.size()]],
                                                                m.pos[corners[(first + k + 1) % corners.size()]]));
                worst = std::max(worst, best);
            }
            return worst;
        };
        double d = worstDistance(0);
        if (corners.size() == 4) d = std::min(d, worstDistance(1));
        return d <= tolerance;
    }

    static double PointTriangleDistance(const P3 &p, const P3 &a, const P3 &b, const P3 &c)
    {
        P3 n = (b - a) ^ (c - a);
        double nn = n.SquaredNorm();
        if (nn > 0) {  // inside the prism over the triangle: distance to the plane
            P3 q = p - n * (((p - a) * n) / nn);
            if (((b - a) ^ (q - a)) * n >= 0 && ((c - b) ^ (q - b)) * n >= 0 && ((a - c) ^ (q - c)) * n >= 0) return (p - q).Norm();
        }
        auto segment = [&](const P3 &x, const P3 &y) {
            P3 e = y - x;
            double t = e.SquaredNorm() > 0 ? std::max(0.0, std::min(1.0, ((p - x) * e) / e.SquaredNorm())) : 0.0;
            return (p - (x + e * t)).Norm();
        };
        return std::min({segment(a, b), segment(b, c), segment(c, a)});
    }

    // ---- seam ------------------------------------------------------------------------------------
    // Owen's seam: front edges A->B and B->C meeting at a very small angle, with the one thin
    // triangle (A B C) between them, are closed by joining A and C (the edge A-C collapses). Only
    // away from the initial front (both edges have a quad on their other side): on the initial
    // front the paper leaves a triangle instead. With preserveInitialFront off, one of the two may
    // be an initial front edge: the other node joins its fixed node, the front itself is unchanged.
    // Transition seam: when the two lengths differ by more than transitionRatio, the longer edge
    // (not initial) first gets a transition split at the shorter one's length, then the seam.
    bool Seam(int h)
    {
        double angle = 0;
        const int n = front.NextFront(h, &angle);
        if (n < 0 || m.heNext[h] != n || angle >= p.seamAngle) return false;
        const bool hInitial = m.heTwin[h] < 0, nInitial = m.heTwin[n] < 0;
        if (hInitial && nInitial) return false;
        if ((hInitial || nInitial) && p.preserveInitialFront) return false;
        const double lh = m.Length(h), ln = m.Length(n);
        if (p.transitions && std::max(lh, ln) > p.transitionRatio * std::min(lh, ln) && std::max(lh, ln) > p.transitionMinLength * meanLength) {
            const bool split = ln > lh ? !nInitial && TransitionSplit(n, lh / ln, true) : !hInitial && TransitionSplit(h, 1 - ln / lh, false);
            if (!split) return false;
            ++stats.transitionSeams;
            return true;  // the seam follows when the queue reaches the new, shorter edge
        }
        const int e = m.heNext[n];  // C -> A
        const int a = m.Org(h), c = m.Dst(n);
        if (m.Dst(e) != a || (m.vertFixed[a] && m.vertFixed[c])) return false;
        const int keep = m.vertFixed[c] ? c : a, gone = keep == a ? c : a;
        const int h0 = keep == a ? m.heTwin[e] : e;  // keep -> gone
        if (h0 < 0 || !m.IsTri(m.heFace[h0]) || !m.IsTri(m.heFace[m.heTwin[h0]])) return false;
        P3 at = m.pos[keep];
        if (!m.vertFixed[keep]) {
            at = (m.pos[a] + m.pos[c]) * 0.5;
            at = proj.Project(at, home[keep]);
        }
        // joining must not cut the surface: both nodes move little out of their tangent plane
        const double limit = 0.1 * std::min(m.Length(h), m.Length(n));
        if (std::fabs((m.pos[gone] - at) * m.VertexNormal(gone)) > limit ||
            std::fabs((m.pos[keep] - at) * m.VertexNormal(keep)) > limit)
            return false;
        // the faces that stay around both nodes must stay valid with the joined node at `at`
        const std::vector<int> faces = m.FacesAround({keep, gone}, {m.heFace[h0], m.heFace[m.heTwin[h0]]});
        bool valid = m.WorstQualityIfMoved({keep, gone}, at, faces, [&](int f, const P3 &n) { return FaceQualityAt(f, n); }).second > 0.05;
        if (m.vertFixed[keep])  // gone's edges move to keep: none may become a new chord between front nodes
            m.ForEachOutgoing(gone, [&](int g) { if (m.Dst(g) != keep && m.NewChordBetweenFrontNodes(keep, m.Dst(g))) valid = false; });
        if (!valid || !m.CollapseEdge(h0, at, !p.preserveInitialFront)) return false;
        ++stats.seams;
        AfterNewFaces({}, {keep});
        PushAround(keep);
        return true;
    }

    // ---- transitions -----------------------------------------------------------------------------
    // Owen's transition split of a front edge s = P->R with a quad (R P x y) behind it: a node M on
    // P-R (at fraction t from P) turns that quad into a quad and a triangle handed back to the
    // unmeshed side: (P x y M) + (M y R) with the triangle at R's end, else (R M x y) + (M P x).
    // The front then runs P-M-y-R (or P-x-M-R): one edge becomes three, the parity of the loop is
    // kept, and the next row can use shorter elements. Never on the initial front (no quad behind).
    bool TransitionSplit(int s, double t, bool triangleAtR)
    {
        const int tw = m.heTwin[s];
        if (tw < 0 || !m.IsTri(m.heFace[s]) || !m.IsQuad(m.heFace[tw]) || m.VertexCount() >= vertexCap) return false;
        const int quad = m.heFace[tw];
        const std::vector<int> loop{tw, m.heNext[tw], m.heNext[m.heNext[tw]], m.hePrev[tw]};
        const int R = m.Org(tw), P = m.Dst(tw), x = m.Dst(loop[1]), y = m.Org(loop[3]), apex = m.Org(m.hePrev[s]);
        transitioned.resize(m.VertexCount(), 0);
        if (transitioned[P] || transitioned[R]) return false;  // one transition per place: no split-seam cycles
        const double len = m.Length(s);
        if (!(t * len > minLength && (1 - t) * len > minLength)) return false;
        const P3 point = m.pos[P] + (m.pos[R] - m.pos[P]) * t;
        int hm = home[P];
        const P3 M = proj.Project(point, hm);
        const P3 n = m.FaceNormal(quad) + m.FaceNormal(m.heFace[s]);
        const std::array<P3, 4> kept = triangleAtR ? std::array<P3, 4>{m.pos[P], m.pos[x], m.pos[y], M}
                                                   : std::array<P3, 4>{m.pos[R], M, m.pos[x], m.pos[y]};
        auto positive = [&](const P3 &a, const P3 &b, const P3 &c) { return ((b - a) ^ (c - a)) * n > 1e-3 * (b - a).SquaredNorm(); };
        if (QuadQuality(kept, n) <= std::max(p.minQuadJacobian, 0.2)) return false;
        if (triangleAtR ? !positive(M, m.pos[y], m.pos[R]) : !positive(M, m.pos[P], m.pos[x])) return false;
        if (!positive(m.pos[P], M, m.pos[apex]) || !positive(M, m.pos[R], m.pos[apex])) return false;  // the triangle ahead, split
        const int diagonalFrom = triangleAtR ? P : R, diagonalTo = triangleAtR ? y : x;
        if (m.EdgeExists(diagonalFrom, diagonalTo) || m.NewChordBetweenFrontNodes(diagonalFrom, diagonalTo)) return false;
        const int level = m.faceLevel[quad];
        // 1. the quad back into two triangles, along the diagonal the new quad keeps
        if (triangleAtR) m.ReplaceRegion(loop, {quad}, {}, {{0, 1, 3}, {1, 2, 3}}, level);  // (R P y) + (P x y)
        else m.ReplaceRegion(loop, {quad}, {}, {{0, 1, 2}, {0, 2, 3}}, level);              // (R P x) + (R x y)
        // 2. the new node on P-R, between triangles now
        const int v = NewVertexOnEdge(s, point);
        transitioned.resize(m.VertexCount(), 0);
        for (int w : {P, R, v, x, y}) transitioned[w] = 1;
        // 3. the two triangles of the new quad merged
        const int across = triangleAtR ? m.FindHalfEdge(y, P) : m.FindHalfEdge(R, x);
        const int q = m.MergeTriangles(across, level);
        ++stats.transitionSplits;
        AfterNewFaces({q}, {v});
        for (int w : {P, R, x, y}) PushAround(w);
        return true;
    }

    // A front edge far longer than both its neighbours (rows of very different sizes meeting) gets
    // a transition split at its middle, on the side where the quad left behind is better.
    bool SplitLongFrontEdge(int h)
    {
        if (m.heTwin[h] < 0) return false;
        const int prev = front.PrevFront(h), next = front.NextFront(h);
        if (prev < 0 || next < 0) return false;
        if (m.Length(h) <= p.transitionRatio * std::max(m.Length(prev), m.Length(next)) || m.Length(h) <= p.transitionMinLength * meanLength) return false;
        return TransitionSplit(h, 0.5, true) || TransitionSplit(h, 0.5, false);
    }

    // ---- small loops ----------------------------------------------------------------------------
    bool CloseSmallLoop(int h, int len)
    {
        if (len < 4) return false;  // a triangle (or a 2-edge lens) stays as it is
        std::vector<int> loop;
        front.Loop(h, loop);
        if (int(loop.size()) != len) return false;
        for (size_t i = 0; i < loop.size(); ++i)
            for (size_t j = i + 1; j < loop.size(); ++j)
                if (m.vertKey[m.Org(loop[i])] == m.vertKey[m.Org(loop[j])]) return false;  // the loop touches itself
        std::vector<int> faces, inner;
        if (!RegionInside(loop, faces, inner)) return false;
        if (inner.size() > 2) return false;  // a large region behind a short loop: advance into it instead
        {
            std::vector<int> corners;
            for (int e : loop) corners.push_back(m.Org(e));
            if (!InnerNodesNearQuad(inner, corners)) return false;
        }
        P3 n(0, 0, 0);
        for (int f : faces) n += m.FaceNormal(f);
        std::vector<int> v;
        for (int e : loop) v.push_back(m.Org(e));
        const int L = len;
        auto at = [&](int i) { return v[((i % L) + L) % L]; };
        std::vector<std::vector<int>> bestPolys;
        double bestQ = p.minQuadJacobian;
        if (L == 4) {
            double q = QuadQuality(v[0], v[1], v[2], v[3], n);
            if (q > bestQ) { bestQ = q; bestPolys = {{0, 1, 2, 3}}; }
        } else if (L == 5) {
            for (int i = 0; i < 5; ++i) {
                double q = QuadQuality(at(i), at(i + 1), at(i + 2), at(i + 3), n);
                if (q > bestQ && TriPositive(at(i + 3), at(i + 4), at(i), n)) {
                    bestQ = q;
                    bestPolys = {{i, (i + 1) % 5, (i + 2) % 5, (i + 3) % 5}, {(i + 3) % 5, (i + 4) % 5, i}};
                }
            }
        } else if (L == 6) {
            for (int i = 0; i < 3; ++i) {
                double q = std::min(QuadQuality(at(i), at(i + 1), at(i + 2), at(i + 3), n),
                                    QuadQuality(at(i + 3), at(i + 4), at(i + 5), at(i), n));
                if (q > bestQ) {
                    bestQ = q;
                    bestPolys = {{i, i + 1, i + 2, (i + 3) % 6}, {(i + 3) % 6, (i + 4) % 6, (i + 5) % 6, i}};
                }
            }
        }
        if (bestPolys.empty()) return false;
        for (const auto &poly : bestPolys) {
            for (size_t k = 0; k < poly.size(); ++k) {
                int i = poly[k], j = poly[(k + 1) % poly.size()];
                if (j != (i + 1) % L && (m.EdgeOutside(v[i], v[j], faces) || m.NewChordBetweenFrontNodes(v[i], v[j])))
                    return false;  // the new diagonal exists, or could exist in the neighbouring patch
            }
            if (poly.size() == 4 && !m.QuadHasFreeDiagonal(v[poly[0]], v[poly[1]], v[poly[2]], v[poly[3]], faces)) return false;
        }
        int level = 0;
        for (int e : loop) level = std::max(level, front.Level(e));
        int first = m.ReplaceRegion(loop, faces, inner, bestPolys, level + 1);
        ++stats.templates;
        std::vector<int> created;
        for (size_t k = 0; k < bestPolys.size(); ++k) created.push_back(first + int(k));
        AfterNewFaces(created, {});
        return true;
    }

    // Triangles enclosed by a front loop (they must reach no other front edge) and inner nodes.
    bool RegionInside(const std::vector<int> &loop, std::vector<int> &faces, std::vector<int> &inner) const
    {
        faces.assign(1, m.heFace[loop[0]]);
        inner.clear();
        std::vector<int> stack{faces[0]};
        while (!stack.empty()) {
            int f = stack.back();
            stack.pop_back();
            if (!m.IsTri(f)) return false;
            int g = m.faceHe[f];
            for (int k = 0; k < 3; ++k, g = m.heNext[g]) {
                if (std::find(loop.begin(), loop.end(), g) != loop.end()) continue;
                int t = m.heTwin[g];
                if (t < 0 || !m.IsTri(m.heFace[t])) return false;
                int nf = m.heFace[t];
                if (std::find(faces.begin(), faces.end(), nf) == faces.end()) {
                    if (faces.size() > 512) return false;
                    faces.push_back(nf);
                    stack.push_back(nf);
                }
            }
        }
        for (int f : faces) {
            int g = m.faceHe[f];
            for (int k = 0; k < 3; ++k, g = m.heNext[g]) {
                int x = m.Org(g);
                bool onLoop = false;
                for (int e : loop) onLoop = onLoop || m.Org(e) == x;
                if (!onLoop && std::find(inner.begin(), inner.end(), x) == inner.end()) {
                    if (m.vertFixed[x]) return false;
                    inner.push_back(x);
                }
            }
        }
        return int(faces.size()) == 2 * int(inner.size()) + int(loop.size()) - 2;
    }

    // ---- post-processing ------------------------------------------------------------------------
    void PairLeftoverTriangles(double minQuality)
    {
        struct Pair { double q; int h; };
        std::vector<Pair> pairs;
        for (int h = 0; h < m.HalfEdgeCount(); ++h) {
            int t = m.heTwin[h];
            if (t < h || !m.HeAlive(h) || !m.IsTri(m.heFace[h]) || !m.IsTri(m.heFace[t])) continue;
            double q = PairQuality(h);
            if (q > minQuality) pairs.push_back({q, h});
        }
        std::sort(pairs.begin(), pairs.end(), [](const Pair &x, const Pair &y) { return x.q > y.q; });
        for (const Pair &pr : pairs) {
            int h = pr.h, t = m.heTwin[h];
            if (!m.HeAlive(h) || t < 0 || !m.IsTri(m.heFace[h]) || !m.IsTri(m.heFace[t])) continue;
            m.MergeTriangles(h, 0);
            ++stats.pairedTriangles;
        }
    }
    // Triangles left in different places (e.g. two loops of odd length) are brought together
    // through the quads between them: a triangle and the quad it touches form a pentagon, re-split
    // into a quad and a triangle that touches another face; when the triangle reaches another
    // triangle the two merge into a quad. A breadth-first search over these moves (simulated on
    // vertex positions, every intermediate quad checked) finds a sequence, which is then applied.
    // Connectivity only: no node moves, no new node.
    struct Move {
        std::array<int, 3> v;  // triangle, counter-clockwise
        std::array<int, 3> e;  // half-edge of side v[k]->v[k+1] in the mesh, -1 for a new diagonal
        int face;              // face entered (the triangle's own face for the start)
        int option;            // pentagon split used to get here
        int parent;
        int depth;
    };

    // The pentagon formed by triangle `t` (its side k shared with quad across) and that quad:
    // vertices and side half-edges, counter-clockwise, as MigrateStep builds it.
    void Pentagon(const Move &t, int k, std::array<int, 5> &v, std::array<int, 5> &e) const
    {
        int tw = m.heTwin[t.e[k]];
        e = {t.e[(k + 1) % 3], t.e[(k + 2) % 3], m.heNext[tw], m.heNext[m.heNext[tw]], m.hePrev[tw]};
        v = {t.v[(k + 1) % 3], t.v[(k + 2) % 3], t.v[k], m.Org(e[3]), m.Org(e[4])};
    }

    bool SplitIsValid(const std::array<int, 5> &v, int i, const P3 &n) const
    {
        for (int a = 0; a < 5; ++a)
            for (int b = a + 1; b < 5; ++b)
                if (m.vertKey[v[a]] == m.vertKey[v[b]]) return false;
        int a = v[i], b = v[(i + 1) % 5], c = v[(i + 2) % 5], d = v[(i + 3) % 5], e = v[(i + 4) % 5];
        // the quad's diagonals must not be edges already (except the edge being removed, v[0]-v[2])
        auto taken = [&](int x, int y) {
            bool removed = (x == v[0] && y == v[2]) || (x == v[2] && y == v[0]);
            return !removed && m.EdgeExists(x, y);
        };
        return !m.EdgeExists(a, c) && !m.NewChordBetweenFrontNodes(a, c) && TriPositive(a, b, c, n) && QuadQuality(c, d, e, a, n) > p.migrationMinJacobian &&
               !(taken(c, e) && taken(d, a));
    }

    void MigrateTrianglesIntoPairs()
    {
        std::vector<char> gaveUp;
        int triangles = 0;  // a search needs a partner: none when a single triangle is left
        for (int f = 0; f < m.FaceCount(); ++f) triangles += m.FaceAlive(f) && m.IsTri(f);
        for (int round = 0; round < 100000 && triangles >= 2; ++round) {
            int tri = -1;
            for (int f = 0; f < m.FaceCount() && tri < 0; ++f)
                if (m.FaceAlive(f) && m.IsTri(f) && (f >= int(gaveUp.size()) || !gaveUp[f])) tri = f;
            if (tri < 0) return;
            std::vector<Move> moves;
            int goal = -1, goalSide = -1;
            if (!SearchMigration(tri, moves, goal, goalSide)) {
                if (int(gaveUp.size()) < m.FaceCount()) gaveUp.resize(m.FaceCount(), 0);
                gaveUp[tri] = 1;
                continue;
            }
            std::vector<int> chain;
            for (int s = goal; s >= 0; s = moves[s].parent) chain.push_back(s);
            std::reverse(chain.begin(), chain.end());
            int current = tri;
            for (size_t i = 1; i < chain.size() && current >= 0; ++i)
                current = MigrateStep(current, moves[chain[i]].face, moves[chain[i]].option);
            int target = current >= 0 ? m.heFace[m.heTwin[moves[goal].e[goalSide]]] : -1;
            int shared = current >= 0 ? SharedHalfEdge(current, target) : -1;
            if (shared < 0) return;  // cannot happen: the search simulated exactly these steps
            m.MergeTriangles(shared, 0);
            ++stats.pairedTriangles;
            triangles -= 2;
        }
    }

    bool SearchMigration(int tri, std::vector<Move> &moves, int &goal, int &goalSide) const
    {
        Move start;
        int g = m.faceHe[tri];
        for (int k = 0; k < 3; ++k, g = m.heNext[g]) { start.v[k] = m.Org(g); start.e[k] = g; }
        start.face = tri;
        start.option = -1;
        start.parent = -1;
        start.depth = 0;
        moves.assign(1, start);
        std::unordered_map<int, int> crossings;  // face -> how many searched triangles entered it
        for (size_t head = 0; head < moves.size() && moves.size() < 100000; ++head) {
            const Move t = moves[head];
            if (t.depth > 96) continue;  // a triangle on a straight front travels along the first row to a corner
            for (int k = 0; k < 3; ++k) {
                if (t.e[k] < 0 || m.heTwin[t.e[k]] < 0) continue;
                int face = m.heFace[m.heTwin[t.e[k]]];
                bool onPath = false;
                for (int s = int(head); s >= 0 && !onPath; s = moves[s].parent) onPath = moves[s].face == face;
                if (onPath) continue;
                P3 n = m.FaceNormal(face) + m.FaceNormal(t.face);
                if (m.IsTri(face)) {
                    int w = m.Org(m.hePrev[m.heTwin[t.e[k]]]);  // the other triangle's apex
                    if (face != tri && QuadQuality(t.v[(k + 1) % 3], t.v[(k + 2) % 3], t.v[k], w, n) > p.migrationMinJacobian) {
                        goal = int(head);
                        goalSide = k;
                        return true;
                    }
                    continue;
                }
                // a face may be crossed by a few different triangles (other pentagon splits)
                if (++crossings[face] > 4) continue;
                std::array<int, 5> v, e;
                Pentagon(t, k, v, e);
                for (int i = 0; i < 5; ++i) {
                    if (!SplitIsValid(v, i, n)) continue;
                    Move next;
                    next.v = {v[i], v[(i + 1) % 5], v[(i + 2) % 5]};
                    next.e = {e[i], e[(i + 1) % 5], -1};
                    next.face = face;
                    next.option = i;
                    next.parent = int(head);
                    next.depth = t.depth + 1;
                    moves.push_back(next);
                }
            }
        }
        return false;
    }

    int SharedHalfEdge(int f, int g) const
    {
        int h = m.faceHe[f];
        for (int k = 0; k < m.faceSize[f]; ++k, h = m.heNext[h])
            if (m.heTwin[h] >= 0 && m.heFace[m.heTwin[h]] == g) return h;
        return -1;
    }

    // Triangle `tri` + adjacent quad `quad` -> triangle (pentagon positions option..option+2) + quad.
    int MigrateStep(int tri, int quad, int option)
    {
        int shared = SharedHalfEdge(tri, quad);
        if (shared < 0) return -1;
        int t = m.heTwin[shared];
        std::vector<int> loop{m.heNext[shared], m.hePrev[shared], m.heNext[t], m.heNext[m.heNext[t]], m.hePrev[t]};
        const int i = option;
        return m.ReplaceRegion(loop, {tri, quad}, {},
                               {{i, (i + 1) % 5, (i + 2) % 5}, {(i + 2) % 5, (i + 3) % 5, (i + 4) % 5, i}}, m.faceLevel[quad]);
    }

    double PairQuality(int h) const
    {
        int t = m.heTwin[h];
        int a = m.Org(h), b = m.Dst(h), c = m.Org(m.hePrev[h]), d = m.Org(m.hePrev[t]);
        if (!m.QuadHasFreeDiagonal(b, c, a, d, {m.heFace[h], m.heFace[t]})) return -1;
        P3 n = m.FaceNormal(m.heFace[h]) + m.FaceNormal(m.heFace[t]);
        return QuadQuality(b, c, a, d, n);
    }

    void DissolveDoublets()
    {
        for (bool changed = true; changed;) {
            changed = false;
            for (int v = 0; v < m.VertexCount(); ++v)
                if (m.vertAlive[v] && !m.vertFixed[v] && m.Valence(v) == 2 && DoubletMergeIsValid(v) && m.DissolveDoublet(v)) {
                    ++stats.doublets;
                    changed = true;
                }
        }
    }

    // The quad left after removing a doublet node must not be inverted.
    bool DoubletMergeIsValid(int v) const
    {
        std::vector<int> out;
        m.ForEachOutgoing(v, [&](int g) { out.push_back(g); });
        if (out.size() != 2 || !m.IsQuad(m.heFace[out[0]]) || !m.IsQuad(m.heFace[out[1]])) return false;
        int h1 = out[0], h2 = out[1];
        int a = m.Dst(h1), b = m.Dst(m.heNext[h1]), c = m.Dst(h2), d = m.Dst(m.heNext[h2]);
        P3 n = m.FaceNormal(m.heFace[h1]) + m.FaceNormal(m.heFace[h2]);
        return QuadQuality(a, b, c, d, n) > p.minQuadJacobian && m.QuadHasFreeDiagonal(a, b, c, d, {m.heFace[h1], m.heFace[h2]}) &&
               InnerNodesNearQuad({v}, {a, b, c, d});
    }

    // Topological clean-up: an edge shared by two quads is turned to join the other pair of
    // opposite corners of their hexagon when that brings the four nodes' valences closer to their
    // ideal (4 inside; on the patch boundary, one more than the number of right angles that fit
    // in the node's angle) and the two new quads are not worse than 0.3 scaled Jacobian (or than
    // the old ones).
    // Squared distance of valence `val` at node v from its ideal (4 for nodes made after `ideal`).
    static double ValenceDeviation(const std::vector<int> &ideal, int v, int val)
    {
        const double d = val - (v < int(ideal.size()) ? ideal[v] : 4);
        return d * d;
    }

    // Ideal valence per node: 4 inside; on the patch boundary, one more than the number of right
    // angles that fit in the node's angle.
    std::vector<int> IdealValences() const
    {
        std::vector<int> ideal(m.VertexCount(), 4);
        for (int v = 0; v < m.VertexCount(); ++v) {
            if (!m.vertAlive[v] || !m.OnBoundary(v)) continue;
            double angle = 0;
            m.ForEachOutgoing(v, [&](int g) { angle += m.CornerAngle(g); });
            ideal[v] = std::max(1, int(std::lround(angle / (M_PI / 2)))) + 1;
        }
        return ideal;
    }

    // Quad clean-up by diagonal collapse: the quad (a b c d) vanishes and c joins a at their
    // midpoint (a and c inside the patch) when that brings the valences of a, b, c, d closer to
    // their ideal: typically a and c of valence 3 with b or d of valence 5. The quads around must
    // stay fair (not below 0.3 scaled Jacobian or below the worst of them now).
    void CollapseQuadDiagonals()
    {
        const std::vector<int> ideal = IdealValences();
        auto dev = [&](int v, int val) { return ValenceDeviation(ideal, v, val); };
        for (int pass = 0; pass < 3; ++pass) {
            int collapsed = 0;
            for (int f = 0; f < m.FaceCount(); ++f) {
                if (!m.FaceAlive(f) || !m.IsQuad(f)) continue;
                std::vector<int> loop{m.faceHe[f], m.heNext[m.faceHe[f]], m.heNext[m.heNext[m.faceHe[f]]], m.hePrev[m.faceHe[f]]};
                for (int i = 0; i < 2; ++i) {
                    const int a = m.Org(loop[i]), b = m.Org(loop[i + 1]), c = m.Org(loop[i + 2]), d = m.Org(loop[(i + 3) % 4]);
                    if (m.vertFixed[a] || m.vertFixed[c] || !m.DistinctNodes({a, b, c, d})) continue;
                    const int va = m.Valence(a), vb = m.Valence(b), vc = m.Valence(c), vd = m.Valence(d);
                    const double before = dev(a, va) + dev(b, vb) + dev(c, vc) + dev(d, vd);
                    const double after = dev(a, va + vc - 2) + dev(b, vb - 1) + dev(d, vd - 1);
                    if (after >= before || vb <= 3 || vd <= 3) continue;
                    if (CollapseQuad(f, i)) { ++collapsed; break; }
                }
            }
            stats.diagonalCollapses += collapsed;
            if (!collapsed) break;
        }
    }

    // Quad open, the inverse of a diagonal collapse: an interior node whose neighbours a and b,
    // `span` edges apart around it, are short of edges (typically valence 5 with two valence-3
    // neighbours two edges apart) is split in two with a new quad between a and b: valences
    // 5, 3, 3 become 3, 4, 4, 4. Each half moves a third of the way toward its own neighbours and
    // back onto the surface; every quad around must stay fair.
    void OpenQuads()
    {
        const std::vector<int> ideal = IdealValences();
        auto dev = [&](int v, int val) { return ValenceDeviation(ideal, v, val); };
        auto devInside = [](int val) { return ValenceDeviation({}, 0, val); };
        for (int pass = 0; pass < 2; ++pass) {
            int opened = 0;
            const int count = m.VertexCount();
            for (int v = 0; v < count && m.VertexCount() < vertexCap; ++v) {
                if (!m.vertAlive[v] || m.vertFixed[v] || m.OnBoundary(v)) continue;
                std::vector<int> out;
                bool allQuads = true;
                m.ForEachOutgoing(v, [&](int g) {
                    out.push_back(g);
                    allQuads = allQuads && m.IsQuad(m.heFace[g]);
                });
                const int n = int(out.size());
                if (!allQuads || n < 5 || n > 8) continue;
                double bestGain = 0.5;
                int bestI = -1, bestSpan = 0;
                for (int i = 0; i < n; ++i)
                    for (int span = 2; span <= n - 2; ++span) {
                        const int a = m.Dst(out[i]), b = m.Dst(out[(i + span) % n]);
                        if (!m.DistinctNodes({v, a, b})) continue;
                        const int va = m.Valence(a), vb = m.Valence(b);
                        const double before = devInside(n) + dev(a, va) + dev(b, vb);
                        const double after = devInside(span + 1) + devInside(n - span + 1) + dev(a, va + 1) + dev(b, vb + 1);
                        if (before - after > bestGain) { bestGain = before - after; bestI = i; bestSpan = span; }
                    }
                if (bestI >= 0 && OpenQuadAt(v, out, bestI, (bestI + bestSpan) % n)) ++opened;
            }
            stats.quadsOpened += opened;
            if (!opened) break;
        }
    }

    bool OpenQuadAt(int v, const std::vector<int> &out, int i, int j)
    {
        const int n = int(out.size());
        // the two halves sit on either side of the line a-b, around v's foot on it: the new quad
        // (a v b v') is then a rhombus with diagonals a-b and v-v'
        const int a = m.Dst(out[i]), b = m.Dst(out[j]);
        const P3 normal = m.VertexNormal(v), ab = m.pos[b] - m.pos[a];
        const double t = std::max(0.25, std::min(0.75, ((m.pos[v] - m.pos[a]) * ab) / ab.SquaredNorm()));
        const P3 centre = (m.pos[v] + (m.pos[a] + ab * t)) * 0.5;
        P3 side = normal ^ ab;
        P3 own(0, 0, 0);  // v's own neighbours (strictly between a and b) tell which side is its
        for (int k = (i + 1) % n; k != j; k = (k + 1) % n) own += m.pos[m.Dst(out[k])] - centre;
        if (!(side.Norm() > 0)) return false;
        side.Normalize();
        if (side * own < 0) side = -side;
        const double half = 0.3 * ab.Norm();
        int home1 = home[v], home2 = home[v];
        const P3 p1 = proj.Project(centre + side * half, home1), p2 = proj.Project(centre - side * half, home2);
        // every quad around (v replaced by its half's position) and the new quad must be fair
        auto fair = [&](int k, const P3 &at) {
            const int g = out[k];
            const P3 n0 = m.FaceNormal(m.heFace[g]);
            const std::array<P3, 4> q{at, m.pos[m.Dst(g)], m.pos[m.Dst(m.heNext[g])], m.pos[m.Org(m.hePrev[g])]};
            const double before = QuadQuality({m.pos[v], q[1], q[2], q[3]}, n0);
            return QuadQuality(q, n0) >= std::min(0.3, before);
        };
        for (int k = i; k != j; k = (k + 1) % n)
            if (!fair(k, p1)) return false;
        for (int k = j; k != i; k = (k + 1) % n)
            if (!fair(k, p2)) return false;
        if (QuadQuality({m.pos[a], p1, m.pos[b], p2}, normal) < 0.3) return false;
        // the surface must not flatten: v's old place stays near the new quad (as in quad formation)
        if (std::min(PointTriangleDistance(m.pos[v], m.pos[a], p1, m.pos[b]), PointTriangleDistance(m.pos[v], m.pos[a], m.pos[b], p2)) >
            0.1 * meanLength)
            return false;
        const int w = m.OpenQuad(v, i, j, p1, p2, m.faceLevel[m.heFace[out[i]]]);
        home.resize(m.VertexCount(), 0);
        home[v] = home1;
        home[w] = home2;
        for (int it = 0; it < 2; ++it)
            for (int x : {v, w}) SmoothNode(x);
        return true;
    }

    // Collapses quad f along its diagonal from corner i to corner i+2 (the second joins the first).
    bool CollapseQuad(int f, int i)
    {
        std::vector<int> loop{m.faceHe[f], m.heNext[m.faceHe[f]], m.heNext[m.heNext[m.faceHe[f]]], m.hePrev[m.faceHe[f]]};
        const int a = m.Org(loop[i]), c = m.Org(loop[i + 2]);
        int hm = home[a];
        const P3 at = proj.Project((m.pos[a] + m.pos[c]) * 0.5, hm);
        // the faces around a and c but f, with a and c at `at`
        const std::vector<int> faces = m.FacesAround({a, c}, {f});
        const std::pair<double, double> worst =
            m.WorstQualityIfMoved({a, c}, at, faces, [&](int g, const P3 &n) { return FaceQualityAt(g, n); });
        // the surface must not flatten: the old nodes stay near the new faces (as in quad formation)
        const P3 oldA = m.pos[a], oldC = m.pos[c];
        m.pos[a] = m.pos[c] = at;
        double farthest = 0;
        for (const P3 &old : {oldA, oldC}) {
            double nearest = 1e300;
            for (int h : faces) {
                const int g = m.faceHe[h];
                const int v0 = m.Org(g), v1 = m.Dst(g), v2 = m.Dst(m.heNext[g]);
                nearest = std::min(nearest, PointTriangleDistance(old, m.pos[v0], m.pos[v1], m.pos[v2]));
                if (m.IsQuad(h)) nearest = std::min(nearest, PointTriangleDistance(old, m.pos[v0], m.pos[v2], m.pos[m.Org(m.hePrev[g])]));
            }
            farthest = std::max(farthest, nearest);
        }
        m.pos[a] = oldA;
        m.pos[c] = oldC;
        if (worst.second < std::min(0.3, worst.first) || worst.second <= 0.05 || farthest > 0.1 * meanLength) return false;
        const int level = m.faceLevel[f];
        m.ReplaceRegion(loop, {f}, {}, {{i, i + 1, i + 2}, {i, i + 2, (i + 3) % 4}}, level);
        const int diagonal = m.FindHalfEdge(a, c);
        if (diagonal >= 0 && m.CollapseEdge(diagonal, at)) {
            home[a] = hm;
            return true;
        }
        if (diagonal >= 0) m.MergeTriangles(diagonal, level);  // undo the split
        return false;
    }

    // Quads still below 0.3 scaled Jacobian: each free node of theirs moves (in its tangent plane,
    // back onto the input surface) to the nearby position that most raises the worst quality of
    // its faces. A local pattern search; only moves that raise that worst quality are kept.
    void ImproveBadQuads()
    {
        for (int pass = 0; pass < 4; ++pass) {
            int moved = 0;
            for (int f = 0; f < m.FaceCount(); ++f) {
                if (!m.FaceAlive(f) || !m.IsQuad(f) || m.QuadScaledJacobian(f) >= 0.3) continue;
                int g = m.faceHe[f];
                for (int k = 0; k < 4; ++k, g = m.heNext[g])
                    if (!m.vertFixed[m.Org(g)]) moved += OptimizeNode(m.Org(g));
            }
            if (!moved) break;
        }
    }

    bool OptimizeNode(int v)
    {
        std::vector<int> faces;
        std::vector<P3> normals;
        double length = 0;
        int edges = 0;
        m.ForEachOutgoing(v, [&](int g) {
            faces.push_back(m.heFace[g]);
            normals.push_back(m.FaceNormal(m.heFace[g]).Normalize());
            length += m.Length(g);
            ++edges;
        });
        if (!edges) return false;
        length /= edges;
        auto worst = [&]() {
            double w = 1e9;
            for (size_t i = 0; i < faces.size(); ++i) w = std::min(w, FaceQualityAt(faces[i], normals[i]));
            return w;
        };
        // how far the faces' centres are from the input surface: a move must not cut a feature
        auto deviation = [&]() {
            double d = 0;
            for (int f : faces) {
                P3 c(0, 0, 0);
                int g = m.faceHe[f];
                for (int k = 0; k < m.faceSize[f]; ++k, g = m.heNext[g]) c += m.pos[m.Org(g)];
                c /= m.faceSize[f];
                int hm = home[v];
                d = std::max(d, (proj.Project(c, hm) - c).Norm());
            }
            return d;
        };
        const P3 start = m.pos[v];
        const double current = worst();
        const double allowed = std::max(deviation(), 0.05 * meanLength);
        const P3 n = m.VertexNormal(v);
        P3 t1 = std::fabs(n[0]) < 0.9 ? P3(1, 0, 0) : P3(0, 1, 0);
        t1 = (t1 - n * (t1 * n)).Normalize();
        const P3 t2 = n ^ t1;
        double best = current;
        P3 bestPos = start;
        int bestHome = home[v];
        for (double step : {0.3, 0.15, 0.07}) {
            const P3 centre = bestPos;
            for (int k = 0; k < 8; ++k) {
                const double angle = k * M_PI / 4;
                int hm = bestHome;
                const P3 candidate = proj.Project(centre + (t1 * std::cos(angle) + t2 * std::sin(angle)) * (step * length), hm);
                m.pos[v] = candidate;
                const double q = worst();
                if (q > best + 1e-6 && deviation() <= allowed) { best = q; bestPos = candidate; bestHome = hm; }
            }
        }
        if (best < current + 0.01) {
            m.pos[v] = start;
            return false;
        }
        m.pos[v] = bestPos;
        home[v] = bestHome;
        return true;
    }

    void ImproveValences()
    {
        const std::vector<int> ideal = IdealValences();
        auto dev = [&](int v, int val) { return ValenceDeviation(ideal, v, val); };
        for (int pass = 0; pass < 4; ++pass) {
            int turned = 0;
            for (int h = 0; h < m.HalfEdgeCount(); ++h) {
                int t = m.heTwin[h];
                if (t < h || !m.HeAlive(h) || !m.IsQuad(m.heFace[h]) || !m.IsQuad(m.heFace[t])) continue;
                // hexagon b c d a e f (quads (a b c d) and (b a e f) share a-b)
                std::vector<int> loop{m.heNext[h], m.heNext[m.heNext[h]], m.hePrev[h], m.heNext[t], m.heNext[m.heNext[t]], m.hePrev[t]};
                int v[6];
                for (int k = 0; k < 6; ++k) v[k] = m.Org(loop[k]);
                bool distinct = true;
                for (int i = 0; i < 6; ++i)
                    for (int j = i + 1; j < 6; ++j) distinct = distinct && m.vertKey[v[i]] != m.vertKey[v[j]];
                if (!distinct) continue;
                int val[6];
                for (int k = 0; k < 6; ++k) val[k] = m.Valence(v[k]);
                const int a = 3, b = 0;  // positions of the current diagonal's ends
                P3 n = m.FaceNormal(m.heFace[h]) + m.FaceNormal(m.heFace[t]);
                double oldQ = std::min(m.QuadScaledJacobian(m.heFace[h]), m.QuadScaledJacobian(m.heFace[t]));
                double oldDev = dev(v[a], val[a]) + dev(v[b], val[b]);
                int bestI = -1;
                double bestGain = 1e-9, bestQ = 0;
                for (int i : {1, 2}) {  // new diagonal between positions i and i+3
                    int j = i + 3;
                    if (m.EdgeExists(v[i], v[j]) || m.NewChordBetweenFrontNodes(v[i], v[j])) continue;
                    double before = oldDev + dev(v[i], val[i]) + dev(v[j], val[j]);
                    double after = dev(v[a], val[a] - 1) + dev(v[b], val[b] - 1) + dev(v[i], val[i] + 1) + dev(v[j], val[j] + 1);
                    double q = std::min(QuadQuality(v[i], v[i + 1], v[i + 2], v[j], n), QuadQuality(v[j], v[(j + 1) % 6], v[(j + 2) % 6], v[i], n));
                    if (q < std::min(0.3, oldQ)) continue;
                    if (before - after > bestGain) { bestGain = before - after; bestI = i; bestQ = q; }
                }
                if (bestI < 0) continue;
                const int i = bestI, j = i + 3;
                std::vector<int> corners1{v[i], v[i + 1], v[i + 2], v[j]}, corners2{v[j], v[(j + 1) % 6], v[(j + 2) % 6], v[i]};
                if (!m.QuadHasFreeDiagonal(corners1[0], corners1[1], corners1[2], corners1[3], {m.heFace[h], m.heFace[t]}) ||
                    !m.QuadHasFreeDiagonal(corners2[0], corners2[1], corners2[2], corners2[3], {m.heFace[h], m.heFace[t]}))
                    continue;
                int level = std::max(m.faceLevel[m.heFace[h]], m.faceLevel[m.heFace[t]]);
                m.ReplaceRegion(loop, {m.heFace[h], m.heFace[t]}, {}, {{i, i + 1, i + 2, j}, {j, (j + 1) % 6, (j + 2) % 6, i}}, level);
                (void)bestQ;
                ++turned;
            }
            stats.valenceTurns += turned;
            if (!turned) break;
        }
    }

    // ---- smoothing ------------------------------------------------------------------------------
    // keepToSurface: a move is undone when it takes one of the node's edges farther from the input
    // surface than it was (and than a twentieth of the mean input edge).
    void SmoothAll(bool keepToSurface = false)
    {
        for (int v = 0; v < m.VertexCount(); ++v)
            if (m.vertAlive[v] && !m.vertFixed[v]) {
                if (!keepToSurface) { SmoothNode(v); continue; }
                const P3 old = m.pos[v];
                const double before = EdgeDeviation(v);
                SmoothNode(v);
                if (EdgeDeviation(v) > std::max(before, 0.05 * meanLength)) m.pos[v] = old;  // an edge would cut a bend
            }
    }

    // How far the midpoints of v's edges are from the input surface.
    double EdgeDeviation(int v) const
    {
        double d = 0;
        m.ForEachOutgoing(v, [&](int g) {
            const P3 mid = (m.pos[v] + m.pos[m.Dst(g)]) * 0.5;
            int hm = home[v];
            d = std::max(d, (proj.Project(mid, hm) - mid).Norm());
        });
        return d;
    }

    // Laplacian target, moved only in the tangent plane, projected back onto the input surface;
    // kept only when no incident face inverts or degrades below its worst current quality.
    void SmoothNode(int v)
    {
        P3 sum(0, 0, 0);
        int n = 0;
        m.ForEachOutgoing(v, [&](int g) {
            sum += m.pos[m.Dst(g)];
            ++n;
        });
        if (n < 2) return;
        P3 target = sum / double(n);
        P3 nv = m.VertexNormal(v);
        P3 move = target - m.pos[v];
        move -= nv * (move * nv);
        TryMove(v, proj.Project(m.pos[v] + move, home[v]));
    }

    double FaceQualityAt(int f, const P3 &n) const
    {
        if (!m.IsQuad(f)) return m.TriangleQuality(f, n);
        const int g = m.faceHe[f];
        return QuadQuality(m.Org(g), m.Org(m.heNext[g]), m.Org(m.heNext[m.heNext[g]]), m.Org(m.hePrev[g]), n);
    }

    bool TryMove(int v, const P3 &to)
    {
        return m.TryMoveNode(v, to, [&](int f, const P3 &n) { return FaceQualityAt(f, n); });
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
