// Q-Morph's front advance on one patch (Owen, Staten, Canann, Saigal 1999): rows of quads from the
// patch boundary (the initial front) inward. Every geometric decision is made on the surface
// itself: front angles are sums of triangle corner angles, side directions are rotations inside a
// triangle, orientation tests use the node's normal from the patch's own faces.
//
// Per front edge A->B (highest state, lowest level first):
//   1. side edges at A and B: the adjacent front edge when the front angle is closed (< 3pi/4),
//      else an existing edge within pi/6 of the ideal direction, else a swap creating one, else
//      a split of the edge the ideal direction crosses; long sides are split to the base length;
//   2. the top edge between the side tips, recovered by swaps;
//   3. the triangles enclosed by base, sides and top merged into one quad (inner nodes removed);
//   4. local smoothing of the new front nodes and their triangle neighbours.
// Special cases: Owen's seam (two front edges at a small angle sewn together), transition seam and
// transition split (front edges of very different lengths), and loops of <= 6 edges closed by
// templates (a quad; a quad and a triangle; two quads). The initial front is never swapped, split
// or moved.
#ifndef VCG_EXT_QMORPH_FRONT_ADVANCE_H
#define VCG_EXT_QMORPH_FRONT_ADVANCE_H

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include <vcg_ext/qmorph/front.h>
#include <vcg_ext/qmorph/patch_stage.h>

namespace vcg_ext {
namespace qmorph {

class FrontAdvance : public PatchStage
{
public:
    explicit FrontAdvance(PatchContext &context) : PatchStage(context), front(context.m) {}

    // Advances the front until no front edge can make progress; what is left are triangles.
    void Run()
    {
        ImproveTriangulation();
        int triangles = 0;
        for (int f = 0; f < m.FaceCount(); ++f) triangles += m.FaceAlive(f) && m.IsTri(f);
        const long cap = kStepsPerTriangle * long(triangles) + kStepsSlack;
        failedAt.assign(m.HalfEdgeCount(), -1);
        for (int sweep = 0; sweep < kSweeps; ++sweep) {
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
                int len = front.LoopLength(h, kTemplateLoop);
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
    }

private:
    // Front steps allowed per input triangle (plus a few): bounds the work on any input.
    static constexpr long kStepsPerTriangle = 40, kStepsSlack = 1000;
    // Passes over the whole front; a pass that makes no progress ends the advance.
    static constexpr int kSweeps = 4;
    // Loops of at most this many edges are closed by templates.
    static constexpr int kTemplateLoop = 6;
    // Before the advance: edges between triangles within this many degrees of coplanar, next to a
    // corner thinner than kThinCornerDeg, are flipped when their opposite angles exceed pi by the
    // margin (a few passes): slivers make poor side edges.
    static constexpr double kFlatDihedralDeg = 15, kThinCornerDeg = 15, kDelaunayMargin = 0.1;
    static constexpr int kDelaunayPasses = 8;
    // Side edges: swaps tried before giving up; a split point at least kSplitFar times the base from
    // the node is taken at once, one at kSplitNear when no swap is possible; an existing edge up to
    // kSideFallback times the side tolerance off the ideal direction is the last resort.
    static constexpr int kSideAttempts = 4;
    static constexpr double kSplitFar = 0.5, kSplitNear = 0.2, kSideFallback = 2;
    // ... and a split never makes a side shorter than this fraction of the patch's mean edge: sides
    // measured by the base alone shrank with it, each split front edge shorter than the last (on
    // armadillo_52k re-meshed at 3 times its mean edge, bases 0.54 -> 0.08 -> 0.04 of a 3.9 target
    // around one junction, a cluster of tiny faces one of which stood on edge).
    static constexpr double kMinSideFraction = 0.1;
    // Split points stay this far inside the crossed edge (fractions of it): no slivers at its ends.
    static constexpr double kSplitMin = 0.15, kSplitMax = 0.85;
    // A side tip up to this many front edges away along the loop is checked for cutting an odd loop.
    static constexpr int kOddLoopLookahead = 7;
    // Top edge recovery gives up after this many swaps.
    static constexpr int kRecoverSwaps = 24;
    // Seams: the joined nodes move at most this fraction of the shorter edge out of their tangent
    // planes, and the faces around keep at least this quality.
    static constexpr double kSeamOffPlane = 0.1, kSeamMinQuality = 0.05;
    // A transition split keeps a quad at least this good behind the front.
    static constexpr double kTransitionMinQuad = 0.2;
    // Templates close a loop only over a small region (nodes, faces); else the front advances into it.
    static constexpr size_t kTemplateMaxInner = 2, kTemplateMaxFaces = 512;

    Front front;
    FrontQueue queue;
    std::vector<int> failedAt;       // per half-edge: success count when it last failed
    std::vector<char> transitioned;  // per node: part of a transition split already
    int successes = 0;

    // Intrinsic Delaunay flips of the near-flat interior edges next to thin triangles, before the
    // front starts: slivers (from splitting) make poor side edges. Well-shaped triangulations
    // (grids, isotropic meshes) are left alone: their structure pairs into good quads. Only edges
    // whose two triangles are within 15 degrees of coplanar are flipped: the surface barely changes.
    void ImproveTriangulation()
    {
        const double maxDihedral = std::cos(kFlatDihedralDeg * M_PI / 180);
        for (int pass = 0; pass < kDelaunayPasses; ++pass) {
            int flips = 0;
            for (int h = 0; h < m.HalfEdgeCount(); ++h) {
                int t = m.heTwin[h];
                if (t < h || !m.HeAlive(h) || !m.IsTri(m.heFace[h]) || !m.IsTri(m.heFace[t])) continue;
                double opposite = m.CornerAngle(m.hePrev[h]) + m.CornerAngle(m.hePrev[t]);
                if (opposite <= M_PI + kDelaunayMargin) continue;
                if (std::min(MinCorner(m.heFace[h]), MinCorner(m.heFace[t])) > kThinCornerDeg * M_PI / 180) continue;
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
        for (int attempt = 0; attempt < kSideAttempts && tip < 0; ++attempt) {
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
            const double sideFloor = kMinSideFraction * meanLength;
            if (canSplit && (point - m.pos[node]).Norm() >= std::max(kSplitFar * base, sideFloor)) {
                tip = NewVertexOnEdge(e, point);
                break;
            }
            if (isKept(e) || !m.CanFlip(e)) {
                if (canSplit && (point - m.pos[node]).Norm() >= std::max(kSplitNear * base, sideFloor)) tip = NewVertexOnEdge(e, point);
                else if (best >= 0 && std::fabs(fan.edges[best].angle - ideal) < kSideFallback * p.sideTolerance) tip = fan.edges[best].vertex;
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
        for (int d = 1; d <= kOddLoopLookahead; ++d) {
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
        if (!(t > kSplitMin && t < kSplitMax)) t = std::max(kSplitMin, std::min(kSplitMax, t));
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
        for (int iter = 0; iter < kRecoverSwaps; ++iter) {
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
        P3 n = m.InputNormal(from);
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
        if (QuadShape(a, b, c, d) <= p.minQuadJacobian) return false;
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
        const double limit = kSeamOffPlane * std::min(m.Length(h), m.Length(n));
        if (std::fabs((m.pos[gone] - at) * m.InputNormal(gone)) > limit ||
            std::fabs((m.pos[keep] - at) * m.InputNormal(keep)) > limit)
            return false;
        // the faces that stay around both nodes must stay valid with the joined node at `at`
        const std::vector<int> faces = m.FacesAround({keep, gone}, {m.heFace[h0], m.heFace[m.heTwin[h0]]});
        bool valid = WorstQualityIfMoved({keep, gone}, at, faces) > kSeamMinQuality;
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
        const P3 n = m.InputFaceNormal(quad) + m.InputFaceNormal(m.heFace[s]);
        const std::array<P3, 4> kept = triangleAtR ? std::array<P3, 4>{m.pos[P], m.pos[x], m.pos[y], M}
                                                   : std::array<P3, 4>{m.pos[R], M, m.pos[x], m.pos[y]};
        auto positive = [&](const P3 &a, const P3 &b, const P3 &c) { return ((b - a) ^ (c - a)) * n > kMinSine * (b - a).SquaredNorm(); };
        if (QuadShape(kept, n) <= std::max(p.minQuadJacobian, kTransitionMinQuad)) return false;
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
        if (inner.size() > kTemplateMaxInner) return false;  // a large region behind a short loop: advance into it instead
        {
            std::vector<int> corners;
            for (int e : loop) corners.push_back(m.Org(e));
            if (!InnerNodesNearQuad(inner, corners)) return false;
        }
        std::vector<int> v;
        for (int e : loop) v.push_back(m.Org(e));
        const int L = len;
        auto at = [&](int i) { return v[((i % L) + L) % L]; };
        std::vector<std::vector<int>> bestPolys;
        double bestQ = p.minQuadJacobian;
        if (L == 4) {
            double q = QuadShape(v[0], v[1], v[2], v[3]);
            if (q > bestQ) { bestQ = q; bestPolys = {{0, 1, 2, 3}}; }
        } else if (L == 5) {
            for (int i = 0; i < 5; ++i) {
                double q = QuadShape(at(i), at(i + 1), at(i + 2), at(i + 3));
                if (q > bestQ && TriPositive(at(i + 3), at(i + 4), at(i))) {
                    bestQ = q;
                    bestPolys = {{i, (i + 1) % 5, (i + 2) % 5, (i + 3) % 5}, {(i + 3) % 5, (i + 4) % 5, i}};
                }
            }
        } else if (L == 6) {
            for (int i = 0; i < 3; ++i) {
                double q = std::min(QuadShape(at(i), at(i + 1), at(i + 2), at(i + 3)),
                                    QuadShape(at(i + 3), at(i + 4), at(i + 5), at(i)));
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
                    if (faces.size() > kTemplateMaxFaces) return false;
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
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
