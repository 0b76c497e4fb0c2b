// The re-meshing's edge flips toward valence 6 (Botsch-Kobbelt), with vcglib's criteria and
// primitives but valences kept up to date in an array.
//
// vcglib 2020.09's IsotropicRemeshing::ImproveValence asks VVStarVF for the four valences of every
// candidate edge (a walk, an allocation and a sort each: on armadillo 0.4 s per pass, a third of the
// whole re-meshing) and never updates the vertex-face adjacency after its own flips, so within a
// pass the valences near earlier flips are read from stale stars. Here each vertex's valence is
// counted once and changed with each flip; the rest is vcglib's test (testSwap's valence and
// quality rule, its 5-degree normal check, the new edge's midpoint near the input surface) plus one
// check against the input: both new faces face the input triangle under that midpoint.
#ifndef VCG_EXT_QMORPH_VALENCE_FLIPS_H
#define VCG_EXT_QMORPH_VALENCE_FLIPS_H

#include <algorithm>
#include <cstdlib>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/simplex/face/topology.h>

#include <vcg_ext/common/edge_flip.h>
#include <vcg_ext/common/input_surface.h>

namespace vcg_ext {
namespace qmorph {

template <class MeshType>
class ValenceFlips
{
public:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;
    typedef typename MeshType::CoordType CoordType;
    typedef typename MeshType::ScalarType ScalarType;

    // One pass over the faces in order; flips every edge that is not a feature (FaceEdgeS) or a
    // border and that brings its four vertices nearer their ideal valences without halving the
    // worse triangle's quality (or raises that quality enough), as vcglib's testSwap. The new
    // diagonal's midpoint must lie within maxSurfaceDistance of `surface`. Needs face-face adjacency
    // (kept valid; vertex-face adjacency is not updated). Returns the number of flips.
    static int Do(MeshType &m, InputSurface<MeshType> &surface, double maxSurfaceDistance)
    {
        std::vector<int> valence(m.vert.size(), 0), ideal(m.vert.size(), kIdealInside);
        for (FaceType &f : m.face)
            if (!f.IsD())
                for (int i = 0; i < 3; ++i) {
                    const FaceType *g = f.cFFp(i);
                    if (g == &f) ideal[Index(m, f.V0(i))] = ideal[Index(m, f.V1(i))] = kIdealOnBorder;
                    if (g <= &f) {  // each edge once (a border edge has g == &f)
                        ++valence[Index(m, f.V0(i))];
                        ++valence[Index(m, f.V1(i))];
                    }
                }
        int flips = 0;
        for (FaceType &f : m.face) {
            if (f.IsD()) continue;
            for (int i = 0; i < 3; ++i) {
                FaceType *g = f.FFp(i);
                if (!(&f > g) || f.IsFaceEdgeS(i)) continue;
                // f = (a b c) across a-b from g = (b a d): the flip makes c-d (when CheckFlipEdge
                // allows it: d is then none of a b c)
                VertexType *a = f.V0(i), *b = f.V1(i), *c = f.V2(i), *d = g->V2(f.FFi(i));
                const int ia = Index(m, a), ib = Index(m, b), ic = Index(m, c), id = Index(m, d);
                auto deviation = [&](int v, int change) { return std::abs(ideal[v] - (valence[v] + change)); };
                const int before = deviation(ia, 0) + deviation(ib, 0) + deviation(ic, 0) + deviation(id, 0);
                const int after = deviation(ia, -1) + deviation(ib, -1) + deviation(ic, 1) + deviation(id, 1);
                const ScalarType qBefore = std::min(vcg::Quality(a->cP(), b->cP(), c->cP()), vcg::Quality(b->cP(), a->cP(), d->cP()));
                const ScalarType qAfter = std::min(vcg::Quality(a->cP(), d->cP(), c->cP()), vcg::Quality(b->cP(), c->cP(), d->cP()));
                const bool better = (after < before && qAfter >= kKeptQuality * qBefore) || (after == before && qAfter > qBefore) ||
                                    qAfter > kRaisedQuality * qBefore;
                // the cheap tests first: valences and qualities are known, the rest walks or searches
                if (!better || !vcg::face::CheckFlipEdge(f, i) || !vcg::face::CheckFlipEdgeNormal(f, i, float(kMaxNormalTurn)) ||
                    !FacesInput(surface, a->cP(), b->cP(), c->cP(), d->cP(), maxSurfaceDistance))
                    continue;
                FlipEdgeKeepingFlags(f, i);
                --valence[ia];
                --valence[ib];
                ++valence[ic];
                ++valence[id];
                ++flips;
                break;  // f changed: its other edges are no longer the ones of the loop
            }
        }
        return flips;
    }

private:
    static constexpr int kIdealInside = 6, kIdealOnBorder = 4;
    // testSwap's rule: a valence gain may cost at most half the quality; a big quality gain alone is enough.
    static constexpr double kKeptQuality = 0.5, kRaisedQuality = 1.5;
    // The faces before and after may differ in normal by at most this (vcglib's fold check).
    static constexpr double kMaxNormalTurn = 5 * M_PI / 180;

    static int Index(const MeshType &m, const VertexType *v) { return int(vcg::tri::Index(m, v)); }

    // The new diagonal c-d of the faces (a b c), (b a d) has its midpoint within maxDistance of the
    // input, and the new faces (a d c), (b c d) face the input triangle nearest it.
    static bool FacesInput(InputSurface<MeshType> &surface, const CoordType &a, const CoordType &b, const CoordType &c,
                           const CoordType &d, double maxDistance)
    {
        const CoordType mid = (c + d) / ScalarType(2);
        CoordType closest;
        const FaceType *under = surface.ClosestWithin(mid, maxDistance, closest);
        if (!under) return false;
        const CoordType n = surface.Normal(under);
        return vcg::Normal(a, d, c) * n > 0 && vcg::Normal(b, c, d) * n > 0;
    }
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
