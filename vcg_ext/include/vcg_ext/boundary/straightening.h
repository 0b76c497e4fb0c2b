// GeodesicStraightening: the straightening of paths on a surface as one call (see
// geodesic_straightening.h for the method and its invariants).
#ifndef VCG_EXT_BOUNDARY_STRAIGHTENING_H
#define VCG_EXT_BOUNDARY_STRAIGHTENING_H

#include <algorithm>
#include <chrono>
#include <vector>

#include <vcg_ext/boundary/straightening_engine.h>
#include <vcg_ext/boundary/surface_path.h>

namespace vcg_ext {

template <class MeshType>
class GeodesicStraightening : public SurfacePathGeometry<MeshType>
{
public:
    typedef MeshEdgeTopology<MeshType> Topology;
    typedef StraighteningParams Params;
    typedef StraighteningResult Result;
    static constexpr int kMaxIterations = Params::kMaxIterations;
    static constexpr double kMinSnapFraction = Params::kMinSnapFraction;

    // Straightens the paths in place; `cb` gets percentages from `progressFrom` to `progressTo`.
    // The paths must be valid: consecutive points share a face, no point shared by two paths
    // except fixed ones at vertices, no crossings (boundary chains of mesh edges are). The ends of
    // open paths never move; a closed path without a fixed point gets its first point fixed.
    static Result Straighten(const Topology &t, std::vector<SurfacePath> &paths, const Params &p,
                             vcg::CallBackPos *cb = nullptr, int progressFrom = 0, int progressTo = 100)
    {
        auto t0 = std::chrono::steady_clock::now();
        Result res;
        res.error = p.Validate();
        if (!res.error.empty()) return res;
        StraighteningEngine<MeshType> engine(t, p);
        engine.Load(paths);
        for (int pass = 0; pass < p.iterations; ++pass) {
            if (cb) cb(progressFrom + (progressTo - progressFrom) * pass / std::max(1, p.iterations), "Region boundaries: straightening");
            const double gain = engine.Pass(res);
            ++res.passes;
            if (!(gain > 1e-9 * engine.InitialLength())) { res.converged = true; break; }
        }
        if (p.iterations > 0) engine.SnapToVertices(res);  // 0 iterations: the paths as given
        engine.Store(paths);
        res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return res;
    }
};

}  // namespace vcg_ext

#endif
