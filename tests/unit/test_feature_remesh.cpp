// Q-Morph with its re-meshing first (Params::targetEdgeLength > 0, qmorph/feature_remesh.h) on
// CAD-style input: closed meshes made of long thin triangles (STL-like fans and strips), and
// Debian's anchor. Every figure is measured independently of the product: the element count
// against area / L^2, triangles left, faces flipped against a copy of the input (grid-based closest
// triangle, quad_checks.h), the front as chains of selected output edges, topology, Hausdorff.
// Last, the node-move guard of the Q-Morph stages (PatchStage::TryMove / SmoothNode) on a star
// whose Laplacian target would turn faces over on the input surface, and the swap guard
// (MixedMesh::CanFlip) against the input under a re-meshed patch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "quad_checks.h"
#include "test_mesh.h"
#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/qmorph.h>
#include <vcg_ext/qmorph/patch_stage.h>

using namespace qmf_test;
typedef vcg_ext::QMorph<TMesh> QM;

namespace {

// Re-meshing may coarsen a front that runs over smooth surface: its output vertices stay on the
// input front (within this fraction of the diagonal) and its edges within this fraction of L of it
// (ShortEdgeCollapse's chord tolerance). Along sharp edges the front must stay exact.
constexpr double kOnCurve = 1e-5;
constexpr double kChord = 0.1 + 1e-6;

// Longest edge over shortest altitude (an equilateral triangle: 2 / sqrt(3)).
double AspectRatio(const TFace &f)
{
    double longest = 0;
    for (int k = 0; k < 3; ++k) longest = std::max(longest, double((f.cP((k + 1) % 3) - f.cP(k)).Norm()));
    const double doubleArea = vcg::Norm((f.cP(1) - f.cP(0)) ^ (f.cP(2) - f.cP(0)));
    return doubleArea > 0 ? longest * longest / doubleArea : 1e30;
}

// Fraction of the faces thinner than `ratio`, and the median aspect ratio.
void SliverStats(const TMesh &m, double ratio, double &fraction, double &median)
{
    std::vector<double> a;
    for (auto &f : m.face)
        if (!f.IsD()) a.push_back(AspectRatio(f));
    std::sort(a.begin(), a.end());
    fraction = double(a.end() - std::upper_bound(a.begin(), a.end(), ratio)) / a.size();
    median = a[a.size() / 2];
}

// Triangles of a convex closed mesh turned to face away from `centre` (outward).
void BuildOutward(TMesh &m, const std::vector<P3> &v, std::vector<std::array<int, 3>> f, const P3 &centre)
{
    for (auto &t : f) {
        const P3 n = (v[t[1]] - v[t[0]]) ^ (v[t[2]] - v[t[0]]);
        if (n * ((v[t[0]] + v[t[1]] + v[t[2]]) / 3.f - centre) < 0) std::swap(t[1], t[2]);
    }
    Build(m, v, f);
}

// A CAD export of a box [0,a] x [0,b] x [0,b]: the 4 long edges (along x) cut into k pieces, each
// long side one zigzag strip of k-wide, b-high slivers between them, the two square ends 2
// triangles each.
void MakeSliverBox(TMesh &m, float a, float b, int k)
{
    std::vector<P3> v;
    const float yz[4][2] = {{0, 0}, {b, 0}, {b, b}, {0, b}};  // the 4 long edges, around the x axis
    for (int e = 0; e < 4; ++e)
        for (int i = 0; i <= k; ++i) v.push_back(P3(a * i / k, yz[e][0], yz[e][1]));
    auto id = [k](int e, int i) { return (e % 4) * (k + 1) + i; };
    std::vector<std::array<int, 3>> f;
    for (int e = 0; e < 4; ++e)
        for (int i = 0; i < k; ++i) {
            f.push_back({id(e, i), id(e, i + 1), id(e + 1, i)});
            f.push_back({id(e, i + 1), id(e + 1, i + 1), id(e + 1, i)});
        }
    for (int end : {0, k}) {
        f.push_back({id(0, end), id(1, end), id(2, end)});
        f.push_back({id(0, end), id(2, end), id(3, end)});
    }
    BuildOutward(m, v, f, P3(a / 2, b / 2, b / 2));
}

// A CAD export of a cylinder (axis z, radius r, height h, n slices): the side one strip of
// full-height slivers, each cap a fan from one rim vertex (as STL writers triangulate a polygon).
void MakeSliverCylinder(TMesh &m, float r, float h, int n)
{
    std::vector<P3> v;
    for (int ring = 0; ring < 2; ++ring)
        for (int i = 0; i < n; ++i) {
            const double t = 2 * M_PI * i / n;
            v.push_back(P3(float(r * std::cos(t)), float(r * std::sin(t)), ring ? h : 0.f));
        }
    std::vector<std::array<int, 3>> f;
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        f.push_back({i, j, n + j});
        f.push_back({i, n + j, n + i});
    }
    for (int ring = 0; ring < 2; ++ring)
        for (int i = 1; i + 1 < n; ++i) f.push_back({ring * n, ring * n + i, ring * n + i + 1});
    BuildOutward(m, v, f, P3(0, 0, h / 2));
}

struct Figures {
    int quads = 0, triangles = 0;
    double elements = 0, expected = 0, triangleFraction = 0, hausdorff = 0;
    int flipped = 0, ambiguous = 0, folded = 0;
    long chainMismatches = 0, curveMismatches = 0;
};

// Q-Morph with re-meshing at target length L on `m` (its front: the selected face-edges), and the
// checks every such run must pass: no error, element count (quads + triangles / 2) within 30% of
// area / L^2, at most 2% triangles, no face flipped against the input, the front as chains of
// selected output edges, a closed 2-manifold with the input's Euler characteristic. Prints the
// figures.
Figures RemeshAndCheck(TMesh &m, double L, const std::string &name)
{
    Figures fig;
    TMesh input;  // taken before Apply: the reference surface of the independent checks
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(input, m);
    vcg::tri::UpdateBounding<TMesh>::Box(input);
    const auto in = vcg_ext::MeshChecks<TMesh>::Inspect(input);
    EXPECT_TRUE(in.IsClosed() && in.IsTwoManifold() && in.IsOriented()) << name << ": the input must be a clean closed mesh";
    const std::vector<PosEdge> front = EdgesByPosition(input, true);
    EXPECT_FALSE(front.empty());
    const double area = TotalArea(input);

    QM::Params p;
    p.targetEdgeLength = L;
    const QM::Result r = QM::Apply(m, p);
    EXPECT_EQ(r.error, "") << name;
    if (!r.error.empty()) return fig;

    fig.quads = r.quads;
    fig.triangles = r.triangles;
    fig.elements = r.quads + 0.5 * r.triangles;
    fig.expected = area / (L * L);
    fig.triangleFraction = double(r.triangles) / std::max(1, r.quads + r.triangles);

    const auto out = vcg_ext::MeshChecks<TMesh>::Inspect(m);
    EXPECT_TRUE(out.IsClosed()) << name << ": " << out.boundaryEdges << " boundary edges";
    EXPECT_EQ(out.nonManifoldEdges, 0) << name;
    EXPECT_EQ(out.nonManifoldVertices, 0) << name;
    EXPECT_TRUE(out.IsOriented()) << name;
    EXPECT_EQ(out.degenerateFaces, 0) << name;
    EXPECT_EQ(out.components, in.components) << name;

    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    const vcg_ext::PolygonMesh pm = vcg_ext::QuadQuality::FromFauxMesh(m);
    EXPECT_EQ(int(pm.faces.size()), r.quads + r.triangles) << name;
    EXPECT_EQ(EulerCharacteristic(pm), long(in.EulerCharacteristic())) << name << ": the topology changed";
    const FlipCount flips = FlippedFaces(pm, input);
    fig.flipped = flips.flipped;
    fig.ambiguous = flips.ambiguous;
    fig.folded = flips.folded;
    const std::vector<PosEdge> frontAfter = EdgesByPosition(m, true);
    fig.chainMismatches = FrontChainMismatches(front, frontAfter);
    fig.curveMismatches = FrontCurveMismatches(front, frontAfter, kOnCurve * input.bbox.Diag(), kChord * L);
    fig.hausdorff = Hausdorff(m, input) / input.bbox.Diag();

    std::printf("%s: L %g, area / L^2 %.0f, quads %d, triangles %d, elements %.1f (%+.1f%%), triangles %.2f%% of the faces, "
                "flipped %d (ambiguous %d), folded %d, front chain mismatches %ld (as curves %ld), Hausdorff %.3f%% of the diagonal, "
                "min SJ %.3f, mean SJ %.3f; %d -> %d triangles re-meshed, front %d -> %d edges\n",
                name.c_str(), L, fig.expected, fig.quads, fig.triangles, fig.elements, 100 * (fig.elements / fig.expected - 1),
                100 * fig.triangleFraction, fig.flipped, fig.ambiguous, fig.folded, fig.chainMismatches, fig.curveMismatches, 100 * fig.hausdorff,
                r.quality.minJacobian, r.quality.meanJacobian, r.remesh.facesBefore, r.remesh.facesAfter,
                r.remesh.frontEdgesBefore, r.remesh.frontEdgesAfter);

    EXPECT_NEAR(fig.elements, fig.expected, 0.3 * fig.expected) << name << ": quads + triangles / 2 against area / L^2";
    EXPECT_LE(fig.triangleFraction, 0.02) << name << ": " << r.triangles << " triangles of " << r.quads + r.triangles << " faces";
    EXPECT_EQ(fig.flipped, 0) << name << ": faces upside down on the input surface";
    EXPECT_EQ(fig.folded, 0) << name << ": quads folded across both diagonals";
    EXPECT_EQ(r.quality.flippedFaces, 0) << name << ": the core's own count";
    EXPECT_EQ(r.quality.invertedQuads, 0) << name;
    EXPECT_EQ(fig.chainMismatches, 0) << name << ": the front is not exactly chains of selected output edges";
    return fig;
}

// The CAD-style test meshes must really be slivers: over 95% of the faces with aspect ratio above 20.
void AssertMadeOfSlivers(const TMesh &m)
{
    double thin = 0, median = 0;
    SliverStats(m, 20, thin, median);
    ASSERT_GT(thin, 0.95) << "the test mesh must be made of slivers (median aspect ratio " << median << ")";
}

}  // namespace

// A 2 x 1 x 1 box whose long sides are strips of 1-high, 0.04-wide slivers (aspect ratio 25),
// re-meshed at the front's own spacing.
TEST(FeatureRemesh, SliverBoxBecomesQuads)
{
    TMesh m;
    MakeSliverBox(m, 2.f, 1.f, 50);
    ASSERT_NO_FATAL_FAILURE(AssertMadeOfSlivers(m));
    ASSERT_EQ(SelectCreases(m, 45), 4 * 50 + 8) << "the 12 box edges: 4 in 50 pieces, 8 whole";
    RemeshAndCheck(m, 0.04, "sliver box");
}

// A cylinder (radius 1, height 3, 64 slices) exported CAD-style: full-height side slivers (aspect
// ratio about 30) and caps fanned from one rim vertex; front: the two rims.
TEST(FeatureRemesh, SliverCylinderBecomesQuads)
{
    TMesh m;
    MakeSliverCylinder(m, 1.f, 3.f, 64);
    ASSERT_NO_FATAL_FAILURE(AssertMadeOfSlivers(m));
    ASSERT_EQ(SelectCreases(m, 45), 2 * 64) << "the two rims";
    RemeshAndCheck(m, 2 * M_PI / 64, "sliver cylinder");
}

// Debian's anchor (libcgal-demo, 1,050 triangles, genus 4): a coarse CAD mesh, its creases over 40
// degrees selected as the front, re-meshed at 1% of its diagonal; it must also stay on its surface.
TEST(FeatureRemesh, AnchorAtOnePercentOfItsDiagonal)
{
    TMesh m;
    ASSERT_TRUE(LoadOff(m, MeshDir() + "/anchor.off"));
    ASSERT_GT(SelectCreases(m, 40), 100);
    const Figures fig = RemeshAndCheck(m, 0.01 * m.bbox.Diag(), "anchor");
    EXPECT_LE(fig.hausdorff, 0.005) << "Hausdorff distance to the input, fraction of the diagonal";
}

// A thin plate, 2 x 2 x 0.004, each side an 8 x 8 grid (MakeCube flattened): its rim's triangles
// are needles (0.25 long, 0.0005 high: under the re-meshing's 0.05 L at L = 0.04), each in the plane
// of its neighbour across the grid's diagonal. Only the top rim is the front; the bottom rim and
// the four short vertical edges are creases the re-meshing must keep (a needle in its
// neighbour's plane has the surface's normal): dropped as a needle's creases, the rim's corners
// were cut by faces turned over (the whole pipeline on such a plate: 10 faces flipped).
TEST(FeatureRemesh, ThinPlateRimOfNeedlesKeepsItsCreases)
{
    const float thickness = 0.004f;
    TMesh m;
    MakeCube(m, 8);
    for (auto &v : m.vert) v.P()[2] *= thickness / 2;
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    ASSERT_EQ(SelectCreases(m, 45), 12 * 8) << "the 12 plate edges, 8 pieces each";
    int front = 0;
    for (auto &f : m.face)
        for (int k = 0; k < 3; ++k) {
            const bool topRim = f.P0(k)[2] == thickness / 2 && f.P1(k)[2] == thickness / 2;
            if (f.IsFaceEdgeS(k) && !topRim) f.ClearFaceEdgeS(k);
            front += f.IsFaceEdgeS(k) ? 1 : 0;
        }
    ASSERT_EQ(front, 2 * 4 * 8) << "the top rim, selected on both sides";
    const double L = 0.04;
    int needles = 0;  // height on the longest side (longest / AspectRatio) under 0.05 L
    for (const auto &f : m.face) {
        double longest = 0;
        for (int k = 0; k < 3; ++k) longest = std::max(longest, double((f.cP((k + 1) % 3) - f.cP(k)).Norm()));
        needles += longest / AspectRatio(f) < 0.05 * L ? 1 : 0;
    }
    ASSERT_EQ(needles, 4 * 8 * 8 * 2) << "the rim's triangles, and only they, must be needles at L";
    const Figures fig = RemeshAndCheck(m, L, "thin plate");
    EXPECT_LE(fig.hausdorff, 0.005) << "Hausdorff distance to the input, fraction of the diagonal";
}

namespace {

using vcg_ext::qmorph::MixedMesh;
using vcg_ext::qmorph::PatchContext;
using vcg_ext::qmorph::PatchParams;
using vcg_ext::qmorph::PatchStage;
typedef vcg_ext::SurfaceProjector::P3 D3;

// The stages' move primitives, opened for the test.
class MoveProbe : public PatchStage
{
public:
    explicit MoveProbe(PatchContext &c) : PatchStage(c) {}
    using PatchStage::SmoothNode;
    using PatchStage::TryMove;
};

// Normal of the triangle of nodes (a b c) with node `v` put at `at`.
D3 NormalWith(const MixedMesh &m, int a, int b, int c, int v, const D3 &at)
{
    auto p = [&](int x) { return x == v ? at : m.pos[x]; };
    return (p(b) - p(a)) ^ (p(c) - p(a));
}

}  // namespace

// A free node v at the origin of the plane z = 0, its star a polygon with a slit reaching in from
// the right (tip at (0.5, 0)): v sees every edge, but the mean of its neighbours, (2.07, 0), lies in
// the slit, where the two triangles at the tip turn over on the input surface. Laplacian smoothing
// (SmoothNode) and a direct TryMove there must both be refused; a fair small move is accepted.
TEST(FeatureRemesh, NodeMoveThatWouldTurnAFaceOverIsRefused)
{
    // the input surface: the plane z = 0 over [-2, 5] x [-2, 2], two triangles, normal +z
    vcg_ext::SurfaceProjector surface;
    surface.Build({D3(-2, -2, 0), D3(5, -2, 0), D3(5, 2, 0), D3(-2, 2, 0)}, {{{0, 1, 2}}, {{0, 2, 3}}});
    // the working mesh on it: node 0 is v, 1..7 its star counter-clockwise
    const std::vector<D3> pts{D3(0, 0, 0),  D3(-1, -1, 0), D3(4, -1, 0), D3(4, -0.5, 0),
                              D3(0.5, 0, 0), D3(4, 0.5, 0), D3(4, 1, 0),  D3(-1, 1, 0)};
    std::vector<std::array<int, 3>> tris;
    for (int i = 1; i <= 7; ++i) tris.push_back({0, i, i % 7 + 1});
    MixedMesh m;
    m.Build(pts, tris);
    ASSERT_FALSE(m.vertFixed[0]) << "v is inside the patch: free to move";
    for (auto &t : tris) ASSERT_GT(NormalWith(m, t[0], t[1], t[2], -1, D3(0, 0, 0)) * D3(0, 0, 1), 0) << "the star starts well oriented";

    std::vector<int> home;
    PatchParams params;
    PatchContext context(m, surface, home, params);
    MoveProbe probe(context);

    // Sanity: the Laplacian target, and that the unchecked move would turn the triangles at the slit's tip over.
    D3 target(0, 0, 0);
    for (int i = 1; i <= 7; ++i) target += pts[i];
    target /= 7.0;
    ASSERT_NEAR(target[0], 14.5 / 7, 1e-12);
    ASSERT_NEAR(target[1], 0, 1e-12);
    int turnedOver = 0;
    for (auto &t : tris) turnedOver += NormalWith(m, t[0], t[1], t[2], 0, target) * surface.Normal(0) < 0;
    ASSERT_EQ(turnedOver, 2) << "at the target, (v, (4, -0.5), tip) and (v, tip, (4, 0.5)) face down";

    probe.SmoothNode(0);
    EXPECT_EQ(m.pos[0], pts[0]) << "smoothing moved v to (" << m.pos[0][0] << ", " << m.pos[0][1] << ")";
    EXPECT_FALSE(probe.TryMove(0, target)) << "the move to the Laplacian target must be refused";
    EXPECT_EQ(m.pos[0], pts[0]);
    EXPECT_FALSE(probe.TryMove(0, D3(1.0, 0.0, 0.3))) << "nor past the tip, from above the surface";
    EXPECT_EQ(m.pos[0], pts[0]);
    for (int f = 0; f < m.FaceCount(); ++f)
        EXPECT_GT(m.FaceNormal(f) * surface.Normal(0), 0) << "face " << f << " is turned over on the input surface";

    // The guard is not a blanket refusal: a small fair move (off the surface: projected back) is kept.
    // (away from the tip, so the two thin triangles there get no worse than they are)
    EXPECT_TRUE(probe.TryMove(0, D3(-0.2, 0, 0.2)));
    EXPECT_NEAR(m.pos[0][0], -0.2, 1e-12);
    EXPECT_NEAR(m.pos[0][1], 0, 1e-12);
    EXPECT_NEAR(m.pos[0][2], 0, 1e-12) << "projected onto the input surface";
}

// The flip guard of the front advance (MixedMesh::CanFlip) under a re-meshed patch, where the
// patch's own surface is not the input (feline_100k re-meshed at 1% of its diagonal: a swap between
// three nearly collinear front nodes made a sliver that faced the re-meshed surface, walked from a
// node's home, and was upside down on the input under it). Two triangles (a b c) and (b a d) on the
// patch's surface, the plane z = 0; a sits just off the chord c-d and 0.05 above the plane, so the
// swap's triangle (c a d) is a sliver standing up toward +y (normal about (0, 0.93, 0.37)). The
// input under the patch (the judge) leans toward -y, (0, -0.6, 0.8): the swap must be refused; with
// the input agreeing with the patch it must not.
TEST(FeatureRemesh, SwapIsJudgedAgainstTheInputNotTheRemeshedPatch)
{
    vcg_ext::SurfaceProjector surface;  // the re-meshed patch's surface: the plane z = 0, normal +z
    surface.Build({D3(-2, -2, 0), D3(2, -2, 0), D3(2, 2, 0), D3(-2, 2, 0)}, {{{0, 1, 2}}, {{0, 2, 3}}});
    const D3 a(0, -0.02, 0.05), b(0, 1, 0), c(-1, 0, 0), d(1, 0, 0);
    MixedMesh m;
    m.Build({a, b, c, d}, {{{0, 1, 2}}, {{1, 0, 3}}});  // (a b c) and (b a d)
    m.otherPatches.assign(m.VertexCount(), {});  // no other patch holds these front nodes
    std::vector<int> home(m.VertexCount(), 0);
    m.SetInputSurface(&surface, &home);
    const int ab = 0;  // half-edge a->b of (a b c)
    ASSERT_EQ(m.Org(ab), 0);
    ASSERT_EQ(m.Dst(ab), 1);
    ASSERT_GE(m.heTwin[ab], 0) << "a-b is the interior edge the swap turns into c-d";

    const D3 sliver = (a - c) ^ (d - c);  // the swap's triangle (c a d)
    ASSERT_GT(sliver * D3(0, 0, 1), 1e-3 * (d - c).SquaredNorm()) << "it faces the patch's surface";
    const D3 leaning(0, -0.6, 0.8);
    ASSERT_LT(sliver * leaning, 0) << "and is upside down on the leaning input";
    for (int f = 0; f < 2; ++f) ASSERT_GT(m.FaceNormal(f) * leaning, 0) << "the triangles before the swap face the input";

    EXPECT_TRUE(m.CanFlip(ab)) << "without a judge the patch's own surface decides: the swap passes";
    m.judge = [&](const D3 &, double) { return leaning; };
    EXPECT_FALSE(m.CanFlip(ab)) << "the input under the sliver says it is upside down";
    m.judge = [](const D3 &, double) { return D3(0, 0, 1); };
    EXPECT_TRUE(m.CanFlip(ab)) << "not a blanket refusal: with the input agreeing, the swap passes";
}

// A front over smooth surface is coarsened into chords, each within 0.1 L of the input's curve,
// also where chords replace chords: the middle ring of a finely sliced cylinder (radius 1, 64
// slices) re-meshed at L = 1.3, coarser than the ring (a check of each removed vertex against the
// new chord alone, as before, let 7 chords of chords stray beyond 0.1 L of the circle).
TEST(FeatureRemesh, ChordsOfASmoothFrontStayNearTheInputCurve)
{
    TMesh m;
    MakeCylinder(m, 64, 16, 1.f, 2.f, 3);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    int ring = 0;
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k)
            if (f.V0(k)->P()[2] == 0.f && f.V1(k)->P()[2] == 0.f) { f.SetFaceEdgeS(k); ++ring; }
    ASSERT_EQ(ring, 2 * 64) << "the middle ring, both sides of each edge";
    TMesh input;
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(input, m);
    vcg::tri::UpdateBounding<TMesh>::Box(input);
    const std::vector<PosEdge> front = EdgesByPosition(input, true);
    const double L = 1.3;

    QM::Params p;
    p.targetEdgeLength = L;
    const QM::Result r = QM::Apply(m, p);
    ASSERT_EQ(r.error, "");
    const std::vector<PosEdge> frontAfter = EdgesByPosition(m, true);
    std::printf("smooth front: %zu -> %zu edges\n", front.size(), frontAfter.size());
    EXPECT_LT(frontAfter.size(), front.size() / 2) << "the front was not coarsened: the test would not test the chords";
    EXPECT_EQ(FrontCurveMismatches(front, frontAfter, kOnCurve * input.bbox.Diag(), kChord * L), 0)
        << "front edges farther than 0.1 L from the input's curve (or their vertices off it)";
}

// A front along a smooth bend is coarsened like one over flat surface: the outer equator of a
// finely sliced torus (radii 3 and 1, 96 x 32 cells, neighbouring faces within 12 degrees) re-meshed
// at L = 1, where the faces beside it come to meet at about 57 degrees. Sharp is the input's
// dihedral (ShortEdgeCollapse::kSharpChainDeg): judged on the faces of the moment, the equator
// froze as a crease once they met at 30 degrees (40 edges at any L from 0.8 to 1.2).
TEST(FeatureRemesh, FrontAlongASmoothBendIsCoarsenedToTheTargetLength)
{
    const float R = 3.f, r = 1.f;
    const int slices = 96;
    TMesh m;
    vcg::tri::Torus(m, R, r, slices, 32);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg::tri::UpdateTopology<TMesh>::VertexFace(m);
    auto onEquator = [&](const P3 &p) { return std::fabs(p[2]) < 1e-5f && vcg::Point2f(p[0], p[1]).Norm() > R; };
    int ring = 0;
    for (TFace &f : m.face)
        for (int k = 0; k < 3; ++k)
            if (onEquator(f.P0(k)) && onEquator(f.P1(k))) {
                f.SetFaceEdgeS(k);
                ++ring;
            }
    ASSERT_EQ(ring, 2 * slices) << "the outer equator, both sides of each edge";
    const auto in = vcg_ext::MeshChecks<TMesh>::Inspect(m);
    ASSERT_TRUE(in.IsClosed() && in.IsTwoManifold() && in.IsOriented());

    TMesh copy;
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(copy, m);
    vcg_ext::InputSurface<TMesh> surface(copy);
    const double L = 1.0, circumference = 2 * M_PI * (R + r);
    const auto st = vcg_ext::qmorph::FeatureRemesh<TMesh>::Do(m, surface, L, 5, 60);
    std::printf("torus equator: %d -> %d front edges (circumference / L %.1f)\n", st.frontEdgesBefore, st.frontEdgesAfter,
                circumference / L);
    EXPECT_EQ(st.frontEdgesBefore, slices);
    // edges between 4/5 L and 4/3 L: circumference / L within about 30%
    EXPECT_LE(st.frontEdgesAfter, 1.3 * circumference / L) << "the front stayed finer than L";
    EXPECT_GE(st.frontEdgesAfter, circumference / (4.0 / 3.0 * L)) << "front edges longer than 4/3 L";
}

// A cube (4 x 4 cells a side, cells 0.5) whose top has needles turned over: one vertex moved
// across a grid line, 0.001 beyond the middle of the far edge of one of its triangles. Its two
// triangles on that line become needles about 0.001 high facing down; they meet each other, the
// rest of the top and the faces across the line at about 180 degrees along 4 edges. Those are
// noise at L = 0.5 (height < 0.05 L), not creases; the cube's 12 edges (48 pieces) are.
TEST(FeatureRemesh, SharpEdgesOfANeedleTurnedOverAreNotCreases)
{
    TMesh m;
    MakeCube(m, 4);
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    vcg::tri::UpdateTopology<TMesh>::VertexFace(m);
    TVertex *v = nullptr;
    for (TVertex &x : m.vert)
        if (std::fabs(x.P()[0] + 0.5f) < 1e-6f && std::fabs(x.P()[1] + 0.5f) < 1e-6f && std::fabs(x.P()[2] - 1) < 1e-6f) v = &x;
    ASSERT_NE(v, nullptr);
    vcg::face::VFIterator<TFace> vfi(v);
    TFace *needle = vfi.F();
    const int corner = vfi.I();
    const P3 a = needle->P1(corner), b = needle->P2(corner), mid = (a + b) * 0.5f;
    v->P() = mid + (mid - v->P()).Normalize() * 0.001f;
    ASSERT_LT(vcg::TriangleNormal(*needle).Normalize()[2], -0.99f) << "the needle faces down";
    int facingDown = 0;
    for (const TFace &f : m.face) facingDown += vcg::TriangleNormal(f).Normalize()[2] < -0.99f && f.cP(0)[2] > 0.999f;
    ASSERT_EQ(facingDown, 2);

    TMesh copy;
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(copy, m);
    vcg_ext::InputSurface<TMesh> surface(copy);
    const auto st = vcg_ext::qmorph::FeatureRemesh<TMesh>::Do(m, surface, 0.5, 1, 60);
    EXPECT_EQ(st.needleCreases, 4);
    EXPECT_EQ(st.featureEdges, 48) << "the cube's edges, and nothing else";
}
