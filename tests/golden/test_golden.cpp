// The golden-output gate: every filter with its default parameters (and the whole pipeline) on a
// cube, a graded strip, fandisk and elephant, each stage's document, log and exported file reduced
// to a digest and compared with the committed value in golden_values.txt. A refactoring must keep
// every digest; a change of behaviour on purpose updates the file in a commit of its own:
//   QMF_GOLDEN_OUT=/tmp/golden.txt build/tests/golden_tests; cp /tmp/golden.txt tests/golden/golden_values.txt
// Digests hold for the regular g++ build (RelWithDebInfo, x86-64): floating point is not
// reassociated there, so the figures are bit-exact.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "plugin_harness.h"  // first: it includes the OFF importer in the order GLU needs
#include "document_digest.h"
#include "planar_domains.h"
#include "test_mesh.h"

using namespace qmf_test;

namespace {

std::map<std::string, std::string> LoadGolden()
{
    std::map<std::string, std::string> golden;
    std::ifstream in(QMF_GOLDEN_VALUES);
    std::string name, digest;
    while (in >> name >> digest) golden[name] = digest;
    return golden;
}

// Compares the digest of one stage with its committed value (and records it for regeneration).
void ExpectGolden(const std::string &name, const Digest &d)
{
    static const std::map<std::string, std::string> golden = LoadGolden();
    if (const char *out = std::getenv("QMF_GOLDEN_OUT")) std::ofstream(out, std::ios::app) << name << " " << d.Hex() << "\n";
    auto it = golden.find(name);
    ASSERT_NE(it, golden.end()) << "no golden value for " << name << " (computed " << d.Hex() << ")";
    EXPECT_EQ(it->second, d.Hex()) << name << ": the output changed";
}

// Applies a filter and checks the digest of the document, the log and the exported file.
void RunStage(PluginHarness &h, const std::string &name, const QString &filter, const RichParameterList &par,
              const std::string &exported = "")
{
    FilterRun r = h.Apply(filter, par);
    ASSERT_TRUE(r.ok) << name << ": " << r.error;
    Digest d;
    AddDocument(d, h.doc);
    AddLog(d, r.log);
    if (!exported.empty()) {
        ASSERT_TRUE(AddFile(d, exported)) << exported;
    }
    ExpectGolden(name, d);
}

// Filters 1-4 one after another with their defaults; Q-Morph also exports its quads.
void RunPipeline(PluginHarness &h, const std::string &name)
{
    MeshModel *mm = h.doc.mm();
    const std::pair<const char *, QString> stages[] = {{"vsa", kVsa}, {"smooth", kSmooth}, {"split", kSplit}};
    for (const auto &s : stages) {
        RunStage(h, name + "/" + s.first, s.second, h.Defaults(s.second));
        h.doc.setCurrentMesh(mm->id());
    }
    const std::string exported = std::string(QMF_TEST_WORK_DIR) + "/golden_" + name + ".obj";
    std::remove(exported.c_str());
    RichParameterList par = h.Defaults(kQMorph);
    par.setValue("ExportPath", FileValue(QString::fromStdString(exported)));
    RunStage(h, name + "/qmorph", kQMorph, par, exported);
}

}  // namespace

TEST(Golden, CubeWholePipeline)
{
    PluginHarness h;
    TMesh t;
    MakeCube(t, 6, 0.2f, 3);
    h.AddCopyOf(t);
    RunPipeline(h, "cube");
}

// Q-Morph alone from a selection of crease edges (as MeshLab's 'Select Crease Edges' makes it).
TEST(Golden, CubeQMorphFromCreases)
{
    PluginHarness h;
    AddCubeWithCreasesSelected(h);
    RunStage(h, "cube_creases/qmorph", kQMorph, h.Defaults(kQMorph));
}

// Q-Morph alone on an open strip whose boundary edges are 8x finer below than above (transitions).
TEST(Golden, GradedStripQMorph)
{
    PluginHarness h;
    TMesh t;
    MakeGradedStrip(t, 48, 6, 0.3, 1);
    h.AddCopyOf(t);
    RunStage(h, "graded_strip/qmorph", kQMorph, h.Defaults(kQMorph));
}

TEST(Golden, FandiskWholePipeline)
{
    PluginHarness h;
    ASSERT_NE(h.LoadOff(MeshDir() + "/fandisk.off"), nullptr);
    RunPipeline(h, "fandisk");
}

// Q-Morph's optional re-meshing at 1% of the diagonal, after filters 1-3.
TEST(Golden, FandiskRemeshed)
{
    PluginHarness h;
    MeshModel *mm = h.LoadOff(MeshDir() + "/fandisk.off");
    ASSERT_NE(mm, nullptr);
    for (const QString &f : {kVsa, kSmooth, kSplit}) {
        ASSERT_TRUE(h.Apply(f).ok) << f.toStdString();
        h.doc.setCurrentMesh(mm->id());
    }
    RichParameterList par = h.Defaults(kQMorph);
    par.setValue("TargetEdgeLength", AbsPercValue(0.01f * mm->cm.bbox.Diag()));
    RunStage(h, "fandisk_remeshed/qmorph", kQMorph, par);
}

TEST(Golden, ElephantWholePipeline)
{
    PluginHarness h;
    ASSERT_NE(h.LoadOff(MeshDir() + "/elephant.off"), nullptr);
    RunPipeline(h, "elephant");
}
