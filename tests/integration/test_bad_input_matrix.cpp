// The bad-input matrix (tests/support/bad_input_cases.h) through the real meshlabserver: each row
// and filter as one call running that filter alone (its block of the shipped
// closed_mesh_to_quads.mlx, default parameters unless the row sets one out of range) on a PLY
// carrying the row's region ids (face quality) and selection (face flags), with the front polyline
// as a second layer for the splitting. Refused: a failing exit status, the message in the log (and
// the MeshLab filter that fixes it), no output file; run: status 0 and the output written. Plus a
// garbage file, which meshlabserver itself refuses to load.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "bad_input_cases.h"
#include "meshlab_runner.h"

using namespace qmf_test;
using namespace qmf_test::bad_input;

namespace {

const int kFaceEdgeSel0 = 0x8000;  // vcg's FACEEDGESEL0; edge k is this << k (PLY face flags)

void WritePly(const std::string &path, const Input &in)
{
    std::ofstream out(path);
    out << "ply\nformat ascii 1.0\nelement vertex " << in.v.size() << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "element face " << in.f.size() << "\nproperty list uchar int vertex_indices\n";
    if (in.hasLabels) out << "property float quality\n";
    if (in.hasSelection) out << "property int flags\n";
    out << "end_header\n";
    char buf[128];
    for (auto &p : in.v) {
        std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g\n", p[0], p[1], p[2]);
        out << buf;
    }
    for (size_t i = 0; i < in.f.size(); ++i) {
        out << "3 " << in.f[i][0] << " " << in.f[i][1] << " " << in.f[i][2];
        if (in.hasLabels) out << " " << in.label[i];
        if (in.hasSelection) {
            int flags = 0;
            for (int k = 0; k < 3; ++k) flags |= in.creaseSel[3 * i + k] ? kFaceEdgeSel0 << k : 0;
            out << " " << flags;
        }
        out << "\n";
    }
}

void WriteObjPolylines(const std::string &path, const Input &in)
{
    std::ofstream out(path);
    int base = 1;
    for (const auto &loop : in.fronts) {
        for (auto &p : loop) out << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
        for (size_t i = 0; i < loop.size(); ++i) out << "l " << base + i << " " << base + (i + 1) % loop.size() << "\n";
        base += int(loop.size());
    }
}

// The filter's block of the shipped whole-pipeline script, as a script of its own.
std::string FilterScript(int filter, const BadParam &bad)
{
    const std::string all = ReadText(Script("closed_mesh_to_quads.mlx"));
    const std::string open = std::string("<filter name=\"") + FilterName(filter) + "\"";
    const size_t from = all.find(open), to = all.find("</filter>", from);
    EXPECT_NE(from, std::string::npos) << FilterName(filter);
    std::string block = all.substr(from, to + 9 - from);
    // the front is loaded first (layer 0), the mesh last (the current layer)
    if (filter == FilterSplit) block = std::regex_replace(block, std::regex("name=\"PolylineLayer\" value=\"1\""), "name=\"PolylineLayer\" value=\"0\"");
    if (!bad.name.empty())
        block = std::regex_replace(block, std::regex("name=\"" + bad.name + "\" value=\"[^\"]*\""),
                                   "name=\"" + bad.name + "\" value=\"" + bad.value + "\"");
    return "<!DOCTYPE FilterScript>\n<FilterScript>\n " + block + "\n</FilterScript>\n";
}

void RunRow(const Case &c)
{
    const Input in = c.make();
    for (int filter = 0; filter < FilterCount; ++filter) {
        SCOPED_TRACE(c.name + " / " + FilterName(filter));
        const std::string dir = WorkDir("bad_input_" + c.name + "_" + std::to_string(filter + 1));
        WritePly(dir + "/in.ply", in);
        std::string inputs = "-i in.ply";
        if (filter == FilterSplit && in.hasFrontLayer) {
            WriteObjPolylines(dir + "/front.obj", in);
            inputs = "-i front.obj -i in.ply";
        }
        std::ofstream(dir + "/filter.mlx") << FilterScript(filter, c.param[filter]);
        const RunResult r = RunMeshLabServer(dir, inputs + " -o out.ply -m ff fq -s filter.mlx");
        const Outcome &o = c.outcome[filter];
        if (o.Runs()) {
            EXPECT_EQ(r.exitCode, 0) << r.output;
            EXPECT_TRUE(FileExists(dir + "/out.ply")) << r.output;
            continue;
        }
        EXPECT_NE(r.exitCode, 0) << r.output;
        const size_t at = r.output.find(std::string(FilterName(filter)) + ": ");
        ASSERT_NE(at, std::string::npos) << "the refusal must be logged\n" << r.output;
        EXPECT_NE(r.output.find(o.refusal, at), std::string::npos) << r.output;
        if (!o.fix.empty()) {
            EXPECT_NE(r.output.find("'" + o.fix + "'", at), std::string::npos) << r.output;
        }
        EXPECT_FALSE(FileExists(dir + "/out.ply")) << "no output file on a refusal";
    }
}

}  // namespace

class BadInputMatrix : public ::testing::TestWithParam<Case> {};

TEST_P(BadInputMatrix, EveryFilterRefusesOrRuns) { RunRow(GetParam()); }

INSTANTIATE_TEST_SUITE_P(MeshLabServer, BadInputMatrix, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<Case> &i) { return i.param.name; });

// Not a mesh at all: meshlabserver's own importer refuses it, before any filter; nothing written.
TEST(BadInputMatrixFile, GarbageFileIsRefusedBeforeAnyFilter)
{
    for (int filter = 0; filter < FilterCount; ++filter) {
        const std::string dir = WorkDir("bad_input_garbage_" + std::to_string(filter + 1));
        std::ofstream(dir + "/in.ply") << "ply\nformat ascii 1.0\nelement vertex 3\nthis is not a mesh \x01\x02\xff\n";
        std::ofstream(dir + "/filter.mlx") << FilterScript(filter, BadParam());
        const RunResult r = RunMeshLabServer(dir, "-i in.ply -o out.ply -s filter.mlx");
        EXPECT_NE(r.exitCode, 0) << r.output;
        EXPECT_EQ(r.output.find(std::string(FilterName(filter)) + ":"), std::string::npos) << "no filter ran\n" << r.output;
        EXPECT_FALSE(FileExists(dir + "/out.ply"));
    }
}
