// Facing feature chains, the last step of the feature-keeping re-meshing.
//
// Where two feature chains (front or sharp creases) run side by side much closer than the target
// length L, the strip between them is a patch too thin for anything but a ladder of quads, one
// rung per pair of facing vertices. CAD parts have such strips as real geometry: lever's plate
// meets two cylinders of radii a few hundredths apart, a ring 0.02 wide between two creases;
// block's boss overlaps its plate by a folded ring of slivers. The
// re-mesher samples each chain on its own, so the vertices of the two rims are staggered, the strip
// fills with needle triangles and Q-Morph has to leave them (half of lever's triangles).
// Here every feature vertex that faces a feature edge across such a strip splits that edge at its
// foot (the nearest point), so that the rims face each other vertex for vertex; the split keeps
// the edge's features (the new vertex is on the straight edge) and the rest of the mesh as it is.
#ifndef VCG_EXT_QMORPH_FACING_FEATURES_H
#define VCG_EXT_QMORPH_FACING_FEATURES_H

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/refine.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/common/edge_key.h>
#include <vcg_ext/common/face_face_adjacency.h>
#include <vcg_ext/common/segment_grid.h>

namespace vcg_ext {
namespace qmorph {

template <class MeshType>
class FacingFeatures
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef typename MeshType::CoordType CoordType;
    typedef vcg::Point3d P3;

    // A strip is at most this wide (times L): wider ones the re-mesher fills with fair triangles.
    // Narrower ones it fills with needles, and staggered rims make the strip's quads slanted
    // slivers: block's boss meets its plate through a folded ring a few hundredths of L wide
    // (0.005 L: 122 quads below 0.3 scaled Jacobian, 0.61%; 0.05 L: 68; 0.1 L: 73; 0.25 L: 97,
    // and 7-20 splits on each organic mesh, with more poor quads beside them).
    static constexpr double kMaxStripWidth = 0.05;
    // ... and wider than this (times L): narrower is features touching, not a strip (lever's rings
    // are down to 7e-4 L wide).
    static constexpr double kMinStripWidth = 1e-6;
    // A foot within this much of the strip's width from an end of the edge already faces that end
    // (a rung tilted by at most atan(0.25), 14 degrees).
    static constexpr double kFacingTilt = 0.25;
    // No split leaves a piece shorter than this fraction of the edge: the patch on the far side of
    // the chain would get a stub in its front, and poor quads around it.
    static constexpr double kMinPiece = 0.1;
    // Each pass splits an edge once (at the foot nearest its middle); a strip's edge faces a few
    // vertices of the other rim at most.
    static constexpr int kMaxPasses = 8;

    // Whether edge i of f is a feature: selected on either side (needs face-face adjacency).
    static bool IsFeature(const FaceType &f, int i)
    {
        return f.IsFaceEdgeS(i) || (f.cFFp(i) != &f && f.cFFp(i)->IsFaceEdgeS(f.cFFi(i)));
    }

    // Features are the selected face-edges (flagged on both sides, a border edge on its one side).
    // Needs face-face and vertex-face adjacency (both rebuilt). Returns the vertices added.
    static int Do(MeshType &m, double L)
    {
        int added = 0;
        for (int pass = 0; pass < kMaxPasses; ++pass) {
            const int n = Pass(m, L);
            if (n == 0) break;
            added += n;
        }
        return added;
    }

private:
    // Edges by their vertices' indices (common/edge_key.h): RefineE reallocates the vertices between
    // asking which edges to split and placing the new vertices.
    static uint64_t Key(const MeshType &m, const VertexType *a, const VertexType *b)
    {
        return EdgeKey(int(vcg::tri::Index(m, a)), int(vcg::tri::Index(m, b)));
    }
    static P3 Pos(const VertexType *v) { return P3::Construct(v->cP()); }

    // vcglib's midpoint split, moved to the foot this pass chose for the edge.
    struct FootPoint : public vcg::tri::MidPoint<MeshType>
    {
        const std::map<uint64_t, P3> *feet;
        explicit FootPoint(MeshType *m, const std::map<uint64_t, P3> *f) : vcg::tri::MidPoint<MeshType>(m), feet(f) {}
        void operator()(VertexType &nv, vcg::face::Pos<FaceType> ep)
        {
            vcg::tri::MidPoint<MeshType>::operator()(nv, ep);
            nv.P() = CoordType::Construct(feet->at(Key(*this->mp, ep.V(), ep.VFlip())));
        }
    };
    struct IsChosen
    {
        const MeshType *m;
        const std::map<uint64_t, P3> *feet;
        bool operator()(vcg::face::Pos<FaceType> &ep) const { return feet->count(Key(*m, ep.V(), ep.VFlip())) > 0; }
    };

    static int Pass(MeshType &m, double L)
    {
        FaceFaceAdjacency<MeshType>::Update(m);
        vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
        // the feature edges, once each, and every vertex's feature neighbours
        SegmentGrid grid(L);
        std::vector<std::pair<VertexType *, VertexType *>> edges;
        std::vector<std::vector<int>> featureNeighbours(m.vert.size());
        for (FaceType &f : m.face) {
            if (f.IsD()) continue;
            for (int i = 0; i < 3; ++i) {
                if (f.FFp(i) < &f || !IsFeature(f, i)) continue;  // once per edge (a border edge has FFp == &f)
                VertexType *a = f.V0(i), *b = f.V1(i);
                grid.Add(Pos(a), Pos(b));
                edges.emplace_back(a, b);
                featureNeighbours[vcg::tri::Index(m, a)].push_back(int(vcg::tri::Index(m, b)));
                featureNeighbours[vcg::tri::Index(m, b)].push_back(int(vcg::tri::Index(m, a)));
            }
        }
        // every feature vertex's foot on the nearest feature edge across a strip; per edge, the
        // foot nearest its middle
        std::map<uint64_t, P3> feet;
        std::map<uint64_t, double> offCentre;
        std::vector<VertexType *> star;
        for (size_t vi = 0; vi < m.vert.size(); ++vi) {
            VertexType *v = &m.vert[vi];
            if (v->IsD() || featureNeighbours[vi].empty()) continue;
            const std::vector<int> &own = featureNeighbours[vi];
            auto across = [&](int id) {
                for (const VertexType *w : {edges[id].first, edges[id].second}) {
                    const int wi = int(vcg::tri::Index(m, w));
                    if (wi == int(vi) || std::find(own.begin(), own.end(), wi) != own.end()) return false;
                }
                return true;
            };
            double width;
            const int id = grid.Nearest(Pos(v), width, across);
            if (id < 0 || width > kMaxStripWidth * L || width < kMinStripWidth * L) continue;
            const VertexType *a = edges[id].first, *b = edges[id].second;
            const P3 foot = grid.Closest(Pos(v), id);
            const double fromA = (foot - Pos(a)).Norm(), fromB = (foot - Pos(b)).Norm();
            if (std::min(fromA, fromB) <= kFacingTilt * width) continue;  // faces an end already
            if (std::min(fromA, fromB) < kMinPiece * (fromA + fromB)) continue;  // the other side's front would get a stub
            // a strip is spanned by triangles: v is next to a or b (not just near them in space)
            vcg::face::VVStarVF<FaceType>(v, star);
            if (std::find(star.begin(), star.end(), a) == star.end() && std::find(star.begin(), star.end(), b) == star.end())
                continue;
            const uint64_t key = Key(m, a, b);
            const double off = std::abs(fromA - fromB);
            auto it = offCentre.find(key);
            if (it != offCentre.end() && it->second <= off) continue;
            offCentre[key] = off;
            feet[key] = foot;
        }
        if (feet.empty()) return 0;
        FootPoint place(&m, &feet);
        IsChosen chosen{&m, &feet};
        vcg::tri::RefineE(m, place, chosen);
        FaceFaceAdjacency<MeshType>::Update(m);
        vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
        return int(feet.size());
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
