// Splitting one triangle along the polyline segments that cross it (seed paper, section 3.3), in
// the triangle's own 2D frame. Pure geometry on local point indices: no mesh.
//
// The triangle is a looped vertex list: its corners and the points on its edges in boundary
// order (counter-clockwise, as the face). Every segment joining two loop points (a chord) splits
// the loop holding both into (a..b) and (b..a), as in the paper. Each remaining loop is a convex
// polygon; instead of the paper's fan it is triangulated by dynamic programming maximising the
// smallest angle (ties: the largest sum of per-triangle smallest angles), never joining three
// points of one triangle edge. Points inside the face (user polylines only) are then inserted in the
// triangle holding them, their segments recovered by edge flips (Sloan 1993) and the loop made
// constrained-Delaunay again by angle-improving flips, which keeps the max-min-angle property.
// Two chords that cross cannot both split a loop: that is reported (the polylines cross).
#ifndef VCG_EXT_EMBEDDING_FACE_SPLIT_H
#define VCG_EXT_EMBEDDING_FACE_SPLIT_H

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <vcg/space/point2.h>

#include <vcg_ext/common/edge_key.h>

namespace vcg_ext {
namespace embedding {

class FaceSplitter
{
public:
    typedef vcg::Point2<double> P2;
    typedef VertexPair Seg;  // a segment between two loop points, smaller index first

    struct Input {
        std::vector<P2> xy;                    // local points: the loop points first, then interior points
        std::vector<unsigned char> edgeMask;   // bit k: on triangle edge k (corners have two bits); 0: interior
        std::vector<int> loop;                 // the loop points in boundary order, counter-clockwise
        std::vector<Seg> segments;             // segments inside the face (none along a triangle edge)
        double tolerance = 0;                  // an interior point this close to a segment lies on it
    };
    struct Output {
        std::string error;
        std::vector<std::array<int, 3>> triangles;  // counter-clockwise
        std::vector<Seg> segmentEdges;              // the segments as triangle edges (split at points on them)
    };

    static Output Split(const Input &in)
    {
        FaceSplitter s(in);
        s.Run();
        return s.out;
    }

    // Smallest angle (radians) of triangle a b c.
    static double MinAngle(const P2 &a, const P2 &b, const P2 &c)
    {
        return std::min({Angle(b - a, c - a), Angle(c - b, a - b), Angle(a - c, b - c)});
    }

private:
    struct Score {
        double minAngle = std::numeric_limits<double>::infinity();
        double sum = 0;
        bool valid = true;
    };
    struct LoopTriangulation {
        std::vector<int> loop;
        std::vector<std::array<int, 3>> tris;
        bool touched = false;  // points or segments were inserted: needs the Delaunay pass
    };

    const Input &in;
    Output out;
    const int nLoop;  // loop points are indices < nLoop
    double eps = 0;   // orientation threshold (relative to the face size)
    std::set<Seg> constrained;
    std::vector<LoopTriangulation> loops;

    explicit FaceSplitter(const Input &input) : in(input), nLoop(int(input.loop.size()))
    {
        double l2 = 0;
        for (const P2 &p : in.xy) l2 = std::max(l2, (p - in.xy[in.loop[0]]).SquaredNorm());
        eps = 1e-13 * l2;
    }

    static double Angle(const P2 &u, const P2 &v) { return std::atan2(std::fabs(u ^ v), u * v); }
    double Orient(int a, int b, int c) const { return (in.xy[b] - in.xy[a]) ^ (in.xy[c] - in.xy[a]); }
    bool IsInterior(int p) const { return in.edgeMask[p] == 0; }

    bool Fail(const std::string &why)
    {
        if (out.error.empty()) out.error = why;
        return false;
    }

    void Run()
    {
        std::vector<Seg> segs = SplitSegmentsAtPoints();
        if (!out.error.empty()) return;
        loops.push_back({in.loop, {}, false});
        for (size_t k = 0; k < in.loop.size(); ++k) constrained.insert(UndirectedPair(in.loop[k], in.loop[(k + 1) % in.loop.size()]));
        std::vector<Seg> inner;
        for (const Seg &s : segs) {
            if (IsInterior(s.first) || IsInterior(s.second)) inner.push_back(s);
            else if (!SplitLoop(s)) return;
        }
        for (LoopTriangulation &l : loops)
            if (!TriangulateLoop(l)) return;
        std::vector<int> loopOf(in.xy.size(), -1);
        for (int p = nLoop; p < int(in.xy.size()); ++p)
            if (!InsertPoint(p, loopOf)) return;
        for (const Seg &s : inner)
            if (!InsertSegment(s, loopOf)) return;
        for (LoopTriangulation &l : loops) {
            if (l.touched) MakeDelaunay(l);
            out.triangles.insert(out.triangles.end(), l.tris.begin(), l.tris.end());
        }
    }

    // Segments through an interior point are split there (junctions of user polylines).
    std::vector<Seg> SplitSegmentsAtPoints()
    {
        std::set<Seg> result;
        for (const Seg &s : in.segments) {
            if (s.first == s.second) continue;
            if ((in.edgeMask[s.first] & in.edgeMask[s.second]) != 0) { Fail("a segment runs along a triangle edge"); return {}; }
            const P2 a = in.xy[s.first], d = in.xy[s.second] - a;
            const double len2 = d.SquaredNorm();
            std::vector<std::pair<double, int>> on{{0.0, s.first}, {1.0, s.second}};
            for (int p = nLoop; p < int(in.xy.size()); ++p) {
                if (p == s.first || p == s.second || len2 <= 0) continue;
                const double t = ((in.xy[p] - a) * d) / len2;
                if (t <= 0 || t >= 1) continue;
                if ((a + d * t - in.xy[p]).Norm() <= in.tolerance) on.push_back({t, p});
            }
            std::sort(on.begin(), on.end());
            for (size_t k = 0; k + 1 < on.size(); ++k) result.insert(UndirectedPair(on[k].second, on[k + 1].second));
        }
        for (const Seg &s : result) out.segmentEdges.push_back(s);
        return std::vector<Seg>(result.begin(), result.end());
    }

    // The paper's step: chord (a, b) splits the loop holding both into (a..b) and (b..a).
    bool SplitLoop(const Seg &s)
    {
        for (size_t li = 0; li < loops.size(); ++li) {
            const std::vector<int> &l = loops[li].loop;
            const int n = int(l.size());
            int i = -1, j = -1;
            for (int k = 0; k < n; ++k) {
                if (l[k] == s.first) i = k;
                if (l[k] == s.second) j = k;
            }
            if (i < 0 || j < 0) continue;
            if (i > j) std::swap(i, j);
            if (j == i + 1 || (i == 0 && j == n - 1)) return true;  // already an edge of this loop
            std::vector<int> first(l.begin() + i, l.begin() + j + 1), second(l.begin() + j, l.end());
            second.insert(second.end(), l.begin(), l.begin() + i + 1);
            loops[li].loop = first;
            loops.push_back({second, {}, false});
            constrained.insert(UndirectedPair(s.first, s.second));
            return true;
        }
        return Fail("two polyline segments cross inside the face");
    }

    bool ValidTriangle(int a, int b, int c) const
    {
        return (in.edgeMask[a] & in.edgeMask[b] & in.edgeMask[c]) == 0 && Orient(a, b, c) > eps;
    }

    static bool Better(const Score &x, const Score &y)
    {
        if (!y.valid) return x.valid;
        if (!x.valid) return false;
        const double tieTol = 1e-12;
        if (x.minAngle > y.minAngle + tieTol) return true;
        if (x.minAngle < y.minAngle - tieTol) return false;
        return x.sum > y.sum + tieTol;
    }

    // Max-min-angle triangulation of a convex loop: best[i][j] triangulates loop[i..j] under chord (i, j).
    bool TriangulateLoop(LoopTriangulation &lt)
    {
        const std::vector<int> &l = lt.loop;
        const int n = int(l.size());
        std::vector<Score> best(size_t(n) * n);
        std::vector<int> choice(size_t(n) * n, -1);
        for (int len = 2; len < n; ++len)
            for (int i = 0; i + len < n; ++i) {
                const int j = i + len;
                Score b;
                b.valid = false;
                for (int k = i + 1; k < j; ++k) {
                    const Score &left = best[size_t(i) * n + k], &right = best[size_t(k) * n + j];
                    if (!left.valid || !right.valid || !ValidTriangle(l[i], l[k], l[j])) continue;
                    Score c;
                    const double a = MinAngle(in.xy[l[i]], in.xy[l[k]], in.xy[l[j]]);
                    c.minAngle = std::min({left.minAngle, right.minAngle, a});
                    c.sum = left.sum + right.sum + a;
                    if (Better(c, b)) { b = c; choice[size_t(i) * n + j] = k; }
                }
                best[size_t(i) * n + j] = b;
            }
        if (!best[n - 1].valid) return Fail("a piece of the face cannot be triangulated without degenerate triangles");
        std::vector<std::pair<int, int>> stack{{0, n - 1}};
        while (!stack.empty()) {
            auto [i, j] = stack.back();
            stack.pop_back();
            if (j - i < 2) continue;
            const int k = choice[size_t(i) * n + j];
            lt.tris.push_back({l[i], l[k], l[j]});
            stack.push_back({i, k});
            stack.push_back({k, j});
        }
        return true;
    }

    // Distance from p to the line a b, signed (positive on the left).
    double SignedDistance(int a, int b, int p) const
    {
        const double len = (in.xy[b] - in.xy[a]).Norm();
        return len > 0 ? Orient(a, b, p) / len : 0.0;
    }

    bool InsertPoint(int p, std::vector<int> &loopOf)
    {
        // The loop whose triangle holds p best (largest smallest signed distance to its sides).
        int bestLoop = -1, bestTri = -1;
        double bestDist = -std::numeric_limits<double>::infinity();
        for (size_t li = 0; li < loops.size(); ++li)
            for (size_t ti = 0; ti < loops[li].tris.size(); ++ti) {
                const auto &t = loops[li].tris[ti];
                const double d = std::min({SignedDistance(t[0], t[1], p), SignedDistance(t[1], t[2], p), SignedDistance(t[2], t[0], p)});
                if (d > bestDist) { bestDist = d; bestLoop = int(li); bestTri = int(ti); }
            }
        if (bestLoop < 0 || bestDist < -in.tolerance) return Fail("a point inside the face lies outside its triangulation");
        LoopTriangulation &lt = loops[bestLoop];
        const std::array<int, 3> t = lt.tris[bestTri];
        loopOf[p] = bestLoop;
        lt.touched = true;
        // On an edge of the triangle (within a tiny distance): split the edge and both triangles.
        const double onEdge = std::sqrt(eps);
        for (int k = 0; k < 3; ++k) {
            const int a = t[k], b = t[(k + 1) % 3];
            if (std::fabs(SignedDistance(a, b, p)) > onEdge) continue;
            if (constrained.count(UndirectedPair(a, b))) return Fail("a point inside the face lies on a polyline segment it does not split");
            const int c = t[(k + 2) % 3];
            int other = -1, d = -1;
            for (size_t ti = 0; ti < lt.tris.size() && other < 0; ++ti)
                for (int j = 0; j < 3; ++j)
                    if (lt.tris[ti][j] == b && lt.tris[ti][(j + 1) % 3] == a) { other = int(ti); d = lt.tris[ti][(j + 2) % 3]; }
            if (other < 0) return Fail("a point inside the face lies on the face boundary");
            lt.tris[bestTri] = {a, p, c};
            lt.tris[other] = {b, p, d};
            lt.tris.push_back({p, b, c});
            lt.tris.push_back({p, a, d});
            return true;
        }
        lt.tris[bestTri] = {t[0], t[1], p};
        lt.tris.push_back({t[1], t[2], p});
        lt.tris.push_back({t[2], t[0], p});
        return true;
    }

    // Triangle index and corner k with tris[i][k] == a, tris[i][k+1] == b.
    static bool FindHalfEdge(const LoopTriangulation &lt, int a, int b, int &tri, int &k)
    {
        for (size_t i = 0; i < lt.tris.size(); ++i)
            for (int j = 0; j < 3; ++j)
                if (lt.tris[i][j] == a && lt.tris[i][(j + 1) % 3] == b) { tri = int(i); k = j; return true; }
        return false;
    }

    // Flips edge a-b (two triangles a b c, b a d -> c a d, d b c) when the quad is strictly convex.
    bool Flip(LoopTriangulation &lt, int a, int b, int *newC = nullptr, int *newD = nullptr)
    {
        int t1, k1, t2, k2;
        if (!FindHalfEdge(lt, a, b, t1, k1) || !FindHalfEdge(lt, b, a, t2, k2)) return false;
        const int c = lt.tris[t1][(k1 + 2) % 3], d = lt.tris[t2][(k2 + 2) % 3];
        if (!(Orient(c, a, d) > eps && Orient(d, b, c) > eps)) return false;
        lt.tris[t1] = {c, a, d};
        lt.tris[t2] = {d, b, c};
        if (newC) *newC = c;
        if (newD) *newD = d;
        return true;
    }

    bool Crosses(int a, int b, int x, int y) const
    {
        if (x == a || x == b || y == a || y == b) return false;
        return ((Orient(a, b, x) > 0) != (Orient(a, b, y) > 0)) && ((Orient(x, y, a) > 0) != (Orient(x, y, b) > 0)) &&
               std::fabs(Orient(a, b, x)) > 0 && std::fabs(Orient(a, b, y)) > 0;
    }

    // Sloan's edge recovery: flip the edges crossing a-b until a-b is an edge.
    bool InsertSegment(const Seg &s, const std::vector<int> &loopOf)
    {
        const int a = s.first, b = s.second;
        int li = IsInterior(a) ? loopOf[a] : loopOf[b];
        if (IsInterior(a) && IsInterior(b) && loopOf[a] != loopOf[b]) return Fail("two polyline segments cross inside the face");
        LoopTriangulation &lt = loops[li];
        if (!IsInterior(a) || !IsInterior(b)) {
            const int onLoop = IsInterior(a) ? b : a;
            if (std::find(lt.loop.begin(), lt.loop.end(), onLoop) == lt.loop.end())
                return Fail("two polyline segments cross inside the face");
        }
        lt.touched = true;
        std::vector<Seg> queue;
        for (const auto &t : lt.tris)
            for (int k = 0; k < 3; ++k) {
                const int x = t[k], y = t[(k + 1) % 3];
                if (x < y && Crosses(a, b, x, y)) {
                    if (constrained.count(UndirectedPair(x, y))) return Fail("two polyline segments cross inside the face");
                    queue.push_back({x, y});
                }
            }
        const size_t guard = 64 + 16 * lt.tris.size() * lt.tris.size();
        for (size_t it = 0; !queue.empty(); ++it) {
            if (it > guard) return Fail("a polyline segment could not be recovered as an edge");
            Seg e = queue.front();
            queue.erase(queue.begin());
            int c = -1, d = -1;
            if (!Flip(lt, e.first, e.second, &c, &d)) { queue.push_back(e); continue; }
            if (Crosses(a, b, c, d)) queue.push_back({c, d});
        }
        int t, k;
        if (!FindHalfEdge(lt, a, b, t, k) && !FindHalfEdge(lt, b, a, t, k))
            return Fail("a polyline segment passes through a point it does not end at");
        constrained.insert(UndirectedPair(a, b));
        return true;
    }

    // Lawson flips on the unconstrained edges while a flip raises the two triangles' smallest angle.
    void MakeDelaunay(LoopTriangulation &lt)
    {
        const size_t guard = 64 + 8 * lt.tris.size() * lt.tris.size();
        for (size_t pass = 0; pass < guard; ++pass) {
            bool flipped = false;
            for (size_t i = 0; i < lt.tris.size() && !flipped; ++i)
                for (int k = 0; k < 3 && !flipped; ++k) {
                    const int a = lt.tris[i][k], b = lt.tris[i][(k + 1) % 3], c = lt.tris[i][(k + 2) % 3];
                    if (a > b || constrained.count(UndirectedPair(a, b))) continue;
                    int t2, k2;
                    if (!FindHalfEdge(lt, b, a, t2, k2)) continue;
                    const int d = lt.tris[t2][(k2 + 2) % 3];
                    const double before = std::min(MinAngle(in.xy[a], in.xy[b], in.xy[c]), MinAngle(in.xy[b], in.xy[a], in.xy[d]));
                    const double after = std::min(MinAngle(in.xy[c], in.xy[a], in.xy[d]), MinAngle(in.xy[d], in.xy[b], in.xy[c]));
                    if (after > before + 1e-12) flipped = Flip(lt, a, b);
                }
            if (!flipped) return;
        }
    }
};

}  // namespace embedding
}  // namespace vcg_ext

#endif
