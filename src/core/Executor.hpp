#pragma once
// The step's worker threads: oneTBB's task arena, limited to WorldSettings::threads. Internal.
//
// Every parallel loop in the step writes only to its own items or to per-worker buffers that are merged in a
// fixed order afterwards, so results are bit-identical for any thread count.

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <cstddef>
#include <memory>

namespace physim {

class Executor {
public:
    explicit Executor(int threads = 1) { setThreads(threads); }

    /// 1: everything on the calling thread; 0: every hardware thread.
    void setThreads(int threads) {
        const int n = threads == 0 ? tbb::info::default_concurrency() : threads;
        if (n == threads_ && (arena_ || n == 1)) return;
        threads_ = n;
        arena_.reset();
        if (n > 1) arena_ = std::make_unique<tbb::task_arena>(n);
    }
    int threads() const { return threads_; }
    /// Upper bound of the worker index passed to loop bodies (for per-worker buffers).
    int workerSlots() const { return threads_; }

    /// Calls fn(begin, end, worker) over disjoint ranges covering [0, n), each of at least `grain` items (except
    /// the last); on one thread, or when n is below two grains, a single call fn(0, n, 0). The range is split
    /// evenly between the threads up front (static partitioner): the step's loops are short and even, and one task
    /// per thread costs less than stealing finer tasks (docs/performance.md).
    template <class Fn>
    void parallelFor(std::size_t n, std::size_t grain, Fn&& fn) {
        if (n == 0) return;
        if (!arena_ || n < 2 * grain) {
            fn(std::size_t{0}, n, 0);
            return;
        }
        auto loop = [&] {
            tbb::parallel_for(
                tbb::blocked_range<std::size_t>(0, n, grain),
                [&](const tbb::blocked_range<std::size_t>& r) {
                    const int worker = tbb::this_task_arena::current_thread_index();
                    fn(r.begin(), r.end(), worker < 0 ? 0 : worker);
                },
                tbb::static_partitioner());
        };
        if (inside_) loop();
        else arena_->execute(loop);
    }

    /// Runs fn() in the arena, so that the many short loops it starts (the solver's passes, a few per colour per
    /// substep) do not each pay for entering it.
    template <class Fn>
    void run(Fn&& fn) {
        if (!arena_ || inside_) {
            fn();
            return;
        }
        arena_->execute([&] {
            struct Inside {
                bool& flag;
                explicit Inside(bool& f) : flag(f) { flag = true; }
                ~Inside() { flag = false; }
            } inside(inside_);
            fn();
        });
    }

private:
    int threads_ = 0;
    std::unique_ptr<tbb::task_arena> arena_;
    bool inside_ = false;  // the calling thread is running run()'s fn, inside the arena
};

}  // namespace physim
