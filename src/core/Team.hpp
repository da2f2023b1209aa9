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
// Nothing ever waits for a particular helper: the driver can take every chunk itself. A helper that starts late
// joins whatever stage is current, and one that starts after the end returns at once. Which thread runs a chunk
// never changes what the chunk computes (the loops write only their own items), so results stay bit-identical.
//
// Every shared variable is a sequentially consistent atomic (a chunk's exception: under a mutex). A chunk counter
// holds its stage's number beside the next chunk, and the driver resets the counters before it writes the stage's
// description: a helper that read a description newer than the stage it saw finds the counters moved on, so it
// can claim nothing with it.

#include <algorithm>
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
        const std::uint64_t stage = stage_.load() + 1;
        // Counters first (a helper holding an older stage's number can claim nothing from here on), then the
        // description, then the stage number that lets helpers read it.
        std::size_t total = 0;  // each member's run is an equal share of the items, in chunks of `grain`
        for (int m = 0; m < members(); ++m) {
            total += (runBegin(m + 1, n) - runBegin(m, n) + grain - 1) / grain;
            counters_[static_cast<std::size_t>(m)].next.store(stage << 32);
        }
        done_.store(0);
        context_.store(const_cast<void*>(static_cast<const void*>(&fn)));
        call_.store(&callChunk<Fn>);
        items_.store(n);
        grain_.store(grain);
        stage_.store(stage);
        work(0, stage);
        for (unsigned spins = 0; done_.load() != total; ++spins) pause(spins);
        inStage_ = false;
        if (failed_.load()) {
            failed_.store(false);
            std::rethrow_exception(error_);
        }
    }

    /// Helper `member` (1 .. members - 1): takes chunks of each stage until finish().
    void help(int member) noexcept {
        std::uint64_t seen = 0;
        for (;;) {
            std::uint64_t stage = stage_.load();
            for (unsigned spins = 0; stage == seen; stage = stage_.load(), ++spins) {
                if (finished_.load()) return;
                pause(spins);
            }
            seen = stage;
            work(member, stage);
        }
    }

    /// The calling thread becomes the driver of a new run. Only between runs: no helper of the last run may
    /// still be inside help(). Allocates nothing, so a team made once serves every step.
    void start() {
        driver_ = std::this_thread::get_id();
        stage_.store(0);
        finished_.store(false);
    }

    /// Driver: no more stages in this run; the helpers return.
    void finish() { finished_.store(true); }

private:
    using Call = void (*)(void* context, std::size_t begin, std::size_t end, int member);

    template <class Fn>
    static void callChunk(void* context, std::size_t begin, std::size_t end, int member) {
        (*static_cast<Fn*>(context))(begin, end, member);
    }

    // The first item of member's run (members() gives n).
    std::size_t runBegin(int member, std::size_t n) const {
        return n * static_cast<std::size_t>(member) / counters_.size();
    }

    // Takes chunks of `stage`: the member's own run first, then the others' in turn.
    void work(int member, std::uint64_t stage) noexcept {
        void* const context = context_.load();
        const Call call = call_.load();
        const std::size_t n = items_.load(), grain = grain_.load();
        std::size_t finished = 0;  // chunks this member ran, counted into done_ once it has no more to take
        for (int k = 0; k < members(); ++k) {
            const int owner = (member + k) % members();
            const std::size_t first = runBegin(owner, n), last = runBegin(owner + 1, n);
            const std::uint64_t end = (last - first + grain - 1) / grain;
            std::atomic<std::uint64_t>& next = counters_[static_cast<std::size_t>(owner)].next;
            std::uint64_t taken = next.load();
            while (taken >> 32 == stage && (taken & 0xffffffffu) < end) {
                if (!next.compare_exchange_weak(taken, taken + 1)) continue;
                const std::size_t begin = first + static_cast<std::size_t>(taken & 0xffffffffu) * grain;
                try {
                    call(context, begin, std::min(last, begin + grain), member);
                } catch (...) {
                    std::lock_guard<std::mutex> lock(errorMutex_);
                    if (!failed_.load()) error_ = std::current_exception();
                    failed_.store(true);
                }
                ++finished;
                taken = next.load();
            }
        }
        if (finished > 0) done_.fetch_add(finished);
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
    std::thread::id driver_;  // set by start(); no thread drives before it
    bool inStage_ = false;  // the driver is inside forEach (a nested call runs inline)
    // The stage's description (written by the driver before it publishes the stage number).
    std::atomic<void*> context_{nullptr};
    std::atomic<Call> call_{nullptr};
    std::atomic<std::size_t> items_{0}, grain_{0};
    alignas(64) std::atomic<std::uint64_t> stage_{0};
    alignas(64) std::atomic<std::size_t> done_{0};
    std::atomic<bool> finished_{false};
    std::atomic<bool> failed_{false};
    std::mutex errorMutex_;
    std::exception_ptr error_;
};

}  // namespace physim
