// An edge flip that keeps the per-edge flags on their edges.
//
// vcglib's face::FlipEdge (2020.09) moves the vertices and the face-face adjacency but not the flag
// bits, which vcg keeps per face and edge index: after flipping edge z of f (and w of g), f's index
// z + 1 and g's index w + 1 name the new diagonal, while the edges they named before now are g's w
// and f's z. Left as they are, a selected (front) or faux edge beside the flipped one would mark
// the new diagonal instead: on the 832k-face armadillo one re-meshing mend turned such a diagonal
// into a stray front edge. vcglib's own remesher moves its crease bits the same way after its flips.
#ifndef VCG_EXT_COMMON_EDGE_FLIP_H
#define VCG_EXT_COMMON_EDGE_FLIP_H

#include <vcg/simplex/face/topology.h>

namespace vcg_ext {

// Flips edge z of f (check vcg::face::CheckFlipEdge first) and moves the selection (FaceEdgeS) and
// faux bits of the two faces' other edges with those edges; the new diagonal carries neither.
template <class FaceType>
void FlipEdgeKeepingFlags(FaceType &f, int z)
{
    FaceType *g = f.FFp(z);
    const int w = f.FFi(z);
    const int zNext = (z + 1) % 3, wNext = (w + 1) % 3;
    // f's edge z + 1 becomes g's edge w, g's edge w + 1 becomes f's edge z
    const bool selectedF = f.IsFaceEdgeS(zNext), selectedG = g->IsFaceEdgeS(wNext);
    const bool fauxF = f.IsF(zNext), fauxG = g->IsF(wNext);
    vcg::face::FlipEdge(f, z);
    auto set = [](FaceType &face, int i, bool selected, bool faux) {
        if (selected) face.SetFaceEdgeS(i); else face.ClearFaceEdgeS(i);
        if (faux) face.SetF(i); else face.ClearF(i);
    };
    set(f, z, selectedG, fauxG);
    set(*g, w, selectedF, fauxF);
    set(f, zNext, false, false);
    set(*g, wNext, false, false);
}

}  // namespace vcg_ext

#endif
