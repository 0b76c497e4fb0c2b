// Determinism: the same input and parameters give byte-identical files, run after run (the whole
// shipped pipeline through meshlabserver, each run in a fresh folder and HOME): the PLY with
// faux edges, selection and region ids, the exported OBJ with real quads, and the front layer.
#include <gtest/gtest.h>

#include <fstream>

#include "meshlab_runner.h"

using namespace qmf_test;

namespace {

struct Files {
    std::string ply, obj, front;
};

Files RunOnce(const std::string &mesh, int run)
{
    const std::string dir = WorkDir("determinism_" + mesh + "_" + std::to_string(run));
    std::string script = ReadText(Script("closed_mesh_to_quads.mlx"));
    const std::string from = "name=\"ExportPath\" value=\"\"";
    EXPECT_NE(script.find(from), std::string::npos);
    script.replace(script.find(from), from.size(), "name=\"ExportPath\" value=\"quads.obj\"");
    std::ofstream(dir + "/pipeline.mlx") << script;
    const std::string input = std::string(QMF_TEST_MESH_DIR) + "/" + mesh + ".off";
    const RunResult r = RunMeshLabServer(dir, "-i " + Quote(input) + " -o out.ply -m ff fq fc -o front.obj -l 1 -s pipeline.mlx");
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return {ReadText(dir + "/out.ply"), ReadText(dir + "/quads.obj"), ReadText(dir + "/front.obj")};
}

}  // namespace

TEST(Determinism, TheWholePipelineGivesTheSameBytesTwice)
{
    for (const char *mesh : {"joint", "fandisk"}) {
        SCOPED_TRACE(mesh);
        const Files a = RunOnce(mesh, 1), b = RunOnce(mesh, 2);
        ASSERT_GT(a.ply.size(), 1000u);
        ASSERT_GT(a.obj.size(), 1000u);
        ASSERT_GT(a.front.size(), 100u);
        EXPECT_TRUE(a.ply == b.ply) << "out.ply differs between runs";
        EXPECT_TRUE(a.obj == b.obj) << "quads.obj differs between runs";
        EXPECT_TRUE(a.front == b.front) << "front.obj differs between runs";
    }
}
