// The output's last check, after the write-back (and after the all-quads split). A face whose
// vector area points away from the input surface (the quality report's flipped face), or a quad
// inverted (a corner turning the other way) or folded, is mended by moving one of its free corners
// to the centroid of its neighbours, projected onto the input, when that mends it and makes no
// face around the corner worse: none turned away from an input triangle closest to its centroid,
// no quad folded or made concave (scaled Jacobians on the input's normal, as the quality report
// reads them). Where two sheets of the input lie closer than the faces' chord error (fingers
// touching: man, two bones side by side: bones), that centroid may project onto the sheet behind;
// then places around the corner are tried on the sheet the face faces. Corners on the front, on a
// border or on a sharp crease of the input never move.
//
// Every operation of the patch meshing is judged against the input already; this catches what
// still slips through: on armadillo_52k x16 (832k faces) a tangle of 8 small triangles standing on
// edge inside one patch (where it comes from is not traced), and the all-quads split of a
// near-degenerate face (needle children at 92-97 degrees to the surface).
#ifndef VCG_EXT_QMORPH_FLIPPED_FACE_MEND_H
#define VCG_EXT_QMORPH_FLIPPED_FACE_MEND_H

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <vcg/complex/complex.h>

#include <vcg_ext/common/input_surface.h>
#include <vcg_ext/common/polygon_geometry.h>
#include <vcg_ext/qmorph/output_polygons.h>
#include <vcg_ext/quad_quality.h>

namespace vcg_ext {
namespace qmorph {

template <class MeshType>
class FlippedFaceMend
{
public:
    typedef typename MeshType::CoordType CoordType;
    typedef vcg::Point3d P3;

    struct Stats {
        int mended = 0;  // flipped faces and inverted quads found and turned back
        int left = 0;    // those no move could mend
    };

    // m in MeshLab's polygonal form (faux-edge quads), with face-face adjacency; front edges are
    // its selected face-edges. Moves vertices only.
    static Stats Do(MeshType &m, InputSurface<MeshType> &surface, double creaseAngleDeg)
    {
        const OutputPolygons pg = OutputPolygons::Gather(m);
        auto position = [&](int v) { return P3::Construct(m.vert[v].cP()); };
        auto facesInput = [&](int face) { return pg.FacesInput(face, position, surface); };
        auto jacobian = [&](int face) {  // of a quad, on the input's normal under it (as reported); 1 for a triangle
            if (pg.size[face] < 4) return 1.0;
            P3 q[4];
            pg.Points(face, position, q);
            if (IsFolded(q)) return -1.0;
            const P3 own = VectorArea(q, 4);
            if (!(own.Norm() > 0)) return -1.0;
            return ScaledJacobian(q, surface.NormalUnder(pg.Centroid(face, position), own / own.Norm()));
        };
        auto bad = [&](int face) { return !facesInput(face) || jacobian(face) <= 0; };
        Stats st;
        std::vector<char> facedBefore;
        std::vector<double> jacobianBefore;
        for (int round = 0; round < kRounds; ++round) {
            std::vector<int> badFaces;
            for (int face = 0; face < pg.FaceCount(); ++face)
                if (bad(face)) badFaces.push_back(face);
            int mendedNow = 0;
            for (int face : badFaces) {
                if (!bad(face)) { ++mendedNow; continue; }  // a neighbour's move mended it
                bool done = false;
                const P3 faceDirection = pg.VectorArea(face, position);
                for (int v : pg.CornersByIndex(face)) {  // in index order: the same moves on a flipped copy
                    if (done) break;
                    if (pg.fixed[v] || surface.OnCrease(position(v), creaseAngleDeg)) continue;
                    // the face mended, and no face around v made worse: none turned over, no quad
                    // folded or made concave (one already bad no worse than before)
                    facedBefore.clear();
                    jacobianBefore.clear();
                    for (int g : pg.facesOf[v]) {
                        facedBefore.push_back(facesInput(g));
                        jacobianBefore.push_back(std::min(kConvex, jacobian(g)));
                    }
                    const CoordType old = m.vert[v].cP();
                    auto tryPlace = [&](const CoordType &place) {
                        m.vert[v].P() = place;
                        bool mended = !bad(face);
                        for (size_t i = 0; i < pg.facesOf[v].size() && mended; ++i) {
                            const int g = pg.facesOf[v][i];
                            mended = (facesInput(g) || !facedBefore[i]) && jacobian(g) >= jacobianBefore[i];
                        }
                        if (!mended) m.vert[v].P() = old;
                        return mended;
                    };
                    // its neighbours' centroid moved onto the input (what mends most); then, where
                    // the sheet under the face is not the one it faces (two sheets of the input
                    // closer than the face's chord error), that place and steps toward and away from
                    // each neighbour moved onto the sheet the face faces
                    const P3 centroid = pg.NeighbourCentroid(v, position);
                    CoordType onSurface;
                    if (surface.Closest(CoordType::Construct(centroid), onSurface)) done = tryPlace(onSurface);
                    if (done || !(faceDirection.Norm() > 0)) continue;
                    for (const P3 &place : Places(pg, v, position, centroid)) {
                        if (surface.ClosestFacing(CoordType::Construct(place), faceDirection, onSurface) && tryPlace(onSurface)) {
                            done = true;
                            break;
                        }
                    }
                }
                mendedNow += done;
            }
            st.mended += mendedNow;
            if (mendedNow == 0) break;
        }
        st.left = 0;
        for (int face = 0; face < pg.FaceCount(); ++face) st.left += bad(face);
        return st;
    }

private:
    // Where a free corner v is tried on the sheet its face faces: its neighbours' centroid, where
    // it is, and steps toward and away from each neighbour.
    template <class Position>
    static std::vector<P3> Places(const OutputPolygons &pg, int v, Position position, const P3 &centroid)
    {
        const P3 here = position(v);
        std::vector<P3> places{centroid, here};
        for (int w : pg.Neighbours(v))
            for (double step : kSteps) places.push_back(here + (position(w) - here) * step);
        return places;
    }

    // Rounds over the faces still flipped: a tangle may need a neighbour moved first.
    static constexpr int kRounds = 4;
    // A move may leave a quad around the corner at any scaled Jacobian down to this (a convex
    // quad, its corners turning the same way), or no lower than it was.
    static constexpr double kConvex = 1e-3;
    // Steps toward (and away from) a neighbour, as fractions of the way to it.
    static constexpr double kSteps[4] = {0.25, 0.5, -0.25, 0.75};
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
