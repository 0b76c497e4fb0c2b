// The thread pool (common/parallel.h) and what runs on it: results merged in index order on the
// calling thread whatever the scheduling, so Q-Morph writes the same bytes with 1 thread and with
// several; progress (tick) only from the calling thread.
#include <gtest/gtest.h>
#include <cstring>
#include <stdexcept>
#include <thread>
#include <vector>
#include "quad_checks.h"
#include "test_mesh.h"
#include <vcg_ext/common/parallel.h>
#include <vcg_ext/qmorph.h>
#include <vcg_ext/vsa_segmentation.h>

using namespace qmf_test;
typedef vcg_ext::QMorph<TMesh> QM;

namespace {

// elephant segmented by VSA, its region boundaries selected: well over a hundred patches.
bool LoadElephantWithRegionFronts(TMesh &m)
{
    if (!LoadOff(m, MeshDir() + "/elephant.off")) return false;
    vcg_ext::VSASegmentation<TMesh>::Params vp;
    vcg_ext::VSASegmentation<TMesh>::Segment(m, vp);
    return SelectRegionBoundaries(m) > 0;
}

}  // namespace

TEST(Parallel, MergesInIndexOrderOnTheCallingThreadWhateverTheStartOrder)
{
    const std::thread::id caller = std::this_thread::get_id();
    const size_t n = 200;
    std::vector<size_t> reversed(n);
    for (size_t i = 0; i < n; ++i) reversed[i] = n - 1 - i;
    for (int threads : {1, 2, 4}) {
        std::vector<size_t> merged;
        std::vector<std::thread::id> workers(n);
        int ticks = 0, ticksElsewhere = 0, mergesElsewhere = 0;
        vcg_ext::OrderedParallelFor<long>(
            n, threads, reversed,
            [&](size_t i) {
                workers[i] = std::this_thread::get_id();
                long s = 0;
                for (size_t k = 0; k <= i * 100; ++k) s += long(k % 7);
                return s;
            },
            [&](size_t i, long &&s) {
                long expect = 0;
                for (size_t k = 0; k <= i * 100; ++k) expect += long(k % 7);
                EXPECT_EQ(s, expect);
                merged.push_back(i);
                mergesElsewhere += std::this_thread::get_id() != caller;
            },
            [&]() {
                ++ticks;
                ticksElsewhere += std::this_thread::get_id() != caller;
            });
        ASSERT_EQ(merged.size(), n);
        for (size_t i = 0; i < n; ++i) EXPECT_EQ(merged[i], i);
        EXPECT_EQ(mergesElsewhere, 0);
        EXPECT_EQ(ticksElsewhere, 0) << "progress must come from the calling thread only";
        EXPECT_GE(ticks, int(n));
        int onCaller = 0;
        for (auto id : workers) onCaller += id == caller;
        if (threads == 1) EXPECT_EQ(onCaller, int(n)) << "one thread: a plain loop";
        else EXPECT_EQ(onCaller, 0) << "with a pool the calling thread only merges";
    }
}

TEST(Parallel, AnExceptionInAWorkItemReachesTheCaller)
{
    for (int threads : {1, 3}) {
        size_t merged = 0;
        EXPECT_THROW(vcg_ext::OrderedParallelFor<int>(
                         50, threads, {},
                         [](size_t i) {
                             if (i == 17) throw std::runtime_error("item 17");
                             return int(i);
                         },
                         [&](size_t, int &&) { ++merged; }, []() {}),
                     std::runtime_error);
        EXPECT_LE(merged, 17u);
    }
}

TEST(Parallel, QMorphWritesTheSameBytesWithOneThreadAndWithSeveral)
{
    TMesh base;
    ASSERT_TRUE(LoadElephantWithRegionFronts(base));
    std::vector<unsigned char> reference;
    int patches = 0;
    for (int threads : {1, 2, 3}) {
        TMesh m;
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, base);
        QM::Params p;
        p.threads = threads;
        QM::Result r = QM::Apply(m, p);
        ASSERT_EQ(r.error, "");
        if (threads == 1) {
            reference = MeshBytes(m);
            patches = r.patches;
            continue;
        }
        EXPECT_EQ(r.patches, patches);
        EXPECT_TRUE(MeshBytes(m) == reference) << threads << " threads changed the output";
    }
    EXPECT_GT(patches, 20) << "the case needs many patches to schedule";
}

TEST(Parallel, QMorphReMeshedWritesTheSameBytesWithOneThreadAndWithTwo)
{
    TMesh base;
    ASSERT_TRUE(LoadOff(base, MeshDir() + "/fandisk.off"));
    ASSERT_GT(SelectCreases(base, 40), 100);
    vcg::tri::UpdateBounding<TMesh>::Box(base);
    std::vector<unsigned char> reference;
    for (int threads : {1, 2}) {
        TMesh m;
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, base);
        QM::Params p;
        p.threads = threads;
        p.targetEdgeLength = 0.02 * base.bbox.Diag();  // the patches judged against the shared input surface
        p.remeshIterations = 2;
        QM::Result r = QM::Apply(m, p);
        ASSERT_EQ(r.error, "");
        if (threads == 1) reference = MeshBytes(m);
        else EXPECT_TRUE(MeshBytes(m) == reference) << "two threads changed the re-meshed output";
    }
}

// The re-meshing's collapse pass spread over many cells of ColouredCells (elephant at 0.5% of its
// diagonal: cells of 8% of it, dozens of each colour on the surface): the same collapses and the
// same bytes with 1, 2 and 3 threads.
TEST(Parallel, ReMeshingSpreadOverManyCellsWritesTheSameBytes)
{
    TMesh base;
    ASSERT_TRUE(LoadElephantWithRegionFronts(base));
    vcg::tri::UpdateBounding<TMesh>::Box(base);
    std::vector<unsigned char> reference;
    int collapses = 0;
    for (int threads : {1, 2, 3}) {
        TMesh m;
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, base);
        QM::Params p;
        p.threads = threads;
        p.targetEdgeLength = 0.005 * base.bbox.Diag();
        p.remeshIterations = 2;
        QM::Result r = QM::Apply(m, p);
        ASSERT_EQ(r.error, "");
        if (threads == 1) {
            reference = MeshBytes(m);
            collapses = r.remesh.collapses;
            continue;
        }
        EXPECT_EQ(r.remesh.collapses, collapses);
        EXPECT_TRUE(MeshBytes(m) == reference) << threads << " threads changed the re-meshed output";
    }
    EXPECT_GT(collapses, 1000) << "the case needs collapses in many cells";
}
