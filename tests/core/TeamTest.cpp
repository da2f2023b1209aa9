// The solver's team of threads (src/core/Team.hpp) and the executor's use of it: every item of every loop is
// done exactly once and before the next loop starts, whoever does it, and nothing waits on a helper that never
// comes.

#include "Executor.hpp"
#include "Team.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <string>
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


// Loops of items that each update two cells, as a colour's rows update two bodies: no two items of a loop share a
// cell, and each loop's items are listed by their lower cell, as the solver lists its blocks about in body order.
struct PairedLoops {
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> items;  // per loop
    std::vector<std::array<std::size_t, 2>> cuts;  // per loop: where share 0's head starts, share 1's ends

    std::size_t mid(std::size_t loop) const { return items[loop].size() / 2; }
};

PairedLoops pairedLoops(std::size_t cells, std::size_t loops, std::uint64_t seed) {
    PairedLoops p;
    std::vector<std::size_t> order(cells);
    std::iota(order.begin(), order.end(), std::size_t{0});
    for (std::size_t l = 0; l < loops; ++l) {
        for (std::size_t i = cells - 1; i > 0; --i) {  // a fixed shuffle: a different matching per loop
            seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
            std::swap(order[i], order[(seed >> 33) % (i + 1)]);
        }
        std::vector<std::pair<std::size_t, std::size_t>> loopItems;
        for (std::size_t i = 0; i + 1 < cells; i += 2)
            loopItems.emplace_back(std::min(order[i], order[i + 1]), std::max(order[i], order[i + 1]));
        std::sort(loopItems.begin(), loopItems.end());
        p.items.push_back(loopItems);
    }
    // The heads, by their definition: an item that touches a cell the other share touches in any loop.
    std::vector<int> shares(cells, 0);
    for (std::size_t l = 0; l < loops; ++l)
        for (std::size_t k = 0; k < p.items[l].size(); ++k) {
            const int bit = k < p.mid(l) ? 1 : 2;
            shares[p.items[l][k].first] |= bit;
            shares[p.items[l][k].second] |= bit;
        }
    for (std::size_t l = 0; l < loops; ++l) {
        auto both = [&](std::size_t k) {
            return shares[p.items[l][k].first] == 3 || shares[p.items[l][k].second] == 3;
        };
        std::size_t low = p.mid(l), high = p.mid(l);
        for (std::size_t k = 0; k < p.mid(l); ++k)
            if (both(k)) low = std::min(low, k);
        for (std::size_t k = p.mid(l); k < p.items[l].size(); ++k)
            if (both(k)) high = k + 1;
        p.cuts.push_back({low, high});
    }
    return p;
}

// Each item mixes its two cells in an order-dependent way: any cell whose items run out of loop order ends
// different.
void mix(std::vector<std::uint64_t>& cell, std::pair<std::size_t, std::size_t> item, std::size_t loop) {
    const std::uint64_t x = cell[item.first] * 3 + cell[item.second] * 5 + loop;
    cell[item.first] = x;
    cell[item.second] = x ^ (x >> 7);
}

TEST(Team, OrderedLoopsGiveEveryCellItsSerialHistory) {
    // A helper thread made by hand, always there: the pool's worker may come too late on a busy machine, and the
    // driver then runs both shares (the next test), which would leave the two-thread path untested.
    const std::size_t cells = 400, loops = 9;
    Team team(2);
    team.start();
    std::thread helper([&team] { team.help(1); });
    int helperRan = 0;  // sequences in which share 1 ran on the helper
    for (std::uint64_t seed = 1; seed <= 30; ++seed) {
        const PairedLoops p = pairedLoops(cells, loops, seed);
        std::vector<std::uint64_t> expected(cells), cell(cells);
        std::iota(expected.begin(), expected.end(), std::uint64_t{1});
        std::iota(cell.begin(), cell.end(), std::uint64_t{1});
        for (std::size_t l = 0; l < loops; ++l)
            for (const auto& item : p.items[l]) mix(expected, item, l);
        const std::thread::id driver = std::this_thread::get_id();
        std::atomic<bool> helperStarted{false};
        auto part = [&](std::size_t l, int share, bool head) {
            const std::size_t cut = p.cuts[l][static_cast<std::size_t>(share)], mid = p.mid(l);
            const std::size_t begin = share == 0 ? (head ? cut : 0) : (head ? mid : cut);
            const std::size_t end = share == 0 ? (head ? mid : cut) : (head ? cut : p.items[l].size());
            if (share == 1 && std::this_thread::get_id() != driver) helperStarted.store(true);
            // The driver's first rest gives the helper up to a second to claim its share.
            if (share == 0 && !head && l == 0)
                for (int waited = 0; !helperStarted.load() && waited < 10000; ++waited)
                    std::this_thread::sleep_for(std::chrono::microseconds(100));
            // A slow rest: a share that went on without waiting for the other's head would overtake it.
            if (!head && (l + seed + static_cast<std::size_t>(share)) % 3 == 0)
                std::this_thread::sleep_for(std::chrono::microseconds(30));
            for (std::size_t k = begin; k < end; ++k) mix(cell, p.items[l][k], l);
        };
        ASSERT_TRUE(team.ordersLoops());
        team.forLoopsInOrder(loops, part);
        EXPECT_EQ(cell, expected) << "seed " << seed;
        helperRan += helperStarted.load();
    }
    team.finish();
    helper.join();
    EXPECT_EQ(helperRan, 30) << "the helper did not run its share in every sequence";
}

TEST(Team, OrderedLoopsRunWholeWithoutTheHelper) {
    // No helper comes: the driver does its loop 0, takes share 1 from its start, and runs both in order.
    Team team(2);
    team.start();
    for (const std::size_t loops : {std::size_t{1}, std::size_t{3}}) {
        std::vector<std::string> calls;
        auto part = [&](std::size_t loop, int share, bool head) {
            calls.push_back(std::to_string(loop) + (share == 0 ? "a" : "b") + (head ? "h" : "r"));
        };
        team.forLoopsInOrder(loops, part);
        const std::vector<std::string> expected =
            loops == 1 ? std::vector<std::string>{"0ah", "0ar", "0bh", "0br"}
                       : std::vector<std::string>{"0ah", "0ar", "0bh", "0br", "1ah", "1bh", "1ar",
                                                  "1br", "2ah", "2bh", "2ar", "2br"};
        EXPECT_EQ(calls, expected) << loops << " loops";
    }
    team.finish();
}

}  // namespace
}  // namespace physim
