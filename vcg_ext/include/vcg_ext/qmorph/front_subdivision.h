// Front edges cut into pieces of about the target length before a patch is re-meshed. The points
// depend only on the edge's two input vertices, so both patches on an edge make the same points;
// they are written once (QuadOutput's shared points) and every front curve stays a chain of
// selected output edges.
#ifndef VCG_EXT_QMORPH_FRONT_SUBDIVISION_H
#define VCG_EXT_QMORPH_FRONT_SUBDIVISION_H

#include <algorithm>
#include <iterator>
#include <unordered_map>
#include <vector>

#include <vcg_ext/common/edge_key.h>
#include <vcg_ext/qmorph/mixed_mesh.h>
#include <vcg_ext/qmorph/partition.h>
#include <vcg_ext/qmorph/quad_output.h>
#include <vcg_ext/qmorph/remesh.h>

namespace vcg_ext {
namespace qmorph {

class FrontSubdivision
{
public:
    std::vector<std::vector<int>> sharedPatches;  // per shared point: the patches holding it (sorted)
    int edgesSubdivided = 0;

    FrontSubdivision(const FrontPartition &partition, QuadOutput &output, double targetLength)
        : part(partition), out(output), L(targetLength)
    {
    }

    // Cuts the boundary (initial front) half-edges of a patch's mesh; sharedOfLocal gets, per new
    // local node, its shared point. Node keys are set so copies of a point count as one node.
    template <class MeshType>
    void Subdivide(const MeshType &m, const PatchInput &in, MixedMesh &mm, std::vector<int> &home,
                   std::unordered_map<int, int> &sharedOfLocal)
    {
        const std::vector<int> &globalOf = in.globalOf;
        const int boundaryCount = mm.HalfEdgeCount();
        std::vector<int> keys(globalOf.begin(), globalOf.end());
        for (int h = 0; h < boundaryCount; ++h) {
            if (!mm.HeAlive(h) || mm.heTwin[h] >= 0 || mm.Org(h) >= int(globalOf.size()) || mm.Dst(h) >= int(globalOf.size())) continue;
            const int ga = globalOf[mm.Org(h)], gb = globalOf[mm.Dst(h)];
            const int lo = std::min(ga, gb), hi = std::max(ga, gb);
            const P3 plo = P3::Construct(m.vert[lo].cP()), phi = P3::Construct(m.vert[hi].cP());
            const int n = PatchRemesher::PiecesFor((phi - plo).Norm(), L);
            if (n < 2) continue;
            const uint64_t key = EdgeKey(lo, hi);
            auto it = out.sharedOfEdge.find(key);
            if (it == out.sharedOfEdge.end()) {
                it = out.sharedOfEdge.emplace(key, int(out.sharedOut.size())).first;
                std::vector<int> both;  // the patches on the edge hold its points
                const std::vector<int> &pl = part.patchesOfVertex[lo], &ph = part.patchesOfVertex[hi];
                std::set_intersection(pl.begin(), pl.end(), ph.begin(), ph.end(), std::back_inserter(both));
                std::vector<int> chain{lo};
                for (int k = 1; k < n; ++k) {
                    out.newPoints.push_back(plo + (phi - plo) * (double(k) / n));
                    out.sharedOut.push_back(NewPointId(int(out.newPoints.size()) - 1));
                    sharedPatches.push_back(both);
                    chain.push_back(out.sharedOut.back());
                }
                chain.push_back(hi);
                if (part.selectedPairs.count(key))
                    for (size_t k = 0; k + 1 < chain.size(); ++k) out.frontChains.push_back({chain[k], chain[k + 1]});
                ++edgesSubdivided;
            }
            // the edge's points from the half-edge's origin to its end
            std::vector<int> order;
            std::vector<P3> points;
            for (int k = 0; k < n - 1; ++k) {
                order.push_back(it->second + (ga == lo ? k : n - 2 - k));
                points.push_back(out.newPoints[NewPointIndex(out.sharedOut[order.back()])]);
            }
            const std::vector<int> made = PatchRemesher::SubdivideBoundaryEdge(mm, home, h, points);
            keys.resize(mm.VertexCount(), 0);
            for (int k = 0; k < n - 1; ++k) {
                sharedOfLocal[made[k]] = order[k];
                keys[made[k]] = SharedPointKey(order[k]);  // copies of one point (both sides of a slit) share it
            }
        }
        mm.SetKeys(keys);
    }

private:
    const FrontPartition &part;
    QuadOutput &out;
    const double L;
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
