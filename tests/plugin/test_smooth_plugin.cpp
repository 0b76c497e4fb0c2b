// Filter 2 in-process: the front layer (contract for filter 3), the source mesh left untouched,
// defaults, re-runs, and bad input (false, message in the log, mesh and document unchanged).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "boundary_test_meshes.h"
#include "plugin_harness.h"

using namespace qmf_test;

namespace {

RichParameterList Defaults(PluginHarness &h, const QString &filter) { return h.Defaults(filter); }
FilterRun RunFilter(PluginHarness &h, const QString &filter) { return h.Apply(filter, Defaults(h, filter)); }

// An n x n-per-side cube (irregular inside each side) with region ids = side (0..5).
MeshModel *AddLabelledCube(PluginHarness &h, int n)
{
    TMesh t;
    MakeCube(t, n, 0.3f, 9);
    MeshModel *mm = h.AddCopyOf(t);
    mm->updateDataMask(MeshModel::MM_FACEQUALITY);
    for (auto &f : mm->cm.face) {
        vcg::Point3f c = (f.P(0) + f.P(1) + f.P(2)) / 3.f;
        int axis = 0;
        for (int k = 1; k < 3; ++k)
            if (std::fabs(c[k]) > std::fabs(c[axis])) axis = k;
        f.Q() = float(2 * axis + (c[axis] > 0 ? 1 : 0));
    }
    return mm;
}

void ExpectRefused(PluginHarness &h, const RichParameterList &par, const std::string &expected)
{
    qmf_test::ExpectRefused(h, kSmooth, par, expected);
}

bool OnCubeEdge(const vcg::Point3f &p)
{
    int atFace = 0;
    for (int k = 0; k < 3; ++k) atFace += std::fabs(std::fabs(p[k]) - 1.f) < 1e-6f;
    return atFace >= 2;
}
}  // namespace

TEST(SmoothPlugin, DefaultsAreThePapers)
{
    PluginHarness h;
    AddLabelledCube(h, 2);
    RichParameterList par = Defaults(h, kSmooth);
    EXPECT_EQ(par.getInt("Iterations"), 3);
    EXPECT_FLOAT_EQ(par.getFloat("SnapDistance"), 25.f);
    EXPECT_EQ(par.getInt("MinRegionFaces"), 0);
}

TEST(SmoothPlugin, CubeGivesAFrontLayerAndLeavesTheMeshUntouched)
{
    const int n = 4;
    PluginHarness h;
    MeshModel *mesh = AddLabelledCube(h, n);
    MeshSnapshot before = MeshSnapshot::Of(*mesh);
    FilterRun r = RunFilter(h, kSmooth);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(r.Logged("Smooth Region Boundaries: 12 curves (0 closed loops), 8 corners, " + std::to_string(12 * n) +
                         " boundary edges between 6 regions"));
    EXPECT_TRUE(r.Logged("total length 24 -> 24 (+0.0%)"));
    EXPECT_TRUE(r.Logged("jaggedness"));
    ASSERT_EQ(h.doc.size(), 2);
    EXPECT_EQ(h.doc.mm(), mesh) << "the triangle mesh stays the current layer";
    EXPECT_TRUE(MeshSnapshot::Of(*mesh) == before) << "filter 2 only reads the mesh";
    MeshModel *front = h.doc.meshList.at(1);
    EXPECT_EQ(front->label(), QString("mesh_front"));
    EXPECT_EQ(front->cm.fn, 0);
    // One vertex per point, corners shared by their three curves; the curves stay on the cube edges.
    EXPECT_EQ(front->cm.en, 12 * n);
    EXPECT_EQ(front->cm.vn, 12 * (n + 1) - 2 * 8);
    std::map<int, int> degree;
    for (auto &e : front->cm.edge) {
        ++degree[int(vcg::tri::Index(front->cm, e.V(0)))];
        ++degree[int(vcg::tri::Index(front->cm, e.V(1)))];
    }
    int corners = 0;
    for (auto &d : degree) corners += d.second == 3;
    EXPECT_EQ(corners, 8);
    for (auto &v : front->cm.vert) EXPECT_TRUE(OnCubeEdge(v.P())) << v.P()[0] << " " << v.P()[1] << " " << v.P()[2];
    EXPECT_TRUE(r.Logged("new layer 'mesh_front': " + std::to_string(front->cm.vn) + " vertices, " +
                         std::to_string(front->cm.en) + " edges"));
}

TEST(SmoothPlugin, AfterSegmentationOnAnIrregularMeshCurvesGetShorter)
{
    PluginHarness h;
    ASSERT_NE(h.LoadOff(MeshDir() + "/elephant.off"), nullptr);
    ASSERT_TRUE(RunFilter(h, kVsa).ok);
    MeshSnapshot before = MeshSnapshot::Of(*h.doc.mm());
    FilterRun r = RunFilter(h, kSmooth);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(MeshSnapshot::Of(*h.doc.mm()) == before);
    double lengthBefore = 0, lengthAfter = 0, jagBefore = 0, jagAfter = 0;
    for (auto &line : r.log)
        if (std::sscanf(line.c_str(), "Smooth Region Boundaries: %*d curves (%*d closed loops), %*d corners, %*d boundary "
                                      "edges between %*d regions; total length %lf -> %lf (%*f%%); jaggedness %lf -> %lf",
                        &lengthBefore, &lengthAfter, &jagBefore, &jagAfter) == 4)
            break;
    ASSERT_GT(lengthBefore, 0);
    EXPECT_LT(lengthAfter, 0.95 * lengthBefore) << "the VSA boundaries of an organic mesh are jagged";
    EXPECT_LT(jagAfter, 0.5 * jagBefore);
    // The layer's segments have the logged total length (float coordinates).
    MeshModel *front = h.doc.meshList.at(1);
    double sum = 0;
    for (auto &e : front->cm.edge) sum += vcg::Distance(e.V(0)->P(), e.V(1)->P());
    EXPECT_NEAR(sum, lengthAfter, 1e-4 * lengthAfter);
}

TEST(SmoothPlugin, RunningAgainReplacesTheFrontLayer)
{
    PluginHarness h;
    AddLabelledCube(h, 3);
    ASSERT_TRUE(RunFilter(h, kSmooth).ok);
    RichParameterList par = Defaults(h, kSmooth);
    par.setValue("Iterations", IntValue(0));
    FilterRun r = h.Apply(kSmooth, par);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(h.doc.size(), 2);
    EXPECT_EQ(h.doc.meshList.at(1)->label(), QString("mesh_front"));
    EXPECT_TRUE(r.Logged("replaced the layer 'mesh_front'"));
}

TEST(SmoothPlugin, SmallRegionsCanBeMergedAway)
{
    PluginHarness h;
    MeshModel *mm = AddLabelledCube(h, 4);
    mm->cm.face[20].Q() = 42;  // a one-face region inside side 0 (cell 2,2 of 4 x 4)
    FilterRun plain = RunFilter(h, kSmooth);
    ASSERT_TRUE(plain.ok);
    EXPECT_TRUE(plain.Logged("13 curves (1 closed loops), 8 corners"));
    RichParameterList par = Defaults(h, kSmooth);
    par.setValue("MinRegionFaces", IntValue(3));
    FilterRun merged = h.Apply(kSmooth, par);
    ASSERT_TRUE(merged.ok) << merged.error;
    EXPECT_TRUE(merged.Logged("1 regions smaller than 3 faces merged into a neighbour"));
    EXPECT_TRUE(merged.Logged("12 curves (0 closed loops), 8 corners"));
    EXPECT_EQ(mm->cm.face[20].Q(), 42.f) << "the face quality is not changed";
}

TEST(SmoothPlugin, RefusesAMeshWithoutRegionIds)
{
    PluginHarness h;
    TMesh t;
    MakeCube(t, 2);
    h.AddCopyOf(t);
    ExpectRefused(h, Defaults(h, kSmooth), "no face quality");
}

TEST(SmoothPlugin, RefusesNonIntegralQualityAndASingleRegion)
{
    PluginHarness h;
    MeshModel *mm = AddLabelledCube(h, 2);
    mm->cm.face[3].Q() = 1.5f;
    ExpectRefused(h, Defaults(h, kSmooth), "not an integral region id");
    for (auto &f : mm->cm.face) f.Q() = 7;
    ExpectRefused(h, Defaults(h, kSmooth), "single region id: there is no region boundary to smooth");
}

TEST(SmoothPlugin, RefusesNonManifoldEdgesOnABoundary)
{
    PluginHarness h;  // a fin: three triangles on the edge 0-1, the third one another region
    MeshModel *mm = h.AddMesh({vcg::Point3f(0, 0, 0), vcg::Point3f(1, 0, 0), vcg::Point3f(0, 1, 0), vcg::Point3f(0, -1, 0),
                               vcg::Point3f(0, 0, 1)},
                              {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    mm->updateDataMask(MeshModel::MM_FACEQUALITY);
    mm->cm.face[0].Q() = mm->cm.face[1].Q() = 0;
    mm->cm.face[2].Q() = 1;
    ExpectRefused(h, Defaults(h, kSmooth), "non-manifold edges");
}

// A problem of the mesh is named before one of its region ids (the filter inspects the mesh only
// when the region ids fail; Smooth inspects it on the way through). Without any face quality:
// RefusesEmptyMeshesAndEdgeOnlyLayers.
TEST(SmoothPlugin, NamesAMeshProblemBeforeARegionIdProblem)
{
    PluginHarness h;  // a NaN coordinate and a quality that is no region id
    MeshModel *mm = AddLabelledCube(h, 2);
    mm->cm.vert[4].P()[1] = std::numeric_limits<float>::quiet_NaN();
    mm->cm.face[3].Q() = 1.5f;
    ExpectRefused(h, Defaults(h, kSmooth), "NaN or infinite");
}

TEST(SmoothPlugin, RefusesNonFiniteCoordinates)
{
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        PluginHarness h;
        MeshModel *mm = AddLabelledCube(h, 2);
        mm->cm.vert[4].P()[1] = bad;
        ExpectRefused(h, Defaults(h, kSmooth), "NaN or infinite");
    }
}

TEST(SmoothPlugin, RefusesEmptyMeshesAndEdgeOnlyLayers)
{
    PluginHarness h;
    h.AddMesh({}, {});
    ExpectRefused(h, Defaults(h, kSmooth), "the mesh is empty");
    PluginHarness p;
    AddLabelledCube(p, 2);
    ASSERT_TRUE(RunFilter(p, kSmooth).ok);
    p.doc.setCurrentMesh(p.doc.meshList.at(1)->id());  // the front layer itself
    ExpectRefused(p, Defaults(p, kSmooth), "no faces");
}

TEST(SmoothPlugin, RefusesParametersOutOfRange)
{
    struct Case { const char *name; float value; bool isFloat; const char *message; };
    const Case cases[] = {{"Iterations", -1, false, "iterations must be between 0 and 1000"},
                          {"Iterations", 1001, false, "iterations must be between 0 and 1000"},
                          {"SnapDistance", 0, true, "snap distance"},
                          {"SnapDistance", 46, true, "snap distance"},
                          {"SnapDistance", std::numeric_limits<float>::quiet_NaN(), true, "snap distance"},
                          {"MinRegionFaces", -1, false, "minimum region size"}};
    for (const Case &c : cases) {
        PluginHarness h;
        AddLabelledCube(h, 2);
        RichParameterList par = Defaults(h, kSmooth);
        if (c.isFloat) par.setValue(c.name, FloatValue(c.value));
        else par.setValue(c.name, IntValue(int(c.value)));
        SCOPED_TRACE(std::string(c.name) + " = " + std::to_string(c.value));
        ExpectRefused(h, par, c.message);
    }
}
