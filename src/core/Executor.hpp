#pragma once
// The core's worker threads: a oneTBB task arena of a given thread count (WorldSettings::threads for the step, the
// CPU continuous solver's own for its batches); the core starts no thread of its own. Internal.
//
// Every parallel loop in the step writes only to its own items or to per-worker buffers that are merged in a
// fixed order afterwards, so results are bit-identical for any thread count.

#include "Team.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

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
        team_.reset();
        if (n > 1) {
            arena_ = std::make_unique<tbb::task_arena>(n);
            team_ = std::make_unique<Team>(n);  // made once: a step allocates nothing for its team
        }
    }
    int threads() const { return threads_; }
    /// Upper bound of the worker index passed to loop bodies (for per-worker buffers).
    int workerSlots() const { return threads_; }

    /// Calls fn(begin, end, worker) over disjoint ranges covering [0, n); on one thread, or when n is below two
    /// grains, a single call fn(0, n, 0). Inside run() the ranges are chunks of at most `grain` items of each
    /// thread's equal share, shared by run()'s team (Team.hpp); elsewhere the range is split evenly between the
    /// threads up front into ranges of at least half a grain (static partitioner: the loops are short and even, and
    /// one task per thread costs less than stealing finer tasks).
    template <class Fn>
    void parallelFor(std::size_t n, std::size_t grain, Fn&& fn) {
        if (n == 0) return;
        if (!arena_ || n < 2 * grain) {
            fn(std::size_t{0}, n, 0);
            return;
        }
        if (inRun_) {
            team_->forEach(n, grain, fn);
            return;
        }
        arena_->execute([&] {
            tbb::parallel_for(
                tbb::blocked_range<std::size_t>(0, n, grain),
                [&](const tbb::blocked_range<std::size_t>& r) {
                    const int worker = tbb::this_task_arena::current_thread_index();
                    fn(r.begin(), r.end(), worker < 0 ? 0 : worker);
                },
                tbb::static_partitioner());
        });
    }

    /// Whether forLoopsInOrder runs its two shares on two threads: inside run(), on a team of two, outside a loop.
    /// Elsewhere the caller does better with parallelFor per loop (more threads) or it makes no difference (one).
    bool ordersLoops() const { return inRun_ && team_ && team_->ordersLoops(); }

    /// fn(loop, share, head) for every part of `loops` loops of two shares (Team::forLoopsInOrder): on run()'s
    /// team of two side by side, elsewhere one after another.
    template <class Fn>
    void forLoopsInOrder(std::size_t loops, Fn&& fn) {
        if (inRun_ && team_) team_->forLoopsInOrder(loops, fn);
        else Team::loopsInOrderAlone(loops, fn);
    }

    /// Runs fn() on the calling thread with the arena's other threads standing by as a Team for the loops fn
    /// starts with parallelFor: the solver's many short loops (a few per colour per substep) then cost a
    /// handful of atomic operations each instead of a task launch and a join.
    template <class Fn>
    void run(Fn&& fn) {
        if (!arena_ || inRun_) {
            fn();
            return;
        }
        arena_->execute([&] {
            Team& team = *team_;
            team.start();
            tbb::task_group helpers;
            // The helpers leave (and are waited for) however this ends, even if starting one fails; a helper not
            // yet started by then finds the team finished and returns at once, so nothing waits on a thread the
            // pool never gave.
            struct Leave {
                Team& team;
                tbb::task_group& helpers;
                bool& inRun;
                ~Leave() {
                    inRun = false;
                    team.finish();
                    helpers.wait();
                }
            } leave{team, helpers, inRun_};
            for (int member = 1; member < threads_; ++member) helpers.run([&team, member] { team.help(member); });
            inRun_ = true;
            fn();
        });
    }

private:
    int threads_ = 0;
    std::unique_ptr<tbb::task_arena> arena_;
    std::unique_ptr<Team> team_;  // the arena's threads as run()'s team (made with the arena, kept for every run)
    bool inRun_ = false;          // run()'s fn is running: parallelFor hands its loops to the team
};

}  // namespace physim
