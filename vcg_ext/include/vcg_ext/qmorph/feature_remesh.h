// Isotropic re-meshing of the whole mesh before Q-Morph (Botsch-Kobbelt: split, collapse, flip
// toward valence 6, tangential relaxation, projection on the input), keeping the front (selected
// face-edges) and the sharp creases as exact chains of output edges.
//
// What is taken from vcglib 2020.09's IsotropicRemeshing, and what is not, so that features stay
// where they are:
// - features (front and unselected sharp creases) are selected face-edges (FaceEdgeS, as its "user
//   selected creases"): never flipped, their vertices never relaxed;
// - its split step is RefineMidpoint with a length test, called directly (SplitLongEdges): a split
//   feature edge's new vertex is its midpoint, on the feature;
// - its collapses are judged against the faces before, not the input, may slide a feature vertex
//   along a nearly straight feature and never coarsen a feature (so a fine front kept rings of small
//   triangles): ShortEdgeCollapse instead, which coarsens feature chains along their curve;
// - its flips read valences from stars it does not update and cost a third of the re-meshing:
//   ValenceFlips, its rule with valences kept in an array, instead;
// - its smoothing can turn faces over: a relaxation of our own, checked against the input, instead;
// - no clean-up pass (it would delete and compact faces with its own rules).
// Afterwards the front is re-selected: an output edge is front when the original edge it lies on
// (found by its midpoint in a segment grid) was selected; creases are sharp edges again and the
// partition cuts them as before.
//
// Orientation independence: vcglib's passes walk faces and their corners in order and round
// accordingly, so the mesh (and the input surface) are re-meshed read canonically
// (common/canonical_faces.h: every face from its lowest vertex on, components of negative
// orientation reversed) and the faces of reversed components are turned back at the end: a
// consistently flipped copy of the input is re-meshed into the same mesh, mirrored.
#ifndef VCG_EXT_QMORPH_FEATURE_REMESH_H
#define VCG_EXT_QMORPH_FEATURE_REMESH_H

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/common/canonical_faces.h>
#include <vcg_ext/common/coloured_sweep.h>
#include <vcg_ext/common/edge_flip.h>
#include <vcg_ext/common/face_corners.h>
#include <vcg_ext/common/face_face_adjacency.h>
#include <vcg_ext/common/input_surface.h>
#include <vcg_ext/common/parallel.h>
#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/common/segment_grid.h>
#include <vcg_ext/qmorph/facing_features.h>
#include <vcg_ext/qmorph/short_edge_collapse.h>
#include <vcg_ext/qmorph/valence_flips.h>

namespace vcg_ext {
namespace qmorph {

template <class MeshType>
class FeatureRemesh
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef typename MeshType::ScalarType ScalarType;
    typedef typename MeshType::CoordType CoordType;
    typedef vcg::Point3d P3;
    typedef typename ShortEdgeCollapse<MeshType>::FeatureKind FeatureKind;

    struct Stats {
        int featureEdges = 0, frontEdgesBefore = 0, frontEdgesAfter = 0;
        int splits = 0, collapses = 0, flips = 0, facingSplits = 0;
        int turnedBack = 0;  // faces found turned away from the input at the end, and mended
        int needleCreases = 0;  // sharp edges of needles and turned faces, not kept (Unreliable)
        int facesBefore = 0, facesAfter = 0;
    };

    // Re-meshes m toward edge length L in `iterations` rounds; edges sharper than creaseAngleDeg
    // (normals) are kept like the front. Needs face-face and vertex-face adjacency.
    // `surface`: the input, as it is now (vertices are projected back onto it). Progress goes from
    // 0 to progressTo percent.
    static Stats Do(MeshType &m, InputSurface<MeshType> &surface, double L, int iterations, double creaseAngleDeg,
                    vcg::CallBackPos *cb = nullptr, int progressTo = 100, int threads = 1)
    {
        vcg::tri::RequireVFAdjacency(m);
        vcg::tri::RequirePerVertexMark(m);
        vcg::tri::RequirePerFaceMark(m);
        Stats st;
        if (cb) cb(0, "Q-Morph: re-meshing, reading the mesh");
        vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
        st.facesBefore = m.fn;
        const int reversedBit = ReadCanonically(m);
        surface.UseCanonicalOrientation(true);
        if (cb) cb(0, "Q-Morph: re-meshing, features");
        SegmentGrid features(L);
        std::vector<FeatureKind> kinds;
        MarkFeatures(m, creaseAngleDeg, features, kinds, st, L);
        auto featureOf = [&](const P3 &a, const P3 &b) { return FeatureAt(features, kinds, a, b); };
        auto toFeatures = [&](const P3 &a, const P3 &b) { return CurveDeviation(features, a, b, L); };

        // vcglib's split length (IsotropicRemeshing::Params::SetTargetLen), in its scalar type
        const ScalarType maxLength = ScalarType(L) * ScalarType(4. / 3.);
        for (int it = 0; it < iterations; ++it) {
            // each step of each round reports (the collapses of the first round on a big scan, which
            // remove most of its faces, report as they go)
            // the round and step in the message: a round's share of the bar is a few percent
            auto progress = [&](double done, const char *step) {
                if (!cb) return;
                char what[96];
                std::snprintf(what, sizeof what, "Q-Morph: re-meshing, round %d of %d, %s", it + 1, iterations, step);
                cb(int(progressTo * (it + done) / iterations), what);
            };
            progress(0, "splits");
            // split toward no edge longer than 4/3 L (see kMaxSplitPasses)
            for (int pass = 0; pass < kMaxSplitPasses && HasLongEdge(m, maxLength); ++pass) st.splits += SplitLongEdges(m, maxLength);
            progress(kCollapseStart, "collapses");
            st.collapses += ShortEdgeCollapse<MeshType>::Do(m, surface, L, featureOf, toFeatures, [&](double done) {
                char step[48];
                std::snprintf(step, sizeof step, "collapses (%d%% of the vertices)", int(100 * done));
                progress(kCollapseStart + done * (kFlipStart - kCollapseStart), step);
            }, threads);
            // the collapses only flag what they remove: on a scan far finer than L the first round
            // leaves most slots dead, and every later pass walked them (compaction keeps the live
            // elements in order, so every index-ordered step makes the same choices)
            vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
            progress(kFlipStart, "flips");
            st.flips += ValenceFlips<MeshType>::Do(m, surface, kSurfaceDistance * L);
            progress(kRelaxStart, "relaxation");
            vcg::tri::UpdateTopology<MeshType>::VertexFace(m);  // the flips kept face-face adjacency only
            const std::vector<char> fixed = FeatureVertices(m);
            for (int k = 0; k < kRelaxSweeps; ++k) Relax(m, surface, fixed, L, threads);
        }
        if (cb) cb(progressTo, "Q-Morph: re-meshing, feature strips");
        st.facingSplits = FacingFeatures<MeshType>::Do(m, L);
        if (cb) cb(progressTo, "Q-Morph: re-meshing, faces turned away from the input");
        st.turnedBack = TurnBackFlippedFaces(m, surface);
        if (cb) cb(progressTo, "Q-Morph: re-meshing, the front selected again");
        vcg::tri::UpdateSelection<MeshType>::VertexClear(m);
        SelectFront(m, features, kinds, st);
        BackToInputOrientation(m, reversedBit);
        surface.UseCanonicalOrientation(false);
        st.facesAfter = m.fn;
        return st;
    }

private:
    // The remesher's surface-distance check: no move or collapse may take a point of a face farther
    // than this (times the target length) from the input surface.
    static constexpr double kSurfaceDistance = 0.1;
    // Tangential relaxation sweeps per round, and the worst triangle quality (vcg::Quality, 2 r / R
    // like, 1 equilateral) a relaxation move may leave when the star was better than that.
    static constexpr int kRelaxSweeps = 2;
    static constexpr double kMinRelaxQuality = 0.1;
    // Split passes per round at most: each halves the long edges, and a CAD sliver can be many
    // times L long (joint at 0.5% of its diagonal: 0.47 of the expected count with one pass, 0.96
    // with three; twelve made the same count, 20% slower).
    static constexpr int kMaxSplitPasses = 3;
    // Where each step of a round starts in its progress (fractions of the round, from the times of
    // armadillo x16's first round: splits 4 s, collapses 14 s, flips 1.4 s, relaxation 1.3 s).
    static constexpr double kCollapseStart = 0.2, kFlipStart = 0.8, kRelaxStart = 0.9;

    // The split test (IsotropicRemeshing's EdgeSplitLenPred: squared lengths in the mesh's scalar type).
    static bool LongerThan(const CoordType &a, const CoordType &b, ScalarType maxLength)
    {
        return vcg::SquaredDistance(a, b) > maxLength * maxLength;
    }

    // Whether SplitLongEdges would split anything (RefineMidpoint rebuilds the face-face adjacency
    // even when it splits nothing).
    static bool HasLongEdge(const MeshType &m, ScalarType maxLength)
    {
        for (const FaceType &f : m.face)
            if (!f.IsD())
                for (int i = 0; i < 3; ++i)
                    if (LongerThan(f.cP0(i), f.cP1(i), maxLength)) return true;
        return false;
    }

    // Per vertex: whether it lies on a feature or border edge (such vertices never move). Needs
    // face-face adjacency.
    static std::vector<char> FeatureVertices(MeshType &m)
    {
        std::vector<char> onFeature(m.vert.size(), 0);
        for (FaceType &f : m.face)
            if (!f.IsD())
                for (int i = 0; i < 3; ++i)
                    if (IsFeature(f, i) || f.FFp(i) == &f)
                        onFeature[vcg::tri::Index(m, f.V0(i))] = onFeature[vcg::tri::Index(m, f.V1(i))] = 1;
        return onFeature;
    }

    // Per vertex off the features, the input triangle closest to it (null for the others). A sweep
    // moves each vertex only at its own turn, so these are the ones under it at that turn: the
    // searches, most of a sweep's cost, run on `threads` threads first (the same answers with any
    // number of threads).
    static std::vector<const FaceType *> InputUnderVertices(MeshType &m, InputSurface<MeshType> &surface,
                                                            const std::vector<char> &fixed, int threads)
    {
        std::vector<const FaceType *> under(m.vert.size(), nullptr);
        const size_t chunks = (m.vert.size() + kVerticesPerChunk - 1) / kVerticesPerChunk;
        OrderedParallelFor<int>(
            chunks, threads, {},
            [&](size_t chunk) {
                const size_t end = std::min(m.vert.size(), (chunk + 1) * kVerticesPerChunk);
                for (size_t i = chunk * kVerticesPerChunk; i < end; ++i) {  // each chunk writes its own entries
                    if (m.vert[i].IsD() || fixed[i]) continue;
                    CoordType onSurface;
                    under[i] = surface.Closest(m.vert[i].cP(), onSurface);
                }
                return 0;
            },
            [](size_t, int &&) {}, [] {});
        return under;
    }
    static constexpr size_t kVerticesPerChunk = 4096;

    // Tangential relaxation (Botsch-Kobbelt): each vertex off the features moves toward the area-
    // weighted centroid of its star, in the tangent plane, then onto the input surface. A move is
    // kept only when no face of the star turns over, against the input surface's normal under the
    // new place or against its own normal before, the star's worst triangle stays fair, and the star
    // stays within kSurfaceDistance L of the old place (a point of the input). Needs
    // vertex-face adjacency; `fixed`: FeatureVertices (both unchanged by it: it only moves vertices).
    // On `threads` threads, the same moves with any number (ColouredSweep, the collapse pass's
    // cells): a vertex moves in its zone when its neighbours are in it too.
    static void Relax(MeshType &m, InputSurface<MeshType> &surface, const std::vector<char> &fixed, double L, int threads)
    {
        const std::vector<const FaceType *> underStart = InputUnderVertices(m, surface, fixed, threads);
        std::vector<int> zone;
        ColouredSweep<MeshType>::template Run<RelaxScratch>(
            m, ShortEdgeCollapse<MeshType>::kCellLengths * L, threads, zone,
            [&](size_t vi, int z, RelaxScratch &scratch) { return RelaxVertex(m, surface, fixed, underStart, zone, L, vi, z, scratch); },
            [](double) {});
    }

    // Distance from p to face f, its corners taken in index order: the same arithmetic whichever
    // way the face runs (a consistently flipped copy of the input is re-meshed into the same mesh).
    static double DistanceToTriangle(const P3 &p, const FaceType &f)
    {
        const std::array<const VertexType *, 3> c = FaceCorners<MeshType>::InMemoryOrder(f);
        return PointTriangleDistance(p, Pos(c[0]), Pos(c[1]), Pos(c[2]));
    }

    struct RelaxScratch {
        std::vector<FaceType *> star;
        std::vector<int> corner;
        std::vector<CoordType> normalsBefore;
    };

    // One vertex of Relax (0), or ColouredSweep::kLater when in zone z (>= 0) it or a neighbour is
    // not in the zone (another thread may be moving it).
    static int RelaxVertex(MeshType &m, InputSurface<MeshType> &surface, const std::vector<char> &fixed,
                           const std::vector<const FaceType *> &underStart, const std::vector<int> &zone, double L, size_t vi,
                           int z, RelaxScratch &scratch)
    {
        if (z >= 0 && zone[vi] != z) return zone[vi] == ColouredSweep<MeshType>::kDeletedVertex ? 0 : ColouredSweep<MeshType>::kLater;
        VertexType &v = m.vert[vi];
        if (v.IsD() || fixed[vi]) return 0;
        std::vector<FaceType *> &star = scratch.star;
        vcg::face::VFStarVF<FaceType>(&v, star, scratch.corner);
        if (z >= 0)
            for (FaceType *f : star)
                for (int k = 0; k < 3; ++k)
                    if (zone[vcg::tri::Index(m, f->cV(k))] != z) return ColouredSweep<MeshType>::kLater;
        if (star.size() < 3) return 0;
        CoordType centroid(0, 0, 0);
        ScalarType area = 0;
        for (FaceType *f : star) {
            const ScalarType a = vcg::DoubleArea(*f);
            centroid += vcg::Barycenter(*f) * a;
            area += a;
        }
        if (!(area > 0)) return 0;
        CoordType onSurface;
        const FaceType *under = underStart[vi];
        if (!under) return 0;
        const CoordType n = surface.Normal(under);
        CoordType move = centroid / area - v.cP();
        move -= n * (move * n);
        const FaceType *target = surface.Closest(CoordType(v.cP() + move), onSurface);
        if (!target) return 0;
        const CoordType old = v.cP();
        double worstBefore = 1, worstAfter = 1;
        std::vector<CoordType> &normalsBefore = scratch.normalsBefore;
        normalsBefore.clear();
        for (FaceType *f : star) {
            worstBefore = std::min(worstBefore, double(vcg::Quality(f->cP(0), f->cP(1), f->cP(2))));
            normalsBefore.push_back(vcg::TriangleNormal(*f));
        }
        v.P() = onSurface;
        bool ok = true;
        double nearestToOld = std::numeric_limits<double>::max();
        for (size_t i = 0; i < star.size() && ok; ++i) {
            const CoordType N = vcg::TriangleNormal(*star[i]);
            ok = N * surface.Normal(target) > 0 && N * normalsBefore[i] > 0;
            worstAfter = std::min(worstAfter, double(vcg::Quality(star[i]->cP(0), star[i]->cP(1), star[i]->cP(2))));
            nearestToOld = std::min(nearestToOld, DistanceToTriangle(P3::Construct(old), *star[i]));
        }
        // the old place is on the input: the star must stay near it, as a collapse's must stay near
        // the removed vertex (a vertex at a spike's tip slid down the spike, cutting the tip off)
        if (!ok || worstAfter < std::min(worstBefore, kMinRelaxQuality) || nearestToOld > kSurfaceDistance * L) v.P() = old;
        return 0;
    }

    // The last check: the relaxation judges a star against the input under its vertex, and vcglib's
    // flips judge nothing against the input, so on a thin part a face may still stand on edge,
    // facing away from the input triangle closest to its own centroid (armadillo's claw at 3x its
    // mean edge with VSA's automatic region cap: one triangle at 94 degrees). Each such face is
    // mended by the first of: its free corners moved to their neighbours' centroid on the input,
    // or one of its non-feature edges flipped, that leaves every face it touches facing the input.
    // Returns the faces mended. Needs face-face and vertex-face adjacency (kept valid).
    static int TurnBackFlippedFaces(MeshType &m, InputSurface<MeshType> &surface)
    {
        auto facesInput = [&](const P3 &a, const P3 &b, const P3 &c) {
            const P3 n = (b - a) ^ (c - a);
            return n.Norm() > 0 && surface.FacesEveryClosest((a + b + c) / 3.0, n);
        };
        auto faces = [&](const FaceType &f) { return facesInput(Pos(f.cV(0)), Pos(f.cV(1)), Pos(f.cV(2))); };
        FaceFaceAdjacency<MeshType>::Update(m);
        vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
        const std::vector<char> fixed = FeatureVertices(m);
        int mended = 0;
        std::vector<FaceType *> star;
        std::vector<int> corner;
        for (FaceType &f : m.face) {
            if (f.IsD() || faces(f)) continue;
            bool done = false;
            for (int k = 0; k < 3 && !done; ++k) {  // a free corner to its neighbours' centroid
                VertexType *v = f.V(k);
                if (fixed[vcg::tri::Index(m, v)]) continue;
                vcg::face::VFStarVF<FaceType>(v, star, corner);
                CoordType centroid(0, 0, 0);
                for (size_t i = 0; i < star.size(); ++i) centroid += star[i]->cV((corner[i] + 1) % 3)->cP();
                CoordType onSurface;
                if (star.empty() || !surface.Closest(centroid / ScalarType(star.size()), onSurface)) continue;
                const CoordType old = v->cP();
                v->P() = onSurface;
                done = std::all_of(star.begin(), star.end(), [&](FaceType *g) { return faces(*g); });
                if (!done) v->P() = old;
            }
            for (int i = 0; i < 3 && !done; ++i) {  // an edge flipped
                FaceType *g = f.FFp(i);
                if (g == &f || IsFeature(f, i) || !vcg::face::CheckFlipEdge(f, i)) continue;
                // f = (v0 v1 a), g across v0-v1 with apex b: the flip makes (v0 b a) and (b v1 a)
                const P3 v0 = Pos(f.cV0(i)), v1 = Pos(f.cV1(i)), a = Pos(f.cV2(i)), b = Pos(g->cV2(f.cFFi(i)));
                if (!facesInput(v0, b, a) || !facesInput(b, v1, a)) continue;
                FlipEdgeKeepingFlags(f, i);
                done = true;
            }
            mended += done;
        }
        FaceFaceAdjacency<MeshType>::Update(m);
        vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
        return mended;
    }

    // Every face of m reordered as CanonicalFaces reads it; those read reversed carry the returned
    // user bit (vcglib's splits copy it to the new faces).
    static int ReadCanonically(MeshType &m)
    {
        CanonicalFaces canon;
        canon.Read(m);
        const int bit = FaceType::NewBitFlag();
        for (size_t f = 0; f < m.face.size(); ++f) {
            FaceType &face = m.face[f];
            if (face.IsD()) continue;
            FaceCorners<MeshType>::Reorder(m, face, canon.corner[f]);
            if (canon.reversed[f]) face.SetUserBit(bit);
            else face.ClearUserBit(bit);
        }
        FaceFaceAdjacency<MeshType>::Update(m);
        vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
        return bit;
    }

    // The faces carrying `bit` turned back (the input's orientation), the bit released.
    static void BackToInputOrientation(MeshType &m, int bit)
    {
        for (FaceType &f : m.face)
            if (!f.IsD() && f.IsUserBit(bit)) {
                FaceCorners<MeshType>::Reverse(m, f);
                f.ClearUserBit(bit);
            }
        FaceType::DeleteBitFlag(bit);
        FaceFaceAdjacency<MeshType>::Update(m);
        vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
        vcg::tri::UpdateNormal<MeshType>::PerFace(m);
    }

    // vcglib's split step: RefineMidpoint with the remesher's length test (LongerThan), called
    // directly, as IsotropicRemeshing::Do would also build a grid over the whole input and rate
    // every face for creases at each pass. A split feature edge's halves stay features
    // (RefineMidpoint copies the face-edge flags). Needs face-face adjacency and keeps it valid.
    // Returns the number of edges split.
    static int SplitLongEdges(MeshType &m, ScalarType maxLength)
    {
        struct LongerThanMax {
            ScalarType maxLength;
            int count = 0;
            bool operator()(vcg::face::Pos<FaceType> &ep)
            {
                if (!LongerThan(ep.V()->P(), ep.VFlip()->P(), maxLength)) return false;
                ++count;
                return true;
            }
        } longer{maxLength};
        vcg::tri::RefineMidpoint(m, longer);
        return longer.count;
    }

    static bool IsFeature(const FaceType &f, int i) { return FacingFeatures<MeshType>::IsFeature(f, i); }

    static P3 Pos(const VertexType *v) { return P3::Construct(v->cP()); }
    static P3 UnitNormal(const FaceType &f)  // in double, as the partition's crease test
    {
        return ((Pos(f.cV(1)) - Pos(f.cV(0))) ^ (Pos(f.cV(2)) - Pos(f.cV(0)))).Normalize();
    }

    // A face lower than this times L (its height on its longest edge) is a needle.
    static constexpr double kNeedleHeight = 0.05;
    // A needle whose normal is within this of a neighbour's (degrees), and not turned over against
    // its other two, lies in that neighbour's plane: its normal is the surface's (the triangles of a
    // wall thinner than 0.05 L, as a thin plate's rim tessellated in rows, are all needles, and
    // their edges on the plate's faces are its creases). Two needles turned over together are
    // within it of each other, but turned over against the rest.
    static constexpr double kSupportedNeedleDeg = 5;
    // A face whose normal is farther than this from each of its neighbours' is turned over.
    static constexpr double kTurnedCos = -0.5;  // 120 degrees

    // Whether f's normal is noise at the scale of the output: a needle in no neighbour's plane (see
    // kSupportedNeedleDeg), or a face turned over against all of its neighbours (a fold of the
    // tessellation, no surface has one). A sharp edge such a face makes is no crease: CAD
    // tessellations have them along their creases (block: needles and caps folded 150-180 degrees
    // from their neighbours), and kept as creases their edges fenced in needles that no quad could
    // take.
    static bool Unreliable(const FaceType &f, double L)
    {
        double longest = 0;
        for (int k = 0; k < 3; ++k) longest = std::max(longest, (Pos(f.cV1(k)) - Pos(f.cV(k))).Norm());
        const double doubleArea = ((Pos(f.cV(1)) - Pos(f.cV(0))) ^ (Pos(f.cV(2)) - Pos(f.cV(0)))).Norm();
        const P3 n = UnitNormal(f);
        const double supportCos = std::cos(kSupportedNeedleDeg * M_PI / 180);
        int inPlane = 0, notTurned = 0;  // neighbours (across a non-border edge) in f's plane, and not turned over against it
        bool border = false;
        for (int k = 0; k < 3; ++k) {
            if (f.cFFp(k) == &f) {
                border = true;
                continue;
            }
            const double c = n * UnitNormal(*f.cFFp(k));
            inPlane += c > supportCos;
            notTurned += c > kTurnedCos;
        }
        if (doubleArea < kNeedleHeight * L * longest) return !(inPlane >= 1 && notTurned >= 2);
        return !border && notTurned == 0;
    }

    // Selected face-edges and sharp creases (but an unreliable face's): both sides flagged, each entered in
    // the grid. Needs face-face adjacency (ReadCanonically leaves it built).
    static void MarkFeatures(MeshType &m, double creaseAngleDeg, SegmentGrid &grid, std::vector<FeatureKind> &kinds, Stats &st, double L)
    {
        const double creaseCos = std::cos(creaseAngleDeg * M_PI / 180);
        const double sharpCos = std::cos(ShortEdgeCollapse<MeshType>::kSharpChainDeg * M_PI / 180);
        for (FaceType &f : m.face)
            for (int i = 0; i < 3; ++i) {
                FaceType *g = f.FFp(i);
                if (g < &f) continue;  // once per edge (a border edge has g == &f)
                const bool selected = IsFeature(f, i);
                const double cosBetween = g != &f ? UnitNormal(f) * UnitNormal(*g) : 1;  // of the faces' normals
                bool crease = creaseAngleDeg < 180 && cosBetween < creaseCos;
                if (crease && (Unreliable(f, L) || Unreliable(*g, L))) {
                    crease = false;
                    ++st.needleCreases;
                }
                if (!selected && !crease && g != &f) continue;
                f.SetFaceEdgeS(i);
                g->SetFaceEdgeS(f.FFi(i));
                grid.Add(Pos(f.V0(i)), Pos(f.V1(i)));
                FeatureKind kind;
                kind.front = selected;
                kind.sharp = cosBetween < sharpCos;
                kinds.push_back(kind);
                ++st.featureEdges;
                st.frontEdgesBefore += selected;
            }
    }

    // How far a new chain edge a-b strays from the original feature curves: its midpoint's distance
    // to them, and the farthest midpoint of an original feature edge beside it (projecting inside
    // it, nearer than kBeside L: a bump of the curve the chord cuts off; farther ones are other
    // features).
    static double CurveDeviation(const SegmentGrid &grid, const P3 &a, const P3 &b, double L)
    {
        double deviation;
        if (grid.Nearest((a + b) * 0.5, deviation) < 0) return std::numeric_limits<double>::infinity();
        const P3 ab = b - a;
        const double l2 = ab.SquaredNorm();
        if (!(l2 > 0)) return deviation;
        grid.ForEachNear(a, b, [&](int id) {
            const P3 m = grid.Midpoint(id);
            const double t = ((m - a) * ab) / l2;
            if (t <= 0 || t >= 1) return;
            const double d = (m - (a + ab * t)).Norm();
            if (d < kBeside * L) deviation = std::max(deviation, d);
        });
        return deviation;
    }
    static constexpr double kBeside = 0.5;

    // The original feature edge a-b lies on (the one nearest its midpoint): front or crease, sharp.
    static FeatureKind FeatureAt(const SegmentGrid &grid, const std::vector<FeatureKind> &kinds, const P3 &a, const P3 &b)
    {
        double d;
        const int id = grid.Nearest((a + b) * 0.5, d);
        return id >= 0 ? kinds[id] : FeatureKind();
    }

    // Every flagged output edge lies on one original feature edge: front when that one was.
    static void SelectFront(MeshType &m, const SegmentGrid &grid, const std::vector<FeatureKind> &kinds, Stats &st)
    {
        vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
        FaceFaceAdjacency<MeshType>::Update(m);
        for (FaceType &f : m.face)
            for (int i = 0; i < 3; ++i) {
                FaceType *g = f.FFp(i);
                if (g < &f) continue;
                const bool front = IsFeature(f, i) && FeatureAt(grid, kinds, Pos(f.V0(i)), Pos(f.V1(i))).front;
                const int j = f.FFi(i);
                if (front) {
                    f.SetFaceEdgeS(i);
                    g->SetFaceEdgeS(j);
                    ++st.frontEdgesAfter;
                } else {
                    f.ClearFaceEdgeS(i);
                    g->ClearFaceEdgeS(j);
                }
            }
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
