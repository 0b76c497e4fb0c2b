// Writing a ready EmbeddingPlan into its mesh: new vertices on edges (one per point, shared by both
// faces), the re-triangulated faces (the first piece reuses the face's slot, the others are
// appended with its attributes), a local update of the half-edge adjacency, the front edges as
// selected face-edges (earlier selected and faux face-edges cleared), then the patch relabelling.
#ifndef VCG_EXT_EMBEDDING_APPLY_H
#define VCG_EXT_EMBEDDING_APPLY_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/embedding/adjacency.h>
#include <vcg_ext/embedding/relabel.h>
#include <vcg_ext/embedding/result.h>
#include <vcg_ext/common/front_edges.h>

namespace vcg_ext {
namespace embedding {

template <class MeshType>
class PlanWriter
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef typename MeshType::CoordType CoordType;
    typedef std::pair<int, int> IdPair;
    typedef EmbeddingResult Result;
    typedef EmbeddingPlan Plan;

    PlanWriter(MeshType &mesh, Plan &pl, Result &res, vcg::CallBackPos *callback) : m(mesh), plan(pl), r(res), cb(callback) {}

    void Run()
    {
        Progress(cb, 70, "Split along front: writing faces");
        Lap lap;
        AddVertices();
        std::vector<int> changed, parent;
        AddFaces(changed, parent);
        UpdateAdjacency(changed, parent);
        Progress(cb, 80, "Split along front: selecting front edges");
        SelectFrontEdges();
        for (int f : changed) UpdateFace(f);
        MeasureNewTriangles(changed);
        r.secondsWrite = lap();
        Progress(cb, 85, "Split along front: relabelling patches");
        PatchRelabelling<MeshType>::Run(m, plan.adj, r);
        WriteVcgTopology();
        r.secondsRelabel = lap();
    }

private:
    MeshType &m;
    Plan &plan;
    Result &r;
    vcg::CallBackPos *cb;
    std::vector<std::array<int, 3>> changedTri;  // per changed face (AddFaces' order): its piece, read canonically
    std::vector<char> changedReversed;           // ... written into the mesh reversed

    EmbedVec P(int v) const { return EmbedVec::Construct(m.vert[v].cP()); }

    void AddVertices()
    {
        const int n = int(plan.newPoints.size());
        if (n == 0) return;
        vcg::tri::Allocator<MeshType>::AddVertices(m, n);
        for (int k = 0; k < n; ++k) {
            const LocatedPoint &s = plan.newPoints[k];
            VertexType &v = m.vert[plan.vertexCount + k];
            int src[3];
            double w[3];
            int count;
            if (s.kind == LocatedPoint::OnEdge) {
                src[0] = plan.adj.fv[s.face][s.edge];
                src[1] = plan.adj.fv[s.face][EmbeddingAdjacency::Next(s.edge)];
                w[0] = 1 - s.t;
                w[1] = s.t;
                count = 2;
            } else {
                for (int i = 0; i < 3; ++i) { src[i] = plan.adj.fv[s.face][i]; w[i] = s.bary[i]; }
                count = 3;
            }
            const int nearest = int(std::max_element(w, w + count) - w);
            v.ImportData(m.vert[src[nearest]]);  // attributes without an interpolation rule
            v.Flags() = 0;
            v.P() = CoordType::Construct(s.pos);
            if (vcg::tri::HasPerVertexNormal(m)) {
                EmbedVec nrm(0, 0, 0);
                for (int i = 0; i < count; ++i) nrm += EmbedVec::Construct(m.vert[src[i]].cN()) * w[i];
                if (nrm.Norm() > 0) v.N() = CoordType::Construct(nrm.Normalize());
            }
            if (vcg::tri::HasPerVertexQuality(m)) {
                double q = 0;
                for (int i = 0; i < count; ++i) q += double(m.vert[src[i]].cQ()) * w[i];
                v.Q() = typename VertexType::QualityType(q);
            }
            if (vcg::tri::HasPerVertexColor(m)) {
                double c[4] = {0, 0, 0, 0};
                for (int i = 0; i < count; ++i)
                    for (int j = 0; j < 4; ++j) c[j] += double(m.vert[src[i]].cC()[j]) * w[i];
                for (int j = 0; j < 4; ++j) v.C()[j] = (unsigned char)std::max(0.0, std::min(255.0, std::round(c[j])));
            }
        }
    }

    // `parent[i]`: the position in plan.splitFaces of the face changed[i] comes from.
    void AddFaces(std::vector<int> &changed, std::vector<int> &parent)
    {
        int added = 0;
        for (const auto &pc : plan.pieces) added += int(pc.size()) - 1;
        if (added > 0) vcg::tri::Allocator<MeshType>::AddFaces(m, added);
        int next = plan.faceCount;
        changed.reserve(plan.splitFaces.size() + added);
        parent.reserve(plan.splitFaces.size() + added);
        for (size_t i = 0; i < plan.splitFaces.size(); ++i) {
            const int f = plan.splitFaces[i];
            for (size_t j = 0; j < plan.pieces[i].size(); ++j) {
                const int slot = j == 0 ? f : next++;
                FaceType &nf = m.face[slot];
                if (slot != f) nf.ImportData(m.face[f]);
                const std::array<int, 3> &piece = plan.pieces[i][j];  // read canonically, like its parent
                const bool rev = plan.adj.reversed[f];
                for (int k = 0; k < 3; ++k) nf.V(k) = &m.vert[piece[rev && k ? 3 - k : k]];  // the input's orientation
                changedTri.push_back(piece);
                changedReversed.push_back(rev);
                changed.push_back(slot);
                parent.push_back(int(i));
            }
        }
    }

    // Local update of the half-edge adjacency: the new faces among themselves (matched by
    // sorting their half-edges), and across the unsplit edges of their parents to the
    // untouched neighbours (the parents' old twins).
    void UpdateAdjacency(const std::vector<int> &changed, const std::vector<int> &parent)
    {
        EmbeddingAdjacency &adj = plan.adj;
        const size_t nSplit = plan.splitFaces.size();
        std::vector<std::array<int, 3>> oldFv(nSplit), oldTwin(nSplit);
        for (size_t i = 0; i < nSplit; ++i) {
            const int f = plan.splitFaces[i];
            oldFv[i] = adj.fv[f];
            oldTwin[i] = {adj.twin[3 * f], adj.twin[3 * f + 1], adj.twin[3 * f + 2]};
        }
        adj.fv.resize(m.face.size(), {-1, -1, -1});
        adj.corner.resize(m.face.size(), {0, 1, 2});
        adj.reversed.resize(m.face.size(), 0);
        adj.twin.resize(3 * m.face.size(), -1);
        adj.vertexFace.resize(m.vert.size(), -1);
        std::vector<std::pair<uint64_t, int>> halfEdges;  // (from, to) -> half-edge
        halfEdges.reserve(3 * changed.size());
        for (size_t i = 0; i < changed.size(); ++i) {
            const int f = changed[i];
            adj.fv[f] = changedTri[i];  // canonical; the face itself was written reversed where changedReversed
            adj.reversed[f] = changedReversed[i];
            adj.corner[f] = {0, char(changedReversed[i] ? 2 : 1), char(changedReversed[i] ? 1 : 2)};
            for (int k = 0; k < 3; ++k) {
                halfEdges.push_back({DirectedKey(adj.fv[f][k], adj.fv[f][EmbeddingAdjacency::Next(k)]), 3 * f + k});
                adj.vertexFace[adj.fv[f][k]] = f;
            }
        }
        std::sort(halfEdges.begin(), halfEdges.end());
        for (size_t i = 0; i < changed.size(); ++i) {
            const int f = changed[i];
            for (int k = 0; k < 3; ++k) {
                const int a = adj.fv[f][k], b = adj.fv[f][EmbeddingAdjacency::Next(k)];
                auto it = std::lower_bound(halfEdges.begin(), halfEdges.end(), std::make_pair(DirectedKey(b, a), -1));
                if (it != halfEdges.end() && it->first == DirectedKey(b, a)) { adj.twin[3 * f + k] = it->second; continue; }
                const std::array<int, 3> &pv = oldFv[parent[i]];
                adj.twin[3 * f + k] = -1;
                for (int j = 0; j < 3; ++j)
                    if (pv[j] == a && pv[EmbeddingAdjacency::Next(j)] == b) {
                        const int h = oldTwin[parent[i]][j];
                        adj.twin[3 * f + k] = h;
                        if (h >= 0) adj.twin[h] = 3 * f + k;
                    }
            }
        }
    }

    void SelectFrontEdges()
    {
        FrontEdges<MeshType>::Clear(m, true);  // the front replaces any earlier selection; faux stays clear
        for (const IdPair &e : plan.frontEdges) {
            const int h = plan.adj.FindEdge(e.first, e.second);
            if (h < 0) { ++r.missingFrontEdges; continue; }
            m.face[h / 3].SetFaceEdgeS(plan.adj.InputEdge(h / 3, h % 3));
            const int t = plan.adj.twin[h];
            if (t >= 0) m.face[t / 3].SetFaceEdgeS(plan.adj.InputEdge(t / 3, t % 3));
        }
    }

    void UpdateFace(int f)
    {
        FaceType &face = m.face[f];
        for (int k = 0; k < 3; ++k) {
            if (plan.adj.twin[3 * f + k] < 0) face.SetB(plan.adj.InputEdge(f, k));
            else face.ClearB(plan.adj.InputEdge(f, k));
        }
        if (vcg::tri::HasPerFaceNormal(m)) {
            EmbedVec n = (P(plan.adj.fv[f][1]) - P(plan.adj.fv[f][0])) ^ (P(plan.adj.fv[f][2]) - P(plan.adj.fv[f][0]));
            if (plan.adj.reversed[f]) n = -n;
            if (n.Norm() > 0) face.N() = CoordType::Construct(n.Normalize());
        }
    }

    // vcg's own FF / VF adjacency, when the mesh has them, are kept valid.
    void WriteVcgTopology()
    {
        if (vcg::tri::HasFFAdjacency(m))
            for (int f = 0; f < int(m.face.size()); ++f) {
                if (m.face[f].IsD()) continue;
                for (int k = 0; k < 3; ++k) {
                    const int h = plan.adj.twin[3 * f + k], e = plan.adj.InputEdge(f, k);
                    m.face[f].FFp(e) = h >= 0 ? &m.face[h / 3] : &m.face[f];
                    m.face[f].FFi(e) = h >= 0 ? plan.adj.InputEdge(h / 3, h % 3) : e;
                }
            }
        if (vcg::tri::HasVFAdjacency(m)) vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
    }

    void MeasureNewTriangles(const std::vector<int> &changed)
    {
        double minAngle = M_PI;
        for (int f : changed) {
            const FaceType &face = m.face[f];
            for (int k = 0; k < 3; ++k) {
                const EmbedVec a = EmbedVec::Construct(face.cP(k));
                const EmbedVec u = EmbedVec::Construct(face.cP((k + 1) % 3)) - a, v = EmbedVec::Construct(face.cP((k + 2) % 3)) - a;
                minAngle = std::min(minAngle, std::atan2((u ^ v).Norm(), u * v));
            }
        }
        r.minAngleDeg = changed.empty() ? 0.0 : minAngle * 180.0 / M_PI;
    }
};

}  // namespace embedding
}  // namespace vcg_ext

#endif
