// The output's last check (qmorph/flipped_face_mend.h): faces turned over on the input surface are
// turned back by moving free corners, never a front corner, never leaving a quad concave.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "test_mesh.h"
#include <vcg/complex/append.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg_ext/qmorph/flipped_face_mend.h>

using namespace qmf_test;

namespace {

typedef vcg_ext::qmorph::FlippedFaceMend<TMesh> Mend;
typedef vcg::Point3d D3;

// Faces of a mesh in the z = 0 plane (counter-clockwise seen from +z) turned over: normal down.
int FacesTurnedOver(const TMesh &m)
{
    int n = 0;
    for (const TFace &f : m.face)
        if (!f.IsD() && vcg::TriangleNormal(f)[2] < 0) ++n;
    return n;
}

// The vertex at (x, y) of a grid.
TVertex *At(TMesh &m, float x, float y)
{
    for (TVertex &v : m.vert)
        if (v.P()[0] == x && v.P()[1] == y) return &v;
    return nullptr;
}


// Two sheets 0.1 apart, z = 0 facing +z (`upper`, an n x n grid of unit cells with its diagonals
// one way) and z = -0.1 facing -z: a plate, or fingers touching.
void MakeTwoSheets(TMesh &upper, TMesh &input, int n)
{
    TMesh lower;
    MakeGrid(upper, n, float(n), 0.f, 1, false);
    MakeGrid(lower, n, float(n), 0.f, 1, false);
    for (TVertex &v : lower.vert) v.P()[2] = -0.1f;
    for (TFace &f : lower.face) std::swap(f.V(0), f.V(1));
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(input, upper);
    vcg::tri::Append<TMesh, TMesh>::Mesh(input, lower);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(input);
    vcg::tri::UpdateBounding<TMesh>::Box(input);
}

// Face-face adjacency reciprocal across every inner side, with no inner side flagged as border
// (after a collapse).
void ExpectValidAdjacency(TMesh &m)
{
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k) {
            TFace *g = f.FFp(k);
            if (g == &f) continue;  // the grid's border
            EXPECT_EQ(g->FFp(f.FFi(k)), &f) << "face-face adjacency not reciprocal";
            EXPECT_EQ(g->V0(f.FFi(k)), f.V1(k));
            EXPECT_EQ(g->V1(f.FFi(k)), f.V0(k));
            EXPECT_FALSE(f.IsB(k)) << "an inner side flagged as border";
        }
}
}  // namespace

TEST(FlippedFaceMend, AVertexDraggedPastItsNeighbourIsPutBack)
{
    // the input: a 4 x 4 grid of unit cells; the output: the same with vertex (1, 1) dragged past
    // (2, 1), so the triangles between turn over
    TMesh input, m;
    MakeGrid(input, 4, 4.f);
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, input);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg_ext::InputSurface<TMesh> surface(input);
    At(m, 1, 1)->P() = P3(2.6f, 1.2f, 0);
    const int turnedOver = FacesTurnedOver(m);
    ASSERT_GT(turnedOver, 0);

    const Mend::Stats st = Mend::Do(m, surface, 60);
    EXPECT_EQ(FacesTurnedOver(m), 0);
    EXPECT_EQ(st.left, 0);
    EXPECT_GE(st.mended, 1);
    for (const TVertex &v : m.vert) EXPECT_EQ(v.cP()[2], 0.f) << "a vertex left the input plane";
}

TEST(FlippedFaceMend, FrontCornersStayAndQuadsStayConvex)
{
    // quads: each cell of the grid is two triangles sharing a faux diagonal; the row y = 2 is a
    // front (selected face-edges). Vertex (2, 2) on the front and (2, 3) off it are dragged so that
    // quads turn over; only (2, 3) may move back.
    TMesh input, m;
    MakeGrid(input, 4, 4.f, 0.f, 1, false);
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, input);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k) {
            const P3 a = f.P0(k), b = f.P1(k);
            if (a[0] != b[0] && a[1] != b[1]) f.SetF(k);                 // the diagonal
            if (a[1] == 2 && b[1] == 2) f.SetFaceEdgeS(k);              // the front
        }
    vcg_ext::InputSurface<TMesh> surface(input);
    TVertex *onFront = At(m, 2, 2), *free = At(m, 2, 3);
    const P3 frontPlace(2.4f, 2.f, 0);  // slid along the front: nothing turns over
    onFront->P() = frontPlace;
    free->P() = P3(2.3f, 1.7f, 0);      // below the front row: its quads turn over
    ASSERT_GT(FacesTurnedOver(m), 0);

    const Mend::Stats st = Mend::Do(m, surface, 60);
    EXPECT_EQ(FacesTurnedOver(m), 0);
    EXPECT_EQ(st.left, 0);
    EXPECT_EQ(onFront->P(), frontPlace) << "a front corner moved";
    EXPECT_GT(free->P()[1], 2.f) << "the free corner is still below the front";
    // every quad convex: each corner turns left seen from +z
    vcg_ext::QuadQuality::ForEachFauxPolygon(m, [&](TFace &, const std::array<int, 4> &c, int n) {
        if (n < 4) return;
        for (int k = 0; k < 4; ++k) {
            const P3 a = m.vert[c[k]].P(), b = m.vert[c[(k + 1) % 4]].P(), d = m.vert[c[(k + 3) % 4]].P();
            EXPECT_GT(((b - a) ^ (d - a))[2], 0.f) << "a concave or inverted quad";
        }
    });
}

TEST(FlippedFaceMend, AFlippedCopyGetsTheSameMoves)
{
    // the dragged-vertex case twice, the second time with every face of input and output read
    // the other way round: the mend must move the same vertices to the same places
    auto run = [](bool flipped) {
        TMesh input, m;
        MakeGrid(input, 4, 4.f, 0.2f, 7);
        if (flipped)
            for (TFace &f : input.face) std::swap(f.V(0), f.V(1));
        vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(input);
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, input);
        vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
        vcg_ext::InputSurface<TMesh> surface(input);
        m.vert[6].P() = m.vert[7].P() + (m.vert[7].P() - m.vert[6].P()) * 0.6f;  // past its neighbour
        const Mend::Stats st = Mend::Do(m, surface, 60);
        EXPECT_EQ(st.left, 0);
        EXPECT_GE(st.mended, 1);
        std::vector<P3> positions;
        for (const TVertex &v : m.vert) positions.push_back(v.cP());
        return positions;
    };
    const std::vector<P3> straight = run(false), mirrored = run(true);
    ASSERT_EQ(straight.size(), mirrored.size());
    for (size_t i = 0; i < straight.size(); ++i) EXPECT_EQ(straight[i], mirrored[i]) << "vertex " << i;
}

TEST(FlippedFaceMend, AVertexOnTheSheetBehindMovesToTheSheetItsFacesFace)
{
    // the input: two sheets 0.1 apart, z = 0 facing +z and z = -0.1 facing -z (fingers side by
    // side); the output: the upper sheet with a ring of front vertices around (2, 2) sunk to
    // z = -0.06 and (2, 2) itself on the lower sheet, so its six faces lie nearer the lower sheet
    // and turn away from it. Its neighbours' centroid is nearer the lower sheet too: only a move onto
    // the sheet its faces face mends them.
    TMesh upper, input, m;
    MakeTwoSheets(upper, input, 4);
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, upper);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg_ext::InputSurface<TMesh> surface(input);

    TVertex *centre = At(m, 2, 2);
    std::vector<TVertex *> ring;
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k)
            if (f.V(k) == centre) {
                for (TVertex *v : {f.V1(k), f.V2(k)})
                    if (std::find(ring.begin(), ring.end(), v) == ring.end()) ring.push_back(v);
            }
    ASSERT_EQ(ring.size(), 6u);
    auto inRing = [&](TVertex *v) { return std::find(ring.begin(), ring.end(), v) != ring.end(); };
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k)
            if (inRing(f.V0(k)) && inRing(f.V1(k))) f.SetFaceEdgeS(k);  // the ring is a front loop
    for (TVertex *v : ring) v->P()[2] = -0.06f;
    centre->P()[2] = -0.1f;
    std::vector<P3> ringBefore;
    for (TVertex *v : ring) ringBefore.push_back(v->P());

    const Mend::Stats st = Mend::Do(m, surface, 60);
    EXPECT_EQ(st.left, 0);
    EXPECT_GE(st.mended, 1);
    EXPECT_FLOAT_EQ(centre->P()[2], 0.f) << "the centre is not on the upper sheet";
    for (size_t i = 0; i < ring.size(); ++i) EXPECT_EQ(ring[i]->P(), ringBefore[i]) << "a front corner moved";
}

TEST(FlippedFaceMend, AFlatTriangleUnderATentIsSplitOnTheSheetItFaces)
{
    // the input: a shell, a tent over [0,4]^2 (apex (2, 2) at z = 0.5, facing +z) and the same
    // tent 0.6 below it facing -z; the output: one flat triangle with its corners on the upper
    // tent's foot. Its centroid lies 0.27 under the upper tent and 0.22 over the lower one, so it
    // counts as flipped, and no corner may move (all on the border): it is split in three at the
    // point of the upper tent nearest its centroid, each child nearer the upper tent (the flat
    // child's centroids: 0.25 or less under it), the front side kept.
    TMesh upper, lower, input, m;
    MakeGrid(upper, 4, 4.f, 0.f, 1, false);
    At(upper, 2, 2)->P()[2] = 0.5f;
    MakeGrid(lower, 4, 4.f, 0.f, 1, false);
    At(lower, 2, 2)->P()[2] = 0.5f;
    for (TVertex &v : lower.vert) v.P()[2] -= 0.6f;
    for (TFace &f : lower.face) std::swap(f.V(0), f.V(1));
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(input, upper);
    vcg::tri::Append<TMesh, TMesh>::Mesh(input, lower);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(input);
    vcg::tri::UpdateBounding<TMesh>::Box(input);
    vcg_ext::InputSurface<TMesh> surface(input);
    Build(m, {P3(1, 1, 0), P3(3, 1, 0), P3(2, 3, 0)}, {{0, 1, 2}});
    m.face[0].Q() = 7;                  // the region id, which the children keep
    m.face[0].SetFaceEdgeS(0);          // (1, 1) - (3, 1): a front side
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);

    const Mend::Stats st = Mend::Do(m, surface, 60);
    EXPECT_EQ(st.split, 1);
    EXPECT_EQ(st.left, 0);
    ASSERT_EQ(m.fn, 3);
    ASSERT_EQ(m.vn, 4);
    ASSERT_EQ(st.splitNormals.size(), 2u);
    const P3 centre = m.vert[3].P();
    EXPECT_GT(centre[2], 0.2f) << "the new point is not on the upper tent";
    int frontSides = 0;
    for (TFace &f : m.face) {
        const P3 n = vcg::TriangleNormal(f);
        EXPECT_GT(n[2], 0.f) << "a child turned over";
        EXPECT_TRUE(surface.FacesEveryClosest(vcg::Point3d::Construct(vcg::Barycenter(f)), vcg::Point3d::Construct(n))) << "a child still faces the sheet behind";
        EXPECT_EQ(f.Q(), 7.f);
        for (int k = 0; k < 3; ++k)
            if (f.IsFaceEdgeS(k)) {
                ++frontSides;
                EXPECT_EQ(f.P0(k)[1], 1.f);
                EXPECT_EQ(f.P1(k)[1], 1.f);
            }
        for (int k = 0; k < 3; ++k) EXPECT_NE(f.FFp(k), nullptr);
    }
    EXPECT_EQ(frontSides, 1) << "the front side was lost or copied";
}

TEST(FlippedFaceMend, ATriangleNoMoveMendsIsCollapsedWithTheTriangleAcrossItsSide)
{
    // the input: a 4 x 4 grid folded along x = 2 (flat for x <= 2, rising 3 per unit beyond: a
    // crease of 72 degrees); the output: the same grid with the crease vertex (2, 2) slid along
    // the crease past (2, 1), to y = 0.8, so the triangles between them turn over. It may not move
    // (on the crease) and every other vertex is on the front (every other edge selected), so no
    // move mends them: (2, 2) is collapsed into (2, 1) with a triangle across, the mesh stays a
    // manifold with valid face-face adjacency, and nothing is left turned over.
    TMesh input, m;
    MakeGrid(input, 4, 4.f);
    for (TVertex &v : input.vert)
        if (v.P()[0] > 2) v.P()[2] = 3 * (v.P()[0] - 2);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(input);
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, input);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg_ext::InputSurface<TMesh> surface(input);
    TVertex *u = At(m, 2, 2);
    ASSERT_NE(u, nullptr);
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k)
            if (f.V0(k) != u && f.V1(k) != u) f.SetFaceEdgeS(k);
    u->P() = P3(2, 0.8f, 0);
    auto turnedOver = [&]() {
        int n = 0;
        for (const TFace &f : m.face)
            if (!f.IsD() && !surface.FacesEveryClosest(vcg::Point3d::Construct(vcg::Barycenter(f)),
                                                       vcg::Point3d::Construct(vcg::TriangleNormal(f))))
                ++n;
        return n;
    };
    ASSERT_GT(turnedOver(), 0);
    const int faces = m.fn, verts = m.vn;

    const Mend::Stats st = Mend::Do(m, surface, 60);
    EXPECT_GE(st.collapsed, 1);
    EXPECT_EQ(st.left, 0);
    EXPECT_EQ(turnedOver(), 0);
    EXPECT_EQ(m.fn, faces - 2 * st.collapsed);
    EXPECT_EQ(m.vn, verts - st.collapsed);
    EXPECT_EQ(int(m.face.size()), m.fn) << "not compacted";
    EXPECT_EQ(st.removedPolygons.size(), size_t(2 * st.collapsed));
    ExpectValidAdjacency(m);
}

namespace {
// A flat 4 x 4 grid whose vertex (2, 2) is slid onto the middle of the side a b across one of its
// triangles (the `which`-th of the four whose a b is a unit side; `inside` of the side inside): that
// triangle becomes a needle (a sliver for a larger `inside`). `across`: what lies across a b;
// `quadAcross`: the triangle across is made half of a quad (faux cell diagonal).
struct NeedleGrid {
    TMesh input, m;
    TFace *needle = nullptr, *across = nullptr;
    int side = -1;

    NeedleGrid(bool quadAcross, int which = 0, float inside = 1e-5f)
    {
        MakeGrid(input, 4, 4.f, 0.f, 1, false);  // diagonals all one way: (2, 2)'s star is a convex hexagon
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, input);
        vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
        TVertex *v = At(m, 2, 2);
        int unitSides = 0;
        for (TFace &f : m.face)
            for (int i = 0; i < 3 && !needle; ++i)
                if (f.V(i) == v && vcg::Distance(f.P1(i), f.P2(i)) == 1.f && unitSides++ == which) needle = &f, side = (i + 1) % 3;
        across = needle->FFp(side);
        const P3 a = needle->P0(side), b = needle->P1(side), mid = (a + b) * 0.5f;
        v->P() = mid + (v->P() - mid) * inside;
        if (quadAcross)
            for (int e = 0; e < 3; ++e)
                if (vcg::Distance(across->P0(e), across->P1(e)) > 1.1f) {  // the cell's diagonal
                    across->SetF(e);
                    across->FFp(e)->SetF(across->FFi(e));
                }
    }
    // Triangles whose apex is nearer their longest side than `height` of it.
    int Needles(double height = 1e-3) const
    {
        int n = 0;
        for (const TFace &f : m.face) {
            if (f.IsD()) continue;
            double longest = 0;
            for (int e = 0; e < 3; ++e) longest = std::max(longest, double(vcg::Distance(f.cP0(e), f.cP1(e))));
            n += vcg::DoubleArea(f) < height * longest * longest;
        }
        return n;
    }
    int FauxSides() const
    {
        int n = 0;
        for (const TFace &f : m.face)
            for (int e = 0; e < 3; ++e) n += f.IsF(e);
        return n;
    }
};
}  // namespace

// A needle lying along its longest side (on a crease of the input its facing would be a coin flip)
// whose corners all lie on the front is flipped away with the polygon across that side, which its
// apex splits: two triangles, or a quad and a triangle when the triangle across is half of a quad.
// Counts, orientation and the quad are kept; with that side on the front too it stays. With a free
// corner it is collapsed instead (one vertex and two triangles fewer).
TEST(FlippedFaceMend, ANeedleIsFlippedAwayWithThePolygonAcrossItsLongestSide)
{
    // the four unit sides of the star: the quads across have their diagonal either way
    for (int which = 0; which < 8; ++which) {
        const bool quadAcross = which >= 4;
        NeedleGrid grid(quadAcross, which % 4);
        TFace *acrossChord = grid.needle->FFp(grid.side);
        for (TFace &f : grid.m.face)  // every corner on the front: no collapse
            for (int k = 0; k < 3; ++k)
                if (!f.IsF(k) && !(&f == grid.needle && k == grid.side) && !(&f == acrossChord && k == grid.needle->FFi(grid.side)))
                    f.SetFaceEdgeS(k);
        ASSERT_EQ(grid.Needles(), 1);
        const int faces = grid.m.fn, faux = grid.FauxSides();
        ASSERT_TRUE(Mend::HasNeedleTriangle(grid.m));
        vcg_ext::InputSurface<TMesh> surface(grid.input);
        const Mend::Stats st = Mend::Do(grid.m, surface, 60);
        EXPECT_EQ(st.needlesFlipped, 1) << (quadAcross ? "quad across, side " : "triangle across, side ") << which % 4;
        EXPECT_EQ(st.needlesRemoved, 1);
        EXPECT_EQ(st.collapsed, 0);
        EXPECT_EQ(grid.Needles(), 0);
        EXPECT_EQ(grid.m.fn, faces);
        EXPECT_EQ(grid.FauxSides(), faux) << "the quad across is still one quad";
        EXPECT_EQ(FacesTurnedOver(grid.m), 0);
        ASSERT_EQ(st.sameNormalAs.size(), 1u);
        for (TFace &f : grid.m.face)
            for (int k = 0; k < 3; ++k)
                if (f.FFp(k) != &f) {
                    EXPECT_EQ(f.FFp(k)->FFp(f.FFi(k)), &f) << "face-face adjacency not reciprocal";
                    EXPECT_EQ(f.IsF(k), f.FFp(k)->IsF(f.FFi(k))) << "a faux side on one face only";
                }
    }
    NeedleGrid onFront(false);  // its longest side on the front too: it stays
    for (TFace &f : onFront.m.face)
        for (int k = 0; k < 3; ++k) f.SetFaceEdgeS(k);
    vcg_ext::InputSurface<TMesh> surface(onFront.input);
    EXPECT_EQ(Mend::Do(onFront.m, surface, 60).needlesRemoved, 0);
    EXPECT_EQ(onFront.Needles(), 1);

    NeedleGrid free(false);  // no front: its apex is collapsed onto a corner
    const int faces = free.m.fn, vertices = free.m.vn;
    vcg_ext::InputSurface<TMesh> freeSurface(free.input);
    const Mend::Stats st = Mend::Do(free.m, freeSurface, 60);
    EXPECT_EQ(st.needlesRemoved, 1);
    EXPECT_EQ(st.collapsed, 1);
    EXPECT_EQ(free.Needles(), 0);
    EXPECT_EQ(free.m.fn, faces - 2);
    EXPECT_EQ(free.m.vn, vertices - 1);
    EXPECT_EQ(FacesTurnedOver(free.m), 0);
}

// A needle whose longest side is on the front (no flip) and whose short sides have half of a quad
// across (man, kept aside: a needle along a thin fin) is collapsed with that half: its free apex
// goes onto a corner, the quad's other half is left a triangle in its place (its diagonal no
// longer faux), the mesh stays a 2-manifold facing the input, the front side is kept. On each of the
// four unit sides of the star, the triangles across the short sides are made halves of quads with
// their cell's other triangle (one of the two: the other's cell diagonal is the needle's side).
TEST(FlippedFaceMend, ANeedleIsCollapsedWithHalfOfAQuadAcrossAShortSide)
{
    for (int which = 0; which < 4; ++which) {
        NeedleGrid grid(false, which);
        int quads = 0;
        for (int d = 1; d < 3; ++d) {
            TFace *t = grid.needle->FFp((grid.side + d) % 3);
            const TFace &original = grid.input.face[vcg::tri::Index(grid.m, t)];
            for (int e = 0; e < 3; ++e)
                if (vcg::Distance(original.cP0(e), original.cP1(e)) > 1.1f && t->FFp(e) != grid.needle && t->FFp(e) != t) {
                    t->SetF(e);
                    t->FFp(e)->SetF(t->FFi(e));
                    ++quads;
                }
        }
        ASSERT_EQ(quads, 1) << which;
        grid.needle->SetFaceEdgeS(grid.side);
        grid.needle->FFp(grid.side)->SetFaceEdgeS(grid.needle->FFi(grid.side));
        ASSERT_EQ(grid.Needles(), 1);
        const int faces = grid.m.fn, vertices = grid.m.vn, faux = grid.FauxSides();
        vcg_ext::InputSurface<TMesh> surface(grid.input);
        const Mend::Stats st = Mend::Do(grid.m, surface, 60);
        EXPECT_EQ(st.needlesRemoved, 1) << which;
        EXPECT_EQ(st.collapsed, 1);
        EXPECT_EQ(st.needlesFlipped, 0);
        EXPECT_EQ(st.quadsHalved, 1);
        EXPECT_EQ(st.removedPolygons.size(), 1u) << "the quad's half left keeps its place";
        EXPECT_EQ(grid.Needles(), 0);
        EXPECT_EQ(grid.m.fn, faces - 2);
        EXPECT_EQ(grid.m.vn, vertices - 1);
        EXPECT_EQ(grid.FauxSides(), faux - 2);
        EXPECT_EQ(FacesTurnedOver(grid.m), 0);
        int front = 0;
        for (TFace &f : grid.m.face)
            for (int k = 0; k < 3; ++k) {
                front += f.IsFaceEdgeS(k);
                if (f.FFp(k) == &f) continue;
                EXPECT_EQ(f.FFp(k)->FFp(f.FFi(k)), &f) << "face-face adjacency not reciprocal";
                EXPECT_EQ(f.IsF(k), f.FFp(k)->IsF(f.FFi(k))) << "a faux side on one face only";
                EXPECT_FALSE(f.IsB(k)) << "an inner side flagged as border";
            }
        EXPECT_EQ(front, 2) << "the front side kept, on both its faces";
    }
}

// A plate under a ridge: an upper sheet (a roof, z = 0.3 - 0.3 |x|, facing up) and a lower sheet
// kPlate below it (facing down). A triangle with every corner on the upper sheet but turned down
// is upside down; its centroid lies under the chord, nearer the lower sheet (0.134 against 0.153),
// so the centroid's judge (the quality report's, evalquad's) reads it facing the input.
TEST(FlippedFaceMend, AFaceUpsideDownOnAThinPlateIsFoundByItsCorners)
{
    const float kPlate = 0.02f;
    TMesh plate;
    Build(plate,
          {{-1, -1, 0}, {0, -1, 0.3f}, {1, -1, 0}, {-1, 2, 0}, {0, 2, 0.3f}, {1, 2, 0},
           {-1, -1, -kPlate}, {0, -1, 0.3f - kPlate}, {1, -1, -kPlate}, {-1, 2, -kPlate}, {0, 2, 0.3f - kPlate}, {1, 2, -kPlate}},
          {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {6, 10, 7}, {6, 9, 10}, {7, 11, 8}, {7, 10, 11}});
    vcg_ext::InputSurface<TMesh> input(plate);
    typedef vcg_ext::qmorph::OutputPolygons Polygons;
    const D3 a(-0.8, 0, 0.06), b(0.8, 0, 0.06), ridge(0, 1, 0.3);
    const D3 down[3] = {a, ridge, b}, up[3] = {a, b, ridge};
    EXPECT_LT(vcg_ext::VectorArea(down, 3)[2], 0);
    EXPECT_TRUE(Polygons::FacesInput(down, 3, input)) << "the centroid's judge is fooled";
    EXPECT_TRUE(Polygons::CornersFaceAway(down, 3, input));
    EXPECT_FALSE(Polygons::FacesInput(up, 3, input)) << "turned up, its centroid is judged on the lower sheet";
    EXPECT_FALSE(Polygons::CornersFaceAway(up, 3, input));
    // a corner on a crease sharper than 90 degrees faces either way: not counted as facing away
    TMesh knife;
    Build(knife, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0.04f}, {0, 1, 0.04f}},
          {{0, 2, 1}, {0, 3, 2}, {4, 1, 2}, {4, 2, 5}});
    vcg_ext::InputSurface<TMesh> onKnife(knife);
    const D3 edgeAndLower[3] = {D3(1, 0.2, 0), D3(1, 0.8, 0), D3(0.5, 0.5, 0)};  // turned up on the lower sheet
    EXPECT_FALSE(Polygons::CornersFaceAway(edgeAndLower, 3, onKnife));
}

// With a larger needle height (All quads, before its split) a sliver goes as a needle does: the
// grid's vertex slid to 3% of a side's length from it is no needle at the default height (nothing
// happens), and at 5% it is removed, leaving no triangle thinner than that, none turned over; with
// every corner on the front, by a flip of its longest side.
TEST(FlippedFaceMend, ASliverIsRemovedAtALargerNeedleHeight)
{
    const double kSliver = 0.05;
    for (bool front : {false, true}) {
        NeedleGrid grid(false, 0, 0.03f);
        if (front) {
            TFace *acrossChord = grid.needle->FFp(grid.side);
            for (TFace &f : grid.m.face)
                for (int k = 0; k < 3; ++k)
                    if (!(&f == grid.needle && k == grid.side) && !(&f == acrossChord && k == grid.needle->FFi(grid.side))) f.SetFaceEdgeS(k);
        }
        ASSERT_EQ(grid.Needles(), 0);
        ASSERT_EQ(grid.Needles(kSliver), 1);
        vcg_ext::InputSurface<TMesh> surface(grid.input);
        EXPECT_EQ(Mend::Do(grid.m, surface, 60).needlesRemoved, 0);
        EXPECT_EQ(grid.Needles(kSliver), 1);
        const Mend::Stats st = Mend::Do(grid.m, surface, 60, false, kSliver);
        EXPECT_EQ(st.needlesRemoved, 1) << (front ? "front" : "free");
        EXPECT_EQ(front ? st.needlesFlipped : st.collapsed, 1);
        EXPECT_EQ(grid.Needles(kSliver), 0);
        EXPECT_EQ(FacesTurnedOver(grid.m), 0);
    }
}

// The four free corners of a cell of a grid of quads dragged right and up by up to about one cell:
// a tangle (three triangles, halves of quads, turned over) in which no single move turns a face
// back without turning another over: without the untangling, all three stay turned over. The
// corners are moved one after the other wherever the number of bad faces around them falls, until
// none is left; every corner stays on the input plane and every quad convex.
TEST(FlippedFaceMend, ATangleOfQuadsIsUndoneCornerByCorner)
{
    TMesh input, m;
    MakeGrid(input, 6, 6.f, 0.f, 1, false);
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, input);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    for (TFace &f : m.face)  // the cell diagonals are faux: unit quads
        for (int k = 0; k < 3; ++k)
            if (f.P0(k)[0] != f.P1(k)[0] && f.P0(k)[1] != f.P1(k)[1]) f.SetF(k);
    vcg_ext::InputSurface<TMesh> surface(input);
    TVertex *a = At(m, 2, 2), *b = At(m, 3, 2), *c = At(m, 3, 3), *d = At(m, 2, 3);
    a->P() = P3(2.92978811f, 2.211514f, 0);
    b->P() = P3(4.09058952f, 2.95451307f, 0);
    c->P() = P3(4.08546734f, 3.9396739f, 0);
    d->P() = P3(2.29157352f, 3.75800991f, 0);
    ASSERT_EQ(FacesTurnedOver(m), 3);  // triangles: halves of quads turned over or folded

    const Mend::Stats st = Mend::Do(m, surface, 60);
    EXPECT_EQ(FacesTurnedOver(m), 0);
    EXPECT_EQ(st.left, 0);
    for (const TVertex &v : m.vert) EXPECT_EQ(v.cP()[2], 0.f) << "a vertex left the input plane";
    const vcg_ext::PolygonMesh pm = vcg_ext::QuadQuality::FromFauxMesh(m);
    for (const std::vector<int> &f : pm.faces) {
        ASSERT_EQ(f.size(), 4u);
        const D3 q[4] = {pm.points[f[0]], pm.points[f[1]], pm.points[f[2]], pm.points[f[3]]};
        EXPECT_GT(vcg_ext::ScaledJacobian(q, D3(0, 0, 1)), 0) << "a quad left concave or turned";
    }
}

namespace {
// Polygons of m (faux-edge quads) turned away from an input triangle closest to their centroid, or
// quads folded or not convex on the input's normal under them: what the last check mends.
int BadPolygons(TMesh &m, vcg_ext::InputSurface<TMesh> &surface)
{
    const vcg_ext::PolygonMesh pm = vcg_ext::QuadQuality::FromFauxMesh(m);
    int bad = 0;
    for (const std::vector<int> &f : pm.faces) {
        D3 q[4];
        for (size_t k = 0; k < f.size(); ++k) q[k] = pm.points[f[k]];
        const int n = int(f.size());
        const D3 area = vcg_ext::VectorArea(q, n);
        D3 centroid(0, 0, 0);
        for (int k = 0; k < n; ++k) centroid += q[k] / double(n);
        bool good = area.Norm() > 0 && surface.FacesEveryClosest(centroid, area);
        if (good && n == 4) good = !vcg_ext::IsFolded(q) && vcg_ext::ScaledJacobian(q, surface.NormalUnder(centroid, area / area.Norm())) > 0;
        bad += !good;
    }
    return bad;
}

}  // namespace

TEST(FlippedFaceMend, AQuadSunkNearerTheSheetBehindIsLiftedPastItsOwnSheet)
{
    // the output: unit quads on the upper sheet, the four corners of the quad [2,3]^2 sunk to
    // z = -0.07, so its centroid is nearer the lower sheet: turned over. No corner put back on
    // the upper sheet alone mends it (its centroid would still be at z = -0.0525). Its corners are
    // moved together toward the upper sheet's point nearest its centroid and past it: by 1.5 times
    // the centroid's distance (kLifts' first), to z = -0.07 + 0.105 = 0.035, off the input by a
    // third of the gap; every face then faces the input and the other vertices stay.
    TMesh upper, input, m;
    MakeTwoSheets(upper, input, 6);
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, upper);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    for (TFace &f : m.face)  // the cell diagonals are faux: unit quads
        for (int k = 0; k < 3; ++k)
            if (f.P0(k)[0] != f.P1(k)[0] && f.P0(k)[1] != f.P1(k)[1]) f.SetF(k);
    vcg_ext::InputSurface<TMesh> surface(input);
    const std::vector<TVertex *> sunk{At(m, 2, 2), At(m, 3, 2), At(m, 3, 3), At(m, 2, 3)};
    for (TVertex *v : sunk) v->P()[2] = -0.07f;
    ASSERT_EQ(BadPolygons(m, surface), 1);

    const Mend::Stats st = Mend::Do(m, surface, 60);
    EXPECT_EQ(BadPolygons(m, surface), 0);
    EXPECT_EQ(st.left, 0);
    EXPECT_EQ(st.mended, 1);
    EXPECT_EQ(m.fn, 72);
    for (const TVertex &v : m.vert) {
        if (std::find(sunk.begin(), sunk.end(), &v) != sunk.end()) {
            EXPECT_NEAR(v.cP()[2], 0.035, 1e-6) << "a sunk corner not lifted past the upper sheet by 1.5 times the centroid's depth";
        } else {
            EXPECT_EQ(v.cP()[2], 0.f) << "a vertex of another face moved";
        }
    }
}

TEST(FlippedFaceMend, AQuadNoMoveMendsIsCollapsedAlongItsDiagonal)
{
    // the input: a 6 x 6 grid folded along y = x (flat for x <= y, rising 3 per unit beyond: a
    // crease of 77 degrees along the cell diagonals), with (3, 2) and (2, 3) pushed out by 0.3;
    // the output: the same, cells off the crease are quads, those on it triangles but [2,3]^2,
    // a quad, with (2, 2) slid along the crease to (2.9, 2.9): that quad turns concave (its corner
    // there reflex), the faces around stay convex. Its corners (2, 2) and (3, 3) are on the crease,
    // every other vertex on the front (every side not at (2, 2) selected): no move mends it. Its diagonal is
    // collapsed, (2, 2) onto (3, 3) (the other way (3, 3) is on the front): one quad and one
    // vertex fewer, a manifold with reciprocal face-face adjacency, every front edge kept (the side
    // (2, 2) - (3.3, 2) glued to the front side (3.3, 2) - (3, 3) is front), nothing left bad.
    TMesh input, m;
    MakeGrid(m, 6, 6.f, 0.f, 1, false);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    TVertex *u = At(m, 2, 2), *w = At(m, 3, 3);
    ASSERT_TRUE(u && w);
    for (TFace &f : m.face)  // on the flat grid: which sides are faux, which front
        for (int k = 0; k < 3; ++k) {
            const bool diagonal = f.P0(k)[0] != f.P1(k)[0] && f.P0(k)[1] != f.P1(k)[1];
            const bool onCrease = f.P0(k)[0] == f.P0(k)[1] && f.P1(k)[0] == f.P1(k)[1];
            const bool atU = f.V0(k) == u || f.V1(k) == u;
            if (diagonal && (!onCrease || (atU && (f.V0(k) == w || f.V1(k) == w)))) f.SetF(k);
            else if (!atU) f.SetFaceEdgeS(k);
        }
    At(m, 3, 2)->P()[0] = 3.3f;
    At(m, 2, 3)->P()[1] = 3.3f;
    for (TVertex &v : m.vert) v.P()[2] = 3 * std::max(0.f, v.P()[0] - v.P()[1]);
    vcg::tri::UpdateNormal<TMesh>::PerFaceNormalized(m);
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(input, m);
    vcg_ext::InputSurface<TMesh> surface(input);
    u->P() = P3(2.9f, 2.9f, 0);
    ASSERT_EQ(BadPolygons(m, surface), 1);
    std::vector<std::pair<P3, P3>> frontBefore;  // as points, (2, 2) read as (3, 3)
    auto renamed = [&](const TVertex *v) { return v == u ? w->cP() : v->cP(); };
    for (const TFace &f : m.face)
        for (int k = 0; k < 3; ++k)
            if (f.IsFaceEdgeS(k)) frontBefore.push_back({renamed(f.cV0(k)), renamed(f.cV1(k))});
    const int faces = m.fn, verts = m.vn;

    const Mend::Stats st = Mend::Do(m, surface, 60);
    EXPECT_EQ(st.quadsCollapsed, 1);
    EXPECT_EQ(st.left, 0);
    EXPECT_EQ(BadPolygons(m, surface), 0);
    EXPECT_EQ(m.fn, faces - 2);
    EXPECT_EQ(m.vn, verts - 1);
    EXPECT_EQ(int(m.face.size()), m.fn) << "not compacted";
    ASSERT_EQ(st.removedPolygons.size(), 1u);
    ExpectValidAdjacency(m);
    for (const auto &e : frontBefore) {
        if (e.first == e.second) continue;  // a side of the collapsed quad
        bool found = false;
        for (const TFace &f : m.face)
            for (int k = 0; k < 3; ++k)
                found = found || (f.IsFaceEdgeS(k) && ((f.cP0(k) == e.first && f.cP1(k) == e.second) || (f.cP0(k) == e.second && f.cP1(k) == e.first)));
        EXPECT_TRUE(found) << "front edge (" << e.first[0] << ", " << e.first[1] << ") - (" << e.second[0] << ", " << e.second[1] << ") lost";
    }
}

TEST(FlippedFaceMend, AFaceWhoseChildWouldTurnOverIsMendedBeforeTheSplit)
{
    // two sheets 0.1 apart (upper z = 0 facing +z, lower z = -0.1 facing -z); the quad (1, 1),
    // (3, 1), (3, 3), (1, 3) with (3, 3) on the lower sheet: its centroid (z = -0.025) is nearer
    // the upper one, so it faces the input, and only one corner faces away; but the all-quads
    // split's child at (3, 3) has its centroid at z = -(0.1 + 0.05 + 0.025 + 0.05) / 4 = -0.05625,
    // nearer the lower sheet: it would turn over.
    TMesh upper, input, m;
    MakeTwoSheets(upper, input, 6);
    vcg_ext::InputSurface<TMesh> surface(input);
    typedef vcg_ext::qmorph::OutputPolygons Polygons;
    const D3 bridging[4] = {D3(1, 1, 0), D3(3, 1, 0), D3(3, 3, -0.1), D3(1, 3, 0)};
    const D3 flat[4] = {D3(1, 1, 0), D3(3, 1, 0), D3(3, 3, 0), D3(1, 3, 0)};
    EXPECT_TRUE(Polygons::FacesInput(bridging, 4, surface)) << "the centroid's judge is fooled";
    EXPECT_FALSE(Polygons::CornersFaceAway(bridging, 4, surface));
    EXPECT_TRUE(Polygons::ChildFacesAway(bridging, 4, surface));
    EXPECT_FALSE(Polygons::ChildFacesAway(flat, 4, surface));

    // the same on the output before the split: a grid of unit quads on the upper sheet with (3, 3)
    // on the lower one; each of its four quads is judged right at its centroid (z = -0.025), so
    // only the check of the children (byCorners) puts it back on the upper sheet
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, upper);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    for (TFace &f : m.face)  // the cell diagonals are faux: unit quads
        for (int k = 0; k < 3; ++k)
            if (f.P0(k)[0] != f.P1(k)[0] && f.P0(k)[1] != f.P1(k)[1]) f.SetF(k);
    TVertex *sunk = At(m, 3, 3);
    sunk->P()[2] = -0.1f;
    ASSERT_EQ(BadPolygons(m, surface), 0);
    TMesh judgedByCentroid;
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(judgedByCentroid, m);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(judgedByCentroid);
    EXPECT_EQ(Mend::Do(judgedByCentroid, surface, 60).mended, 0);

    const Mend::Stats st = Mend::Do(m, surface, 60, true);
    EXPECT_GE(st.mended, 1);
    EXPECT_EQ(st.left, 0);
    EXPECT_FLOAT_EQ(sunk->P()[2], 0.f) << "the corner is not back on the upper sheet";
}
