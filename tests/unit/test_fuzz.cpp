// Seeded fuzzing of the core of the four steps. Every case is small random input: a generated
// shape (cube, cylinder, sphere, tetrahedron, open grid, random triangles) with random damage
// (faces flipped, duplicated, zero-area or with a repeated vertex, a non-manifold fin or vertex, a
// collapsed vertex, needles, unmerged vertices, deleted faces, NaN, a second component, a scale),
// random region labels, random polylines on and off the surface, random edge selections and random
// (sometimes invalid) parameters. Each step must either succeed with its invariants or return an
// error and leave the mesh exactly as it was; a crash fails the run, a hang hits CTest's timeout.
//
// Bounded by count (CTest): kDefaultRuns cases. Each case has its own seed, printed on failure.
// Longer run (README): QMF_FUZZ_RUNS=20000 QMF_FUZZ_SEED=100000 build/tests/unit_tests --gtest_filter='Fuzz.*'
// (QMF_FUZZ_MAX_FAILING=n: stop after n failing cases, 5 by default)
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <random>
#include <set>

#include "mesh_snapshot.h"
#include "quad_checks.h"
#include "test_mesh.h"
#include <vcg/complex/append.h>
#include <vcg_ext/common/region_ids.h>
#include <vcg_ext/geodesic_straightening.h>
#include <vcg_ext/mesh_checks.h>
#include <vcg_ext/polyline_embedding.h>
#include <vcg_ext/qmorph.h>
#include <vcg_ext/vsa_segmentation.h>

using namespace qmf_test;

namespace {

typedef vcg_ext::VSASegmentation<TMesh> Vsa;
typedef vcg_ext::RegionBoundarySmoothing<TMesh> Smoothing;
typedef vcg_ext::PolylineEmbedding<TMesh> Embedding;
typedef vcg_ext::QMorph<TMesh> QM;
typedef vcg_ext::MeshChecks<TMesh> Checks;
typedef std::mt19937 Rng;
typedef std::vector<std::array<int, 3>> Faces;

const int kDefaultRuns = 400;         // the CTest run: about 10 s in the regular build
const unsigned kDefaultSeed = 1;

int EnvInt(const char *name, int fallback)
{
    const char *s = std::getenv(name);
    return s && *s ? std::atoi(s) : fallback;
}

int Uniform(Rng &rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
double Real(Rng &rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
bool Chance(Rng &rng, double p) { return Real(rng, 0, 1) < p; }

// ---------------------------------------------------------------- random meshes
struct Soup {
    std::vector<P3> v;
    Faces f;
    std::string what;  // the recipe, for the failure message
};

Soup SoupOf(const TMesh &m)
{
    Soup s;
    for (auto &x : m.vert) s.v.push_back(x.cP());
    for (auto &x : m.face)
        s.f.push_back({int(vcg::tri::Index(m, x.cV(0))), int(vcg::tri::Index(m, x.cV(1))), int(vcg::tri::Index(m, x.cV(2)))});
    return s;
}

Soup RandomShape(Rng &rng)
{
    TMesh m;
    const int kind = Uniform(rng, 0, 5);
    const unsigned seed = unsigned(rng());
    switch (kind) {
    case 0: MakeCube(m, Uniform(rng, 1, 3), float(Real(rng, 0, 0.45)), seed); break;
    case 1: MakeCylinder(m, Uniform(rng, 3, 8), Uniform(rng, 1, 3), 1.f, float(Real(rng, 0.1, 3)), Uniform(rng, 1, 2)); break;
    case 2: MakeSphere(m, Uniform(rng, 0, 1)); break;
    case 3: Build(m, {P3(0, 0, 0), P3(1, 0, 0), P3(0, 1, 0), P3(0, 0, 1)}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}); break;
    case 4: MakeGrid(m, Uniform(rng, 1, 4), 1.f, float(Real(rng, 0, 0.45)), seed, Chance(rng, 0.5)); break;
    default: {  // random triangles on a few random points: anything goes
        std::vector<P3> v;
        Faces f;
        const int n = Uniform(rng, 3, 9);
        for (int i = 0; i < n; ++i) v.push_back(P3(float(Real(rng, -1, 1)), float(Real(rng, -1, 1)), float(Real(rng, -1, 1))));
        for (int i = Uniform(rng, 1, 12); i > 0; --i) f.push_back({Uniform(rng, 0, n - 1), Uniform(rng, 0, n - 1), Uniform(rng, 0, n - 1)});
        Build(m, v, f);
    }
    }
    Soup s = SoupOf(m);
    s.what = "shape " + std::to_string(kind);
    return s;
}

// Random damage, each kind with its own probability (several may combine).
void Damage(Soup &s, Rng &rng)
{
    if (s.f.empty()) return;
    auto face = [&]() -> std::array<int, 3> & { return s.f[Uniform(rng, 0, int(s.f.size()) - 1)]; };
    auto note = [&](const char *w) { s.what += std::string(", ") + w; };
    if (Chance(rng, 0.15)) {  // a second component, beside the first (every shape fits in [-1.5, 1.5]^3)
        Soup t = RandomShape(rng);
        const int base = int(s.v.size());
        const P3 shift(float(Real(rng, 3, 5)), 0, 0);
        for (auto &p : t.v) s.v.push_back(p + shift);
        for (auto &x : t.f) s.f.push_back({x[0] + base, x[1] + base, x[2] + base});
        note("two components");
    }
    if (Chance(rng, 0.1)) { auto &t = face(); std::swap(t[1], t[2]); note("a face flipped"); }
    if (Chance(rng, 0.15)) { for (auto &t : s.f) std::swap(t[0], t[1]); note("all faces flipped"); }
    if (Chance(rng, 0.1)) { s.f.push_back(face()); note("a duplicate face"); }
    if (Chance(rng, 0.1)) { auto t = face(); s.f.push_back({t[0], t[0], t[1]}); note("a repeated vertex"); }
    if (Chance(rng, 0.1)) {  // a vertex on the middle of an edge, and a zero-area face through it
        auto t = face();
        s.v.push_back((s.v[t[0]] + s.v[t[1]]) * 0.5f);
        s.f.push_back({t[0], int(s.v.size()) - 1, t[1]});
        note("a zero-area face");
    }
    if (Chance(rng, 0.1)) { auto t = face(); s.v[t[0]] = s.v[t[1]]; note("a collapsed vertex"); }
    if (Chance(rng, 0.1)) {  // a needle: a vertex almost onto its neighbour
        auto t = face();
        s.v[t[0]] = s.v[t[1]] + (s.v[t[0]] - s.v[t[1]]) * float(std::pow(10.0, -Uniform(rng, 2, 6)));
        note("a needle");
    }
    if (Chance(rng, 0.1)) {  // a fin: a third face on an edge
        auto t = face();
        s.v.push_back(s.v[t[0]] + P3(0.3f, 0.7f, 0.5f));
        s.f.push_back({t[0], t[1], int(s.v.size()) - 1});
        note("a fin");
    }
    if (Chance(rng, 0.1)) {  // a triangle hanging on one vertex
        auto t = face();
        s.v.push_back(s.v[t[0]] * 2.f + P3(0.1f, 0, 0));
        s.v.push_back(s.v[t[0]] * 2.f + P3(0, 0.1f, 0));
        s.f.push_back({t[0], int(s.v.size()) - 2, int(s.v.size()) - 1});
        note("a non-manifold vertex");
    }
    if (Chance(rng, 0.07)) {  // a face given its own copies of its vertices: unmerged
        auto &t = face();
        for (int &i : t) { s.v.push_back(s.v[i]); i = int(s.v.size()) - 1; }
        note("unmerged vertices");
    }
    if (Chance(rng, 0.05)) { s.v.push_back(P3(5, 5, 5)); note("an unreferenced vertex"); }
    if (Chance(rng, 0.1)) {
        const float scale = Chance(rng, 0.5) ? 1e-4f : 1e4f;
        for (auto &p : s.v) p *= scale;
        note(scale < 1 ? "scaled 1e-4" : "scaled 1e4");
    }
}

// The mesh of a soup, then the damage that needs vcg: deleted faces and NaN coordinates.
void RandomMesh(TMesh &m, Rng &rng, std::string &what)
{
    Soup s = RandomShape(rng);
    Damage(s, rng);
    Build(m, s.v, s.f);
    what = s.what;
    if (m.fn > 1 && Chance(rng, 0.07)) {
        vcg::tri::Allocator<TMesh>::DeleteFace(m, m.face[Uniform(rng, 0, int(m.face.size()) - 1)]);
        what += ", a deleted face";
    }
    if (m.vn > 0 && Chance(rng, 0.03)) {
        m.vert[Uniform(rng, 0, int(m.vert.size()) - 1)].P()[1] = std::nanf("");
        what += ", NaN";
    }
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
}

// ---------------------------------------------------------------- invariants
std::vector<std::array<int, 3>> LiveTriangles(const TMesh &m)
{
    std::vector<std::array<int, 3>> t;
    for (auto &f : m.face)
        t.push_back(f.IsD() ? std::array<int, 3>{-1, -1, -1}
                            : std::array<int, 3>{int(vcg::tri::Index(m, f.cV(0))), int(vcg::tri::Index(m, f.cV(1))),
                                                 int(vcg::tri::Index(m, f.cV(2)))});
    return t;
}

// Labels complete: every live face has a label in [0, regions), every region is used and is one
// edge-connected piece (faces joined across edges with the same label on both sides).
void ExpectLabelsComplete(const TMesh &m, const Vsa::Result &r)
{
    ASSERT_EQ(r.faceRegion.size(), m.face.size());
    ASSERT_GE(r.regions, 1);
    std::vector<int> used(r.regions, 0);
    for (size_t i = 0; i < m.face.size(); ++i) {
        const int l = r.faceRegion[i];
        if (m.face[i].IsD()) { EXPECT_EQ(l, -1); continue; }
        ASSERT_TRUE(l >= 0 && l < r.regions) << "face " << i << " label " << l;
        EXPECT_EQ(m.face[i].cQ(), float(l)) << "face quality = region id";
        used[l]++;
    }
    for (int k = 0; k < r.regions; ++k) EXPECT_GT(used[k], 0) << "region " << k << " has no face";
    const auto tris = LiveTriangles(m);
    vcg_ext::IndexUnionFind uf(int(tris.size()));
    const auto edges = vcg_ext::EdgePairing::Group(tris);
    for (int e = 0; e < edges.Count(); ++e)  // every pair of faces on an edge (non-manifold ones too)
        for (int j = 0; j < edges.Size(e); ++j)
            for (int k = j + 1; k < edges.Size(e); ++k) {
                const int f = edges.Begin(e)[j] / 3, g = edges.Begin(e)[k] / 3;
                if (r.faceRegion[f] == r.faceRegion[g]) uf.Unite(f, g);
            }
    std::set<int> roots;
    std::set<int> labels;
    for (size_t i = 0; i < tris.size(); ++i)
        if (tris[i][0] >= 0 && !vcg_ext::MeshChecks<TMesh>::IsZeroArea(m.face[i])) {
            roots.insert(uf.Find(int(i)));
            labels.insert(r.faceRegion[i]);
        }
    EXPECT_LE(roots.size(), size_t(r.regions)) << "a region is in several pieces";
}

// Polyline points on the surface: at a vertex or inside an edge of the mesh, finite, at the
// position the surface point gives, consecutive points of a curve on one face.
void ExpectPolylinesOnSurface(const Smoothing::Result &r)
{
    typedef vcg_ext::SurfacePathGeometry<TMesh> Geometry;
    const auto &t = r.topology;
    for (const auto &c : r.curves) {
        const auto &pts = c.path.points;
        for (size_t i = 0; i < pts.size(); ++i) {
            const vcg_ext::SurfacePoint &q = pts[i];
            if (q.IsVertex()) {
                ASSERT_LT(size_t(q.vertex), t.mesh->vert.size());
            } else {
                ASSERT_TRUE(q.edge >= 0 && q.edge < t.EdgeCount()) << q.edge;
                EXPECT_TRUE(q.t >= 0 && q.t <= 1) << q.t;
            }
            const auto p = Geometry::Position(t, q);
            EXPECT_TRUE(Checks::IsFinite(p));
            if (i > 0) {
                EXPECT_TRUE(Geometry::ShareFace(t, pts[i - 1], q)) << "segment " << i << " leaves the faces";
            }
        }
        if (c.path.closed && pts.size() > 2) {
            EXPECT_TRUE(Geometry::ShareFace(t, pts.back(), pts.front()));
        }
    }
    const auto lines = Smoothing::ToPolylines(t, r.curves);
    for (const auto &p : lines.points) EXPECT_TRUE(Checks::IsFinite(p));
}

double SignedVolume(const TMesh &m)
{
    double vol = 0;
    for (auto &f : m.face) {
        if (f.IsD()) continue;
        const vcg::Point3d a = vcg::Point3d::Construct(f.cP(0)), b = vcg::Point3d::Construct(f.cP(1)),
                           c = vcg::Point3d::Construct(f.cP(2));
        vol += a * (b ^ c) / 6;
    }
    return vol;
}

// How much the total area may change only because the split's new vertices sit on the float grid:
// a vertex on an edge (or inside a face) is off its exact place by up to kPlacementUlps ulps of its
// coordinates (|p| 2^-23 each), and moving a vertex by d changes each incident face's area by at
// most d times half the opposite edge. On a needle whose width is a few ulps (a grid vertex 1e-6 from
// the line of its boundary edge) that is a few percent of its area, which no float split can avoid;
// on ordinary meshes it is far below the relative bound. New vertices: positions not in the input.
const double kPlacementUlps = 2;
double FloatPlacementAreaSlack(const TMesh &m, const std::set<std::array<float, 3>> &inputPositions)
{
    typedef vcg::Point3d D3;
    double slack = 0;
    for (auto &f : m.face) {
        if (f.IsD()) continue;
        for (int k = 0; k < 3; ++k) {
            const P3 &p = f.cP(k);
            if (inputPositions.count({p[0], p[1], p[2]})) continue;
            const double d = kPlacementUlps * std::ldexp(D3::Construct(p).Norm(), -23);
            slack += 0.5 * (D3::Construct(f.cP((k + 1) % 3)) - D3::Construct(f.cP((k + 2) % 3))).Norm() * d;
        }
    }
    return slack;
}

// Random labels: the nearest of k random seed faces (patches), or noise, or one label.
std::vector<int> RandomLabels(const TMesh &m, Rng &rng)
{
    std::vector<int> labels(m.face.size(), -1);
    const int mode = Uniform(rng, 0, 2), k = Uniform(rng, 1, 5);
    std::vector<P3> seeds;
    for (int i = 0; i < k; ++i) seeds.push_back(m.face[Uniform(rng, 0, int(m.face.size()) - 1)].cP(0));
    for (size_t i = 0; i < m.face.size(); ++i) {
        if (m.face[i].IsD()) continue;
        if (mode == 0) labels[i] = Uniform(rng, 0, k);
        else if (mode == 1) labels[i] = 7;
        else {
            const P3 c = (m.face[i].cP(0) + m.face[i].cP(1) + m.face[i].cP(2)) / 3.f;
            int best = 0;
            for (int j = 1; j < k; ++j)
                if ((c - seeds[j]).SquaredNorm() < (c - seeds[best]).SquaredNorm()) best = j;
            labels[i] = best * 3 - 2;  // ids need not be 0..K-1
        }
    }
    return labels;
}

// A random polyline: random points on the surface (inside faces, on edges, at vertices), some
// moved off the surface or NaN, consecutive or random segments, open or closed.
void RandomPolyline(const TMesh &m, Rng &rng, TMesh &poly)
{
    poly.Clear();
    const int n = Uniform(rng, 0, 8);
    std::vector<P3> pts;
    for (int i = 0; i < n; ++i) {
        const TFace &f = m.face[Uniform(rng, 0, int(m.face.size()) - 1)];
        double a = Real(rng, 0, 1), b = Real(rng, 0, 1);
        if (a + b > 1) { a = 1 - a; b = 1 - b; }
        const int where = Uniform(rng, 0, 3);
        if (where == 1) b = 0;                     // on an edge
        if (where == 2) { a = Uniform(rng, 0, 1); b = 0; }  // at a vertex
        P3 p = f.cP(0) + (f.cP(1) - f.cP(0)) * float(a) + (f.cP(2) - f.cP(0)) * float(b);
        if (Chance(rng, 0.1)) p += P3(0, 0, float(Real(rng, -0.1, 0.1)));  // off the surface
        if (Chance(rng, 0.02)) p[0] = std::nanf("");
        pts.push_back(p);
        if (Chance(rng, 0.05)) pts.push_back(p);  // a repeated point
    }
    vcg::tri::Allocator<TMesh>::AddVertices(poly, pts.size());
    for (size_t i = 0; i < pts.size(); ++i) poly.vert[i].P() = pts[i];
    const int np = int(pts.size());
    if (np < 2) return;
    if (Chance(rng, 0.8)) {
        const bool closed = np > 2 && Chance(rng, 0.3);
        for (int i = 0; i + 1 < np + (closed ? 1 : 0); ++i)
            vcg::tri::Allocator<TMesh>::AddEdge(poly, &poly.vert[i], &poly.vert[(i + 1) % np]);
    } else {
        for (int i = Uniform(rng, 1, 6); i > 0; --i)
            vcg::tri::Allocator<TMesh>::AddEdge(poly, &poly.vert[Uniform(rng, 0, np - 1)], &poly.vert[Uniform(rng, 0, np - 1)]);
    }
}

void SelectRandomEdges(TMesh &m, Rng &rng)
{
    const bool live = m.fn == int(m.face.size());  // the selection helpers read FFp of every face
    const int mode = Uniform(rng, live ? 0 : 2, 3);
    if (mode == 0) { SelectCreases(m, Real(rng, 10, 100)); return; }
    if (mode == 1) { SelectRegionBoundaries(m); return; }
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    for (auto &f : m.face)
        for (int k = 0; k < 3; ++k)
            if (!f.IsD() && Chance(rng, mode == 2 ? 0.1 : 0.5)) {
                f.SetFaceEdgeS(k);
                if (Chance(rng, 0.9) && f.FFp(k) && f.FFp(k) != &f && !f.FFp(k)->IsD()) f.FFp(k)->SetFaceEdgeS(f.FFi(k));
            }
}

// ---------------------------------------------------------------- the four steps
struct Tally {
    int runs[4] = {0, 0, 0, 0}, ok[4] = {0, 0, 0, 0};
    int invertedQuads = 0, casesWithInvertedQuads = 0;  // a quality finding, not an invariant: reported
    int flippedWithoutCreases = 0;  // flipped faces when creases over 90 degrees were not cut: reported
};

// Step 1. Returns whether it succeeded.
bool FuzzVsa(TMesh &m, Rng &rng, Tally &tally)
{
    Vsa::Params p;
    p.mode = Chance(rng, 0.3) ? Vsa::FixedRegionCount : Vsa::ThresholdSeeding;
    p.initialSeeds = Uniform(rng, -1, 6);
    p.thresholdAngleDeg = Chance(rng, 0.9) ? Real(rng, 5, 120) : Real(rng, -10, 200);
    p.maxRegions = Uniform(rng, 0, 30);
    p.maxIterations = Uniform(rng, 0, 10);
    p.randomSeed = uint32_t(rng());
    p.relaxationsPerSeed = Uniform(rng, 1, 5);
    p.teleportAttempts = Uniform(rng, 0, 4);
    if (Chance(rng, 0.02)) p.relativeTolerance = -1;
    // face clusters (big meshes' seeding) on a quarter of the runs, sizes -1..10, from the seed
    // already drawn (another draw would change every later case of the stream)
    if (p.randomSeed % 4 == 0) p.facesPerCluster = int(p.randomSeed / 4 % 12) - 1;
    const Snapshot before = Snapshot::Of(m);
    ++tally.runs[0];
    const Vsa::Result r = Vsa::Segment(m, p);
    if (!r.error.empty()) {
        EXPECT_TRUE(Snapshot::Of(m) == before) << "VSA refused (" << r.error << ") but changed the mesh";
        return false;
    }
    ++tally.ok[0];
    const Snapshot after = Snapshot::Of(m, false, false);
    EXPECT_TRUE(after.coords == before.coords && after.faces == before.faces) << "VSA moved vertices or faces";
    ExpectLabelsComplete(m, r);
    EXPECT_TRUE(std::isfinite(r.l21Error));
    return true;
}

// Step 2: the mesh is only read. Returns the polylines as an edge mesh when it succeeded.
bool FuzzSmoothing(const TMesh &m, const std::vector<int> &labels, Rng &rng, TMesh &poly, Tally &tally)
{
    Smoothing::Params p;
    p.iterations = Uniform(rng, -1, 5);
    p.snapPercent = Chance(rng, 0.9) ? Real(rng, 0, 45) : Real(rng, -5, 60);
    p.minRegionFaces = Uniform(rng, -1, 4);
    const Snapshot before = Snapshot::Of(m);
    ++tally.runs[1];
    const Smoothing::Result r = Smoothing::Smooth(m, labels, p);
    EXPECT_TRUE(Snapshot::Of(m) == before) << "smoothing changed the mesh";
    if (!r.error.empty()) return false;
    ++tally.ok[1];
    ExpectPolylinesOnSurface(r);
    poly.Clear();
    Smoothing::BuildEdgeMesh(Smoothing::ToPolylines(r.topology, r.curves), poly);
    return true;
}

// Step 3. Returns whether it succeeded.
bool FuzzEmbedding(TMesh &m, const TMesh &poly, Rng &rng, Tally &tally)
{
    Embedding::Params p;
    const double tolerances[] = {1e-4, 1e-2, 0.5, 0, -1, 20};
    p.locateTolerancePercent = Chance(rng, 0.8) ? 1e-4 : tolerances[Uniform(rng, 0, 5)];
    const Snapshot before = Snapshot::Of(m);
    const vcg_ext::MeshCheckReport in = Checks::Inspect(m);
    const double area = TotalArea(m), volume = SignedVolume(m);
    std::set<std::array<float, 3>> inputPositions;
    for (auto &v : m.vert) inputPositions.insert({v.cP()[0], v.cP()[1], v.cP()[2]});
    ++tally.runs[2];
    const Embedding::Result r = Embedding::Embed(m, poly, p);
    if (!r.error.empty()) {
        EXPECT_TRUE(Snapshot::Of(m) == before) << "splitting refused (" << r.error << ") but changed the mesh";
        return false;
    }
    ++tally.ok[2];
    const vcg_ext::MeshCheckReport out = Checks::Inspect(m);
    EXPECT_EQ(out.IsClosed(), in.IsClosed());
    EXPECT_EQ(out.IsTwoManifold(), in.IsTwoManifold());
    EXPECT_EQ(out.inconsistentEdges, 0) << "a face flipped";
    EXPECT_EQ(out.degenerateFaces, 0);
    EXPECT_EQ(out.EulerCharacteristic(), in.EulerCharacteristic());
    EXPECT_EQ(out.components, in.components);
    EXPECT_NEAR(TotalArea(m), area, 1e-4 * area + FloatPlacementAreaSlack(m, inputPositions));
    if (in.IsClosed()) {
        EXPECT_NEAR(SignedVolume(m), volume, 1e-4 * std::max(1e-12, std::fabs(area) * std::sqrt(area)));
    }
    // The front: every polyline point is now a mesh vertex on a selected edge.
    std::set<std::array<float, 3>> onFront;
    for (auto &f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k)
                if (f.IsFaceEdgeS(k))
                    for (int j : {k, (k + 1) % 3}) onFront.insert({f.cP(j)[0], f.cP(j)[1], f.cP(j)[2]});
    // (points within the locate tolerance of the surface are embedded at their closest point there)
    const float tol = float(1.01 * std::max(r.tolerance, 1e-5 * m.bbox.Diag()));
    for (auto &e : poly.edge)
        for (int k = 0; k < 2; ++k) {
            const P3 q = e.cV(k)->cP();
            if ((e.cV(0)->cP() - e.cV(1)->cP()).Norm() <= tol) continue;  // a segment of zero length: dropped
            bool found = false;
            for (auto &x : onFront) found = found || (P3(x[0], x[1], x[2]) - q).Norm() <= tol;
            EXPECT_TRUE(found) << "polyline point " << q[0] << " " << q[1] << " " << q[2] << " is not on the front";
        }
    std::vector<int> ids;
    EXPECT_EQ(vcg_ext::RegionIds<TMesh>::Read(m, ids), "") << "labels complete after relabelling";
    return true;
}

// Step 4.
void FuzzQMorph(TMesh &m, Rng &rng, Tally &tally)
{
    QM::Params p;
    p.preserveInitialFront = Chance(rng, 0.7);
    p.transitions = Chance(rng, 0.8);
    p.cleanup = Chance(rng, 0.8);
    p.rescueBadQuads = Chance(rng, 0.8);
    p.smoothing = Chance(rng, 0.8);
    p.smoothingIterations = Uniform(rng, -1, 8);
    p.closedAngleDeg = Chance(rng, 0.9) ? Real(rng, 100, 170) : Real(rng, 0, 200);
    p.creaseAngleDeg = Chance(rng, 0.9) ? Real(rng, 30, 180) : Real(rng, -10, 200);
    vcg::tri::UpdateBounding<TMesh>::Box(m);
    if (Chance(rng, 0.15)) p.targetEdgeLength = m.bbox.Diag() * Real(rng, 0.03, 0.3);
    if (Chance(rng, 0.02)) p.targetEdgeLength = Chance(rng, 0.5) ? 1e-9 : -1;
    p.remeshIterations = Uniform(rng, 0, 4);

    const Snapshot before = Snapshot::Of(m);
    const vcg_ext::MeshCheckReport in = Checks::Inspect(m);
    const std::set<PosEdge> selected = SelectedEdges(m);
    TMesh input;
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(input, m);
    ++tally.runs[3];
    const QM::Result r = QM::Apply(m, p);
    if (!r.error.empty()) {
        EXPECT_TRUE(Snapshot::Of(m) == before) << "Q-Morph refused (" << r.error << ") but changed the mesh";
        return;
    }
    ++tally.ok[3];
    const std::string params = "crease angle " + std::to_string(p.creaseAngleDeg) + ", closed angle " +
                               std::to_string(p.closedAngleDeg) + ", target length " + std::to_string(p.targetEdgeLength) +
                               " (diagonal " + std::to_string(input.bbox.Diag()) + ")";
    SCOPED_TRACE(params);
    const vcg_ext::MeshCheckReport out = Checks::Inspect(m);
    EXPECT_EQ(out.IsClosed(), in.IsClosed());
    EXPECT_TRUE(out.IsTwoManifold());
    EXPECT_TRUE(out.IsOriented());
    EXPECT_EQ(out.degenerateFaces, 0);
    EXPECT_EQ(out.components, in.components);
    EXPECT_EQ(out.EulerCharacteristic(), in.EulerCharacteristic());
    if (p.targetEdgeLength > 0) {
        // re-meshing may coarsen the front: along sharp edges only where straight, over smooth
        // surface within ShortEdgeCollapse's chord tolerance (0.1 L)
        const double diag = input.bbox.Diag();
        EXPECT_EQ(FrontCurveMismatches(std::vector<PosEdge>(selected.begin(), selected.end()), EdgesByPosition(m, true),
                                       1e-5 * diag, 0.1 * p.targetEdgeLength + 1e-5 * diag),
                  0)
            << "the front is no longer chains of selected edges along its curves";
    } else {
        EXPECT_TRUE(SelectedEdges(m) == selected) << "the front changed";
    }
    vcg::tri::UpdateTopology<TMesh>::FaceFace(m);
    const vcg_ext::PolygonMesh pm = vcg_ext::QuadQuality::FromFauxMesh(m);
    EXPECT_EQ(r.quads + r.triangles, int(pm.faces.size()));
    tally.invertedQuads += r.quality.invertedQuads;
    tally.casesWithInvertedQuads += r.quality.invertedQuads > 0;
    // Creases sharper than 90 degrees are cut (front) at crease angles up to 90: then no face may
    // be upside down. Above, quads may fold over such a crease (the user turned that off): counted.
    const int flipped = FlippedFaces(pm, input).flipped;
    if (p.creaseAngleDeg <= 90) {
        EXPECT_EQ(flipped, 0) << "faces upside down on the input surface";
    } else {
        tally.flippedWithoutCreases += flipped;
    }
}

// One random case from its seed: the four steps in a row, each also on independent random input
// (labels, polylines, edge selections), so a refusal early in the chain does not hide the later steps.
void RunCase(unsigned seed, Tally &tally)
{
    Rng rng(seed);
    TMesh m;
    std::string what;
    RandomMesh(m, rng, what);
    SCOPED_TRACE("QMF_FUZZ_SEED=" + std::to_string(seed) + " QMF_FUZZ_RUNS=1: " + what);
    const bool hasFaces = m.fn > 0;

    const bool segmented = FuzzVsa(m, rng, tally);
    TMesh poly;
    bool haveFront = false;
    if (hasFaces) {
        std::vector<int> labels;
        if (!segmented || Chance(rng, 0.3)) labels = RandomLabels(m, rng);
        else vcg_ext::RegionIds<TMesh>::Read(m, labels);
        haveFront = FuzzSmoothing(m, labels, rng, poly, tally);
        if (!haveFront || Chance(rng, 0.3)) RandomPolyline(m, rng, poly);
    }
    TMesh copy;
    vcg::tri::Append<TMesh, TMesh>::MeshCopy(copy, m);
    const bool split = hasFaces && FuzzEmbedding(m, poly, rng, tally);
    if (!split || Chance(rng, 0.3)) {
        m.Clear();
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, copy);
        if (hasFaces) SelectRandomEdges(m, rng);
    }
    FuzzQMorph(m, rng, tally);
}

}  // namespace

TEST(Fuzz, FourStepsSurviveRandomInput)
{
    const int runs = EnvInt("QMF_FUZZ_RUNS", kDefaultRuns);
    const unsigned seed0 = unsigned(EnvInt("QMF_FUZZ_SEED", int(kDefaultSeed)));
    Tally tally;
    const ::testing::TestResult &result = *::testing::UnitTest::GetInstance()->current_test_info()->result();
    const int maxFailing = EnvInt("QMF_FUZZ_MAX_FAILING", 5);  // the run stops after that many failing cases
    int failures = 0;                                          // (each prints the seed that replays it)
    for (int i = 0; i < runs && failures < maxFailing; ++i) {
        const int partsBefore = result.total_part_count();
        RunCase(seed0 + unsigned(i), tally);
        failures += result.total_part_count() > partsBefore;
    }
    std::printf("[ fuzz ] %d cases from seed %u (%d failing): VSA %d/%d succeeded, smoothing %d/%d, splitting %d/%d, Q-Morph %d/%d "
                "(the rest refused with an error, the mesh unchanged); %d quads with a scaled Jacobian <= 0 in %d cases; %d faces "
                "flipped with crease cutting above 90 degrees\n",
                tally.runs[0], seed0, failures, tally.ok[0], tally.runs[0], tally.ok[1], tally.runs[1], tally.ok[2], tally.runs[2], tally.ok[3],
                tally.runs[3], tally.invertedQuads, tally.casesWithInvertedQuads, tally.flippedWithoutCreases);
    // The run must reach every step's success path, else it tests only the refusals.
    if (runs >= kDefaultRuns) {
        for (int s = 0; s < 4; ++s) EXPECT_GT(tally.ok[s], runs / 20) << "step " << s + 1 << " almost never succeeds";
    }
}

// Cases longer runs found, kept as they were fixed: a 5-edge template's triangle standing on edge
// over an input edge on a flipped coarse sphere (counted flipped or not by which of two equally close
// triangles an independent check takes; Q-Morph's triangles now face both); a needle split whose
// area the test measured in float (off by more than the split changed it).
TEST(Fuzz, EarlierFindingsStayFixed)
{
    Tally tally;
    for (unsigned seed : {101375u, 101186u}) RunCase(seed, tally);
    EXPECT_EQ(tally.ok[3], 2) << "both reach Q-Morph's success path";
}
