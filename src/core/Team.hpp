#pragma once
// A team of threads for a sequence of short loops that must run one after another (the solver: a loop per colour
// per pass, a few hundred per step). Internal.
//
// One thread drives: it runs the code between loops and, for each loop, publishes it as a numbered stage, takes
// chunks of it like everyone else, and waits until every chunk is done. The others (helpers, from the thread
// pool) wait for stages and take chunks. Each member has its own run, an equal share of the items (member m's
// starts at item n m / members), and takes its chunks first, so a body's record tends to stay in one core's cache
// from one loop to the next: the solver's loops list rows and bodies in about the bodies' order, and equal shares
// of each split them at about the same body. A member that is done takes what is left of the others' runs, so a
// thread the system holds back delays a loop by at most the chunk it holds.
//
// A team of two can also run a sequence of loops as one stage (forLoopsInOrder: a pass's colours). Each member keeps
// its half of every loop and waits only for the part of the other's half of the loop before that it depends on,
// instead of for the whole loop: the two run side by side through the colours, one wait per pass.
//
// Nothing ever waits for a particular helper: the driver can take every chunk itself. A helper that starts late
// joins whatever stage is current, and one that starts after the end returns at once. Which thread runs a chunk
// never changes what the chunk computes (the loops write only their own items), so results stay bit-identical.
//
// On two threads a loop pays for every cache line that moves between the cores (a round trip of hundreds of
// nanoseconds), so each loop moves as few as it can, and no thread waits on a store:
//   - the stage's number and description share one line, written by the driver as a sequence lock (odd while
//     it writes), so a helper gets the whole stage in one move;
//   - a member's chunk counter is written by the others only when they take from its run: a counter tagged with
//     an older stage counts as untouched (chunk 0), so the driver resets nothing between loops;
//   - finished chunks add to a running total, which the driver compares with the sum of the loops' chunks.
// Stores are releases and loads acquires (no full fences): a helper sees a stage's description and the previous
// loops' writes once it sees the stage's number, and the driver sees the chunks' writes once it sees the total.
// A helper that read a stage late can claim nothing with it: every counter it could take from is then tagged
// with that stage and used up, or with a newer one.

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace physim {

class Team {
public:
    explicit Team(int members) : counters_(static_cast<std::size_t>(std::max(members, 1))) {}
    Team(const Team&) = delete;
    Team& operator=(const Team&) = delete;

    int members() const { return static_cast<int>(counters_.size()); }

    /// Driver: calls fn(begin, end, member) over chunks of `grain` items covering [0, n), on the team, and
    /// returns when all are done (rethrowing a chunk's exception). From any other thread, or from inside a
    /// chunk, one call fn(0, n, 0) on the calling thread.
    template <class Fn>
    void forEach(std::size_t n, std::size_t grain, Fn& fn) {
        if (n == 0) return;
        grain = std::max<std::size_t>(grain, 1);
        const std::size_t chunks = (n + grain - 1) / grain;
        if (chunks < 2 || members() < 2 || inStage_ || std::this_thread::get_id() != driver_) {
            fn(std::size_t{0}, n, 0);
            return;
        }
        inStage_ = true;
        const std::uint64_t stage = ++stageCount_;
        for (int m = 0; m < members(); ++m) doneTarget_ += chunkCount(m, n, grain);  // each member's run
        const Description d{const_cast<void*>(static_cast<const void*>(&fn)), &callChunk<Fn>, n, grain};
        publish(stage, d);
        work(0, stage, d);
        for (unsigned spins = 0; done_.load(std::memory_order_acquire) != doneTarget_; ++spins) pause(spins);
        inStage_ = false;
        rethrowFailure();
    }

    /// Whether forLoopsInOrder runs on two threads here: a team of exactly two, called by its driver outside a
    /// stage. Elsewhere it runs its parts one after another on the calling thread.
    bool ordersLoops() const {
        return members() == 2 && !inStage_ && std::this_thread::get_id() == driver_;
    }

    /// Driver: `loops` loops in order, each cut into two fixed shares (share 0 the driver's, share 1 the
    /// helper's), each share into a head and a rest: fn(loop, share, head) runs every part once. A share's part
    /// of loop l starts once the other share's head of loop l - 1 is done, and its own parts of loop l - 1, never
    /// waiting for the other's rest: the caller puts into a share's head every item that touches anything the
    /// other share touches in any loop, so the two run side by side and wait only where they meet. One wait for
    /// the whole sequence instead of one per loop. If the helper has not claimed its share when the driver has
    /// done its loop 0, the driver claims it and runs both (the pool may never give the thread). Same results
    /// whoever runs a share, as long as each part writes only its own items and what no part of the other share
    /// in the same loop touches.
    template <class Fn>
    void forLoopsInOrder(std::size_t loops, Fn& fn) {
        if (loops == 0) return;
        if (!ordersLoops() || loops > kMaxOrderedLoops) {
            loopsInOrderAlone(loops, fn);
            return;
        }
        inStage_ = true;
        const std::uint64_t stage = ++stageCount_;
        doneTarget_ += 2;  // the two shares
        const Description d{const_cast<void*>(static_cast<const void*>(&fn)), nullptr, loops, 0,
                            &callPart<Fn>};
        publish(stage, d);
        runShares(0, stage, d);
        for (unsigned spins = 0; done_.load(std::memory_order_acquire) != doneTarget_; ++spins) pause(spins);
        inStage_ = false;
        rethrowFailure();
    }

    /// forLoopsInOrder's parts one after another on the calling thread: every part of loop l before loop l + 1.
    template <class Fn>
    static void loopsInOrderAlone(std::size_t loops, Fn& fn) {
        for (std::size_t loop = 0; loop < loops; ++loop)
            for (const int share : {0, 1})
                for (const bool head : {true, false}) fn(loop, share, head);
    }

    /// Helper `member` (1 .. members - 1): takes chunks of each stage until finish().
    void help(int member) noexcept {
        std::uint64_t seen = 0;
        for (;;) {
            std::uint64_t stage = 0;
            Description d;
            for (unsigned spins = 0; !read(seen, stage, d); ++spins) {
                if (finished_.load(std::memory_order_acquire)) return;
                pause(spins);
            }
            seen = stage;
            if (d.part != nullptr) runShares(member, stage, d);
            else work(member, stage, d);
        }
    }

    /// The calling thread becomes the driver of a new run. Only between runs: no helper of the last run may
    /// still be inside help(). Allocates nothing, so a team made once serves every step.
    void start() {
        driver_ = std::this_thread::get_id();
        stageCount_ = 0;
        doneTarget_ = 0;
        done_.store(0, std::memory_order_relaxed);
        for (Counter& c : counters_) c.next.store(0, std::memory_order_relaxed);
        for (Counter& c : progress_) c.next.store(0, std::memory_order_relaxed);
        helperShare_.store(0, std::memory_order_relaxed);
        sequence_.store(0, std::memory_order_relaxed);
        finished_.store(false, std::memory_order_release);
    }

    /// Driver: no more stages in this run; the helpers return.
    void finish() { finished_.store(true, std::memory_order_release); }

private:
    using Call = void (*)(void* context, std::size_t begin, std::size_t end, int member);

    using PartCall = void (*)(void* context, std::size_t loop, int share, bool head);

    template <class Fn>
    static void callChunk(void* context, std::size_t begin, std::size_t end, int member) {
        (*static_cast<Fn*>(context))(begin, end, member);
    }
    template <class Fn>
    static void callPart(void* context, std::size_t loop, int share, bool head) {
        (*static_cast<Fn*>(context))(loop, share, head);
    }

    // A stage: forEach's (call, items, grain) or forLoopsInOrder's (part, items = loops).
    struct Description {
        void* context = nullptr;
        Call call = nullptr;
        std::size_t items = 0, grain = 0;
        PartCall part = nullptr;
    };

    void rethrowFailure() {
        if (failed_.load(std::memory_order_acquire)) {
            failed_.store(false, std::memory_order_relaxed);
            std::rethrow_exception(error_);
        }
    }

    void recordFailure() noexcept {
        std::lock_guard<std::mutex> lock(errorMutex_);
        if (!failed_.load(std::memory_order_relaxed)) error_ = std::current_exception();
        failed_.store(true, std::memory_order_relaxed);
    }

    // How far a share of an ordered stage has come: 2 l + 1 once its head of loop l is done, 2 l + 2 once all of
    // loop l is; tagged with the stage, so an older stage's count reads as nothing done. Stages count from start()
    // (a few hundred a run), parts below 2^32 (kMaxOrderedLoops).
    static std::uint64_t progressMark(std::uint64_t stage, std::size_t parts) {
        return stage << 32 | static_cast<std::uint64_t>(parts);
    }
    static constexpr std::size_t kMaxOrderedLoops = std::size_t{1} << 30;

    void runPart(const Description& d, std::uint64_t stage, std::size_t loop, int share, bool head) noexcept {
        try {
            d.part(d.context, loop, share, head);
        } catch (...) {
            recordFailure();
        }
        const std::size_t parts = 2 * loop + (head ? 1 : 2);
        progress_[static_cast<std::size_t>(share)].next.store(progressMark(stage, parts), std::memory_order_release);
    }

    // The first item of member's run (members() gives n).
    std::size_t runBegin(int member, std::size_t n) const {
        return n * static_cast<std::size_t>(member) / counters_.size();
    }
    std::size_t chunkCount(int member, std::size_t n, std::size_t grain) const {
        return (runBegin(member + 1, n) - runBegin(member, n) + grain - 1) / grain;
    }

    // Driver: stage s is sequence 2 s, written as 2 s - 1 while its description changes.
    void publish(std::uint64_t stage, const Description& d) {
        sequence_.store(2 * stage - 1, std::memory_order_relaxed);
        std::atomic_thread_fence(std::memory_order_release);
        context_.store(d.context, std::memory_order_relaxed);
        call_.store(d.call, std::memory_order_relaxed);
        items_.store(d.items, std::memory_order_relaxed);
        grain_.store(d.grain, std::memory_order_relaxed);
        part_.store(d.part, std::memory_order_relaxed);
        sequence_.store(2 * stage, std::memory_order_release);
    }

    // Helper: a stage newer than `seen`, whole, into stage and d; false if there is none yet (or it is being
    // written).
    bool read(std::uint64_t seen, std::uint64_t& stage, Description& d) const {
        const std::uint64_t before = sequence_.load(std::memory_order_acquire);
        if (before & 1 || before / 2 == seen) return false;
        d = {context_.load(std::memory_order_relaxed), call_.load(std::memory_order_relaxed),
             items_.load(std::memory_order_relaxed), grain_.load(std::memory_order_relaxed),
             part_.load(std::memory_order_relaxed)};
        std::atomic_thread_fence(std::memory_order_acquire);
        if (sequence_.load(std::memory_order_relaxed) != before) return false;
        stage = before / 2;
        return true;
    }

    // Takes chunks of `stage`: the member's own run first, then the others' in turn.
    void work(int member, std::uint64_t stage, const Description& d) noexcept {
        std::size_t finished = 0;  // chunks this member ran, added to done_ once it has no more to take
        for (int k = 0; k < members(); ++k) {
            const int owner = (member + k) % members();
            const std::size_t first = runBegin(owner, d.items), last = runBegin(owner + 1, d.items);
            const std::uint64_t end = chunkCount(owner, d.items, d.grain);
            std::atomic<std::uint64_t>& next = counters_[static_cast<std::size_t>(owner)].next;
            std::uint64_t taken = next.load(std::memory_order_relaxed);
            for (;;) {
                const std::uint64_t tag = taken >> 32;
                if (tag > stage) break;  // a newer stage: this one is over
                const std::uint64_t chunk = tag == stage ? taken & 0xffffffffu : 0;  // older tag: untouched run
                if (chunk >= end) break;
                if (!next.compare_exchange_weak(taken, stage << 32 | (chunk + 1), std::memory_order_relaxed))
                    continue;
                const std::size_t begin = first + static_cast<std::size_t>(chunk) * d.grain;
                try {
                    d.call(d.context, begin, std::min(last, begin + d.grain), member);
                } catch (...) {
                    recordFailure();
                }
                ++finished;
                taken = next.load(std::memory_order_relaxed);
            }
        }
        if (finished > 0) done_.fetch_add(finished, std::memory_order_release);
    }

    // An ordered stage (forLoopsInOrder) on member 0 (the driver, share 0) or 1 (share 1, if it claims it first).
    void runShares(int member, std::uint64_t stage, const Description& d) noexcept {
        if (member == 1 && !claimHelperShare(stage)) return;  // the driver took it: nothing left here
        const int other = 1 - member;
        bool both = false;  // the driver runs share 1 too
        // The driver takes share 1 if the helper has not claimed it when loop 0 is done: the only point where
        // running it from its start keeps the order (share 0 has done loop 0 alone, which shares no item with
        // share 1's loop 0, and nothing later).
        auto takeShare1 = [&] {
            if (member != 0 || !claimHelperShare(stage)) return;
            runPart(d, stage, 0, 1, true);
            runPart(d, stage, 0, 1, false);
            both = true;
        };
        for (std::size_t loop = 0; loop < d.items; ++loop) {
            if (loop == 1) takeShare1();
            if (loop > 0 && !both) {
                // The other share's head of the loop before: everything of it this share's next loop may touch.
                const std::uint64_t needed = progressMark(stage, 2 * loop - 1);
                const std::atomic<std::uint64_t>& theirs = progress_[static_cast<std::size_t>(other)].next;
                for (unsigned spins = 0; theirs.load(std::memory_order_acquire) < needed; ++spins) pause(spins);
            }
            runPart(d, stage, loop, member, true);
            if (both) runPart(d, stage, loop, other, true);
            runPart(d, stage, loop, member, false);
            if (both) runPart(d, stage, loop, other, false);
        }
        if (d.items == 1) takeShare1();
        done_.fetch_add(both ? 2 : 1, std::memory_order_release);
    }

    // Share 1 of `stage` goes to whoever asks first; false if it is taken (or the stage is over).
    bool claimHelperShare(std::uint64_t stage) {
        std::uint64_t last = helperShare_.load(std::memory_order_relaxed);
        while (last < stage)
            if (helperShare_.compare_exchange_weak(last, stage, std::memory_order_relaxed)) return true;
        return false;
    }

    // Waiting: spin briefly (stages are microseconds apart), then give the core away (a 2-core machine may have
    // the thread we wait for queued behind us).
    static void pause(unsigned spins) {
        if (spins < 4096) {
#if defined(__x86_64__) || defined(__i386__)
            _mm_pause();
#endif
        } else {
            std::this_thread::yield();
        }
    }

    struct alignas(64) Counter {
        std::atomic<std::uint64_t> next{0};  // stage << 32 | the next chunk of this member's run (0 its first)
    };
    std::vector<Counter> counters_;
    std::array<Counter, 2> progress_;  // an ordered stage's progress per share (progressMark)
    alignas(64) std::atomic<std::uint64_t> helperShare_{0};  // the last ordered stage whose share 1 was claimed
    // The driver's own state.
    std::thread::id driver_;  // set by start(); no thread drives before it
    bool inStage_ = false;  // the driver is inside forEach (a nested call runs inline)
    std::uint64_t stageCount_ = 0;
    std::size_t doneTarget_ = 0;  // chunks of every stage so far: done_ reaches it when the present one is done
    // The stage, one line: its sequence number, then its description.
    alignas(64) std::atomic<std::uint64_t> sequence_{0};
    std::atomic<void*> context_{nullptr};
    std::atomic<Call> call_{nullptr};
    std::atomic<std::size_t> items_{0}, grain_{0};
    std::atomic<PartCall> part_{nullptr};
    alignas(64) std::atomic<std::size_t> done_{0};  // chunks finished in this run
    alignas(64) std::atomic<bool> finished_{false};
    std::atomic<bool> failed_{false};
    std::mutex errorMutex_;
    std::exception_ptr error_;
};

}  // namespace physim
