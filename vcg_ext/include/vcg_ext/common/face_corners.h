// Reordering the corners of a vcg face in place, so that it is the same triangle read from another
// corner or the other way round: its vertices move, and with them what is stored per edge (border,
// face-edge selection and faux bits) and per corner (wedge texture coordinates). vcg's own FlipFace
// and SwapEdge carry the faux bits only. Adjacency (FF, VF) is the caller's to rebuild. Also a
// face's corners in an order that does not depend on how it is read.
#ifndef VCG_EXT_COMMON_FACE_CORNERS_H
#define VCG_EXT_COMMON_FACE_CORNERS_H

#include <algorithm>
#include <array>

#include <vcg/complex/complex.h>

namespace vcg_ext {

template <class MeshType>
class FaceCorners
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef std::array<char, 3> Order;

    // The face's vertices in memory order (lowest address first): the same for every reading of the
    // triangle (another first corner, the other way round), so arithmetic on them gives the same
    // bits on a consistently flipped copy of a mesh.
    static std::array<const VertexType *, 3> InMemoryOrder(const FaceType &f)
    {
        std::array<const VertexType *, 3> c{{f.cV(0), f.cV(1), f.cV(2)}};
        std::sort(c.begin(), c.end());
        return c;
    }

    // The face's corner k becomes its old corner from[k] (a permutation of 0, 1, 2).
    static void Reorder(MeshType &m, FaceType &f, const Order &from)
    {
        if (from[0] == 0 && from[1] == 1 && from[2] == 2) return;
        typename FaceType::VertexType *v[3] = {f.V(0), f.V(1), f.V(2)};
        const int flags = f.Flags();
        int edgeBits = 0, allEdgeBits = 0;
        for (int k = 0; k < 3; ++k) {
            f.V(k) = v[int(from[k])];
            // new edge k joins the old corners from[k] and from[k + 1]: the old edge is the one
            // starting at whichever of them the other follows
            const int a = from[k], b = from[(k + 1) % 3];
            const int old = (a + 1) % 3 == b ? a : b;
            for (int bit0 : {int(FaceType::BORDER0), int(FaceType::FACEEDGESEL0), int(FaceType::FAUX0)}) {
                allEdgeBits |= bit0 << k;
                if (flags & (bit0 << old)) edgeBits |= bit0 << k;
            }
        }
        f.Flags() = (flags & ~allEdgeBits) | edgeBits;
        if (vcg::tri::HasPerWedgeTexCoord(m)) {
            const typename FaceType::TexCoordType wt[3] = {f.WT(0), f.WT(1), f.WT(2)};
            for (int k = 0; k < 3; ++k) f.WT(k) = wt[int(from[k])];
        }
    }

    // The other way round, from the same first corner: (a, b, c) -> (a, c, b).
    static void Reverse(MeshType &m, FaceType &f) { Reorder(m, f, Order{{0, 2, 1}}); }
};

}  // namespace vcg_ext

#endif
