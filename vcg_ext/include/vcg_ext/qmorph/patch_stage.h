// What the stages of Q-Morph on one patch share (PatchContext: the working mesh, its input
// surface, the parameters, the counts) and the base of every stage (PatchStage): the context under
// short names and the few rating and moving primitives all stages use.
#ifndef VCG_EXT_QMORPH_PATCH_STAGE_H
#define VCG_EXT_QMORPH_PATCH_STAGE_H

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

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
    int cavities = 0;  // disks of quads re-meshed as grids

    PatchStats &operator+=(const PatchStats &o)
    {
        quadsFormed += o.quadsFormed; templates += o.templates; swaps += o.swaps; splits += o.splits;
        failures += o.failures; pairedTriangles += o.pairedTriangles; doublets += o.doublets;
        iterations += o.iterations; valenceTurns += o.valenceTurns; seams += o.seams;
        transitionSeams += o.transitionSeams; transitionSplits += o.transitionSplits;
        diagonalCollapses += o.diagonalCollapses; quadsOpened += o.quadsOpened;
        cavities += o.cavities;
        return *this;
    }
};

struct PatchContext {
    MixedMesh &m;
    const SurfaceProjector &proj;  // the patch's input surface
    std::vector<int> &home;        // per node: a triangle of the input surface near it (projection start)
    const PatchParams &p;
    PatchStats stats;
    int vertexCap;                 // the patch never grows beyond this many nodes: bounds the work on bad input
    double meanLength = 0;         // mean input edge length of the patch
    double minLength = 0;          // no split makes edges shorter than this

    // A patch grows to at most this many times its input nodes (plus a few for tiny patches).
    static constexpr int kVertexCapFactor = 4, kVertexCapSlack = 64;
    // Splits stop at this fraction of the mean input edge.
    static constexpr double kMinLengthFraction = 0.02;

    PatchContext(MixedMesh &mesh, const SurfaceProjector &surface, std::vector<int> &homeTriangle, const PatchParams &params)
        : m(mesh), proj(surface), home(homeTriangle), p(params)
    {
        home.resize(m.VertexCount(), 0);
        m.SetInputSurface(&proj, &home);
        vertexCap = kVertexCapFactor * m.VertexCount() + kVertexCapSlack;
        double sum = 0;
        int n = 0;
        for (int h = 0; h < m.HalfEdgeCount(); ++h)
            if (m.HeAlive(h)) { sum += m.Length(h); ++n; }
        meanLength = n ? sum / n : 0;
        minLength = kMinLengthFraction * meanLength;
    }
};

class PatchStage
{
protected:
    explicit PatchStage(PatchContext &context)
        : m(context.m), proj(context.proj), home(context.home), p(context.p), stats(context.stats),
          vertexCap(context.vertexCap), meanLength(context.meanLength), minLength(context.minLength)
    {
    }

    MixedMesh &m;
    const SurfaceProjector &proj;
    std::vector<int> &home;
    const PatchParams &p;
    PatchStats &stats;
    const int vertexCap;
    const double meanLength, minLength;

    // A quad whose shortest side is below this fraction of its longest is as bad as a fold.
    static constexpr double kNeedleRatio = 0.02;
    // A ladder's cell has rungs at most this fraction of its sides, and sides alike: the shorter
    // at least kLadderSides of the longer.
    static constexpr double kLadderRungs = 0.25, kLadderSides = 0.5;
    // ... and corners near right angles: scaled Jacobian at least this.
    static constexpr double kLadderMinJacobian = 0.7;
    // Triangles are valid when the sine of their smallest angle stays above this: thinner ones
    // are degenerate once written in float.
    static constexpr double kMinSine = 1e-3;
    // Removing nodes or joining them must not flatten the surface by more than this times the
    // patch's mean input edge.
    static constexpr double kFlattening = 0.1;
    // Removed inner nodes stay within this fraction of the new polygon's shortest side.
    static constexpr double kInnerNodeSideFraction = 0.2;
    // Edges shorter than this times the minimum length are never split.
    static constexpr double kUnsplittableFactor = 5;
    // A quad below this scaled Jacobian is poor: operations must not make quads worse than this (or
    // than the worst they replace), and quads still below it have their nodes re-placed at the end.
    static constexpr double kFairQuad = 0.3;
    // Node moves: no face around may fall to this quality (folded), nor below min(worst before, fair).
    static constexpr double kMinMoveQuality = 1e-3, kFairMoveQuality = 0.2;

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
            if (m.PlannedSides(v) >= 0) {  // the node's two front edges and its planned side edges
                ideal[v] = m.PlannedSides(v) + 2;
                continue;
            }
            double angle = 0;
            m.ForEachOutgoing(v, [&](int g) { angle += m.CornerAngle(g); });
            ideal[v] = std::max(1, int(std::lround(angle / (M_PI / 2)))) + 1;
        }
        return ideal;
    }

    // The input surface's normal under a polygon of nodes, present or planned: at its centroid,
    // the nearest of the walks from every corner's home (one can stop on the wrong side of a tight
    // bend), as the judge has it when there is one (the true input under a re-meshed patch).
    P3 InputNormalOf(std::initializer_list<int> corners) const
    {
        P3 c(0, 0, 0);
        int homes[4], count = 0;
        for (int v : corners) {
            c += m.pos[v];
            if (count < 4) homes[count++] = m.HomeOf(v);
        }
        const P3 n = m.InputSurfaceNormalAt(c / double(corners.size()), homes, count, true);
        return n.SquaredNorm() > 0 ? n : m.InputNormal(*corners.begin());
    }

    // Shape of the quad (a b c d) on the input surface (see the other QuadShape); -1 also when it
    // has repeated nodes. `thinRectangles`: a needle that is a thin rectangle counts too.
    double QuadShape(int a, int b, int c, int d, bool thinRectangles = false) const
    {
        if (!m.DistinctNodes({a, b, c, d})) return -1;
        const std::array<P3, 4> pos{m.pos[a], m.pos[b], m.pos[c], m.pos[d]};
        // nor may it face away from the surface at any corner (a quad over a spike of the input)
        const P3 N = VectorArea(pos.data(), 4);
        for (int v : {a, b, c, d})
            if (N * m.InputNormal(v) <= 0) return -1;
        return QuadShape(pos, InputNormalOf({a, b, c, d}), thinRectangles);
    }
    // Shape of the quad `pos` against the input surface's normal n under it: its scaled Jacobian,
    // -1 when a needle, upside down or turned over at a corner on the surface, or folded.
    // With `thinRectangles`, a needle that is a ladder's cell (two short rungs across a strip
    // narrower than any fair quad, as its two triangles are, and two long sides alike) is judged
    // by its angles alone.
    static double QuadShape(const std::array<P3, 4> &pos, const P3 &n, bool thinRectangles = false)
    {
        double side[4], shortest = 1e300, longest = 0;  // a needle is as bad as a fold
        for (int k = 0; k < 4; ++k) {
            side[k] = (pos[(k + 1) % 4] - pos[k]).Norm();
            shortest = std::min(shortest, side[k]);
            longest = std::max(longest, side[k]);
        }
        bool thinRectangle = false;  // two needle rungs facing each other across a long pair of sides
        for (int k = 0; k < 2 && thinRectangles && shortest > kMinSine * longest; ++k)
            thinRectangle |= std::max(side[k], side[k + 2]) <= kLadderRungs * std::min(side[k + 1], side[(k + 3) % 4]) &&
                             std::min(side[k + 1], side[(k + 3) % 4]) > kLadderSides * std::max(side[k + 1], side[(k + 3) % 4]);
        if (!(shortest > kNeedleRatio * longest) && !thinRectangle) return -1;
        const P3 N = VectorArea(pos.data(), 4);
        const double l = N.Norm();
        if (!(l > 0) || N * n <= 0) return -1;
        // turned over on the surface at a corner, or folded across both diagonals: invalid
        const double nl = n.Norm();
        if (!(nl > 0) || ScaledJacobian(pos.data(), n / nl) <= 0 || IsFolded(pos.data())) return -1;
        const double sj = ScaledJacobian(pos.data(), N / l);
        // a ladder's cells are rectangles: a thin quad with slanted rungs is a needle after all
        if (!(shortest > kNeedleRatio * longest) && sj < kLadderMinJacobian) return -1;
        return sj;
    }
    // The triangle (a b c) is well oriented on the input surface, and not a sliver.
    bool TriPositive(int a, int b, int c) const
    {
        const P3 n = InputNormalOf({a, b, c});
        P3 u = m.pos[b] - m.pos[a], v = m.pos[c] - m.pos[a], w = m.pos[c] - m.pos[b];
        double l2 = std::max({u.SquaredNorm(), v.SquaredNorm(), w.SquaredNorm()});
        double nl = n.Norm();
        if (!(m.DistinctNodes({a, b, c}) && nl > 0 && (u ^ v) * n > kMinSine * l2 * nl)) return false;
        for (int x : {a, b, c})  // nor upside down at a corner (a triangle across a tight bend)
            if ((u ^ v) * m.InputNormal(x) <= 0) return false;
        // nor standing on edge over an input edge, facing one of its triangles and not the other (a
        // template's triangle across a front corner of 180 degrees on a coarse sphere)
        return !m.facesEveryClosest || m.facesEveryClosest((m.pos[a] + m.pos[b] + m.pos[c]) / 3.0, u ^ v);
    }

    // Shape of any face against reference normal n: a quad's QuadShape, a triangle's quality.
    double FaceQualityAt(int f, const P3 &n) const
    {
        if (!m.IsQuad(f)) return m.TriangleQuality(f, n);
        if (m.FaceNormal(f) * n <= 0) return -1;  // upside down against n (the judge's normal, when there is one)
        const int g = m.faceHe[f];
        return QuadShape(m.Org(g), m.Org(m.heNext[g]), m.Org(m.heNext[m.heNext[g]]), m.Org(m.hePrev[g]));
    }

    // Worst FaceQualityAt over `faces`, each rated against the input surface's normal under it (a
    // closest-point query per face: callers ask for it only when the answer can matter).
    double WorstQuality(const std::vector<int> &faces) const
    {
        double worst = 1e9;
        for (int f : faces) worst = std::min(worst, FaceQualityAt(f, m.InputFaceNormal(f, true)));
        return worst;
    }

    // WorstQuality with the `moved` nodes all at `at` (the surface under the new place); positions
    // are restored.
    double WorstQualityIfMoved(std::initializer_list<int> moved, const P3 &at, const std::vector<int> &faces)
    {
        std::vector<P3> old;
        for (int v : moved) old.push_back(m.pos[v]);
        for (int v : moved) m.pos[v] = at;
        const double worst = WorstQuality(faces);
        size_t k = 0;
        for (int v : moved) m.pos[v] = old[k++];
        return worst;
    }

    // Moves node v to the input surface's point nearest `to` when no face around it folds (quality
    // kMinMoveQuality), turns over on the surface or gets worse than the worst one now or than
    // kFairMoveQuality; its home follows.
    bool TryMove(int v, const P3 &to)
    {
        int hm = home[v];
        const P3 at = proj.Project(to, hm);
        const int old = home[v];
        home[v] = hm;  // the faces are rated against the surface under the new place
        const std::vector<int> faces = m.FacesAround({v});
        const double after = WorstQualityIfMoved({v}, at, faces);
        // the quality now matters only when the move leaves a face below kFairMoveQuality
        if (after > kMinMoveQuality && (after >= kFairMoveQuality || after >= WorstQuality(faces))) {
            m.pos[v] = at;
            return true;
        }
        home[v] = old;
        return false;
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
        P3 nv = m.InputNormal(v);
        P3 move = target - m.pos[v];
        move -= nv * (move * nv);
        TryMove(v, m.pos[v] + move);
    }

    int NewVertexOnEdge(int h, const P3 &point)
    {
        int from = m.Org(h);
        int v = m.SplitEdge(h, point);
        home.resize(m.VertexCount(), 0);
        home[v] = home[from];
        TryMove(v, m.pos[v]);  // a point of a current edge: back onto the input surface
        ++stats.splits;
        return v;
    }

    bool Splittable(int h) const
    {
        int t = m.heTwin[h];
        return t >= 0 && !m.heInitial[h] && m.IsTri(m.heFace[h]) && m.IsTri(m.heFace[t]) && m.VertexCount() < vertexCap &&
               m.Length(h) > kUnsplittableFactor * minLength;
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
        const double tolerance = std::min(kInnerNodeSideFraction * shortest, kFlattening * meanLength);
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
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
