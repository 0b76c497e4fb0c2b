// The output's last check, after the write-back (and after the all-quads split). A face whose
// vector area points away from the input surface (the quality report's flipped face), or a quad
// inverted (a corner turning the other way) or folded, is mended by moving one of its free corners
// to the centroid of its neighbours, projected onto the input, when that mends it and makes no
// face around the corner worse: none turned away from an input triangle closest to its centroid,
// no quad folded or made concave (scaled Jacobians on the input's normal, as the quality report
// reads them). Where two sheets of the input lie closer than the faces' chord error (fingers
// touching: man, two bones side by side: bones), that centroid may project onto the sheet behind;
// then places around the corner are tried on the sheet the face faces. Corners on the front, on a
// border or on a sharp crease of the input never move. What single moves leave: tangles (corners
// moved while the count of bad faces around them falls), then faces whose centroid sags nearer
// such a sheet behind (their free corners lifted together toward the sheet they face).
// A quad no move mends is collapsed along its diagonal (the all-quads output stays all quads).
// A triangle no move mends is removed by collapsing a side with the triangle across it, or with
// half of a quad across it (tiny triangles at the fingers of man, kept aside), else split on the
// sheet it faces. A needle (its apex on its longest side), flipped or not, is removed too:
// collapsed, else flipped away with the polygon across its longest side (lying along a sharp
// crease of the input, which side it faces is a tie any judge breaks its own way: diplodocus' fin,
// kept aside). The caller runs it again while a round changed faces (QMorph::kMendRounds).
//
// Before the all-quads split it also runs on faces whose every corner lies on an input triangle
// facing away (OutputPolygons::CornersFaceAway, `byCorners`), or one of whose straight children
// (a corner, two side midpoints, the centre) would be turned away under its centroid
// (OutputPolygons::ChildFacesAway: a face bridging two sheets of the input closer than its size):
// judged right by their centroid, their children would not be; and with a larger needle height, so
// that slivers go too.
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
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vcg_ext/common/edge_flip.h>
#include <vcg_ext/common/face_face_adjacency.h>
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
        int split = 0;      // of those, triangles split in three on the sheet they face
        int collapsed = 0;  // triangles removed by collapsing a side with the triangle across it (flipped ones and needles)
        int quadsHalved = 0;  // of those, collapsed with half of a quad: the quad's other half is left a triangle
        int needlesRemoved = 0;  // needle triangles not found flipped, removed by a collapse or a flip
        int needlesFlipped = 0;  // needles (flipped or not) removed by flipping their longest side
        int quadsCollapsed = 0;  // bad quads no move mends, removed by collapsing a diagonal (polygons in removedPolygons)
        std::vector<std::pair<int, int>> sameNormalAs;  // (polygon, polygon): the first now lies where the second was judged
        int left = 0;       // those no move could mend
        std::vector<int> removedPolygons;  // the collapsed triangles' polygons (in the order of the output's polygons), ascending
        std::vector<P3> splitNormals;  // per face added by the splits (appended to m.face, two per split): the normal it faces

        // Another round's counts added (`left`: what that round left); the lists are per round.
        void Add(const Stats &round)
        {
            mended += round.mended;
            split += round.split;
            collapsed += round.collapsed;
            quadsHalved += round.quadsHalved;
            needlesRemoved += round.needlesRemoved;
            needlesFlipped += round.needlesFlipped;
            quadsCollapsed += round.quadsCollapsed;
            left = round.left;
        }
    };

    // m in MeshLab's polygonal form (faux-edge quads), with face-face adjacency; front edges are
    // its selected face-edges. Moves vertices; a triangle no move mends, or a needle, is collapsed,
    // flipped away or (flipped) split (the face vectors are compacted when a collapse deleted
    // faces: the output's polygons keep their order, less `removedPolygons`).
    // byCorners: a face whose corners all lie on input triangles facing away, or whose all-quads
    // children would turn away, counts as flipped too;
    // needleHeight: a triangle whose apex is nearer its longest side than this fraction of it is a
    // needle (kNeedleHeight: degenerate once written in float; more: slivers).
    static Stats Do(MeshType &m, InputSurface<MeshType> &surface, double creaseAngleDeg, bool byCorners = false,
                    double needleHeight = kNeedleHeight)
    {
        const OutputPolygons pg = OutputPolygons::Gather(m);
        auto position = [&](int v) { return P3::Construct(m.vert[v].cP()); };
        auto facesInput = [&](int face) { return pg.FacesInput(face, position, surface); };
        // of a quad, on the input's normal under it (as reported) and on its own (a bent dart, one
        // corner reflex in its own plane, can face the input at every corner: man, kept aside);
        // 1 for a triangle
        auto jacobian = [&](int face) {
            if (pg.size[face] < 4) return 1.0;
            P3 q[4];
            pg.Points(face, position, q);
            return std::min(OutputPolygons::QuadJacobian(q, surface), ScaledJacobian(q));
        };
        auto childrenWouldTurn = [&](int face) {  // in the all-quads split
            P3 q[4];
            pg.Points(face, position, q);
            return OutputPolygons::CornersFaceAway(q, pg.size[face], surface) || OutputPolygons::ChildFacesAway(q, pg.size[face], surface);
        };
        auto bad = [&](int face) { return !facesInput(face) || jacobian(face) <= 0 || (byCorners && childrenWouldTurn(face)); };
        Stats st;
        FacesBefore before;
        bool mayBeBad = true;  // false once a round found every face good (most runs)
        for (int round = 0; round < kRounds; ++round) {
            std::vector<int> badFaces;
            for (int face = 0; face < pg.FaceCount(); ++face)
                if (bad(face)) badFaces.push_back(face);
            if (badFaces.empty()) {
                mayBeBad = false;
                break;
            }
            int mendedNow = 0;
            for (int face : badFaces) {
                if (!bad(face)) { ++mendedNow; continue; }  // a neighbour's move mended it
                bool done = false;
                const P3 faceDirection = pg.VectorArea(face, position);
                for (int v : pg.CornersByIndex(face)) {  // in index order: the same moves on a flipped copy
                    if (done) break;
                    if (pg.NeverMoves(v, position(v), surface, creaseAngleDeg)) continue;
                    // the face mended, and no face around v made worse: none turned over, no quad
                    // folded or made concave (one already bad no worse than before)
                    before.Take(pg.facesOf[v], facesInput, jacobian);
                    const CoordType old = m.vert[v].cP();
                    auto tryPlace = [&](const CoordType &place) {
                        m.vert[v].P() = place;
                        const bool mended = !bad(face) && before.NoneWorse(facesInput, jacobian);
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
        if (mayBeBad) st.mended += UntangleStars(pg, m, surface, creaseAngleDeg, position, bad, jacobian);
        if (mayBeBad) st.mended += LiftOffTheSheetBehind(pg, m, surface, creaseAngleDeg, position, bad, facesInput, jacobian);
        std::vector<int> leftTriangles;
        st.left = 0;
        const std::vector<int> polygonOf = OutputPolygons::PolygonOfFace(m);  // per face of m: its polygon
        std::vector<char> touched(m.vert.size(), 0);  // corners of a collapse's star: pg no longer describes them
        std::vector<char> removed(pg.FaceCount(), 0);
        int mendedByCollapse = 0;
        for (int face = 0; face < pg.FaceCount(); ++face) {
            if (removed[face]) continue;
            const bool isBad = bad(face);
            if (!isBad && !(pg.size[face] == 3 && IsNeedle(m.face[pg.face[face]], needleHeight))) continue;
            if (isBad) ++st.left;
            if (pg.size[face] == 4) {
                // a bad quad no move mends: its diagonal collapsed (the mesh keeps its kinds of faces)
                if (CollapseQuad(m, pg, face, touched, position, facesInput, jacobian, surface, creaseAngleDeg)) {
                    ++st.quadsCollapsed;
                    ++mendedByCollapse;
                    removed[face] = 1;
                    st.removedPolygons.push_back(face);
                }
                continue;
            }
            if (pg.size[face] != 3) continue;
            // a flipped triangle or a needle: collapsed with the triangle across a side, else (a
            // needle) flipped away, else (flipped) split on the sheet it faces
            int across = CollapseSide(m, pg, face, polygonOf, touched, position, facesInput, jacobian, surface, creaseAngleDeg, needleHeight);
            if (across >= 0) {
                ++st.collapsed;
                if (isBad) ++mendedByCollapse;
                else ++st.needlesRemoved;
                removed[face] = removed[across] = 1;
                st.removedPolygons.push_back(face);
                if (pg.size[across] == 4) ++st.quadsHalved;  // left a triangle, in the quad's place
                else st.removedPolygons.push_back(across);
                continue;
            }
            across = FlipNeedleSide(m, pg, face, polygonOf, touched, position, jacobian, surface, needleHeight);
            if (across >= 0) {
                ++st.needlesRemoved;
                ++st.needlesFlipped;
                if (isBad) ++st.mended, --st.left;
                st.sameNormalAs.push_back({face, across});
                removed[face] = removed[across] = 1;  // no longer what pg says
            } else if (isBad) {
                leftTriangles.push_back(pg.face[face]);
            }
        }
        for (int f : leftTriangles)
            if (SplitOnFacedSheet(m, f, surface, st.splitNormals)) ++st.split;
        st.mended += st.split + mendedByCollapse;
        st.left -= st.split + mendedByCollapse;
        std::sort(st.removedPolygons.begin(), st.removedPolygons.end());
        if (st.collapsed || st.quadsCollapsed) vcg::tri::Allocator<MeshType>::CompactEveryVector(m);  // keeps the order of what is left
        if (st.split || st.collapsed || st.quadsCollapsed || st.needlesFlipped) {
            FaceFaceAdjacency<MeshType>::Update(m);
            if (vcg::tri::HasVFAdjacency(m)) vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
        }
        return st;
    }

    // Whether m has a pure triangle (no faux side) that is a needle (NeedleSide).
    static bool HasNeedleTriangle(const MeshType &m)
    {
        for (const FaceType &f : m.face)
            if (!f.IsD() && !f.IsF(0) && !f.IsF(1) && !f.IsF(2) && IsNeedle(f, kNeedleHeight)) return true;
        return false;
    }

private:
    typedef typename MeshType::FaceType FaceType;
    typedef typename MeshType::VertexType VertexType;

    // A triangle no move mends (a flat triangle over a flap of the input thinner than its chord
    // error: its centroid nearer the sheet behind, its corners on the sheet it faces) split in three
    // at the point of the sheet it faces nearest its centroid, when the three children face the
    // input. f keeps its first side; the two new faces go at the end of m.face, their normals (the
    // sheet's) at the end of `normals`. Front and faux flags of the three old sides are kept.
    static bool SplitOnFacedSheet(MeshType &m, int f, InputSurface<MeshType> &surface, std::vector<P3> &normals)
    {
        const P3 p[3] = {P3::Construct(m.face[f].cP(0)), P3::Construct(m.face[f].cP(1)), P3::Construct(m.face[f].cP(2))};
        const P3 direction = (p[1] - p[0]) ^ (p[2] - p[0]);
        CoordType onSheet;
        const FaceType *under = surface.ClosestFacing(CoordType::Construct((p[0] + p[1] + p[2]) / 3.0), direction, onSheet);
        if (!under) return false;
        const P3 c = P3::Construct(onSheet);
        for (int k = 0; k < 3; ++k) {  // child k: side k and the new point
            const P3 a = p[k], b = p[(k + 1) % 3];
            const P3 area = (b - a) ^ (c - a);
            if (!(area.Norm() > 0) || !surface.FacesEveryClosest((a + b + c) / 3.0, area)) return false;
        }
        const int v[3] = {int(vcg::tri::Index(m, m.face[f].V(0))), int(vcg::tri::Index(m, m.face[f].V(1))), int(vcg::tri::Index(m, m.face[f].V(2)))};
        const int centre = int(m.vert.size());
        vcg::tri::Allocator<MeshType>::AddVertices(m, 1)->P() = onSheet;
        const int first = int(m.face.size());
        vcg::tri::Allocator<MeshType>::AddFaces(m, 2);
        for (int k = 1; k < 3; ++k) {  // children 1 and 2: copies of f with their side's flags
            FaceType &child = m.face[first + k - 1];
            child.ImportData(m.face[f]);
            child.V(0) = &m.vert[v[k]];
            child.V(1) = &m.vert[v[(k + 1) % 3]];
            child.V(2) = &m.vert[centre];
            for (int e = 1; e < 3; ++e) ClearSide(child, e);
            if (m.face[f].IsFaceEdgeS(k)) child.SetFaceEdgeS(0); else child.ClearFaceEdgeS(0);
            if (m.face[f].IsF(k)) child.SetF(0); else child.ClearF(0);
            normals.push_back(P3::Construct(surface.Normal(under)));
        }
        m.face[f].V(2) = &m.vert[centre];
        for (int e = 1; e < 3; ++e) ClearSide(m.face[f], e);
        return true;
    }

    // A triangle (polygon `face`) no move mends, removed by collapsing one of its sides, shortest
    // first, with the triangle across it: the side's free end u goes to its other end w (u on no
    // front edge or border; on a sharp crease of the input only if w is too), where vcglib's link
    // condition holds (the surface stays a 2-manifold of the same genus) and every other polygon
    // around u, with u at w, faces the input, no quad is folded or made worse (as a corner move
    // is judged) and no triangle becomes a needle (one left by a collapse turned into children
    // upside down in the all-quads split: block). Tiny triangles at the fingers of a scan are what
    // no move mends (man, kept aside).
    // The triangle across may be half of a quad: its other half is then left a triangle, which
    // must face the input and not be a needle (man's needles along a thin fin have quads across
    // their short sides, kept aside); only when the quad's two halves are consecutive faces, so
    // that the triangle keeps the quad's place in the output's order.
    // vcglib's FFEdgeCollapse does it (faces deleted, not compacted; face-face adjacency kept
    // valid); a front edge on either side it glues keeps its selection on both, and a faux side
    // glued to a real one (the quad's half left) becomes real. Returns the polygon across, or -1.
    template <class Position, class Faces, class Jacobian>
    static int CollapseSide(MeshType &m, const OutputPolygons &pg, int face, const std::vector<int> &polygonOf,
                            std::vector<char> &touched, Position position, Faces facesInput, Jacobian jacobian,
                            InputSurface<MeshType> &surface, double creaseAngleDeg, double needleHeight)
    {
        FaceType &f = m.face[pg.face[face]];
        auto index = [&](const VertexType *v) { return int(vcg::tri::Index(m, v)); };
        for (int k = 0; k < 3; ++k)
            if (touched[index(f.V(k))]) return -1;
        int order[3] = {0, 1, 2};
        std::sort(order, order + 3, [&](int a, int b) {
            return vcg::SquaredDistance(f.P0(a), f.P1(a)) < vcg::SquaredDistance(f.P0(b), f.P1(b));
        });
        for (int k : order) {
            FaceType *g = f.FFp(k);
            if (g == &f || f.IsFaceEdgeS(k) || f.IsF(k)) continue;
            const int j = f.FFi(k);
            const int across = polygonOf[vcg::tri::Index(m, g)];
            if (across < 0 || touched[index(g->V2(j))] || !vcg::face::FFLinkCondition(f, k)) continue;
            FaceType *half = nullptr;  // the quad's other half, left a triangle
            if (pg.size[across] == 4) {
                for (int z = 0; z < 3; ++z)
                    if (g->IsF(z)) half = g->FFp(z);
                if (!half || std::abs(long(vcg::tri::Index(m, g)) - long(vcg::tri::Index(m, half))) != 1 || touched[index(half->V(0))] || touched[index(half->V(1))] || touched[index(half->V(2))]) continue;
            }
            for (int end = 0; end < 2; ++end) {
                // FFEdgeCollapse(t, e) moves t's V0(e) onto its V1(e): f's side k one way, g's side j the other
                FaceType &t = end == 0 ? f : *g;
                const int e = end == 0 ? k : j;
                const int u = index(t.V0(e)), w = index(t.V1(e));
                // the polygons around u but the two triangles, with u at w: facing the input, no
                // quad worse (as a corner move is judged); the quad's half left a triangle facing the
                // input, no needle
                bool fine = MayCollapse(m, pg, u, w, {face, across}, position, facesInput, jacobian, surface, creaseAngleDeg, needleHeight);
                if (half && fine) {
                    const CoordType old = m.vert[u].cP();
                    m.vert[u].P() = m.vert[w].cP();
                    const P3 q[3] = {P3::Construct(half->cP(0)), P3::Construct(half->cP(1)), P3::Construct(half->cP(2))};
                    fine = OutputPolygons::FacesInput(q, 3, surface) && NeedleSide(q, needleHeight) < 0;
                    m.vert[u].P() = old;
                }
                if (!fine) continue;
                std::vector<VertexType *> ring;
                vcg::face::VVOrderedStarFF(vcg::face::Pos<FaceType>(&t, e, t.V0(e)), ring);
                CollapseKeepingFront(m, t, e);
                touched[u] = touched[w] = 1;
                for (VertexType *v : ring) touched[index(v)] = 1;
                if (half)
                    for (int c = 0; c < 3; ++c) touched[index(half->V(c))] = 1;
                return across;
            }
        }
        return -1;
    }

    // Whether vertex u may be collapsed onto w: u free (on a sharp crease of the input only if w is
    // too), and every polygon around u but the ones removed (`gone`), with u at w, facing the input,
    // no quad worse (as a corner move is judged), no new needle. m is left as it was.
    template <class Position, class Faces, class Jacobian>
    static bool MayCollapse(MeshType &m, const OutputPolygons &pg, int u, int w, std::array<int, 2> gone, Position position,
                            Faces facesInput, Jacobian jacobian, InputSurface<MeshType> &surface, double creaseAngleDeg,
                            double needleHeight)
    {
        if (pg.fixed[u]) return false;
        if (surface.OnCrease(position(u), creaseAngleDeg) && !surface.OnCrease(position(w), creaseAngleDeg)) return false;
        const CoordType old = m.vert[u].cP();
        std::vector<double> before;
        std::vector<char> needleBefore;
        for (int h : pg.facesOf[u]) {
            before.push_back(std::min(kConvex, jacobian(h)));
            needleBefore.push_back(IsNeedle(pg, h, position, needleHeight));
        }
        m.vert[u].P() = m.vert[w].cP();
        bool fine = true;
        for (size_t i = 0; i < pg.facesOf[u].size() && fine; ++i) {
            const int h = pg.facesOf[u][i];
            if (h == gone[0] || h == gone[1]) continue;
            fine = facesInput(h) && jacobian(h) >= before[i] && (needleBefore[i] || !IsNeedle(pg, h, position, needleHeight));
        }
        m.vert[u].P() = old;
        return fine;
    }

    // vcglib's FFEdgeCollapse of t's side e (its V0 onto its V1), a front edge on either side it
    // glues kept one on both, a faux side glued to a real one made real (vcglib's detach leaves the
    // border bit on sides that are glued again).
    static void CollapseKeepingFront(MeshType &m, FaceType &t, int e)
    {
        std::array<std::pair<FaceType *, int>, 4> glued;  // the sides it glues, in pairs
        for (int s = 0; s < 2; ++s) {
            FaceType &tri = s == 0 ? t : *t.FFp(e);
            const int side = s == 0 ? e : t.FFi(e);
            for (int d = 1; d < 3; ++d) glued[2 * s + d - 1] = {tri.FFp((side + d) % 3), tri.FFi((side + d) % 3)};
        }
        vcg::face::FFEdgeCollapse(m, t, e);
        for (int s = 0; s < 4; s += 2) {
            auto &x = glued[s], &y = glued[s + 1];
            const bool front = x.first->IsFaceEdgeS(x.second) || y.first->IsFaceEdgeS(y.second);
            for (auto &side : {x, y}) {
                side.first->ClearB(side.second);
                side.first->ClearF(side.second);
                if (front) side.first->SetFaceEdgeS(side.second);
            }
        }
    }

    // A bad quad (polygon `face`) no move mends, removed by collapsing its diagonal (the faux side of
    // its two triangles): one end u onto the other w, either way round, where u is free (on a sharp
    // crease of the input only if w is too), vcglib's link condition holds and every other polygon
    // around u, with u at w, faces the input, is no worse a quad (as a corner move is judged) and no
    // needle. The two sides at each of the quad's other corners become one. What the all-quads
    // split leaves over plates of the input thinner than its parent faces (man, kept aside).
    template <class Position, class Faces, class Jacobian>
    static bool CollapseQuad(MeshType &m, const OutputPolygons &pg, int face, std::vector<char> &touched, Position position,
                             Faces facesInput, Jacobian jacobian, InputSurface<MeshType> &surface, double creaseAngleDeg)
    {
        FaceType &f = m.face[pg.face[face]];
        auto index = [&](const VertexType *v) { return int(vcg::tri::Index(m, v)); };
        for (int k = 0; k < 4; ++k)
            if (touched[pg.corners[face][k]]) return false;
        int z = -1;
        for (int k = 0; k < 3; ++k)
            if (f.IsF(k)) z = k;
        if (z < 0 || f.FFp(z) == &f || !vcg::face::FFLinkCondition(f, z)) return false;
        FaceType &other = *f.FFp(z);
        for (int end = 0; end < 2; ++end) {
            // FFEdgeCollapse(t, e) moves t's V0(e) onto its V1(e): f's diagonal one way, the other half's the other
            FaceType &t = end == 0 ? f : other;
            const int e = end == 0 ? z : f.FFi(z);
            const int u = index(t.V0(e)), w = index(t.V1(e));
            if (!MayCollapse(m, pg, u, w, {face, face}, position, facesInput, jacobian, surface, creaseAngleDeg, kNeedleHeight)) continue;
            std::vector<VertexType *> ring;
            vcg::face::VVOrderedStarFF(vcg::face::Pos<FaceType>(&t, e, t.V0(e)), ring);
            CollapseKeepingFront(m, t, e);
            touched[u] = touched[w] = 1;
            for (VertexType *v : ring) touched[index(v)] = 1;
            return true;
        }
        return false;
    }

    // A needle: its apex closer to its longest side than needleHeight of that side (at kNeedleHeight
    // its normal is rounding noise; lying along a sharp crease of the input, it faces one side or the
    // other whichever way a judge breaks the tie; larger: a sliver). Returns that side, or -1.
    static int NeedleSide(const FaceType &f, double needleHeight)
    {
        const P3 p[3] = {P3::Construct(f.cP(0)), P3::Construct(f.cP(1)), P3::Construct(f.cP(2))};
        return NeedleSide(p, needleHeight);
    }
    static int NeedleSide(const P3 *p, double needleHeight)
    {
        int k = 0;
        double longest = 0;
        for (int e = 0; e < 3; ++e) {
            const double l = vcg::Distance(p[e], p[(e + 1) % 3]);
            if (l > longest) longest = l, k = e;
        }
        const P3 a = p[k], b = p[(k + 1) % 3], apex = p[(k + 2) % 3];
        const double height = ((b - a) ^ (apex - a)).Norm() / longest;
        return longest > 0 && height < needleHeight * longest ? k : -1;
    }
    static bool IsNeedle(const FaceType &f, double needleHeight) { return NeedleSide(f, needleHeight) >= 0; }
    // Whether polygon h of pg is a triangle and a needle.
    template <class Position>
    static bool IsNeedle(const OutputPolygons &pg, int h, Position position, double needleHeight)
    {
        if (pg.size[h] != 3) return false;
        P3 q[4];
        pg.Points(h, position, q);
        return NeedleSide(q, needleHeight) >= 0;
    }

    // A needle (polygon `face`, a triangle P Q M, M its apex near its longest side P Q) removed by
    // flipping P Q with the triangle across it, which M then splits: a triangle across (Q P X)
    // becomes Q M X and M P X; half of a quad (Q P A B) becomes the quad Q M A B and the triangle
    // M P A (the quad's diagonal first turned to Q A, so each polygon keeps its place in the output's
    // order: the quad where the quad was, the triangle where the needle was). Kept when the new
    // faces face the input, are no needles, and the new quad is no worse than the old one (or than
    // kConvex).
    // P Q must not be a front edge. Returns the polygon across, or -1.
    template <class Position, class Jacobian>
    static int FlipNeedleSide(MeshType &m, const OutputPolygons &pg, int face, const std::vector<int> &polygonOf,
                              std::vector<char> &touched, Position position, Jacobian jacobian,
                              InputSurface<MeshType> &surface, double needleHeight)
    {
        FaceType &f = m.face[pg.face[face]];
        const int k = NeedleSide(f, needleHeight);
        if (k < 0 || f.IsFaceEdgeS(k) || f.IsF(k) || f.FFp(k) == &f) return -1;
        FaceType *g = f.FFp(k);
        const int across = polygonOf[vcg::tri::Index(m, g)];
        auto index = [&](const VertexType *v) { return int(vcg::tri::Index(m, v)); };
        const int P = index(f.V0(k)), Q = index(f.V1(k)), M = index(f.V2(k));
        if (across < 0 || touched[P] || touched[Q] || touched[M]) return -1;
        const int n = pg.size[across];
        int c = 0;  // the quad's (or triangle's) corner Q, followed by P counter-clockwise
        while (c < n && pg.corners[across][c] != Q) ++c;
        if (c == n || pg.corners[across][(c + 1) % n] != P) return -1;
        const int A = pg.corners[across][(c + 2) % n], B = n == 4 ? pg.corners[across][(c + 3) % n] : -1;
        for (int v : {A, B})
            if (v >= 0 && touched[v]) return -1;
        auto facesInput = [&](std::initializer_list<int> corners) {
            P3 q[4];
            int count = 0;
            for (int v : corners) q[count++] = position(v);
            return OutputPolygons::FacesInput(q, count, surface);
        };
        auto needle = [&](int a, int b, int c) {
            const P3 q[3] = {position(a), position(b), position(c)};
            return NeedleSide(q, needleHeight) >= 0;
        };
        if (n == 3) {
            if (!facesInput({Q, M, A}) || !facesInput({M, P, A}) || needle(Q, M, A) || needle(M, P, A)) return -1;
        } else {
            const P3 q[4] = {position(Q), position(M), position(A), position(B)};
            if (IsFolded(q) || !facesInput({M, P, A}) || !facesInput({Q, M, A, B}) || needle(M, P, A)) return -1;
            if (OutputPolygons::QuadJacobian(q, surface) < std::min(kConvex, jacobian(across))) return -1;
            const int w = f.FFi(k);
            const int z = (w + 1) % 3;
            if (g->IsF(z)) {  // the diagonal P B: turned to Q A, so the chord's triangle is Q P A
                if (!vcg::face::CheckFlipEdge(*g, z)) return -1;
                FlipEdgeKeepingFlags(*g, z);
                const int diagonal = (z + 1) % 3;  // the new one: faux, as the one it replaces
                g->SetF(diagonal);
                g->FFp(diagonal)->SetF(g->FFi(diagonal));
            }
        }
        if (!vcg::face::CheckFlipEdge(f, k)) return -1;  // (a quad's diagonal stays turned: the same quad)
        FlipEdgeKeepingFlags(f, k);
        for (int v : {P, Q, M, A, B})
            if (v >= 0) touched[v] = 1;
        return across;
    }

    static void ClearSide(FaceType &f, int e)
    {
        f.ClearFaceEdgeS(e);
        f.ClearF(e);
    }

    // What no single mending move undoes (a tangle: bad faces sharing corners, where a move that
    // mends one turns another; the all-quads split's children on bones and man, kept aside): a
    // free corner of a bad face moved wherever the number of bad faces around it falls (the
    // fewest, then the best worst quad), so that two bad neighbours can be mended one after the
    // other. Every move lowers the number of bad faces: it ends. Returns the faces mended.
    template <class Position, class Bad, class Jacobian>
    static int UntangleStars(const OutputPolygons &pg, MeshType &m, InputSurface<MeshType> &surface, double creaseAngleDeg,
                             Position position, Bad bad, Jacobian jacobian)
    {
        int mended = 0;
        auto score = [&](int v) {  // (bad faces around v, their worst Jacobian)
            std::pair<int, double> s{0, 1.0};
            for (int g : pg.facesOf[v]) {
                s.first += bad(g);
                s.second = std::min(s.second, jacobian(g));
            }
            return s;
        };
        for (int round = 0; round < kRounds; ++round) {
            int mendedNow = 0;
            for (int face = 0; face < pg.FaceCount(); ++face) {
                if (!bad(face)) continue;
                const P3 faceDirection = pg.VectorArea(face, position);
                for (int v : pg.CornersByIndex(face)) {
                    if (pg.NeverMoves(v, position(v), surface, creaseAngleDeg)) continue;
                    const CoordType old = m.vert[v].cP();
                    const std::pair<int, double> before = score(v);
                    std::pair<int, double> best = before;
                    CoordType bestPlace = old;
                    auto tryPlace = [&](const CoordType &place) {
                        m.vert[v].P() = place;
                        const std::pair<int, double> s = score(v);
                        if (s.first < best.first || (s.first == best.first && s.first < before.first && s.second > best.second)) {
                            best = s;
                            bestPlace = place;
                        }
                    };
                    const P3 centroid = pg.NeighbourCentroid(v, position);
                    CoordType onSurface;
                    for (const P3 &place : Places(pg, v, position, centroid)) {
                        if (surface.Closest(CoordType::Construct(place), onSurface)) tryPlace(onSurface);
                        if (faceDirection.Norm() > 0 && surface.ClosestFacing(CoordType::Construct(place), faceDirection, onSurface))
                            tryPlace(onSurface);
                    }
                    m.vert[v].P() = bestPlace;
                    mendedNow += before.first - best.first;
                    if (!bad(face)) break;
                }
            }
            mended += mendedNow;
            if (mendedNow == 0) break;
        }
        return mended;
    }

    // The faces around corners about to move, as they were: a move may turn none of them away from
    // the input that faced it, nor leave a quad worse than it was (or than kConvex).
    struct FacesBefore {
        const std::vector<int> *faces = nullptr;
        std::vector<char> faced;
        std::vector<double> jacobian;

        template <class Faces, class Jacobian>
        void Take(const std::vector<int> &around, Faces facesInput, Jacobian jacobianOf)
        {
            faces = &around;
            faced.clear();
            jacobian.clear();
            for (int g : around) {
                faced.push_back(facesInput(g));
                jacobian.push_back(std::min(kConvex, jacobianOf(g)));
            }
        }
        template <class Faces, class Jacobian>
        bool NoneWorse(Faces facesInput, Jacobian jacobianOf) const
        {
            for (size_t i = 0; i < faces->size(); ++i) {
                const int g = (*faces)[i];
                if (!((facesInput(g) || !faced[i]) && jacobianOf(g) >= jacobian[i])) return false;
            }
            return true;
        }
    };

    // What no move on the input mends: a face turned over because its centroid lies nearer a sheet
    // of the input that faces away than the one it faces, where the two are closer than its chord
    // error (fingers touching: man; a fin: diplodocus, kept aside). Its free corners are moved
    // together, off the input, toward the point of the faced sheet (within its longest side)
    // nearest its centroid, so that the centroid reaches that sheet and passes it: by the
    // centroid's distance to it times kLifts, spread over the free corners (at least kMinLift of
    // the face's longest side: a centroid on the sheet's very edge). Kept when the face is mended
    // and no face around the moved corners made worse (as a corner move is judged). The moves are
    // a fraction of the gap between the sheets, far below the Hausdorff bar. Returns the faces
    // mended (when it came, on the 31 meshes kept aside with All quads: man 21 -> 19, diplodocus
    // 7 -> 6 flipped).
    template <class Position, class Bad, class Faces, class Jacobian>
    static int LiftOffTheSheetBehind(const OutputPolygons &pg, MeshType &m, InputSurface<MeshType> &surface, double creaseAngleDeg,
                                     Position position, Bad bad, Faces facesInput, Jacobian jacobian)
    {
        int mended = 0;
        for (int face = 0; face < pg.FaceCount(); ++face) {
            if (!bad(face) || facesInput(face)) continue;
            const P3 direction = pg.VectorArea(face, position);
            if (!(direction.Norm() > 0)) continue;
            P3 q[4];
            pg.Points(face, position, q);
            double longest = 0;
            for (int k = 0; k < pg.size[face]; ++k) longest = std::max(longest, vcg::Distance(q[k], q[(k + 1) % pg.size[face]]));
            const P3 centroid = OutputPolygons::Centroid(q, pg.size[face]);
            CoordType onSheet;
            const FaceType *sheet = surface.ClosestFacing(CoordType::Construct(centroid), direction, onSheet, longest);
            if (!sheet) continue;
            std::vector<int> lifted;  // the face's free corners
            for (int v : pg.CornersByIndex(face))
                if (!pg.NeverMoves(v, position(v), surface, creaseAngleDeg)) lifted.push_back(v);
            if (lifted.empty()) continue;
            // the faces around them, once each, with their state before
            std::vector<int> around;
            for (int v : lifted) around.insert(around.end(), pg.facesOf[v].begin(), pg.facesOf[v].end());
            std::sort(around.begin(), around.end());
            around.erase(std::unique(around.begin(), around.end()), around.end());
            FacesBefore before;
            before.Take(around, facesInput, jacobian);
            std::vector<CoordType> old;
            for (int v : lifted) old.push_back(m.vert[v].cP());
            // toward the point of that sheet nearest the centroid (up from a chord sagging below a
            // plate's sheet, down onto the near one of two sheets touching), along its normal when
            // the centroid is on it
            const P3 toSheet = P3::Construct(onSheet) - centroid;
            const double distance = toSheet.Norm();
            const P3 way = distance > kMinLift * longest ? toSheet / distance : P3::Construct(surface.Normal(sheet));
            const double reach = std::max(distance, kMinLift * longest);
            for (double lift : kLifts) {
                const P3 offset = way * (lift * reach * pg.size[face] / double(lifted.size()));
                for (size_t i = 0; i < lifted.size(); ++i) m.vert[lifted[i]].P() = CoordType::Construct(P3::Construct(old[i]) + offset);
                if (!bad(face) && before.NoneWorse(facesInput, jacobian)) {
                    ++mended;
                    break;
                }
                for (size_t i = 0; i < lifted.size(); ++i) m.vert[lifted[i]].P() = old[i];
            }
        }
        return mended;
    }

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
    // A triangle whose apex is closer to its longest side than this fraction of it is a needle
    // (the sine below which a triangle is degenerate once written in float, as in the patches).
    static constexpr double kNeedleHeight = 1e-3;
    // Lifts off the sheet behind, as multiples of the centroid's distance to the sheet it faces, and
    // the least one, as a fraction of the face's longest side.
    static constexpr double kLifts[3] = {1.5, 3, 6};
    static constexpr double kMinLift = 0.01;
    // Steps toward (and away from) a neighbour, as fractions of the way to it.
    static constexpr double kSteps[4] = {0.25, 0.5, -0.25, 0.75};
};

}  // namespace qmorph
}  // namespace vcg_ext

#endif
