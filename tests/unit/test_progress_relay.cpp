// The progress relay (common/progress_relay.h): the work runs on a worker thread, MeshLab's
// callback only on the calling thread, the last report repeated while a step is busy; the core's
// entry points give the same output with a callback as without.
#include <gtest/gtest.h>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>
#include "quad_checks.h"
#include "test_mesh.h"
#include <vcg_ext/common/progress_relay.h>
#include <vcg_ext/qmorph.h>
#include <vcg_ext/vsa_segmentation.h>

using namespace qmf_test;
using vcg_ext::ProgressRelay;

namespace {

// What the callback saw; the callback is a plain function pointer, so it records into a global.
struct Seen {
    std::mutex mutex;
    std::condition_variable changed;
    std::vector<std::thread::id> threads;
    std::vector<int> percents;
    std::vector<std::string> messages;
    void Clear()
    {
        std::lock_guard<std::mutex> lock(mutex);
        threads.clear();
        percents.clear();
        messages.clear();
    }
    int Count(int percent, const std::string &message)
    {
        std::lock_guard<std::mutex> lock(mutex);
        int n = 0;
        for (size_t i = 0; i < percents.size(); ++i) n += percents[i] == percent && messages[i] == message;
        return n;
    }
} g_seen;

bool Record(const int percent, const char *message)
{
    std::lock_guard<std::mutex> lock(g_seen.mutex);
    g_seen.threads.push_back(std::this_thread::get_id());
    g_seen.percents.push_back(percent);
    g_seen.messages.push_back(message ? message : "");
    g_seen.changed.notify_all();
    return true;
}

}  // namespace

TEST(ProgressRelay, TheCallbackRunsOnTheCallingThreadAndTheWorkOnAnother)
{
    g_seen.Clear();
    const std::thread::id caller = std::this_thread::get_id();
    std::thread::id workThread;
    const int result = ProgressRelay::Run(&Record, [&](vcg::CallBackPos *report) {
        workThread = std::this_thread::get_id();
        for (int i = 0; i <= 100; i += 10) report(i, ("step " + std::to_string(i)).c_str());
        return 42;
    });
    EXPECT_EQ(result, 42);
    EXPECT_NE(workThread, caller);
    ASSERT_FALSE(g_seen.threads.empty());
    for (std::thread::id t : g_seen.threads) EXPECT_EQ(t, caller) << "the callback left the calling thread";
    // reports may be coalesced, but the last one always arrives (with its own text: the work's
    // string died with its loop iteration)
    EXPECT_EQ(g_seen.percents.back(), 100);
    EXPECT_EQ(g_seen.messages.back(), "step 100");
}

TEST(ProgressRelay, RepeatsTheLastReportWhileTheWorkIsBusy)
{
    g_seen.Clear();
    // The work reports once and then stays busy until the caller has been told three times (a
    // step of one indivisible call). Without the heartbeat it would wait for the liveness bound.
    const int repeats = ProgressRelay::Run(&Record, [&](vcg::CallBackPos *report) {
        report(7, "one long step");
        std::unique_lock<std::mutex> lock(g_seen.mutex);
        g_seen.changed.wait_for(lock, std::chrono::seconds(60), [&]() {
            int n = 0;
            for (size_t i = 0; i < g_seen.percents.size(); ++i) n += g_seen.percents[i] == 7;
            return n >= 3;
        });
        return 0;
    });
    EXPECT_EQ(repeats, 0);
    EXPECT_GE(g_seen.Count(7, "one long step"), 3) << "the busy step was not repeated to the caller";
}

TEST(ProgressRelay, WithoutACallbackOrInsideARelayTheWorkRunsInline)
{
    const std::thread::id caller = std::this_thread::get_id();
    std::thread::id plain, outer, inner;
    ProgressRelay::Run(nullptr, [&](vcg::CallBackPos *report) {
        EXPECT_EQ(report, nullptr);
        plain = std::this_thread::get_id();
        return 0;
    });
    EXPECT_EQ(plain, caller);
    g_seen.Clear();
    ProgressRelay::Run(&Record, [&](vcg::CallBackPos *report) {
        outer = std::this_thread::get_id();
        return ProgressRelay::Run(report, [&](vcg::CallBackPos *nested) {
            inner = std::this_thread::get_id();
            nested(50, "nested");
            return 0;
        });
    });
    EXPECT_NE(outer, caller);
    EXPECT_EQ(inner, outer) << "a relay inside the work must not start another thread";
    EXPECT_GE(g_seen.Count(50, "nested"), 1);
}

TEST(ProgressRelay, AnExceptionInTheWorkReachesTheCaller)
{
    EXPECT_THROW(ProgressRelay::Run(&Record, [](vcg::CallBackPos *report) -> int {
                     report(1, "about to fail");
                     throw std::runtime_error("failed");
                 }),
                 std::runtime_error);
}

// VSA and Q-Morph with a callback: every call on the calling thread, the same output as without.
TEST(ProgressRelay, VsaAndQMorphWriteTheSameWithACallbackAndCallItOnTheCallingThread)
{
    TMesh base;
    ASSERT_TRUE(LoadOff(base, MeshDir() + "/fandisk.off"));
    std::vector<unsigned char> reference;
    for (bool withCallback : {false, true}) {
        g_seen.Clear();
        TMesh m;
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, base);
        vcg::CallBackPos *cb = withCallback ? &Record : nullptr;
        const auto segmented = vcg_ext::VSASegmentation<TMesh>::Segment(m, vcg_ext::VSASegmentation<TMesh>::Params(), cb);
        ASSERT_EQ(segmented.error, "");
        ASSERT_GT(SelectRegionBoundaries(m), 0);
        const auto meshed = vcg_ext::QMorph<TMesh>::Apply(m, vcg_ext::QMorph<TMesh>::Params(), cb);
        ASSERT_EQ(meshed.error, "");
        if (!withCallback) {
            reference = MeshBytes(m);
            continue;
        }
        EXPECT_TRUE(MeshBytes(m) == reference) << "the callback changed the output";
        // reports may be coalesced (a fast machine can finish a stage between two wake-ups of the
        // calling thread), but each stage's last one reaches the caller
        ASSERT_GE(g_seen.threads.size(), 2u);
        for (std::thread::id t : g_seen.threads) EXPECT_EQ(t, std::this_thread::get_id());
        int vsa = 0, qmorph = 0;
        for (const std::string &message : g_seen.messages) {
            vsa += message.rfind("VSA:", 0) == 0;
            qmorph += message.rfind("Q-Morph:", 0) == 0;
        }
        EXPECT_GE(vsa, 1);
        EXPECT_GE(qmorph, 1);
    }
}
