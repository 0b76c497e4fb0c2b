// Splitting a triangle mesh along polylines (seed paper, section 3.3): afterwards every polyline
// is a chain of mesh edges, those edges are selected face-edges, and the region ids in face quality
// are constant on each patch the polylines cut out.
//
//   1. Locate   every polyline point: at a vertex, inside an edge or inside a face (embedding_locate.h).
//   2. Trace    segments whose ends share no face across the faces between them (embedding_trace.h).
//   3. Split    each face holding polyline points: one new vertex per point on an edge, shared by
//               both faces of that edge; chords cut the face's looped vertex list, the pieces are
//               triangulated maximising the smallest angle (embedding_face_split.h). No snapping:
//               points are embedded where they are located.
//   4. Relabel  patches (faces connected without crossing a selected edge): each takes the region id
//               covering most of its area before the split (a patch whose majority id a larger patch
//               already took gets a new id), so id boundaries are exactly the selected edges of a
//               closed front.
//
// Prepare() does steps 1-3 without touching the mesh (bad input: an error, nothing changed;
// embedding_plan.h); Apply() writes the result (embedding_apply.h, embedding_relabel.h). Work is
// O(F) set-up (adjacency, one locating pass over the faces, relabelling) plus time proportional to
// the polyline points and the faces they cross.
#ifndef VCG_EXT_POLYLINE_EMBEDDING_H
#define VCG_EXT_POLYLINE_EMBEDDING_H

#include <chrono>
#include <string>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/progress_relay.h>
#include <vcg_ext/embedding/apply.h>
#include <vcg_ext/embedding/plan.h>
#include <vcg_ext/embedding/result.h>

namespace vcg_ext {

template <class MeshType, class PolylineType = MeshType>
class PolylineEmbedding
{
public:
    typedef embedding::EmbeddingResult Result;  // counts, min angle, region ids, timings
    typedef embedding::EmbeddingPlan Plan;      // what Prepare() hands to Apply()

    struct Params {
        double locateTolerancePercent = 1e-4;  // % of the mesh bounding-box diagonal

        std::string Validate() const
        {
            if (!(locateTolerancePercent > 0 && locateTolerancePercent <= 10))
                return "the locate tolerance must be in (0, 10] % of the bounding box diagonal";
            return "";
        }
    };

    // Steps 1-3 (read-only): on error, Result::error says why and the plan is not ready.
    static Result Prepare(const MeshType &m, const PolylineType &poly, const Params &p, Plan &plan,
                          vcg::CallBackPos *cb = nullptr)
    {
        return ProgressRelay::Run(cb, [&](vcg::CallBackPos *report) { return PrepareHere(m, poly, p, plan, report); });
    }

    // Writes a ready plan into the mesh it was prepared on (step 4 included).
    static Result Apply(MeshType &m, Plan &plan, vcg::CallBackPos *cb = nullptr)
    {
        return ProgressRelay::Run(cb, [&](vcg::CallBackPos *report) { return ApplyHere(m, plan, report); });
    }

    // Prepare + Apply.
    static Result Embed(MeshType &m, const PolylineType &poly, const Params &p, vcg::CallBackPos *cb = nullptr)
    {
        return ProgressRelay::Run(cb, [&](vcg::CallBackPos *report) {
            Plan plan;
            Result r = PrepareHere(m, poly, p, plan, report);
            if (!r.error.empty()) return r;
            return ApplyHere(m, plan, report);
        });
    }

private:
    static Result PrepareHere(const MeshType &m, const PolylineType &poly, const Params &p, Plan &plan, vcg::CallBackPos *cb)
    {
        auto t0 = std::chrono::steady_clock::now();
        plan = Plan();
        Result r;
        r.error = p.Validate();
        r.inputProblem = !r.error.empty();
        if (r.error.empty()) {
            embedding::PlanBuilder<MeshType, PolylineType> builder(m, plan, cb);
            r = builder.Run(poly, p.locateTolerancePercent, static_cast<const void *>(&m) == static_cast<const void *>(&poly));
        }
        r.secondsPrepare = embedding::Seconds(t0);
        r.seconds = r.secondsPrepare;
        plan.ready = r.error.empty();
        plan.stats = r;
        return r;
    }

    static Result ApplyHere(MeshType &m, Plan &plan, vcg::CallBackPos *cb)
    {
        auto t0 = std::chrono::steady_clock::now();
        Result r = plan.stats;
        if (!plan.ready) { r.error = "the plan is not ready"; return r; }
        if (int(m.vert.size()) != plan.vertexCount || int(m.face.size()) != plan.faceCount) {
            r.error = "the mesh changed since the plan was prepared";
            return r;
        }
        embedding::PlanWriter<MeshType> writer(m, plan, r, cb);
        writer.Run();
        plan.ready = false;
        r.secondsApply = embedding::Seconds(t0);
        r.seconds = r.secondsPrepare + r.secondsApply;
        return r;
    }

};

}  // namespace vcg_ext

#endif
