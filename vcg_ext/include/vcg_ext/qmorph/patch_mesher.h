// Q-Morph on one patch: a triangulated surface piece whose boundary is the initial front. The
// mesher only orders the stages, which share a PatchContext:
//   front advance (front_advance.h)        rows of quads from the front, seams, transitions, templates;
//   node placement (node_placement.h)      smoothing sweeps before the leftovers are paired;
//   leftover triangles (leftover_triangles.h)  pairs merged, distant ones brought together, doublets;
//   topology clean-up (topology_cleanup.h) two rounds of turns, collapses and opens, then cavities
//   and cavity patterns (cavity_patterns.h) re-meshed as grids, a smoothing sweep that keeps edges
//                                          on the surface after each;
//   node placement                         final smoothing sweeps, bad quads' nodes re-placed.
#ifndef VCG_EXT_QMORPH_PATCH_MESHER_H
#define VCG_EXT_QMORPH_PATCH_MESHER_H

#include <vector>

#include <vcg_ext/qmorph/cavity_patterns.h>
#include <vcg_ext/qmorph/front_advance.h>
#include <vcg_ext/qmorph/leftover_triangles.h>
#include <vcg_ext/qmorph/node_placement.h>
#include <vcg_ext/qmorph/patch_stage.h>
#include <vcg_ext/qmorph/topology_cleanup.h>

namespace vcg_ext {
namespace qmorph {

class PatchMesher
{
public:
    PatchMesher(MixedMesh &mesh, const SurfaceProjector &surface, std::vector<int> &homeTriangle, const PatchParams &params)
        : context(mesh, surface, homeTriangle, params)
    {
    }

    PatchStats Run()
    {
        const PatchParams &p = context.p;
        FrontAdvance(context).Run();
        NodePlacement placement(context);
        // Leftover triangles: smooth first (their shapes improve), then merge good adjacent pairs,
        // then bring distant ones together through the quads.
        if (p.smoothing)
            for (int it = 0; it < kSmoothingBeforePairing; ++it) placement.SmoothAll();
        LeftoverTriangles leftovers(context);
        leftovers.Run();
        if (p.cleanup) {
            TopologyCleanup cleanup(context);
            for (int round = 0; round < kCleanupRounds; ++round) {  // a smoothing sweep between rounds: better shapes let more operations pass
                cleanup.Round([&] { leftovers.DissolveDoublets(); });
                CavityPatterns(context).Run();  // what the local operations leave, then they get another go
                if (p.smoothing) placement.SmoothAll(true);
            }
        }
        if (p.smoothing) {
            for (int it = 0; it < p.finalSmoothing; ++it) placement.SmoothAll(true);  // topology is final: keep edges on the surface
            if (p.rescueBadQuads) placement.ImproveBadFaces();
        }
        return context.stats;
    }

private:
    static constexpr int kSmoothingBeforePairing = 2, kCleanupRounds = 2;
    PatchContext context;
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
