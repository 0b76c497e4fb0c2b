// Independent work items on a pool of std::threads, results merged on the calling thread in
// index order: the output is the same with 1 thread and with all cores, whatever the scheduling.
//
// The calling thread only merges and reports progress (MeshLab's callback touches Qt widgets and
// must run on the thread that entered applyFilter); with one thread everything runs inline on
// it, exactly as a plain loop.
#ifndef VCG_EXT_COMMON_PARALLEL_H
#define VCG_EXT_COMMON_PARALLEL_H

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <memory>
#include <mutex>
#include <numeric>
#include <thread>
#include <vector>

#include <vcg_ext/common/progress_period.h>

namespace vcg_ext {

// Threads to use: `requested` when > 0, else the machine's cores (at least 1).
inline int ThreadCount(int requested)
{
    if (requested > 0) return requested;
    return std::max(1, int(std::thread::hardware_concurrency()));
}

// Runs `work(i)` (returning a Result) for every i in [0, count) on `threads` threads, starting
// the items in `startOrder` (a permutation of [0, count); empty: index order; e.g. biggest first,
// so one large item does not start last), and calls `merge(i, Result &&)` on the calling thread
// for i = 0, 1, ... in this order as soon as item i and all before it are done; `tick()` is called
// on the calling thread after each merge and at least every kProgressPeriodSeconds. `work` must be
// safe to run concurrently for different i. An exception thrown by `work` is rethrown here after
// the threads have stopped.
template <class Result, class Work, class Merge, class Tick>
void OrderedParallelFor(size_t count, int threads, const std::vector<size_t> &startOrder, Work work, Merge merge, Tick tick)
{
    threads = std::max(1, std::min<int>(threads, int(count)));
    if (threads <= 1) {
        for (size_t i = 0; i < count; ++i) {
            merge(i, work(i));
            tick();
        }
        return;
    }
    std::vector<size_t> order = startOrder;
    if (order.size() != count) {
        order.resize(count);
        std::iota(order.begin(), order.end(), size_t(0));
    }
    std::vector<std::unique_ptr<Result>> done(count);
    std::mutex mutex;
    std::condition_variable ready;
    std::atomic<size_t> next(0);
    std::atomic<bool> stop(false);
    std::exception_ptr failure;

    auto worker = [&]() {
        for (;;) {
            const size_t k = next.fetch_add(1);
            if (k >= count || stop) return;
            const size_t i = order[k];
            std::unique_ptr<Result> r;
            try {
                r.reset(new Result(work(i)));
            } catch (...) {
                std::lock_guard<std::mutex> lock(mutex);
                if (!failure) failure = std::current_exception();
                stop = true;
                ready.notify_one();
                return;
            }
            std::lock_guard<std::mutex> lock(mutex);
            done[i] = std::move(r);
            ready.notify_one();
        }
    };
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(worker);

    const auto tickPeriod = std::chrono::duration<double>(kProgressPeriodSeconds);
    size_t merged = 0;
    try {
        std::unique_lock<std::mutex> lock(mutex);
        while (merged < count && !stop) {
            ready.wait_for(lock, tickPeriod, [&] { return stop || done[merged] != nullptr; });
            while (merged < count && done[merged]) {
                std::unique_ptr<Result> r = std::move(done[merged]);
                lock.unlock();
                merge(merged, std::move(*r));
                r.reset();
                tick();
                lock.lock();
                ++merged;
            }
            if (merged < count && !stop) {
                lock.unlock();
                tick();
                lock.lock();
            }
        }
    } catch (...) {  // from merge or tick: stop the pool before leaving
        stop = true;
        for (std::thread &t : pool) t.join();
        throw;
    }
    for (std::thread &t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace vcg_ext

#endif
