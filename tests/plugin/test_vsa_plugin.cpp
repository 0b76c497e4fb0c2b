// Filter 1 in-process: output contract and bad input.
#include <gtest/gtest.h>

#include <limits>

#include "plugin_harness.h"

using namespace qmf_test;

namespace {

void MakeOctahedron(PluginHarness &h)
{
    h.AddMesh({vcg::Point3f(1, 0, 0), vcg::Point3f(-1, 0, 0), vcg::Point3f(0, 1, 0), vcg::Point3f(0, -1, 0),
               vcg::Point3f(0, 0, 1), vcg::Point3f(0, 0, -1)},
              {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
}

// Bad input: false, message in errorMessage and in the log, mesh untouched.
void ExpectRefused(PluginHarness &h, const RichParameterList &par, const std::string &expected)
{
    qmf_test::ExpectRefused(h, kVsa, par, expected);
}
}  // namespace

TEST(VsaPlugin, WritesRegionIdsColoursAndLog)
{
    PluginHarness h;
    MakeOctahedron(h);
    RichParameterList par = h.Defaults(kVsa);
    par.setValue("SeedingMode", EnumValue(1));
    par.setValue("MaxRegions", IntValue(8));
    FilterRun r = h.Apply(kVsa, par);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_TRUE(r.Logged("VSA: 8 regions on 8 faces"));
    MeshModel &mm = *h.doc.mm();
    ASSERT_TRUE(mm.hasDataMask(MeshModel::MM_FACEQUALITY));
    ASSERT_TRUE(mm.hasDataMask(MeshModel::MM_FACECOLOR));
    std::set<int> ids;
    std::set<unsigned> colours;
    for (auto &f : mm.cm.face) {
        ids.insert(int(f.Q()));
        EXPECT_EQ(f.Q(), std::round(f.Q()));
        colours.insert(unsigned(f.C()[0]) << 16 | unsigned(f.C()[1]) << 8 | f.C()[2]);
    }
    EXPECT_EQ(ids, (std::set<int>{0, 1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(colours.size(), 8u) << "one distinct colour per region";
}

TEST(VsaPlugin, ColourIsOptional)
{
    PluginHarness h;
    MakeOctahedron(h);
    RichParameterList par = h.Defaults(kVsa);
    par.setValue("ColorByRegion", BoolValue(false));
    ASSERT_TRUE(h.Apply(kVsa, par).ok);
    EXPECT_FALSE(h.doc.mm()->hasDataMask(MeshModel::MM_FACECOLOR));
    EXPECT_TRUE(h.doc.mm()->hasDataMask(MeshModel::MM_FACEQUALITY));
}

TEST(VsaPlugin, RefusesEmptyMeshAndPointCloud)
{
    PluginHarness h;
    h.AddMesh({}, {});
    ExpectRefused(h, h.Defaults(kVsa), "the mesh is empty");
    PluginHarness p;
    p.AddMesh({vcg::Point3f(0, 0, 0), vcg::Point3f(1, 0, 0)}, {});
    ExpectRefused(p, p.Defaults(kVsa), "no faces");
}

TEST(VsaPlugin, RefusesNonFiniteCoordinates)
{
    for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
        PluginHarness h;
        MakeOctahedron(h);
        h.doc.mm()->cm.vert[4].P()[2] = bad;
        ExpectRefused(h, h.Defaults(kVsa), "NaN or infinite");
    }
}

TEST(VsaPlugin, RefusesParametersOutOfRange)
{
    struct Case { const char *name; int value; bool isFloat; const char *message; };
    const Case cases[] = {{"ThresholdAngle", 0, true, "threshold angle"},   {"ThresholdAngle", 180, true, "threshold angle"},
                          {"ThresholdAngle", -3, true, "threshold angle"},  {"MaxRegions", -1, false, "max regions"},
                          {"InitialSeeds", 0, false, "initial seeds"},      {"MaxIterations", 0, false, "max iterations"},
                          {"SeedingMode", 7, false, "seeding mode"}};
    for (const Case &c : cases) {
        PluginHarness h;
        MakeOctahedron(h);
        RichParameterList par = h.Defaults(kVsa);
        if (c.isFloat) par.setValue(c.name, FloatValue(float(c.value)));
        else if (std::string(c.name) == "SeedingMode") par.setValue(c.name, EnumValue(c.value));
        else par.setValue(c.name, IntValue(c.value));
        SCOPED_TRACE(c.name);
        ExpectRefused(h, par, c.message);
    }
}

TEST(VsaPlugin, AcceptsOpenAndNonManifoldMeshes)
{
    PluginHarness h;  // a fin: three triangles on one edge, plus an open boundary
    h.AddMesh({vcg::Point3f(0, 0, 0), vcg::Point3f(1, 0, 0), vcg::Point3f(0, 1, 0), vcg::Point3f(0, -1, 0),
               vcg::Point3f(0, 0, 1)},
              {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    FilterRun r = h.Apply(kVsa);
    ASSERT_TRUE(r.ok) << r.error;
    for (auto &f : h.doc.mm()->cm.face) EXPECT_GE(f.Q(), 0.f);
}

// At the first filter of the pipeline: unmerged vertices and inconsistent orientation are refused
// with the MeshLab filter that fixes them (mesh untouched); a non-manifold mesh is segmented with a
// warning in the log naming its fix (the later filters refuse it).
TEST(VsaPlugin, NamesTheFixOfBadInputAtTheFirstFilter)
{
    TMesh cube;
    MakeCube(cube, 3);
    {
        PluginHarness h;  // a triangle soup: every face with its own vertices
        std::vector<vcg::Point3f> v;
        std::vector<std::array<int, 3>> f;
        for (auto &face : cube.face) {
            f.push_back({int(v.size()), int(v.size()) + 1, int(v.size()) + 2});
            for (int k = 0; k < 3; ++k) v.push_back(face.V(k)->P());
        }
        h.AddMesh(v, f);
        ExpectRefused(h, h.Defaults(kVsa), "run 'Merge Close Vertices' first");
    }
    {
        PluginHarness h;
        MeshModel *mm = h.AddCopyOf(cube);
        std::swap(mm->cm.face[3].V(0), mm->cm.face[3].V(1));
        ExpectRefused(h, h.Defaults(kVsa), "run 'Re-Orient all faces coherentely' first");
    }
    {
        PluginHarness h;  // a bow tie: a triangle hanging on one corner of the cube
        std::vector<vcg::Point3f> v;
        std::vector<std::array<int, 3>> f;
        for (auto &x : cube.vert) v.push_back(x.P());
        for (auto &x : cube.face)
            f.push_back({int(vcg::tri::Index(cube, x.V(0))), int(vcg::tri::Index(cube, x.V(1))), int(vcg::tri::Index(cube, x.V(2)))});
        const int corner = f[0][0];
        v.push_back(v[corner] * 2);
        v.push_back(v[corner] * 2 + vcg::Point3f(0.5f, 0, 0));
        f.push_back({corner, int(v.size()) - 2, int(v.size()) - 1});
        h.AddMesh(v, f);
        FilterRun r = h.Apply(kVsa);
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_TRUE(r.Logged("Segment by Variational Shape Approximation: warning: the mesh is not 2-manifold"));
        EXPECT_TRUE(r.Logged("run 'Repair non Manifold Vertices by splitting' first")) << r.log.front();
    }
    {
        PluginHarness h;  // inward-pointing faces: valid, no warning
        MeshModel *mm = h.AddCopyOf(cube);
        for (auto &x : mm->cm.face) std::swap(x.V(1), x.V(2));
        FilterRun r = h.Apply(kVsa);
        ASSERT_TRUE(r.ok) << r.error;
        EXPECT_FALSE(r.Logged("warning"));
    }
}
