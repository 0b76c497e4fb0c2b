// The initial front of Q-Morph and the patches it cuts out of a triangle mesh.
//
// Front edges: the selected face-edges, the mesh boundary, non-manifold edges and (by default)
// unselected sharp creases, so that no quad folds over a crease. Patches: faces joined across
// non-front edges. Node sectors: the corners around a vertex joined across non-front edges; a
// vertex the front passes through has one sector per side, and each sector becomes its own node
// of the patch mesh (so slits, annuli and patches touching themselves need no special case).
//
// Orientation independence: the faces are read canonically (common/canonical_faces.h: from the
// lowest vertex on, components of negative orientation reversed), so a mesh and its consistently
// flipped copy give the same patches and every later decision the same: the output is the same
// mesh, written back mirrored.
#ifndef VCG_EXT_QMORPH_PARTITION_H
#define VCG_EXT_QMORPH_PARTITION_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <unordered_set>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/canonical_faces.h>
#include <vcg_ext/common/edge_key.h>
#include <vcg_ext/common/edge_pairing.h>
#include <vcg_ext/common/union_find.h>
#include <vcg_ext/qmorph/mixed_mesh.h>

namespace vcg_ext {
namespace qmorph {

// One patch cut out as its own triangle list, ready for a MixedMesh and a SurfaceProjector.
struct PatchInput {
    std::vector<P3> points;                 // per local node (one per sector)
    std::vector<int> globalOf;              // local node -> input vertex
    std::vector<std::array<int, 3>> tris;   // counter-clockwise, local nodes
    std::vector<char> cut;                  // per local half-edge 3t+k: on the front
    std::vector<int> home;                  // per local node: a triangle holding it (for projection)
    std::vector<int> plannedSides;          // per local node: interior edges planned there (FrontNodePlan), -1: none
    float quality = 0;                      // the region id covering most of the patch's area
    bool hasFront = false;
    bool reversed = false;                  // the input's faces are the other way round (write back mirrored)
};

struct FrontPartition {
    std::vector<int> faceIdx;                    // live face -> index in the mesh's face vector
    std::vector<std::array<int, 3>> tri;         // per live face: its vertex indices, lowest first, read
                                                 // reversed where `reversed` (see the top of the file)
    std::vector<char> reversed;                  // per live face: its component is read reversed
    std::vector<char> inputEdge;                 // per half-edge 3f+k: the face's own edge index there
    std::vector<char> cut;                       // per half-edge 3f+k: on the front
    std::vector<int> patchOf;                    // per live face: its patch (the patch's lowest face)
    std::vector<int> sectorOf;                   // per corner 3f+k: its node sector (lowest corner)
    std::vector<int> order;                      // live faces grouped by patch, in face order within
    std::vector<std::vector<int>> patchesOfVertex;  // per input vertex: the patches holding it, sorted
    std::vector<char> openVertex;                // per input vertex: on a border or non-manifold edge
    std::vector<int> plannedSides;               // per sector: interior edges planned there, -1: none (empty: no plan)
    std::unordered_set<uint64_t> selectedPairs;  // selected input edges (vertex pairs): selected again at the end
    int frontEdges = 0;                          // distinct edges on the initial front
    int creaseEdges = 0;                         // of which sharp creases that were not selected

    // Builds the front and patches of the live faces of m; creaseAngleDeg >= 180 cuts no crease.
    template <class MeshType>
    void Build(const MeshType &m, double creaseAngleDeg)
    {
        CanonicalFaces canon;
        canon.Read(m);
        for (size_t i = 0; i < m.face.size(); ++i)
            if (!m.face[i].IsD()) {
                faceIdx.push_back(int(i));
                tri.push_back(canon.tri[i]);
                reversed.push_back(canon.reversed[i]);
                for (int k = 0; k < 3; ++k) inputEdge.push_back(char(canon.InputEdge(int(i), k)));
            }
        const int F = int(tri.size());
        cut.assign(3 * F, 0);
        std::vector<int> twin(3 * F, -1);
        const double creaseCos = std::cos(creaseAngleDeg * M_PI / 180);
        const EdgePairing::Groups edges = EdgePairing::Group(tri);
        openVertex.assign(m.vert.size(), 0);
        for (int e = 0; e < edges.Count(); ++e) {
            const int n = edges.Size(e), *h = edges.Begin(e);
            if (n != 2) openVertex[EdgePairing::From(tri, h[0])] = openVertex[EdgePairing::To(tri, h[0])] = 1;
            bool selected = false;
            for (int k = 0; k < n; ++k) selected = selected || m.face[faceIdx[h[k] / 3]].IsFaceEdgeS(inputEdge[h[k]]);
            if (selected) selectedPairs.insert(EdgeKey(EdgePairing::From(tri, h[0]), EdgePairing::To(tri, h[0])));
            if (n == 2) {
                twin[h[0]] = h[1];
                twin[h[1]] = h[0];
            }
            const bool crease = !selected && n == 2 && creaseAngleDeg < 180 && IsCrease(m, h[0] / 3, h[1] / 3, creaseCos);
            creaseEdges += crease;
            if (selected || crease || n != 2) {
                for (int k = 0; k < n; ++k) cut[h[k]] = 1;
                ++frontEdges;
            }
        }
        IndexUnionFind faceSet(F), cornerSet(3 * F);
        for (int h = 0; h < 3 * F; ++h) {
            const int t = twin[h];
            if (t < h || cut[h]) continue;
            const int f = h / 3, g = t / 3, k = h % 3, l = t % 3;
            faceSet.Unite(f, g);
            // edge k of f goes tri[f][k] -> tri[f][k+1]; edge l of g goes tri[f][k+1] -> tri[f][k]
            cornerSet.Unite(3 * f + k, 3 * g + (l + 1) % 3);
            cornerSet.Unite(3 * f + (k + 1) % 3, 3 * g + l);
        }
        patchOf.resize(F);
        sectorOf.resize(3 * F);
        for (int f = 0; f < F; ++f) patchOf[f] = faceSet.Find(f);
        for (int c = 0; c < 3 * F; ++c) sectorOf[c] = cornerSet.Find(c);
        order.resize(F);
        std::iota(order.begin(), order.end(), 0);
        std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return patchOf[a] < patchOf[b]; });
        patchesOfVertex.assign(m.vert.size(), {});
        for (int f = 0; f < F; ++f)
            for (int k = 0; k < 3; ++k) {
                std::vector<int> &ps = patchesOfVertex[tri[f][k]];
                if (std::find(ps.begin(), ps.end(), patchOf[f]) == ps.end()) ps.push_back(patchOf[f]);
            }
        for (auto &ps : patchesOfVertex) std::sort(ps.begin(), ps.end());
        localOfSector.assign(3 * F, -1);
    }

    // Calls fn(begin, end) for each patch: the range of `order` holding its faces.
    template <class Fn>
    void ForEachPatch(Fn fn) const
    {
        for (size_t s = 0; s < order.size();) {
            size_t e = s;
            while (e < order.size() && patchOf[order[e]] == patchOf[order[s]]) ++e;
            fn(s, e);
            s = e;
        }
    }

    // The patch of order[begin, end) as its own triangle list.
    template <class MeshType>
    PatchInput Extract(const MeshType &m, size_t begin, size_t end)
    {
        PatchInput in;
        std::map<float, double> qualityArea;  // region id -> area (doubled)
        const bool hasQuality = vcg::tri::HasPerFaceQuality(m);
        for (size_t i = begin; i < end; ++i) {
            const int f = order[i];
            std::array<int, 3> t;
            for (int k = 0; k < 3; ++k) {
                const int sec = sectorOf[3 * f + k];
                if (localOfSector[sec] < 0) {
                    localOfSector[sec] = int(in.points.size());
                    in.points.push_back(P3::Construct(m.vert[tri[f][k]].cP()));
                    in.globalOf.push_back(tri[f][k]);
                    in.home.push_back(int(in.tris.size()));
                    in.plannedSides.push_back(plannedSides.empty() ? -1 : plannedSides[sec]);
                }
                t[k] = localOfSector[sec];
                in.cut.push_back(cut[3 * f + k]);
            }
            in.tris.push_back(t);
            if (hasQuality) {
                const P3 a = in.points[t[0]], b = in.points[t[1]], c = in.points[t[2]];
                qualityArea[float(m.face[faceIdx[f]].cQ())] += ((b - a) ^ (c - a)).Norm();
            }
        }
        double bestArea = -1;
        for (auto &qv : qualityArea)
            if (qv.second > bestArea) { bestArea = qv.second; in.quality = qv.first; }
        for (char c : in.cut) in.hasFront = in.hasFront || c;
        in.reversed = begin < end && reversed[order[begin]];
        for (size_t i = begin; i < end; ++i)
            for (int k = 0; k < 3; ++k) localOfSector[sectorOf[3 * order[i] + k]] = -1;
        return in;
    }

private:
    std::vector<int> localOfSector;  // scratch of Extract: local node per sector, -1 outside the patch

    // Sharp edges inside a patch (VSA regions may hold creases up to twice the threshold angle)
    // are cut like front edges: quads then follow them instead of folding over them.
    template <class MeshType>
    bool IsCrease(const MeshType &m, int f, int g, double creaseCos) const
    {
        auto normal = [&](int t) {
            const P3 a = P3::Construct(m.vert[tri[t][0]].cP()), b = P3::Construct(m.vert[tri[t][1]].cP()),
                     c = P3::Construct(m.vert[tri[t][2]].cP());
            return ((b - a) ^ (c - a)).Normalize();
        };
        return normal(f) * normal(g) < creaseCos;
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
