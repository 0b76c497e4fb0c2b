// Filter 3 in-process: output contract (selection, ids, layers, log), defaults, bad input, and the
// whole pipeline segmentation + smoothing + splitting on fandisk and elephant.
#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "plugin_harness.h"
#include "split_test_meshes.h"
#include <vcg_ext/common/front_edges.h>

using namespace qmf_test;
using namespace qmf_test::split;

namespace {

// An edge-only layer (not current) holding the polyline.
MeshModel *AddPolylineLayer(PluginHarness &h, const TMesh &poly, const QString &name)
{
    MeshModel *mm = h.doc.addNewMesh("", name, false);
    if (poly.vn) vcg::tri::Allocator<CMeshO>::AddVertices(mm->cm, poly.vn);
    for (int i = 0; i < poly.vn; ++i) mm->cm.vert[i].P() = poly.vert[i].cP();
    for (auto &e : poly.edge)
        vcg::tri::Allocator<CMeshO>::AddEdge(mm->cm, &mm->cm.vert[vcg::tri::Index(poly, e.cV(0))], &mm->cm.vert[vcg::tri::Index(poly, e.cV(1))]);
    mm->UpdateBoxAndNormals();
    return mm;
}

// The triangle mesh as a TMesh (positions, faces, face flags and quality) for the invariant checker.
void ToTMesh(const CMeshO &m, TMesh &t, bool withQuality)
{
    std::vector<P3> v;
    std::vector<std::array<int, 3>> f;
    for (auto &x : m.vert) v.push_back(x.cP());
    for (auto &x : m.face)
        f.push_back({int(vcg::tri::Index(m, x.cV(0))), int(vcg::tri::Index(m, x.cV(1))), int(vcg::tri::Index(m, x.cV(2)))});
    Build(t, v, f);
    for (size_t i = 0; i < m.face.size(); ++i) {
        t.face[i].Flags() = m.face[i].cFlags();
        t.face[i].Q() = withQuality ? m.face[i].cQ() : 0.f;
    }
}

void ToPolyline(const CMeshO &m, TMesh &t)
{
    t.Clear();
    if (m.vn) vcg::tri::Allocator<TMesh>::AddVertices(t, m.vn);
    for (int i = 0; i < m.vn; ++i) t.vert[i].P() = m.vert[i].cP();
    for (auto &e : m.edge) vcg::tri::Allocator<TMesh>::AddEdge(t, &t.vert[vcg::tri::Index(m, e.cV(0))], &t.vert[vcg::tri::Index(m, e.cV(1))]);
}

// A triangle OFF file read without vcg's importer (which would pull GLU in with the GL headers).
MeshModel *LoadTriangleOff(PluginHarness &h, const std::string &path)
{
    std::ifstream in(path);
    std::string magic;
    int nv = 0, nf = 0, ne = 0;
    in >> magic >> nv >> nf >> ne;
    if (magic != "OFF" || nv <= 0) return nullptr;
    std::vector<vcg::Point3f> v(nv);
    std::vector<std::array<int, 3>> f(nf);
    for (auto &p : v) in >> p[0] >> p[1] >> p[2];
    for (auto &t : f) {
        int n;
        in >> n >> t[0] >> t[1] >> t[2];
        if (n != 3) return nullptr;
    }
    return in ? h.AddMesh(v, f) : nullptr;
}

MeshModel *Layer(PluginHarness &h, const QString &label)
{
    for (MeshModel *m : h.doc.meshList)
        if (m->label() == label) return m;
    return nullptr;
}

void MakeSectionedCube(PluginHarness &h, TMesh &cube, TMesh &poly)
{
    MakeCube(cube, 6, 0.3f, 11);
    ASSERT_TRUE(PlaneSectionPolyline(cube, D3(0.2, 0.3, 1).Normalize(), 0.1234, poly));
    h.AddCopyOf(cube);
    AddPolylineLayer(h, poly, "mesh_front");
}

RichParameterList Defaults(PluginHarness &h, const QString &filter) { return h.Defaults(filter); }
FilterRun RunFilter(PluginHarness &h, const QString &filter) { return h.Apply(filter, Defaults(h, filter)); }

// Bad input: false, the message in errorMessage and in the log, mesh and document unchanged.
void ExpectRefused(PluginHarness &h, const RichParameterList &par, const std::string &expected)
{
    qmf_test::ExpectRefused(h, kSplit, par, expected);
}
void ExpectRefused(PluginHarness &h, const std::string &expected) { ExpectRefused(h, Defaults(h, kSplit), expected); }
}  // namespace

TEST(SplitPlugin, SplitsAlongTheFrontSelectsEdgesRelabelsAndAddsTheEdgeLayer)
{
    PluginHarness h;
    TMesh cube, poly;
    MakeSectionedCube(h, cube, poly);
    MeshModel *mesh = h.doc.mm();
    FilterRun r = RunFilter(h, kSplit);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(h.doc.mm(), mesh) << "the mesh stays the current layer";
    EXPECT_TRUE(r.Logged("faces crossed")) << "log";
    EXPECT_TRUE(r.Logged(std::to_string(poly.en) + " front edges selected"));
    EXPECT_TRUE(r.Logged("min angle of the new triangles"));
    EXPECT_TRUE(r.Logged(std::to_string(poly.vn) + " vertices and"));

    ASSERT_TRUE(mesh->hasDataMask(MeshModel::MM_FACEQUALITY));
    ASSERT_TRUE(mesh->hasDataMask(MeshModel::MM_FACECOLOR));
    EXPECT_EQ(mesh->cm.vn, cube.vn + poly.vn);
    auto front = vcg_ext::FrontEdges<CMeshO>::Collect(mesh->cm);
    EXPECT_EQ(int(front.size()), poly.en);
    EXPECT_EQ(vcg_ext::FrontEdges<CMeshO>::CountOneSided(mesh->cm), 0);
    std::set<float> ids;
    std::set<unsigned> colours;
    for (auto &f : mesh->cm.face) {
        ids.insert(f.Q());
        colours.insert(unsigned(f.C()[0]) << 16 | unsigned(f.C()[1]) << 8 | f.C()[2]);
    }
    EXPECT_EQ(ids.size(), 2u) << "the loop cuts the cube in two patches";
    EXPECT_EQ(colours.size(), 2u) << "one colour per patch";

    MeshModel *layer = Layer(h, "mesh_front_edges");
    ASSERT_NE(layer, nullptr);
    EXPECT_EQ(layer->cm.en, poly.en);
    EXPECT_EQ(layer->cm.fn, 0);
    std::set<std::pair<int, int>> layerEdges;  // the layer's edges are the selected ones, by position
    for (auto &e : layer->cm.edge) {
        int a = -1, b = -1;
        for (int v = 0; v < mesh->cm.vn; ++v) {
            if (mesh->cm.vert[v].cP() == e.cV(0)->cP()) a = v;
            if (mesh->cm.vert[v].cP() == e.cV(1)->cP()) b = v;
        }
        layerEdges.insert(vcg_ext::UndirectedPair(a, b));
    }
    const std::vector<std::pair<int, int>> fromLayer(layerEdges.begin(), layerEdges.end());
    EXPECT_EQ(fromLayer, front);

    TMesh after, polyline;
    ToTMesh(mesh->cm, after, true);
    ToPolyline(Layer(h, "mesh_front")->cm, polyline);
    ExpectSplitInvariants(cube, after, polyline);
}

TEST(SplitPlugin, RerunRefreshesTheEdgeLayerAndTheLayerIsOptional)
{
    PluginHarness h;
    TMesh cube, poly;
    MakeSectionedCube(h, cube, poly);
    ASSERT_TRUE(RunFilter(h, kSplit).ok);
    const int layers = h.doc.size();
    FilterRun r = RunFilter(h, kSplit);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(h.doc.size(), layers) << "the edge layer is refreshed, not added again";
    EXPECT_TRUE(r.Logged("0 vertices and 0 faces added")) << "the front is already made of edges";
    EXPECT_EQ(Layer(h, "mesh_front_edges")->cm.en, poly.en);

    PluginHarness g;
    MakeSectionedCube(g, cube, poly);
    RichParameterList par = Defaults(g, kSplit);
    par.setValue("FrontEdgesLayer", BoolValue(false));
    ASSERT_TRUE(g.Apply(kSplit, par).ok);
    EXPECT_EQ(g.doc.size(), 2);
    EXPECT_EQ(Layer(g, "mesh_front_edges"), nullptr);
}

TEST(SplitPlugin, DefaultPolylineLayerIsTheFrontLayerElseTheNextOne)
{
    PluginHarness h;
    TMesh cube, poly;
    MakeCube(cube, 3);
    MakePolyline(poly, {P3(1, 0.1f, 0.2f), P3(1, 0.3f, 0.4f)});
    MeshModel *mesh = h.AddCopyOf(cube);
    MeshModel *other = AddPolylineLayer(h, poly, "other");
    EXPECT_EQ(Defaults(h, kSplit).getMesh("PolylineLayer"), other) << "no '_front' layer: the next one";
    MeshModel *front = AddPolylineLayer(h, poly, "mesh_front");
    EXPECT_EQ(h.doc.mm(), mesh);
    EXPECT_EQ(Defaults(h, kSplit).getMesh("PolylineLayer"), front);
    h.doc.setCurrent(front);
    EXPECT_NE(Defaults(h, kSplit).getMesh("PolylineLayer"), front) << "never the current layer when others exist";
}

TEST(SplitPlugin, UserPolylineWithPointsInsideFacesIsTraced)
{
    PluginHarness h;
    TMesh cube, poly;
    MakeCube(cube, 5, 0.25f, 3);
    // A closed loop on the cube's faces through points inside faces, around the x axis.
    MakePolyline(poly, {P3(0.13f, -1, 0.21f), P3(-0.11f, 0.17f, -1), P3(0.09f, 1, -0.23f), P3(-0.07f, -0.19f, 1)}, true);
    h.AddCopyOf(cube);
    AddPolylineLayer(h, poly, "drawn");
    FilterRun r = RunFilter(h, kSplit);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(r.Logged("4 inside faces")) << "located inside faces";
    EXPECT_TRUE(r.Logged("4 segments (4 traced"));
    std::set<float> ids;
    for (auto &f : h.doc.mm()->cm.face) ids.insert(f.Q());
    EXPECT_EQ(ids.size(), 2u);
    TMesh after;
    ToTMesh(h.doc.mm()->cm, after, true);
    SplitExpectations x;
    x.pointsInFaces = true;
    x.straightSegments = false;  // the chains bend over the cube's edges
    ExpectSplitInvariants(cube, after, poly, x);
}

TEST(SplitPlugin, BadInputIsRefusedAndNothingChanges)
{
    {  // one layer: the default polyline layer is the mesh itself
        PluginHarness h;
        TMesh cube;
        MakeCube(cube, 2);
        h.AddCopyOf(cube);
        ExpectRefused(h, "the polyline layer is the mesh itself");
    }
    {
        PluginHarness h;
        TMesh cube, none;
        MakeCube(cube, 2);
        h.AddCopyOf(cube);
        AddPolylineLayer(h, none, "mesh_front");
        ExpectRefused(h, "is empty: it has no edges");
    }
    {
        PluginHarness h;
        TMesh cube;
        MakeCube(cube, 2);
        h.AddCopyOf(cube);
        h.AddCopyOf(cube, "mesh_front");
        h.doc.setCurrent(h.doc.meshList[0]);
        ExpectRefused(h, "not a polyline");
    }
    {
        PluginHarness h;
        TMesh cube, poly;
        MakeSectionedCube(h, cube, poly);
        RichParameterList par = Defaults(h, kSplit);
        par.setValue("PolylineLayer", MeshValue(nullptr));
        ExpectRefused(h, par, "the polyline layer is missing");
        for (float bad : {0.f, -1.f, 11.f}) {
            par = Defaults(h, kSplit);
            par.setValue("LocateTolerance", FloatValue(bad));
            ExpectRefused(h, par, "locate tolerance");
        }
    }
    {
        PluginHarness h;
        TMesh cube, poly;
        MakeCube(cube, 3);
        MakePolyline(poly, {P3(1, 0.1f, 0.2f), P3(1.02f, 0.3f, 0.4f)});
        h.AddCopyOf(cube);
        AddPolylineLayer(h, poly, "mesh_front");
        ExpectRefused(h, "from the surface");
    }
    {  // a polyline crossing itself
        PluginHarness h;
        TMesh cube, poly;
        MakeCube(cube, 3, 0.2f, 4);
        MakePolyline(poly, {P3(1, -0.8f, -0.8f), P3(1, 0.8f, 0.7f), P3(1, 0.8f, -0.75f), P3(1, -0.7f, 0.8f)});
        h.AddCopyOf(cube);
        AddPolylineLayer(h, poly, "mesh_front");
        ExpectRefused(h, "cross");
    }
    {  // non-manifold mesh (a fin of three faces on one edge)
        PluginHarness h;
        h.AddMesh({vcg::Point3f(0, 0, 0), vcg::Point3f(1, 0, 0), vcg::Point3f(0, 1, 0), vcg::Point3f(0, -1, 0),
                   vcg::Point3f(0, 0, 1)},
                  {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
        TMesh poly;
        MakePolyline(poly, {P3(0.2f, 0.1f, 0), P3(0.3f, 0.3f, 0)});
        AddPolylineLayer(h, poly, "mesh_front");
        ExpectRefused(h, "not 2-manifold");
    }
    {  // NaN coordinates
        PluginHarness h;
        TMesh cube, poly;
        MakeSectionedCube(h, cube, poly);
        h.doc.mm()->cm.vert[3].P()[0] = std::numeric_limits<float>::quiet_NaN();
        ExpectRefused(h, "NaN");
    }
}

// Segmentation + smoothing + splitting on fandisk and elephant.
TEST(SplitPlugin, PipelineOnFandiskAndElephant)
{
    for (const char *name : {"fandisk", "elephant"}) {
        SCOPED_TRACE(name);
        PluginHarness h;
        ASSERT_NE(LoadTriangleOff(h, MeshDir() + "/" + name + ".off"), nullptr);
        ASSERT_TRUE(h.Apply(kVsa).ok);
        FilterRun smooth = RunFilter(h, kSmooth);
        ASSERT_TRUE(smooth.ok) << smooth.error;
        MeshModel *mesh = h.doc.mm();
        TMesh before, polyline;
        ToTMesh(mesh->cm, before, true);
        MeshModel *front = Layer(h, "mesh_front");
        ASSERT_NE(front, nullptr);
        ASSERT_EQ(Defaults(h, kSplit).getMesh("PolylineLayer"), front);
        ToPolyline(front->cm, polyline);

        FilterRun r = RunFilter(h, kSplit);
        ASSERT_TRUE(r.ok) << r.error;
        for (auto &l : r.log) std::printf("  %s: %s\n", name, l.c_str());
        EXPECT_TRUE(r.Logged("(0 traced")) << "consecutive front points share a face";
        TMesh after;
        ToTMesh(mesh->cm, after, true);
        EXPECT_GT(after.fn, before.fn);
        SplitExpectations x;
        x.segmentsAreEdges = true;  // every consecutive pair of front points is a selected mesh edge
        ExpectSplitInvariants(before, after, polyline, x);
    }
}

// The front saved as OBJ (6 decimals) and loaded back as a layer splits the mesh the same way.
TEST(SplitPlugin, FrontReadBackWithSixDecimalsGivesTheSameSplit)
{
    PluginHarness exact, rounded;
    for (PluginHarness *h : {&exact, &rounded}) {
        ASSERT_NE(LoadTriangleOff(*h, MeshDir() + "/elephant.off"), nullptr);
        ASSERT_TRUE(h->Apply(kVsa).ok);
        ASSERT_TRUE(RunFilter(*h, kSmooth).ok);
    }
    MeshModel *front = Layer(rounded, "mesh_front");
    TMesh poly, back;
    ToPolyline(front->cm, poly);
    RoundTripObj6(poly, back);
    int moved = 0;
    for (int i = 0; i < front->cm.vn; ++i) {
        moved += front->cm.vert[i].P() != back.vert[i].P();
        front->cm.vert[i].P() = back.vert[i].P();
    }
    EXPECT_GT(moved, front->cm.vn / 2) << "the 6-decimal round trip moves the points off their edges";
    FilterRun a = RunFilter(exact, kSplit), b = RunFilter(rounded, kSplit);
    ASSERT_TRUE(a.ok) << a.error;
    ASSERT_TRUE(b.ok) << b.error;
    ASSERT_EQ(a.log.size(), b.log.size());
    for (size_t i = 0; i < a.log.size(); ++i) {  // same counts (the timing differs)
        const std::string la = a.log[i].substr(0, a.log[i].find(" deg;")), lb = b.log[i].substr(0, b.log[i].find(" deg;"));
        EXPECT_EQ(la.substr(0, la.rfind("min angle")), lb.substr(0, lb.rfind("min angle")));
    }
    EXPECT_EQ(exact.doc.mm()->cm.fn, rounded.doc.mm()->cm.fn);
    EXPECT_EQ(vcg_ext::FrontEdges<CMeshO>::Collect(exact.doc.mm()->cm), vcg_ext::FrontEdges<CMeshO>::Collect(rounded.doc.mm()->cm));
}

// After Split Triangles along Front the GUI keeps the mesh's shading (flat: face normals; smooth:
// vertex normals) and shows the new patch colours.
TEST(SplitPlugin, TheGuiKeepsTheShadingOfTheMesh)
{
    typedef MLRenderingData::ATT_NAMES A;
    for (bool flat : {true, false}) {
        PluginHarness h;
        TMesh cube, poly;
        MakeSectionedCube(h, cube, poly);
        const MLRenderingData::RendAtts after = ExpectShadingKept(h, kSplit, flat);
        EXPECT_TRUE(after[A::ATT_FACECOLOR]);
        EXPECT_FALSE(after[A::ATT_VERTCOLOR]);
    }
    // The mechanism: declaring vertex normals changed turns flat shading into per-vertex shading.
    MLRenderingData::RendAtts flat, changed, after;
    flat[A::ATT_VERTPOSITION] = flat[A::ATT_FACENORMAL] = true;
    MLPoliciesStandAloneFunctions::fromMeshModelMaskToMLRenderingAtts(MeshModel::MM_VERTNORMAL, changed);
    MLPoliciesStandAloneFunctions::updatedRendAttsAccordingToPriorities(MLRenderingData::PR_SOLID, changed, flat, after);
    EXPECT_TRUE(after[A::ATT_VERTNORMAL] && !after[A::ATT_FACENORMAL]);
}
