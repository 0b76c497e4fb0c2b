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

// Q-Morph with p on a copy of base per thread count: every run writes the bytes of the first.
// Returns the runs' results, in the order of `threadCounts`.
std::vector<QM::Result> ExpectSameBytesWithEachThreadCount(const TMesh &base, QM::Params p, const std::vector<int> &threadCounts)
{
    std::vector<QM::Result> results;
    std::vector<unsigned char> reference;
    for (int threads : threadCounts) {
        TMesh m;
        vcg::tri::Append<TMesh, TMesh>::MeshCopy(m, const_cast<TMesh &>(base));
        p.threads = threads;
        results.push_back(QM::Apply(m, p));
        EXPECT_EQ(results.back().error, "");
        if (results.size() == 1) reference = MeshBytes(m);
        else EXPECT_TRUE(MeshBytes(m) == reference) << threads << " threads changed the output";
    }
    return results;
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
    const std::vector<QM::Result> r = ExpectSameBytesWithEachThreadCount(base, QM::Params(), {1, 2, 3});
    for (const QM::Result &ri : r) EXPECT_EQ(ri.patches, r[0].patches);
    EXPECT_GT(r[0].patches, 20) << "the case needs many patches to schedule";
}

TEST(Parallel, QMorphReMeshedWritesTheSameBytesWithOneThreadAndWithTwo)
{
    TMesh base;
    ASSERT_TRUE(LoadOff(base, MeshDir() + "/fandisk.off"));
    ASSERT_GT(SelectCreases(base, 40), 100);
    vcg::tri::UpdateBounding<TMesh>::Box(base);
    QM::Params p;
    p.targetEdgeLength = 0.02 * base.bbox.Diag();  // the patches judged against the shared input surface
    p.remeshIterations = 2;
    ExpectSameBytesWithEachThreadCount(base, p, {1, 2});
}

// The re-meshing's collapse pass spread over many cells of ColouredCells (elephant at 0.5% of its
// diagonal: cells of 8% of it, dozens of each colour on the surface): the same collapses and the
// same bytes with 1, 2 and 3 threads.
TEST(Parallel, ReMeshingSpreadOverManyCellsWritesTheSameBytes)
{
    TMesh base;
    ASSERT_TRUE(LoadElephantWithRegionFronts(base));
    vcg::tri::UpdateBounding<TMesh>::Box(base);
    QM::Params p;
    p.targetEdgeLength = 0.005 * base.bbox.Diag();
    p.remeshIterations = 2;
    const std::vector<QM::Result> r = ExpectSameBytesWithEachThreadCount(base, p, {1, 2, 3});
    for (const QM::Result &ri : r) EXPECT_EQ(ri.remesh.collapses, r[0].remesh.collapses);
    EXPECT_GT(r[0].remesh.collapses, 1000) << "the case needs collapses in many cells";
}
