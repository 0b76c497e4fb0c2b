// The collapse step of the feature-keeping re-meshing: every edge shorter than 4/5 of the target
// length L is collapsed when the result is right against the input surface.
//
// vcglib's 2020.09 collapse pass judges a collapse against the faces before it, not against the
// input, and it can neither coarsen a feature nor be told which vertices are fixed; so a fine
// front (a straightened region boundary on a scan follows the input's short edges) stayed fine,
// with dense rings of small triangles beside it, and thin parts of a coarse surface could turn over.
// Here a vertex p is removed by merging it with a neighbour q:
// - p off the features: with any neighbour closer than 4/5 L, at the edge's midpoint (on the input)
//   when q is off the features too, else at q;
// - p inside a feature chain (exactly two feature edges, a-p and p-q): into q along the chain,
//   when both edges are of one kind (front or crease) and a-q stays on the curve: exactly (up to
//   rounding) where the chain is a sharp edge of the input surface, a CAD crease whose geometry is
//   the feature; within a small chord distance where it runs over smooth input (a straightened region
//   boundary on a scan, itself a polyline through the input's triangles), of the removed vertex and
//   of the input's curve (the chain may already be made of chords);
// - a vertex with one or three or more feature edges (a corner or an end) never moves.
// Every collapse is refused unless each new triangle keeps facing the input surface's normal and
// its old orientation, stays fair, has no edge over 4/3 L, and the surface stays within 0.1 L of the
// input (the new triangles' centroids from it, p from the new triangles).
#ifndef VCG_EXT_QMORPH_SHORT_EDGE_COLLAPSE_H
#define VCG_EXT_QMORPH_SHORT_EDGE_COLLAPSE_H

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/edge_collapse.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/space/distance3.h>

#include <vcg_ext/common/face_face_adjacency.h>
#include <vcg_ext/common/coloured_sweep.h>
#include <vcg_ext/common/input_surface.h>

namespace vcg_ext {
namespace qmorph {

template <class MeshType>
class ShortEdgeCollapse
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef typename MeshType::CoordType CoordType;
    typedef vcg::Point3d P3;
    typedef vcg::tri::BasicVertexPair<VertexType> VertexPair;
    typedef vcg::tri::EdgeCollapser<MeshType, VertexPair> Collapser;
    // The input's feature curve under the feature edge a-b: front (else a crease), and sharp (a
    // sharp edge of the input surface, kSharpChainDeg).
    struct FeatureKind {
        bool front = false, sharp = false;
    };
    typedef std::function<FeatureKind(const P3 &a, const P3 &b)> FeatureOf;
    // How far the segment a-b strays from the input's feature curves (as they were before any
    // collapse) that it would replace.
    typedef std::function<double(const P3 &a, const P3 &b)> CurveDeviation;

    // Botsch-Kobbelt's bounds: edges below 4/5 L are collapsed, none above 4/3 L is made.
    static constexpr double kMinLength = 4.0 / 5.0;
    static constexpr double kMaxLength = 4.0 / 3.0;
    // Largest distance (times L) of a removed chain vertex from the new chain edge, of a removed
    // vertex from the new triangles, and of a new triangle's centroid from the input.
    static constexpr double kChordTolerance = 0.1;
    // A feature edge whose input faces meet at more than this (degrees between normals) is a sharp
    // edge of the surface: its chain is coarsened only where it is straight (chord below
    // kStraightChord times the shorter of its two edges: straight up to rounding). Judged on the
    // input, not on the faces of the moment: beside a region boundary over a curved scan those bend
    // more with every collapse, and the chain froze at the input's resolution (feline at 1% of its
    // diagonal: 2.3 times the front edges of a chain at L).
    static constexpr double kSharpChainDeg = 30;
    static constexpr double kStraightChord = 1e-5;
    static constexpr double kSurfaceDistance = 0.1;
    // A chain vertex where the feature turns more than this (degrees) is a corner, never removed.
    static constexpr double kMaxChainTurnDeg = 60;
    // Worst triangle quality (vcg::Quality, 1 equilateral) a collapse may leave, unless the star
    // was already worse.
    static constexpr double kMinQuality = 0.15;
    // Side of the cells the pass is spread over on threads, times L: a zone's margin (a quarter of
    // it) is then four target lengths, beyond the stars a collapse touches.
    static constexpr double kCellLengths = 16;
    // One pass over the vertices; features are the selected face-edges (flagged on both sides, a
    // border edge on its one side). Needs face-face adjacency (rebuilt at the end); vertex-face
    // adjacency is rebuilt first.
    // `progress` (optional, called on this thread) gets the fraction of the vertices visited.
    // Returns the number of collapses.
    //
    // On `threads` threads, the same mesh with any number (ColouredSweep, cells of kCellLengths L):
    // a visit reads and changes only faces whose every vertex is in its zone (Pass::VisitVertex),
    // else the vertex waits for the last visits, on this thread. vcglib's collapse also counts the
    // mesh's faces and vertices down: those collapses are made one at a time.
    static int Do(MeshType &m, InputSurface<MeshType> &surface, double L, const FeatureOf &featureOf,
                  const CurveDeviation &toCurves, const std::function<void(double)> &progress = {}, int threads = 1)
    {
        vcg::tri::RequireVFAdjacency(m);
        Pass pass(m, surface, L, featureOf, toCurves);
        vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
        pass.MarkShortEdges();

        const long collapses = ColouredSweep<MeshType>::template Run<std::vector<Neighbour>>(
            m, kCellLengths * L, threads, pass.zone,
            [&](size_t vi, int z, std::vector<Neighbour> &ring) {
                const Visit v = pass.VisitVertex(vi, z, ring);
                return v == Visit::Later ? ColouredSweep<MeshType>::kLater : v == Visit::Collapsed ? 1 : 0;
            },
            [&](double done) {
                if (progress) progress(done);
            });
        FaceFaceAdjacency<MeshType>::Update(m);
        return int(collapses);
    }

private:

    enum class Visit { Nothing, Collapsed, Later };

    struct Neighbour {
        VertexType *v = nullptr;
        bool feature = false;
    };

    // The state of one pass, and the visit of one vertex.
    struct Pass {
        MeshType &m;
        InputSurface<MeshType> &surface;
        const double L, minLength;
        const FeatureOf &featureOf;
        const CurveDeviation &toCurves;
        std::vector<char> border;     // per vertex: on a border edge (never moves)
        // Per vertex: whether an edge at it may be shorter than minLength. Every candidate is at the
        // end of such an edge, so a vertex without one is passed over without building its ring
        // (most vertices after the first round). Kept true where it is true: a collapse changes
        // only the edges at the vertex it keeps, whose ends are marked again.
        std::vector<char> nearShort;
        std::vector<int> zone;        // per vertex: its zone for the colour being visited (ColouredSweep)
        std::mutex counting;          // vcglib's collapse counts the mesh's faces and vertices down

        Pass(MeshType &m_, InputSurface<MeshType> &s, double L_, const FeatureOf &f, const CurveDeviation &t)
            : m(m_), surface(s), L(L_), minLength(kMinLength * L_), featureOf(f), toCurves(t), border(m_.vert.size(), 0)
        {
            for (FaceType &face : m.face)
                if (!face.IsD())
                    for (int i = 0; i < 3; ++i)
                        if (face.FFp(i) == &face) border[Index(face.V0(i))] = border[Index(face.V1(i))] = 1;
        }

        size_t Index(const VertexType *v) const { return size_t(vcg::tri::Index(m, v)); }

        void MarkShort(VertexType *a, VertexType *b)
        {
            if (Distance(a, b) < minLength) nearShort[Index(a)] = nearShort[Index(b)] = 1;
        }
        void MarkShortEdges()
        {
            nearShort.assign(m.vert.size(), 0);
            for (FaceType &f : m.face)
                if (!f.IsD())
                    for (int i = 0; i < 3; ++i) MarkShort(f.V0(i), f.V1(i));
        }

        // Whether v and every neighbour of v are in zone `z` (z < 0: no zones, always).
        bool StarIn(VertexType *v, int z, std::vector<Neighbour> &scratch) const
        {
            if (z < 0) return true;
            if (zone[Index(v)] != z) return false;
            Ring(v, scratch);
            return std::all_of(scratch.begin(), scratch.end(), [&](const Neighbour &n) { return zone[Index(n.v)] == z; });
        }

        // Visits vertex vi: collapses it into the first candidate that allows it. In zone z (>= 0)
        // only when every face the collapses could read or change has all its vertices in the
        // zone: p's star, each candidate's, and the stars of the vertices opposite each edge p-q
        // (whose vertex-face lists a collapse changes); else Later.
        Visit VisitVertex(size_t vi, int z, std::vector<Neighbour> &ring)
        {
            // nothing of a vertex outside the zone is read: another thread may be changing it
            if (z >= 0 && zone[vi] != z) return zone[vi] == ColouredSweep<MeshType>::kDeletedVertex ? Visit::Nothing : Visit::Later;
            VertexType *p = &m.vert[vi];
            if (p->IsD() || border[vi] || !nearShort[vi]) return Visit::Nothing;
            Ring(p, ring);
            if (z >= 0 && !std::all_of(ring.begin(), ring.end(), [&](const Neighbour &n) { return zone[Index(n.v)] == z; }))
                return Visit::Later;
            std::vector<VertexType *> candidates;
            const int features = int(std::count_if(ring.begin(), ring.end(), [](const Neighbour &n) { return n.feature; }));
            if (features == 0) {
                std::sort(ring.begin(), ring.end(), [p](const Neighbour &a, const Neighbour &b) {
                    return Distance(p, a.v) < Distance(p, b.v);
                });
                for (const Neighbour &n : ring)
                    if (Distance(p, n.v) < minLength) candidates.push_back(n.v);
            } else if (features == 2) {
                VertexType *ends[2];
                FeatureKind kinds[2];
                int k = 0;
                for (const Neighbour &n : ring)
                    if (n.feature) {
                        kinds[k] = featureOf(Pos(p), Pos(n.v));
                        ends[k++] = n.v;
                    }
                const bool sharp = kinds[0].sharp || kinds[1].sharp;
                const double chord = sharp ? kStraightChord * std::min(Distance(p, ends[0]), Distance(p, ends[1])) : kChordTolerance * L;
                if (kinds[0].front == kinds[1].front)  // a front chain and a crease stay apart
                    for (int e = 0; e < 2; ++e)
                        if (Distance(p, ends[e]) < minLength && ChainAllows(p, ends[1 - e], ends[e], L, chord, sharp, toCurves))
                            candidates.push_back(ends[e]);
            }
            if (z >= 0) {
                std::vector<Neighbour> scratch;
                for (VertexType *q : candidates) {
                    if (!StarIn(q, z, scratch)) return Visit::Later;
                    for (vcg::face::VFIterator<FaceType> vfi(p); !vfi.End(); ++vfi) {
                        VertexType *opposite = vfi.V1() == q ? vfi.V2() : vfi.V2() == q ? vfi.V1() : nullptr;
                        if (opposite && !StarIn(opposite, z, scratch)) return Visit::Later;
                    }
                }
            }
            for (VertexType *q : candidates) {
                P3 X;
                if (!Allowed(surface, p, q, features == 0 && !border[Index(q)] && !OnFeature(q), L, X)) continue;
                {
                    VertexPair pair(p, q);
                    std::lock_guard<std::mutex> lock(counting);
                    Collapser::Do(m, pair, CoordType::Construct(X), true);
                }
                FlagFeaturesOnBothSides(q);
                for (vcg::face::VFIterator<FaceType> vfi(q); !vfi.End(); ++vfi) {
                    MarkShort(q, vfi.V1());
                    MarkShort(q, vfi.V2());
                }
                return Visit::Collapsed;
            }
            return Visit::Nothing;
        }
    };

    static P3 Pos(const VertexType *v) { return P3::Construct(v->cP()); }
    static double Distance(const VertexType *a, const VertexType *b) { return (Pos(a) - Pos(b)).Norm(); }

    // The neighbours of p, each once, with whether the edge to it is a feature.
    static void Ring(VertexType *p, std::vector<Neighbour> &ring)
    {
        ring.clear();
        for (vcg::face::VFIterator<FaceType> vfi(p); !vfi.End(); ++vfi) {
            FaceType *f = vfi.F();
            const int z = vfi.I();
            Add(ring, f->V1(z), f->IsFaceEdgeS(z));
            Add(ring, f->V2(z), f->IsFaceEdgeS((z + 2) % 3));
        }
    }
    static void Add(std::vector<Neighbour> &ring, VertexType *v, bool feature)
    {
        for (Neighbour &n : ring)
            if (n.v == v) {
                n.feature = n.feature || feature;
                return;
            }
        Neighbour n;
        n.v = v;
        n.feature = feature;
        ring.push_back(n);
    }

    // a-p-q, a chain of two feature edges of one kind: p may go onto q when the new edge a-q is not
    // too long and passes within maxChord of p.
    static bool ChainAllows(const VertexType *p, const VertexType *a, const VertexType *q, double L, double maxChord, bool sharp,
                            const CurveDeviation &toCurves)
    {
        const P3 A = Pos(a), P = Pos(p), Q = Pos(q);
        if ((Q - A).Norm() > kMaxLength * L) return false;
        const P3 in = (P - A).Normalize(), out = (Q - P).Normalize();
        if (in * out < std::cos(kMaxChainTurnDeg * M_PI / 180)) return false;
        P3 closest;
        double chord;
        vcg::SegmentPointDistance(vcg::Segment3d(A, Q), P, closest, chord);
        if (chord > maxChord) return false;
        // over smooth surface the chain may already be a chord of chords: the new edge is held to
        // the input's curve itself (a sharp chain is coarsened only where straight: nothing drifts)
        return sharp || toCurves(A, Q) <= maxChord;
    }

    // Whether a feature edge ends at v.
    static bool OnFeature(VertexType *v)
    {
        for (vcg::face::VFIterator<FaceType> vfi(v); !vfi.End(); ++vfi)
            if (vfi.F()->IsFaceEdgeS(vfi.I()) || vfi.F()->IsFaceEdgeS((vfi.I() + 2) % 3)) return true;
        return false;
    }

    // The triangles of v's star that survive the collapse of v-w, with v put at X, checked in the
    // plane: each keeps its old orientation and has no edge from X over 4/3 L; worst qualities
    // before and after, and the distance from v's old place to the new triangles, are accumulated.
    static bool StarShapeAllows(VertexType *v, VertexType *w, const P3 &X, double L, double &worstBefore, double &worstAfter,
                                double &nearestToV)
    {
        const P3 V = Pos(v);
        for (vcg::face::VFIterator<FaceType> vfi(v); !vfi.End(); ++vfi) {
            FaceType *f = vfi.F();
            const int z = vfi.I();
            const P3 b = Pos(f->V1(z)), c = Pos(f->V2(z));
            worstBefore = std::min(worstBefore, double(vcg::Quality(V, b, c)));
            if (f->V1(z) == w || f->V2(z) == w) continue;  // deleted by the collapse
            if ((b - X).Norm() > kMaxLength * L || (c - X).Norm() > kMaxLength * L) return false;
            const P3 before = (b - V) ^ (c - V), after = (b - X) ^ (c - X);
            if (!(after.Norm() > 0) || after * before <= 0) return false;
            worstAfter = std::min(worstAfter, double(vcg::Quality(X, b, c)));
            double d;
            P3 closest;
            vcg::TrianglePointDistance(vcg::Triangle3<double>(X, b, c), V, d, closest);
            nearestToV = std::min(nearestToV, d);
        }
        return true;
    }

    // The same triangles against the input surface: each faces the input's normal under its
    // centroid (and every input triangle as close: a triangle standing on edge over an input edge
    // faces one of them only, an independent check may take either), and its centroid stays near
    // the input. One closest-point search per triangle answers the three questions.
    static bool StarOnInput(InputSurface<MeshType> &surface, VertexType *v, VertexType *w, const P3 &X, double L)
    {
        for (vcg::face::VFIterator<FaceType> vfi(v); !vfi.End(); ++vfi) {
            FaceType *f = vfi.F();
            const int z = vfi.I();
            if (f->V1(z) == w || f->V2(z) == w) continue;
            const P3 b = Pos(f->V1(z)), c = Pos(f->V2(z));
            const P3 after = (b - X) ^ (c - X);
            const P3 centroid = (X + b + c) / 3.0;
            const P3 n = after / after.Norm();
            typename InputSurface<MeshType>::Near under = surface.Nearest(centroid);
            if (surface.NormalUnder(under, n) * n <= 0 || !surface.FacesEveryClosest(under, n)) return false;
            if (!under.face || (P3::Construct(under.closest) - centroid).Norm() > kSurfaceDistance * L) return false;
        }
        return true;
    }

    // Whether p may go into q: every triangle that changes stays right against the input surface.
    // The merged vertex (`X`) goes to the edge's midpoint (on the input) when q is free too, else
    // stays at q. Only reads the mesh. The tests in the plane first: the closest-point searches are
    // most of a collapse's cost.
    static bool Allowed(InputSurface<MeshType> &surface, VertexType *p, VertexType *q, bool qFree, double L, P3 &X)
    {
        VertexPair pair(p, q);
        if (!Collapser::LinkConditions(pair)) return false;
        X = Pos(q);
        if (qFree) {
            CoordType onSurface;
            if (!surface.Closest(CoordType::Construct((Pos(p) + Pos(q)) * 0.5), onSurface)) return false;
            X = P3::Construct(onSurface);
        }
        double worstBefore = 1, worstAfter = 1, nearestToP = std::numeric_limits<double>::max(), nearestToQ = 0;
        if (!StarShapeAllows(p, q, X, L, worstBefore, worstAfter, nearestToP)) return false;
        if (qFree) {
            nearestToQ = std::numeric_limits<double>::max();
            if (!StarShapeAllows(q, p, X, L, worstBefore, worstAfter, nearestToQ)) return false;
        }
        if (worstAfter < std::min(worstBefore, kMinQuality)) return false;
        if (std::max(nearestToP, nearestToQ) > kSurfaceDistance * L) return false;
        return StarOnInput(surface, p, q, X, L) && (!qFree || StarOnInput(surface, q, p, X, L));
    }

    // A feature edge merged with a plain one (the triangle a-p-q of a chain collapse, whose edge a-q
    // was plain) is flagged on one side only: flag it on every face around q that has it.
    static void FlagFeaturesOnBothSides(VertexType *q)
    {
        std::vector<VertexType *> featureEnds;
        for (vcg::face::VFIterator<FaceType> vfi(q); !vfi.End(); ++vfi) {
            if (vfi.F()->IsFaceEdgeS(vfi.I())) featureEnds.push_back(vfi.V1());
            if (vfi.F()->IsFaceEdgeS((vfi.I() + 2) % 3)) featureEnds.push_back(vfi.V2());
        }
        for (vcg::face::VFIterator<FaceType> vfi(q); !vfi.End(); ++vfi) {
            if (std::count(featureEnds.begin(), featureEnds.end(), vfi.V1())) vfi.F()->SetFaceEdgeS(vfi.I());
            if (std::count(featureEnds.begin(), featureEnds.end(), vfi.V2())) vfi.F()->SetFaceEdgeS((vfi.I() + 2) % 3);
        }
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
