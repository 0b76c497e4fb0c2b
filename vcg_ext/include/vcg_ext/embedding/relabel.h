// Relabelling the patches a front cuts out of a mesh: faces connected without crossing a selected
// face-edge form a patch; each patch gets one region id in face quality (and one colour), so the
// region-id boundaries are exactly the selected edges of a closed front.
#ifndef VCG_EXT_EMBEDDING_RELABEL_H
#define VCG_EXT_EMBEDDING_RELABEL_H

#include <algorithm>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/embedding/adjacency.h>
#include <vcg_ext/embedding/result.h>
#include <vcg_ext/common/region_ids.h>
#include <vcg_ext/common/union_find.h>

namespace vcg_ext {
namespace embedding {

template <class MeshType>
class PatchRelabelling
{
public:
    typedef typename MeshType::FaceType FaceType;

    // Fills r.patches, r.faceRegion, r.danglingFrontEdges; writes face quality / colour when the
    // mesh has them. `adj` must describe the mesh as it is.
    static void Run(MeshType &mesh, const EmbeddingAdjacency &adjacency, EmbeddingResult &result)
    {
        PatchRelabelling p(mesh, adjacency, result);
        p.Relabel();
    }

private:
    MeshType &m;
    const EmbeddingAdjacency &adj;
    EmbeddingResult &r;

    PatchRelabelling(MeshType &mesh, const EmbeddingAdjacency &adjacency, EmbeddingResult &result)
        : m(mesh), adj(adjacency), r(result)
    {
    }

    // From the face read canonically: the same rounding on a flipped copy of the mesh.
    double Area(int f) const
    {
        const EmbedVec a = P(adj.fv[f][0]), b = P(adj.fv[f][1]), c = P(adj.fv[f][2]);
        return 0.5 * ((b - a) ^ (c - a)).Norm();
    }
    EmbedVec P(int v) const { return EmbedVec::Construct(m.vert[v].cP()); }

    // Patches: faces connected without crossing a selected edge. Each takes the id covering most
    // of its area (the new faces carry their parent's id); ids already taken by a larger patch
    // are replaced by new ones, so different patches always have different ids. Areas are only
    // computed for the few patches that hold several ids or share one.
    void Relabel()
    {
        const int n = int(m.face.size());
        std::vector<int> oldId(n, -1);
        if (!(vcg::tri::HasPerFaceQuality(m) && RegionIds<MeshType>::Read(m, oldId).empty())) oldId.assign(n, -1);
        // Union-find over the faces in index order (cache friendly), joined across unselected edges.
        IndexUnionFind patches(n);
        std::vector<int> patch(n, -1);
        for (int f = 0; f < n; ++f) {
            if (m.face[f].IsD()) continue;
            for (int k = 0; k < 3; ++k) {
                const int h = adj.twin[3 * f + k];
                if (h < 0 || h / 3 < f || m.face[f].IsFaceEdgeS(adj.InputEdge(f, k))) continue;
                patches.Unite(f, h / 3);
            }
        }
        std::vector<int> claim;  // per patch: its majority id
        std::vector<char> mixed;
        for (int f = 0; f < n; ++f) {  // a root is its set's lowest face: patches numbered in face order
            if (m.face[f].IsD()) continue;
            const int root = patches.Find(f);
            if (root == f) {
                patch[f] = int(claim.size());
                claim.push_back(oldId[f]);
                mixed.push_back(0);
            } else {
                patch[f] = patch[root];
                if (oldId[f] != claim[patch[f]]) mixed[patch[f]] = 1;
            }
        }
        const int k = int(claim.size());
        if (std::find(mixed.begin(), mixed.end(), 1) != mixed.end()) {
            std::vector<std::vector<std::pair<int, double>>> idArea(k);  // (old id, area) per mixed patch
            for (int f = 0; f < n; ++f) {
                if (patch[f] < 0 || !mixed[patch[f]]) continue;
                auto &ia = idArea[patch[f]];
                auto it = std::find_if(ia.begin(), ia.end(), [&](const std::pair<int, double> &x) { return x.first == oldId[f]; });
                if (it == ia.end()) ia.push_back({oldId[f], Area(f)});
                else it->second += Area(f);
            }
            for (int pid = 0; pid < k; ++pid) {
                if (!mixed[pid]) continue;
                double bestArea = -1;
                for (const auto &x : idArea[pid])
                    if (x.second > bestArea || (x.second == bestArea && x.first < claim[pid])) { claim[pid] = x.first; bestArea = x.second; }
            }
        }
        // Patches without an id or sharing one: by decreasing area, the first keeps it, the others get new ids.
        std::unordered_map<int, int> claims;
        for (int pid = 0; pid < k; ++pid) ++claims[claim[pid]];
        std::vector<char> contested(k, 0);
        std::vector<double> area(k, 0.0);
        bool anyContested = false;
        for (int pid = 0; pid < k; ++pid)
            if (claim[pid] < 0 || claims[claim[pid]] > 1) contested[pid] = 1, anyContested = true;
        if (anyContested)
            for (int f = 0; f < n; ++f)
                if (patch[f] >= 0 && contested[patch[f]]) area[patch[f]] += Area(f);
        std::vector<int> order;
        for (int pid = 0; pid < k; ++pid)
            if (contested[pid]) order.push_back(pid);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return area[a] > area[b]; });
        int nextFree = 0;
        for (int i = 0; i < n; ++i) nextFree = std::max(nextFree, oldId[i] + 1);
        std::vector<int> newId(claim);
        std::unordered_set<int> taken;
        for (int pid : order) {
            if (claim[pid] >= 0 && !taken.count(claim[pid])) taken.insert(claim[pid]);
            else newId[pid] = nextFree++;
        }
        r.patches = k;
        r.faceRegion.assign(n, -1);
        for (int f = 0; f < n; ++f)
            if (patch[f] >= 0) r.faceRegion[f] = newId[patch[f]];
        r.danglingFrontEdges = 0;
        for (int f = 0; f < n; ++f)
            for (int e = 0; e < 3; ++e) {
                const int h = adj.twin[3 * f + e];
                if (patch[f] >= 0 && h > 3 * f + e && m.face[f].IsFaceEdgeS(adj.InputEdge(f, e)) && patch[h / 3] == patch[f]) ++r.danglingFrontEdges;
            }
        if (vcg::tri::HasPerFaceQuality(m))
            for (int f = 0; f < n; ++f)
                if (!m.face[f].IsD()) m.face[f].Q() = typename FaceType::QualityType(r.faceRegion[f]);
        if (vcg::tri::HasPerFaceColor(m)) ColorPatches(patch, newId);
    }

    // The colours RegionIds::ColorFaces gives (hue scattered over the id range), once per patch.
    void ColorPatches(const std::vector<int> &patch, const std::vector<int> &patchId)
    {
        if (patchId.empty()) return;
        const int lo = *std::min_element(patchId.begin(), patchId.end());
        const int hi = *std::max_element(patchId.begin(), patchId.end());
        const int range = std::max(1, hi - lo + 1);
        std::vector<vcg::Color4b> colour;
        for (int id : patchId) colour.push_back(vcg::Color4b::Scatter(range, id - lo, .75f, .95f));
        for (int f = 0; f < int(m.face.size()); ++f)
            if (patch[f] >= 0) m.face[f].C() = colour[patch[f]];
    }
};

}  // namespace embedding
}  // namespace vcg_ext

#endif
