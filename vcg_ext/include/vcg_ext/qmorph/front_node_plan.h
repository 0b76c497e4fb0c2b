// How many interior edges each patch sends into a node of the initial front, planned over all the
// patches around the node so that the node ends regular (valence 4) where angles allow.
//
// Each patch is meshed on its own, and Q-Morph decides a node's side edges from its angle in that
// patch alone (Owen: a front angle below 3pi/4 closes the end), re-measured as the rows advance. So
// the two patches at a front node each decide by themselves, and near the threshold they often both
// open the node or both close it: on armadillo_52k 30% of the irregular vertices were front nodes,
// mostly of valence 5 (two side edges on a side of 180-225 degrees, one on the other) or 3. The
// plan looks at every sector of the node at once: with c front edges at the node it gives the
// sectors 4 - c interior edges in all, e to each, so that its quad corners (the sector angle /
// (e + 1)) are nearest to right angles; a node where no such split keeps every corner in
// [kMinCorner, kMaxCorner] (a cone tip, a node of five front edges) has no plan. The front follows
// a plan only where its own threshold is in doubt (Front::EndClosed); the patch clean-up aims at the
// planned valence (PatchStage::IdealValences).
#ifndef VCG_EXT_QMORPH_FRONT_NODE_PLAN_H
#define VCG_EXT_QMORPH_FRONT_NODE_PLAN_H

#include <algorithm>
#include <cmath>
#include <vector>

#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/qmorph/partition.h>

namespace vcg_ext {
namespace qmorph {

struct FrontNodePlan {
    // Planned corners stay within these angles (degrees).
    static constexpr double kMinCorner = 50, kMaxCorner = 160;
    // At most this many sectors (front edges) at a planned node, this many edges per sector.
    static constexpr int kMaxSectors = 4, kMaxEdges = 3;

    // Interior edges per sector of a node with these sector angles (degrees, in a fixed order),
    // 4 - (number of sectors) in all; empty when no split keeps the corners in range.
    static std::vector<int> Split(const std::vector<double> &sectorDeg)
    {
        const int k = int(sectorDeg.size());
        const int total = 4 - k;
        if (k < 2 || k > kMaxSectors || total < 0) return {};
        std::vector<int> e(k, 0), best;
        double bestCost = INFINITY;
        // every e in [0, kMaxEdges]^k summing to `total`, in lexicographic order (the first of equal
        // costs wins: the same plan whichever patch asks)
        for (;;) {
            int sum = 0;
            for (int x : e) sum += x;
            if (sum == total) {
                double cost = 0;
                bool inRange = true;
                for (int i = 0; i < k; ++i) {
                    const double corner = sectorDeg[i] / (e[i] + 1);
                    inRange = inRange && corner >= kMinCorner && corner <= kMaxCorner;
                    cost += (e[i] + 1) * (corner - 90) * (corner - 90);
                }
                if (inRange && cost < bestCost) {
                    bestCost = cost;
                    best = e;
                }
            }
            int i = k - 1;
            while (i >= 0 && e[i] == kMaxEdges) e[i--] = 0;
            if (i < 0) break;
            ++e[i];
        }
        return best;
    }

    // Per node sector of the partition (indexed like part.sectorOf's values): the interior edges
    // planned there, or -1 (Q-Morph decides). Nodes on a border or a non-manifold edge, and nodes
    // with a sector that is not bounded by two front edges, are not planned.
    template <class MeshType>
    static std::vector<int> Plan(const MeshType &m, const FrontPartition &part)
    {
        const int F = int(part.tri.size());
        std::vector<int> planned(3 * F, -1);
        std::vector<double> sectorAngle(3 * F, 0);
        std::vector<int> cutFrom(m.vert.size(), 0);  // front half-edges leaving each vertex
        std::vector<std::vector<int>> sectorsOf(m.vert.size());
        for (int f = 0; f < F; ++f) {
            P3 p[3];
            for (int k = 0; k < 3; ++k) p[k] = P3::Construct(m.vert[part.tri[f][k]].cP());
            for (int k = 0; k < 3; ++k) {
                const int v = part.tri[f][k], sec = part.sectorOf[3 * f + k];
                sectorAngle[sec] += AngleBetween(p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k]);
                if (part.cut[3 * f + k]) ++cutFrom[v];
                std::vector<int> &s = sectorsOf[v];
                if (std::find(s.begin(), s.end(), sec) == s.end()) s.push_back(sec);
            }
        }
        for (size_t v = 0; v < sectorsOf.size(); ++v) {
            std::vector<int> &s = sectorsOf[v];
            if (s.size() < 2 || part.openVertex[v] || int(s.size()) != cutFrom[v]) continue;
            std::sort(s.begin(), s.end());
            std::vector<double> deg;
            for (int sec : s) deg.push_back(sectorAngle[sec] * 180 / M_PI);
            const std::vector<int> e = Split(deg);
            for (size_t i = 0; i < e.size(); ++i) planned[s[i]] = e[i];
        }
        return planned;
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
