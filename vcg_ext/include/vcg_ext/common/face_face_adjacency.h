// Face-face adjacency of a vcg triangle mesh in linear time: vcglib's UpdateTopology::FaceFace
// sorts one record per face edge (O(F log F), about a third of a second per build at 850,000
// faces, and the re-meshing builds it a dozen times). On a mesh whose every edge has one or two
// faces and no face repeats a vertex, the adjacency is unique, so the half-edges paired by
// EdgePairing give exactly vcglib's; any other mesh (a non-manifold edge, whose faces vcglib links
// in a ring in its own sort order, or a degenerate face) goes to vcglib itself.
#ifndef VCG_EXT_COMMON_FACE_FACE_ADJACENCY_H
#define VCG_EXT_COMMON_FACE_FACE_ADJACENCY_H

#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/common/edge_pairing.h>

namespace vcg_ext {

template <class MeshType>
class FaceFaceAdjacency
{
public:
    typedef typename MeshType::FaceType FaceType;

    // Sets FFp / FFi of every live face as vcglib's UpdateTopology<MeshType>::FaceFace does.
    static void Update(MeshType &m)
    {
        vcg::tri::RequireFFAdjacency(m);
        if (m.fn == 0) return;
        std::vector<EdgePairing::Triangle> tris(m.face.size());
        for (size_t i = 0; i < m.face.size(); ++i) {
            const FaceType &f = m.face[i];
            if (f.IsD()) {
                tris[i] = {-1, -1, -1};
                continue;
            }
            for (int k = 0; k < 3; ++k) tris[i][k] = int(vcg::tri::Index(m, f.cV(k)));
            if (tris[i][0] == tris[i][1] || tris[i][1] == tris[i][2] || tris[i][2] == tris[i][0]) return Vcglib(m);
        }
        const EdgePairing::Groups edges = EdgePairing::Group(tris);
        for (int e = 0; e < edges.Count(); ++e)
            if (edges.Size(e) > 2) return Vcglib(m);
        for (int e = 0; e < edges.Count(); ++e) {
            const int *h = edges.Begin(e);
            const int other = edges.Size(e) == 2 ? h[1] : h[0];
            Link(m, h[0], other);
            Link(m, other, h[0]);
        }
    }

private:
    static void Vcglib(MeshType &m) { vcg::tri::UpdateTopology<MeshType>::FaceFace(m); }

    // Half-edge h (edge h % 3 of face h / 3) gets `to` across it.
    static void Link(MeshType &m, int h, int to)
    {
        m.face[size_t(h / 3)].FFp(h % 3) = &m.face[size_t(to / 3)];
        m.face[size_t(h / 3)].FFi(h % 3) = char(to % 3);
    }
};

}  // namespace vcg_ext

#endif
