// Progress that never freezes: a filter's work runs on a worker thread while the thread that called
// it relays the work's progress to MeshLab's callback, each new report as it comes and the last one
// again at least every kProgressPeriodSeconds. Some steps are one indivisible whole-mesh call (vcglib's
// topology and grid builds take seconds at millions of faces); during them the GUI still processes
// events and shows the step under way instead of a frozen bar.
//
// The callback runs only on the calling thread (MeshLab's touches Qt widgets and must stay on the
// thread that entered applyFilter); the worker only records what it reports. The work is the same
// code on another thread: the output does not change. vcg::CallBackPos is a plain function pointer
// with no context, so the worker finds its relay through a thread-local pointer; a relay started
// inside the work (a core entry point calling another) runs inline on the worker.
#ifndef VCG_EXT_COMMON_PROGRESS_RELAY_H
#define VCG_EXT_COMMON_PROGRESS_RELAY_H

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>

#include <wrap/callback.h>

#include <vcg_ext/common/progress_period.h>

namespace vcg_ext {

class ProgressRelay
{
public:
    // Returns work(report): run on a worker thread when cb is set (report relays to cb), inline
    // with cb itself otherwise or when already on a relay's worker. An exception thrown by the
    // work is rethrown here.
    template <class Work>
    static auto Run(vcg::CallBackPos *cb, Work work) -> decltype(work(cb))
    {
        if (!cb || Active()) return work(cb);
        typedef decltype(work(cb)) Result;
        ProgressRelay relay;
        std::optional<Result> result;
        std::exception_ptr failure;
        std::thread worker([&]() {
            Active() = &relay;
            try {
                result.emplace(work(&ProgressRelay::Report));
            } catch (...) {
                failure = std::current_exception();
            }
            Active() = nullptr;
            std::lock_guard<std::mutex> lock(relay.mutex);
            relay.finished = true;
            relay.changed.notify_one();
        });
        relay.Forward(cb);
        worker.join();
        if (failure) std::rethrow_exception(failure);
        return std::move(*result);
    }

private:
    std::mutex mutex;
    std::condition_variable changed;
    bool finished = false, fresh = false, reported = false;
    int percent = 0;
    std::string message;

    static ProgressRelay *&Active()
    {
        thread_local ProgressRelay *active = nullptr;
        return active;
    }

    // The worker's callback: records the report for the calling thread.
    static bool Report(const int percent, const char *message)
    {
        ProgressRelay *relay = Active();
        if (!relay) return true;  // a thread of the work's own pool: reports belong to its caller
        std::lock_guard<std::mutex> lock(relay->mutex);
        relay->percent = percent;
        relay->message = message ? message : "";
        relay->fresh = relay->reported = true;
        relay->changed.notify_one();
        return true;
    }

    // On the calling thread until the work finishes: each fresh report, and the last one again
    // after every heartbeat without one; cb is called with the lock released.
    void Forward(vcg::CallBackPos *cb)
    {
        const auto heartbeat = std::chrono::duration<double>(kProgressPeriodSeconds);
        std::unique_lock<std::mutex> lock(mutex);
        for (;;) {
            changed.wait_for(lock, heartbeat, [&]() { return fresh || finished; });
            if (finished && !fresh) return;
            fresh = false;
            if (!reported) continue;
            const int p = percent;
            const std::string m = message;
            lock.unlock();
            cb(p, m.c_str());
            lock.lock();
        }
    }
};

}  // namespace vcg_ext

#endif
