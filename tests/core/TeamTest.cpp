// The solver's team of threads (src/core/Team.hpp) and the executor's use of it: every item of every loop is
// done exactly once and before the next loop starts, whoever does it, and nothing waits on a helper that never
// comes.

#include "Executor.hpp"
#include "Team.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

namespace physim {
namespace {

// Loops that each read what the loop before wrote (item i of loop k adds item i + 1 of loop k - 1, wrapping),
// so a loop started before the last one finished, or an item done twice or not at all, changes the sums.
std::vector<std::uint64_t> chainedLoops(Executor& executor, std::size_t n, int loops) {
    std::vector<std::uint64_t> a(n), b(n);  // unsigned: the sums grow as 3^loops and wrap
    std::iota(a.begin(), a.end(), std::uint64_t{1});
    executor.run([&] {
        for (int k = 0; k < loops; ++k) {
            executor.parallelFor(n, 7, [&](std::size_t begin, std::size_t end, int worker) {
                // Helpers' chunks finish late: a driver that went on without them would read stale items.
                if (worker != 0) std::this_thread::sleep_for(std::chrono::microseconds(50));
                for (std::size_t i = begin; i < end; ++i)
                    b[i] = a[i] + 2 * a[(i + 1) % n] + static_cast<std::uint64_t>(k);
            });
            std::swap(a, b);
        }
    });
    return a;
}

TEST(Team, ChainedLoopsMatchOneThreadExactly) {
    Executor one(1);
    const std::vector<std::uint64_t> expected = chainedLoops(one, 1000, 40);
    for (const int threads : {2, 3, 8}) {
        Executor many(threads);
        EXPECT_EQ(chainedLoops(many, 1000, 40), expected) << threads << " threads";
        // The same team again: a run starts from a clean stage count and a team not yet finished.
        EXPECT_EQ(chainedLoops(many, 1000, 40), expected) << threads << " threads, second run";
    }
}

TEST(Team, EveryItemOnceWithAHelperThatJoinsLate) {
    // Driver and helper threads made by hand: the helper starts only after the driver has begun, and the
    // driver must not depend on it.
    Team team(2);
    team.start();
    std::vector<std::atomic<int>> hits(5000);
    std::thread helper;
    int loops = 0;
    for (int k = 0; k < 200; ++k) {
        auto body = [&](std::size_t begin, std::size_t end, int member) {
            EXPECT_GE(member, 0);
            EXPECT_LT(member, 2);
            for (std::size_t i = begin; i < end; ++i) hits[i].fetch_add(1);
        };
        team.forEach(hits.size(), 16, body);
        ++loops;
        if (k == 50) helper = std::thread([&team] { team.help(1); });
    }
    team.finish();
    helper.join();
    for (std::size_t i = 0; i < hits.size(); ++i) ASSERT_EQ(hits[i].load(), loops) << "item " << i;
}

TEST(Team, LoopsOfChangingSizesNeverMix) {
    // Thousands of short loops, each of its own size and grain, on three members: a helper that read a loop late
    // must never run a chunk of it (or of the next) with the other's size, nor a chunk after its loop returned.
    Team team(3);
    team.start();
    std::thread helpers[2];
    for (int m = 0; m < 2; ++m) helpers[m] = std::thread([&team, m] { team.help(m + 1); });
    std::atomic<int> current{-1};
    std::atomic<int> strays{0};
    for (int k = 0; k < 20000; ++k) {
        const std::size_t n = 2 + static_cast<std::size_t>(k * 37 % 97), grain = 1 + static_cast<std::size_t>(k % 5);
        std::atomic<std::size_t> covered{0};
        current.store(k);
        auto body = [&, k, n, grain](std::size_t begin, std::size_t end, int) {
            if (current.load() != k || end > n || begin >= end || end - begin > grain) strays.fetch_add(1);
            covered.fetch_add(end - begin);
        };
        team.forEach(n, grain, body);
        current.store(-1);
        ASSERT_EQ(covered.load(), n) << "loop " << k;
    }
    team.finish();
    for (std::thread& h : helpers) h.join();
    EXPECT_EQ(strays.load(), 0);
}

TEST(Team, DriverAloneFinishesEveryLoop) {
    // No helper ever comes: the driver takes every chunk itself and returns.
    Team team(4);
    team.start();
    std::vector<int> hits(300, 0);
    auto body = [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t i = begin; i < end; ++i) ++hits[i];
    };
    for (int k = 0; k < 10; ++k) team.forEach(hits.size(), 8, body);
    team.finish();
    for (const int h : hits) EXPECT_EQ(h, 10);
}

TEST(Team, ChunksStayWithinEqualShares) {
    // Three members' runs of 100 items are [0, 33), [33, 66), [66, 100): a chunk is at most a grain and never
    // crosses from one run into the next, so each member's first chunks cover the same part of every loop.
    Team team(3);
    team.start();
    std::vector<std::pair<std::size_t, std::size_t>> chunks;
    auto body = [&](std::size_t begin, std::size_t end, int) { chunks.emplace_back(begin, end); };
    team.forEach(100, 16, body);  // no helper: the driver takes every chunk, in order of the runs
    team.finish();
    const std::vector<std::pair<std::size_t, std::size_t>> expected = {{0, 16},  {16, 32}, {32, 33}, {33, 49},
                                                                       {49, 65}, {65, 66}, {66, 82}, {82, 98},
                                                                       {98, 100}};
    EXPECT_EQ(chunks, expected);
}

TEST(Team, NestedLoopRunsInlineOnItsThread) {
    Executor executor(2);
    std::vector<int> inner(64, 0);
    std::atomic<int> outerChunks{0};
    executor.run([&] {
        executor.parallelFor(64, 4, [&](std::size_t begin, std::size_t end, int) {
            outerChunks.fetch_add(1);
            for (std::size_t i = begin; i < end; ++i) {
                // A loop started inside a chunk is one call on this thread, covering the whole range.
                std::size_t calls = 0, covered = 0;
                executor.parallelFor(10, 1, [&](std::size_t b, std::size_t e, int) {
                    ++calls;
                    covered += e - b;
                });
                EXPECT_EQ(calls, 1u);
                EXPECT_EQ(covered, 10u);
                inner[i] = 1;
            }
        });
    });
    EXPECT_EQ(outerChunks.load(), 16);
    for (const int x : inner) EXPECT_EQ(x, 1);
}

TEST(Team, AChunksExceptionReachesTheDriverAndTheTeamGoesOn) {
    Executor executor(2);
    std::vector<int> hits(100, 0);
    executor.run([&] {
        EXPECT_THROW(executor.parallelFor(100, 5,
                                          [&](std::size_t begin, std::size_t, int) {
                                              if (begin == 50) throw std::runtime_error("chunk at 50");
                                          }),
                     std::runtime_error);
        // The next loop runs whole.
        executor.parallelFor(100, 5, [&](std::size_t begin, std::size_t end, int) {
            for (std::size_t i = begin; i < end; ++i) ++hits[i];
        });
    });
    for (const int h : hits) EXPECT_EQ(h, 1);
}

}  // namespace
}  // namespace physim
