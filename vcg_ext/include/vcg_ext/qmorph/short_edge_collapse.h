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
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/edge_collapse.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/space/distance3.h>

#include <vcg_ext/common/face_face_adjacency.h>
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
    // Vertices between two progress reports (about a second on a big scan's first round).
    static constexpr size_t kProgressVertices = 1 << 15;

    // One pass over the vertices; features are the selected face-edges (flagged on both sides, a
    // border edge on its one side). Needs face-face adjacency (rebuilt at the end); vertex-face
    // adjacency is rebuilt first.
    // `progress` (optional) gets the fraction of the vertices visited, every kProgressVertices.
    // Returns the number of collapses.
    static int Do(MeshType &m, InputSurface<MeshType> &surface, double L, const FeatureOf &featureOf,
                  const CurveDeviation &toCurves, const std::function<void(double)> &progress = {})
    {
        vcg::tri::RequireVFAdjacency(m);
        std::vector<char> border(m.vert.size(), 0);
        for (FaceType &f : m.face)
            if (!f.IsD())
                for (int i = 0; i < 3; ++i)
                    if (f.FFp(i) == &f) border[vcg::tri::Index(m, f.V0(i))] = border[vcg::tri::Index(m, f.V1(i))] = 1;
        vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
        const double minLength = kMinLength * L;
        // Per vertex: whether an edge at it may be shorter than minLength. Every candidate is at
        // the end of such an edge, so a vertex without one is passed over without building its
        // ring (most vertices after the first round). Kept true where it is true: a collapse
        // changes only the edges at the vertex it keeps, whose ends are marked again.
        std::vector<char> nearShort(m.vert.size(), 0);
        auto markShort = [&](VertexType *a, VertexType *b) {
            if (Distance(a, b) < minLength) nearShort[vcg::tri::Index(m, a)] = nearShort[vcg::tri::Index(m, b)] = 1;
        };
        for (FaceType &f : m.face)
            if (!f.IsD())
                for (int i = 0; i < 3; ++i) markShort(f.V0(i), f.V1(i));
        int collapses = 0;
        std::vector<Neighbour> ring;
        for (size_t vi = 0; vi < m.vert.size(); ++vi) {
            if (progress && vi % kProgressVertices == 0) progress(double(vi) / double(m.vert.size()));
            VertexType *p = &m.vert[vi];
            if (p->IsD() || border[vi] || !nearShort[vi]) continue;
            Ring(p, ring);
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
            for (VertexType *q : candidates)
                if (TryCollapse(m, surface, p, q, features == 0 && !border[vcg::tri::Index(m, q)] && !OnFeature(q), L)) {
                    for (vcg::face::VFIterator<FaceType> vfi(q); !vfi.End(); ++vfi) {
                        markShort(q, vfi.V1());
                        markShort(q, vfi.V2());
                    }
                    ++collapses;
                    break;
                }
        }
        FaceFaceAdjacency<MeshType>::Update(m);
        return collapses;
    }

private:
    struct Neighbour {
        VertexType *v = nullptr;
        bool feature = false;
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

    // Removes p into q when every triangle that changes stays right against the input surface. The
    // merged vertex goes to the edge's midpoint (on the input) when q is free too, else stays at q.
    // The tests in the plane first: the closest-point searches are most of a collapse's cost.
    static bool TryCollapse(MeshType &m, InputSurface<MeshType> &surface, VertexType *p, VertexType *q, bool qFree, double L)
    {
        VertexPair pair(p, q);
        if (!Collapser::LinkConditions(pair)) return false;
        P3 X = Pos(q);
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
        if (!StarOnInput(surface, p, q, X, L) || (qFree && !StarOnInput(surface, q, p, X, L))) return false;
        Collapser::Do(m, pair, CoordType::Construct(X), true);
        FlagFeaturesOnBothSides(q);
        return true;
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
