// Progress through MeshLab's callback: the four filters on fandisk call it on the thread that
// entered applyFilter only (it touches Qt widgets), with percents in 0..100 and each filter's own
// messages, and write the same mesh as without a callback.
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "plugin_harness.h"
#include "test_mesh.h"

using namespace qmf_test;

namespace {

struct Call {
    std::thread::id thread;
    int percent;
    std::string message;
};
std::vector<Call> g_calls;  // appended under no lock: a call from another thread is itself the failure checked

bool Record(const int percent, const char *message)
{
    g_calls.push_back({std::this_thread::get_id(), percent, message ? message : ""});
    return true;
}

const char *const kFilters[] = {"Segment by Variational Shape Approximation", "Smooth Region Boundaries",
                                "Split Triangles along Front", "Q-Morph Quad Conversion"};

// The four filters with their defaults; returns the output's face corners and flags.
std::vector<float> RunPipeline(vcg::CallBackPos *cb, std::vector<std::vector<Call>> *calls)
{
    PluginHarness h;
    h.callback = cb;
    MeshModel *mm = h.LoadOff(MeshDir() + "/fandisk.off");
    EXPECT_NE(mm, nullptr);
    if (!mm) return {};
    for (const char *f : kFilters) {
        g_calls.clear();
        if (std::string(f) == kFilters[3]) h.doc.setCurrentMesh(mm->id());
        FilterRun r = h.Apply(f);
        EXPECT_TRUE(r.ok) << f << ": " << r.error;
        if (calls) calls->push_back(g_calls);
    }
    std::vector<float> out;
    for (const CFaceO &face : mm->cm.face) {
        if (face.IsD()) continue;
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) out.push_back(face.cP(k)[c]);
        out.push_back(float(face.cFlags()));
    }
    return out;
}

}  // namespace

TEST(ProgressPlugin, EveryFilterReportsOnTheCallingThreadAndWritesTheSameMesh)
{
    const std::vector<float> reference = RunPipeline(nullptr, nullptr);
    std::vector<std::vector<Call>> calls;
    const std::vector<float> withProgress = RunPipeline(&Record, &calls);
    ASSERT_FALSE(reference.empty());
    EXPECT_TRUE(withProgress == reference) << "the callback changed the output";
    ASSERT_EQ(calls.size(), 4u);
    const std::string prefixes[] = {"VSA:", "Region boundaries:", "Split along front:", "Q-Morph:"};
    for (size_t i = 0; i < calls.size(); ++i) {
        ASSERT_FALSE(calls[i].empty()) << kFilters[i] << " reported no progress";
        int own = 0;
        for (const Call &c : calls[i]) {
            EXPECT_EQ(c.thread, std::this_thread::get_id()) << kFilters[i] << ": " << c.message;
            EXPECT_GE(c.percent, 0);
            EXPECT_LE(c.percent, 100);
            own += c.message.rfind(prefixes[i], 0) == 0;
        }
        // reports may be coalesced on a fast machine, but the core's last one always arrives
        // (every core message carries its stage's prefix for that reason)
        EXPECT_GT(own, 0) << kFilters[i];
    }
}
