// Q-Morph quad conversion of a vcg triangle mesh from its selected face-edges (and boundary).
//
// The front (selected face-edges + boundary edges) cuts the surface into patches; every patch is
// cut out as its own mesh (a node where the front passes is copied once per fan sector, so slits,
// patches touching themselves and annuli need no special case), meshed by PatchMesher from its
// boundary loops, and written back. Initial front edges are never changed, so patches are
// independent and the front stays a set of mesh edges; after the run those edges are again the
// only selected face-edges. Output in MeshLab's polygonal form: a quad is two triangles sharing a
// faux edge. Face quality (region id) is kept per patch (its area-majority value).
#ifndef VCG_EXT_QMORPH_H
#define VCG_EXT_QMORPH_H

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <climits>
#include <iterator>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <string>
#include <unordered_set>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/flag.h>

#include <vcg_ext/common/face_corners.h>
#include <vcg_ext/common/format.h>
#include <vcg_ext/common/input_surface.h>
#include <vcg_ext/common/live_box.h>
#include <vcg_ext/common/parallel.h>
#include <vcg_ext/common/point_query_memo.h>
#include <vcg_ext/common/progress_relay.h>
#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/qmorph/all_quads.h>
#include <vcg_ext/qmorph/feature_remesh.h>
#include <vcg_ext/qmorph/flat_quad_split.h>
#include <vcg_ext/qmorph/flipped_face_mend.h>
#include <vcg_ext/qmorph/front_node_plan.h>
#include <vcg_ext/qmorph/worst_element_smoothing.h>
#include <vcg_ext/qmorph/partition.h>
#include <vcg_ext/qmorph/patch_mesher.h>
#include <vcg_ext/qmorph/quad_output.h>
#include <vcg_ext/quad_quality.h>

namespace vcg_ext {

template <class MeshType>
class QMorph
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef typename MeshType::CoordType CoordType;
    typedef qmorph::P3 P3;

    struct Params {
        bool preserveInitialFront = true;  // the paper: no seam onto initial front edges, a triangle is
                                           // left instead; off: the seam joins the other node to the
                                           // front node (initial front edges are never changed either way)
        bool transitions = true;           // Owen's transition seam and transition split
        bool cleanup = true;               // valence turns and diagonal collapses after the front
        bool rescueBadQuads = true;        // quads below 0.3 scaled Jacobian: their nodes re-placed (and the output's worst raised)
        bool smoothing = true;             // tangent-plane smoothing (local, and final sweeps)
        int smoothingIterations = 5;       // final smoothing sweeps, 0..100
        double closedAngleDeg = 135;       // front angle closing an edge end (Owen: 3pi/4)
        double creaseAngleDeg = 60;        // edges this sharp (angle between face normals) are front
                                           // too, so no quad folds over a crease; >= 180: off
        bool remeshFirst = false;          // isotropic re-meshing of the whole mesh first, at targetEdgeLength
                                           // or, when that is 0, at AutomaticEdgeLength
        double targetEdgeLength = 0;       // > 0: re-meshing at this length (absolute units), even with
                                           // remeshFirst off; 0: automatic (remeshFirst) or none
        int remeshIterations = 5;          // split/collapse/flip/relax rounds of that re-meshing
        bool allQuads = false;             // no triangle left: every face split into quads at the end
                                           // (qmorph/all_quads.h), after re-meshing at twice a length given
                                           // (at the automatic length itself: see RemeshLength)
        int threads = 0;                   // patches meshed at once (and the re-meshing's searches): 0 = the
                                           // machine's cores (same output)
        bool planFrontNodes = true;        // side edges at initial-front nodes planned over all their
                                           // patches (qmorph/front_node_plan.h); off: each patch decides

        std::string Validate() const
        {
            if (smoothingIterations < 0 || smoothingIterations > 100) return "smoothing iterations must be in 0..100";
            if (!(creaseAngleDeg > 0 && creaseAngleDeg <= 180)) return "the crease angle must be in (0, 180] degrees";
            if (!(closedAngleDeg > 30 && closedAngleDeg < 180)) return "the closed-end angle must be in (30, 180) degrees";
            if (!(targetEdgeLength >= 0 && std::isfinite(targetEdgeLength))) return "the target edge length must be a finite number >= 0 (0: automatic)";
            if (remeshIterations < 1 || remeshIterations > 50) return "re-meshing iterations must be in 1..50";
            return "";
        }
    };

    struct Result {
        std::string error;
        int initialFrontEdges = 0, patches = 0, patchesWithoutFront = 0;
        int creaseEdges = 0;  // sharp edges that were not selected but cut the patches too
        double targetEdgeLength = 0;   // re-meshing length used (0: none)
        bool automaticLength = false;  // ... chosen by AutomaticEdgeLength
        typename qmorph::FeatureRemesh<MeshType>::Stats remesh;
        int quads = 0, triangles = 0;
        int pentagons = 0;  // all quads: triangles merged with a quad before the split (AllQuads::Stats)
        int upsideDownBeforeSplit = 0;  // all quads: faces with every corner on input facing away, turned back first
        int sliversBeforeSplit = 0;     // all quads: slivers (kSliverHeight) removed first
        qmorph::PatchStats ops;
        typename qmorph::WorstElementSmoothing<MeshType>::Stats shape;  // the output's final shape pass
        typename qmorph::FlippedFaceMend<MeshType>::Stats mend;         // the output's last check
        int flatQuadsSplit = 0;  // quads with a straight corner at a node that never moves, split in two triangles
        QuadQualityReport quality;
        double seconds = 0;
        double remeshSeconds = 0;  // the re-meshing's share of `seconds` (not in RemeshSummary: runs compare it)

        // The run in one line (the filter's log, the tests and the benchmark print the same).
        std::string Summary() const
        {
            return Format("Q-Morph: %d patches (%d without front), %d initial front edges (%d of them unselected sharp creases); "
                          "%d quads, %d triangles left (%.1f%% of the area in quads); %d quads formed, %d by templates, %d seams, "
                          "%d transition seams, %d transition splits, %d triangle pairs merged, %d doublets removed, %d edges "
                          "turned, %d quads collapsed and %d opened for valence, %d cavities re-meshed as grids; %d swaps, %d splits%s; %.3f s",
                          patches, patchesWithoutFront, initialFrontEdges, creaseEdges, quads, triangles, 100 * quality.quadAreaFraction,
                          ops.quadsFormed, ops.templates, ops.seams, ops.transitionSeams, ops.transitionSplits, ops.pairedTriangles,
                          ops.doublets, ops.valenceTurns, ops.diagonalCollapses, ops.quadsOpened, ops.cavities, ops.swaps, ops.splits,
                          AllQuadsSummary().c_str(),
                          seconds);
        }
        // What the all-quads split did first ("" when nothing).
        std::string AllQuadsSummary() const
        {
            std::string s;
            if (pentagons) s += Format("; all quads: %d triangles merged with a quad into a pentagon first", pentagons);
            if (upsideDownBeforeSplit)
                s += Format("%s %d faces with every corner on input facing away turned back first", s.empty() ? "; all quads:" : ",",
                            upsideDownBeforeSplit);
            if (sliversBeforeSplit) s += Format("%s %d sliver triangles removed first", s.empty() ? "; all quads:" : ",", sliversBeforeSplit);
            return s;
        }
        // The re-meshing in one line; empty when the patches were not re-meshed.
        std::string RemeshSummary() const
        {
            if (!(targetEdgeLength > 0)) return "";
            return Format("Q-Morph re-meshing to edge length %g%s: %d front edges became %d (%d feature edges before), %d -> %d "
                          "triangles; %d splits, %d collapses, %d flips, %d splits facing feature strips%s%s",
                          targetEdgeLength, automaticLength ? " (automatic)" : "", remesh.frontEdgesBefore, remesh.frontEdgesAfter, remesh.featureEdges,
                          remesh.facesBefore, remesh.facesAfter, remesh.splits, remesh.collapses, remesh.flips, remesh.facingSplits,
                          remesh.needleCreases ? Format(", %d sharp edges of needles or turned faces not kept as creases", remesh.needleCreases).c_str() : "",
                          remesh.turnedBack ? Format(", %d faces turned back onto the input", remesh.turnedBack).c_str() : "");
        }
        std::string QualitySummary() const
        {
            const QuadQualityReport &q = quality;
            return Format("Q-Morph quality: scaled Jacobian min %.3f mean %.3f p5 %.3f (against the input surface's "
                          "normal), %d quads below 0.3, %d inverted; flipped faces: %d, folded quads: %d; irregular "
                          "vertices %d of %d (%.1f%%)",
                          q.minJacobian, q.meanJacobian, q.p5Jacobian, q.quadsBelow03, q.invertedQuads, q.flippedFaces,
                          q.foldedQuads, q.irregularVertices, q.interiorAllQuadVertices, 100 * q.IrregularFraction()) +
                   (q.frontKnown ? Format(": %d inside patches, %d at front nodes, %d at front junctions", q.IrregularInsidePatches(),
                                          q.irregularAtFrontNodes, q.irregularAtFrontJunctions)
                                 : std::string()) +
                   (shape.moves ? Format("; worst elements raised: %d corners moved, elements below 0.3 %d -> %d", shape.moves,
                                         shape.poorBefore, shape.poorAfter)
                                : std::string()) +
                   (flatQuadsSplit ? Format("; %d quads with a straight corner at a fixed node split into two triangles", flatQuadsSplit)
                                   : std::string()) +
                   (mend.mended || mend.needlesRemoved
                        ? Format("; last check: %d faces found flipped or inverted and turned back, %d needle triangles removed",
                                 mend.mended, mend.needlesRemoved)
                        : std::string()) +
                   (mend.split || mend.collapsed || mend.needlesFlipped
                        ? Format(" (%d triangles split on the sheet they face, %d collapsed with the triangle across a side%s, "
                                 "%d needles flipped away with the polygon across their longest side)",
                                 mend.split, mend.collapsed,
                                 mend.quadsHalved ? Format(" (%d of them half of a quad, left a triangle)", mend.quadsHalved).c_str() : "",
                                 mend.needlesFlipped)
                        : std::string());
        }
    };

    // Why the mesh and parameters cannot be converted (the mesh is then left as it is), or "".
    static std::string Check(const MeshType &m, const Params &params)
    {
        std::string why = params.Validate();
        if (why.empty()) why = CheckInput(m);
        if (why.empty()) why = CheckRemeshSize(m, params);
        return why;
    }

    static std::string CheckInput(const MeshType &m)
    {
        MeshCheckReport r = MeshChecks<MeshType>::Inspect(m);
        std::string why = r.PipelineProblem();
        if (!why.empty()) return why;
        if (r.IsClosed() && CountSelectedEdges(m) == 0)
            return "the mesh is closed and has no selected edges: there is no initial front. Run 'Split Triangles "
                   "along Front' (or 'Select Crease Edges') first";
        return "";
    }

    // The re-meshing length these parameters give on m (0: no re-meshing).
    // With allQuads and a length given, twice that length: the final split halves every edge, so the
    // quads have the length asked for. With allQuads and the automatic length, that length itself:
    // the quad-dominant mesh the split starts from is then the one of the defaults (re-meshed at
    // twice the automatic length, scans' thin parts get too few rows, and a poor face has only poorer
    // children: mean scaled Jacobian 0.85-0.89 on five of the shared meshes), at the price of four
    // times its faces.
    static double RemeshLength(const MeshType &m, const Params &params)
    {
        if (params.targetEdgeLength > 0) return params.allQuads ? 2 * params.targetEdgeLength : params.targetEdgeLength;
        return params.remeshFirst ? AutomaticEdgeLength(m) : 0;
    }

    // The automatic target edge length: the side of equilateral triangles that tile the surface in as
    // many triangles as the input has (so the quads keep the input's resolution whatever its
    // triangles' shapes), no longer than kMaxAutoDiagonalFraction of the bounding-box diagonal (a
    // coarse CAD tessellation of a few hundred slivers has too few triangles to tell its
    // resolution; its features get at least that), and no longer than 1 / kMinRowsAcross of the
    // patches' width 2 A / F (A the area, F the front's length: the side of square patches with
    // that front): Q-Morph's rows need room (see kMinRowsAcross). Neither the input's density nor
    // the patches' width asks for more than kMaxAutoTriangles triangles.
    static double AutomaticEdgeLength(const MeshType &m)
    {
        const vcg::Box3d box = LiveVertexBox(m);
        const double area = SurfaceArea(m), front = FrontLength(m);
        double L = EquilateralSide(area, std::max(1, m.fn));
        if (front > 0) L = std::min(L, 2 * area / front / kMinRowsAcross);
        L = std::max(L, EquilateralSide(area, kMaxAutoTriangles));
        return std::min(L, kMaxAutoDiagonalFraction * box.Diag());
    }

    // The length of the front (selected edges, each counted once). Each face's selected edges are
    // added shortest first, so a flipped copy of the mesh (its edges at other indices) gives the same
    // bits: the automatic length, and the re-meshing's grid of cells with it, must not depend on the
    // orientation.
    static double FrontLength(const MeshType &m)
    {
        double twice = 0;  // an edge is selected on both its faces
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            double lengths[3] = {0, 0, 0};  // an unselected edge adds an exact 0
            for (int k = 0; k < 3; ++k)
                if (f.IsFaceEdgeS(k)) lengths[k] = vcg::Distance(vcg::Point3d::Construct(f.cP0(k)), vcg::Point3d::Construct(f.cP1(k)));
            std::sort(lengths, lengths + 3);
            for (double l : lengths) twice += l;
        }
        return twice / 2;
    }

    // Bounded memory: a target edge length far below the mesh's scale would make a huge mesh.
    static std::string CheckRemeshSize(const MeshType &m, const Params &params)
    {
        const double L = RemeshLength(m, params);
        if (L <= 0) return "";
        const double estimate = SurfaceArea(m) / (kEquilateralArea * L * L);
        const double cap = 2e7;
        if (estimate > cap)
            return "the target edge length " + std::to_string(L) + " is too small for this mesh: re-meshing would make about " +
                   std::to_string(long(estimate)) + " triangles (at most " + std::to_string(long(cap)) + ")";
        return "";
    }

    // The area, each face's from its corners in memory order (whichever corner a face starts at and
    // whichever way it turns, the same bits: see FrontLength).
    static double SurfaceArea(const MeshType &m)
    {
        double area = 0;
        for (const FaceType &f : m.face) {
            if (f.IsD()) continue;
            const std::array<const VertexType *, 3> c = FaceCorners<MeshType>::InMemoryOrder(f);
            const vcg::Point3d a = vcg::Point3d::Construct(c[0]->cP());
            area += ((vcg::Point3d::Construct(c[1]->cP()) - a) ^ (vcg::Point3d::Construct(c[2]->cP()) - a)).Norm() / 2;
        }
        return area;
    }

    static int CountSelectedEdges(const MeshType &m)
    {
        int n = 0;
        for (const FaceType &f : m.face)
            if (!f.IsD())
                for (int k = 0; k < 3; ++k) n += f.IsFaceEdgeS(k) ? 1 : 0;
        return n;  // face-edges (an interior edge selected on both sides counts twice)
    }

    // Converts m; on bad input (Check) returns the error and leaves m as it is.
    static Result Apply(MeshType &m, const Params &params, vcg::CallBackPos *cb = nullptr)
    {
        return ProgressRelay::Run(cb, [&](vcg::CallBackPos *report) {
            auto t0 = std::chrono::steady_clock::now();
            Result res;
            Progress(report, 0, "Q-Morph: checking the mesh");
            res.error = Check(m, params);
            if (!res.error.empty()) return res;

            vcg::tri::RequireFFAdjacency(m);  // to read the quads back for the quality report
            Run(m, params, report, res);
            res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            return res;
        });
    }

private:
    static constexpr double kMaxAutoTriangles = 250000;
    static constexpr double kMaxAutoDiagonalFraction = 0.01;
    // Rows of quads across a patch at the automatic length, at least: on CGAL's scans whose
    // segmentation is fine for their resolution (bull, dino, femur, triceratops: 4.2-5.8 rows at the
    // input's own density) the quads had mean scaled Jacobian 0.82-0.89 and 11-21% irregular
    // vertices; every shared mesh that met the quality bars had at least 6.4.
    static constexpr double kMinRowsAcross = 8;
    // Rounds of the output's last check (FlippedFaceMend): one is enough on every mesh measured but
    // man (kept aside), which needs two.
    static constexpr int kMendRounds = 3;
    // All quads: a triangle whose apex is nearer its longest side than this fraction of it (an
    // angle under about 6 degrees) is removed before the split by the last check's needle
    // operations (a collapse or a flip, each refused if it makes a needle or turns a face over):
    // the split's children of such a sliver have a corner under 6 or over 160 degrees (block's
    // quads below 0.3: 0.52% -> 0.39%). At 0.1, more quads turned over (diplodocus 7 -> 10, man 22 -> 25).
    static constexpr double kSliverHeight = 0.05;
    // The re-meshing's share of the progress bar (about half of the stage's time on big scans).
    static constexpr int kRemeshProgress = 50;

    static void Progress(vcg::CallBackPos *cb, int percent, const char *msg)
    {
        if (cb) cb(std::max(0, std::min(99, percent)), msg);
    }

    // Partition, then each patch: cut out, (front subdivision and re-meshing,) Q-Morph, collected;
    // then everything written back at once.
    static void Run(MeshType &m, const Params &par, vcg::CallBackPos *cb, Result &res)
    {
        res.targetEdgeLength = RemeshLength(m, par);
        res.automaticLength = res.targetEdgeLength > 0 && !(par.targetEdgeLength > 0);
        InputSurface<MeshType> input(m, cb);  // the quality report's reference (and the re-meshing's)
        if (res.targetEdgeLength > 0) {
            const auto t0 = std::chrono::steady_clock::now();
            res.remesh = qmorph::FeatureRemesh<MeshType>::Do(m, input, res.targetEdgeLength, par.remeshIterations, par.creaseAngleDeg,
                                                             cb, kRemeshProgress, ThreadCount(par.threads));
            res.remeshSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        }
        const int patchesFrom = res.targetEdgeLength > 0 ? kRemeshProgress : 1;
        Progress(cb, patchesFrom, "Q-Morph: patches, partition");
        qmorph::FrontPartition part;
        part.Build(m, par.creaseAngleDeg);
        if (par.planFrontNodes) part.plannedSides = qmorph::FrontNodePlan::Plan(m, part);
        res.initialFrontEdges = part.frontEdges;
        res.creaseEdges = part.creaseEdges;
        const qmorph::PatchParams pp = PatchParamsOf(par);
        qmorph::QuadOutput out(m.vert.size());
        // Patches are independent (initial front edges never change): meshed on a pool, biggest
        // first, appended in patch order on this thread, which alone calls the progress callback.
        std::vector<std::pair<size_t, size_t>> patches;
        part.ForEachPatch([&](size_t begin, size_t end) { patches.push_back({begin, end}); });
        std::vector<size_t> biggestFirst(patches.size());
        std::iota(biggestFirst.begin(), biggestFirst.end(), size_t(0));
        std::stable_sort(biggestFirst.begin(), biggestFirst.end(), [&](size_t a, size_t b) {
            return patches[a].second - patches[a].first > patches[b].second - patches[b].first;
        });
        struct Meshed {
            qmorph::QuadOutput::PatchPolygons polygons;
            qmorph::PatchStats ops;
            bool hasFront = false;
        };
        // counted as patches finish, not as they merge: merges wait for patch order, and a small
        // patch started last (biggest first) held the percent still for most of the stage
        std::atomic<size_t> facesDone{0};
        OrderedParallelFor<Meshed>(
            patches.size(), ThreadCount(par.threads), biggestFirst,
            [&](size_t i) {
                const size_t begin = patches[i].first, end = patches[i].second;
                Meshed r;
                // Extract writes only its own patch's sectors of the partition's scratch.
                qmorph::PatchInput in = part.Extract(m, begin, end);
                r.hasFront = in.hasFront;
                PointQueryMemo<P3> judged;  // before mm: its judge holds a reference to it
                qmorph::MixedMesh mm;
                mm.Build(in.points, in.tris, in.cut);
                mm.plannedSides = in.plannedSides;
                // The input judges: under a re-meshed patch the patch's own surface is not the input,
                // and on the input itself a walk over the patch can end on the far side of a tight bend.
                const double side = in.reversed ? -1 : 1;  // the patch is read the other way round
                // The patch's distance starts the search only where the patch is the input itself.
                const bool patchIsInput = !(res.targetEdgeLength > 0);
                // Read-only queries (no lock), each remembered by this patch's memo: one patch asks
                // again and again under the same centroids.
                mm.judge = [&input, &judged, side, patchIsInput](const P3 &p, double near) {
                    return judged.Get(p, patchIsInput ? near : -1, [&](const P3 &q, double within) {
                        return input.NormalUnder(q, P3(0, 0, 0), within) * side;
                    });
                };
                mm.facesEveryClosest = [&input, side](const P3 &p, const P3 &direction) {
                    return input.FacesEveryClosest(p, direction * side);
                };
                mm.patchIsInput = patchIsInput;
                mm.SetKeys(in.globalOf);
                SurfaceProjector surface;
                surface.Build(in.points, in.tris);
                if (in.hasFront) {
                    TellOtherPatches(part, part.patchOf[part.order[begin]], in, mm);
                    r.ops = qmorph::PatchMesher(mm, surface, in.home, pp).Run();
                }
                r.polygons = qmorph::QuadOutput::Collect(mm, surface, in.home, in);
                facesDone += end - begin;
                return r;
            },
            [&](size_t, Meshed &&r) {
                ++res.patches;
                if (!r.hasFront) ++res.patchesWithoutFront;
                res.ops += r.ops;
                out.Append(r.polygons);
            },
            [&]() {
                const double done = double(facesDone.load()) / double(std::max<size_t>(1, part.order.size()));
                Progress(cb, patchesFrom + int((99 - patchesFrom) * done), "Q-Morph: meshing patches");
            });
        res.quads = out.quads;
        res.triangles = out.triangles;
        Progress(cb, 99, "Q-Morph: writing the quad mesh");
        out.WriteTo(m, part);
        const bool raiseWorst = par.smoothing && par.rescueBadQuads;  // the rescue of each patch's bad quads, on the whole output
        if (par.allQuads) {
            // first on the faces the split cuts too (a poor face only has poorer children); the log
            // counts the pass on the split mesh
            if (raiseWorst) qmorph::WorstElementSmoothing<MeshType>::Do(m, input, par.creaseAngleDeg);
            // faces upside down on a thin plate whose centroid the judge reads right (their children
            // would turn over: bones, diplodocus, man, kept aside: 46 -> 36 flipped quads), and
            // slivers (their children's worst corners are under 6 or over 160 degrees: block)
            Progress(cb, 99, "Q-Morph: all quads, upside-down faces and slivers");
            const auto before = qmorph::FlippedFaceMend<MeshType>::Do(m, input, par.creaseAngleDeg, true, kSliverHeight);
            res.upsideDownBeforeSplit = before.mended;
            res.sliversBeforeSplit = before.needlesRemoved;
            Progress(cb, 99, "Q-Morph: all quads");
            const typename qmorph::AllQuads<MeshType>::Stats split = qmorph::AllQuads<MeshType>::Split(m, input, par.creaseAngleDeg);
            res.quads = split.quads;
            res.pentagons = split.pentagons;
            res.triangles = 0;
        }
        if (raiseWorst) {
            Progress(cb, 99, "Q-Morph: raising the worst elements");
            res.shape = qmorph::WorstElementSmoothing<MeshType>::Do(m, input, par.creaseAngleDeg);
        }
        if (par.rescueBadQuads && !par.allQuads) {
            const std::vector<int> polygonBefore = qmorph::OutputPolygons::PolygonOfFace(m);
            res.flatQuadsSplit = qmorph::FlatQuadSplit<MeshType>::Do(m, input, par.creaseAngleDeg);
            res.quads -= res.flatQuadsSplit;
            res.triangles += 2 * res.flatQuadsSplit;
            if (res.flatQuadsSplit) {  // a split quad's second face is a polygon of its own now, with the quad's normal
                std::vector<P3> normals;
                QuadQuality::ForEachFauxPolygon(m, [&](FaceType &f, const std::array<int, 4> &, int) {
                    normals.push_back(out.referenceNormals[polygonBefore[vcg::tri::Index(m, f)]]);
                });
                out.referenceNormals.swap(normals);
            }
        }
        Progress(cb, 99, "Q-Morph: quality report");
        auto measure = [&]() {
            const PolygonMesh pm = QuadQuality::FromFauxMesh(m);
            return QuadQuality::Measure(pm, input.NormalsUnder(pm, out.referenceNormals));
        };
        res.quality = measure();
        // the last check, only when needed; again while a round collapsed, flipped or split faces
        // and left something to mend: the faces around one it could not mend may have changed (a
        // needle next to a flipped triangle along a thin fin: man, kept aside)
        for (int round = 0; round < kMendRounds; ++round) {
            const QuadQualityReport &q = res.quality;
            if (!(q.flippedFaces || q.invertedQuads || q.foldedQuads || qmorph::FlippedFaceMend<MeshType>::HasNeedleTriangle(m))) break;
            Progress(cb, 99, "Q-Morph: flipped faces");
            const typename qmorph::FlippedFaceMend<MeshType>::Stats mend = qmorph::FlippedFaceMend<MeshType>::Do(m, input, par.creaseAngleDeg);
            for (const auto &same : mend.sameNormalAs) out.referenceNormals[same.first] = out.referenceNormals[same.second];
            for (auto p = mend.removedPolygons.rbegin(); p != mend.removedPolygons.rend(); ++p)
                out.referenceNormals.erase(out.referenceNormals.begin() + *p);
            out.referenceNormals.insert(out.referenceNormals.end(), mend.splitNormals.begin(), mend.splitNormals.end());
            res.triangles += 2 * mend.split - 2 * (mend.collapsed - mend.quadsHalved);
            res.quads -= mend.quadsHalved + mend.quadsCollapsed;
            res.mend.Add(mend);
            if (mend.mended || mend.needlesRemoved) res.quality = measure();
            if (!(mend.split || mend.collapsed || mend.quadsCollapsed || mend.needlesFlipped)) break;
        }
    }

    // The per-patch parameters (angles in radians) from the filter's.
    static qmorph::PatchParams PatchParamsOf(const Params &par)
    {
        qmorph::PatchParams pp;
        pp.smoothing = par.smoothing;
        pp.finalSmoothing = par.smoothingIterations;
        pp.closedAngle = par.closedAngleDeg * M_PI / 180;
        pp.preserveInitialFront = par.preserveInitialFront;
        pp.transitions = par.transitions;
        pp.cleanup = par.cleanup;
        pp.rescueBadQuads = par.rescueBadQuads;
        return pp;
    }

    // Which other patches hold each front node: a chord between two front nodes that another patch
    // also holds could be made there too (see MixedMesh::NewChordBetweenFrontNodes).
    static void TellOtherPatches(const qmorph::FrontPartition &part, int patch, const qmorph::PatchInput &in, qmorph::MixedMesh &mm)
    {
        mm.otherPatches.assign(mm.VertexCount(), {});
        for (int v = 0; v < mm.VertexCount(); ++v) {
            if (!mm.vertFixed[v]) continue;
            std::vector<int> &ps = mm.otherPatches[v];
            ps = part.patchesOfVertex[in.globalOf[v]];
            ps.erase(std::remove(ps.begin(), ps.end(), patch), ps.end());
        }
    }
};

}  // namespace vcg_ext

#endif
