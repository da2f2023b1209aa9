// BroadPhase's pair finding: pairs with a contact are not reported again, a pair the caller declines is offered
// again by the next call although nothing moved, one it passes by only once a proxy of it moves again, proxies moved
// together are queried like proxies moved alone, and the pairs found are the brute-force overlaps however the static
// boxes are searched (their wide tree once built) and however they change.

#include "BroadPhase.hpp"
#include "Executor.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace physim {
namespace {

Aabb box(double x0, double y0, double x1, double y1) { return {Vec2(x0, y0), Vec2(x1, y1)}; }

TEST(BroadPhase, KnownPairsAreNotReportedAgain) {
    BroadPhase bp;
    Executor executor(1);
    bp.createProxy(box(0, 0, 1, 1), 0, false);
    bp.createProxy(box(0.5, 0, 1.5, 1), 1, false);
    bp.createProxy(box(0.9, 0, 2, 1), 2, true);  // static: meets both movable ones
    PairSet known;
    known.insert(PairSet::key(0, 2));
    std::vector<ShapePair> pairs;
    const auto takeAll = [](std::uint32_t, std::uint32_t) { return true; };
    bp.findNewPairs(pairs, known, takeAll, executor);
    EXPECT_EQ(pairs, (std::vector<ShapePair>{{0, 1}, {1, 2}}));
    EXPECT_EQ(bp.moveCount(), 0u);
}

TEST(BroadPhase, ADeclinedPairIsOfferedAgainUntilTaken) {
    BroadPhase bp;
    Executor executor(1);
    bp.createProxy(box(0, 0, 1, 1), 0, false);
    bp.createProxy(box(0.5, 0, 1.5, 1), 1, false);
    bp.createProxy(box(5, 5, 6, 6), 2, false);  // overlaps nothing
    const PairSet known;
    std::vector<ShapePair> pairs;
    int asked = 0;
    const auto decline = [&](std::uint32_t, std::uint32_t) {
        ++asked;
        return false;
    };
    bp.findNewPairs(pairs, known, decline, executor);
    EXPECT_TRUE(pairs.empty());
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(bp.moveCount(), 1u) << "only the proxy whose query met the declined pair is asked again";
    bp.findNewPairs(pairs, known, decline, executor);  // nothing moved: offered again, declined again
    EXPECT_EQ(asked, 2);
    const auto take = [](std::uint32_t, std::uint32_t) { return true; };
    bp.findNewPairs(pairs, known, take, executor);
    EXPECT_EQ(pairs, (std::vector<ShapePair>{{0, 1}}));
    EXPECT_EQ(bp.moveCount(), 0u);
    bp.findNewPairs(pairs, known, take, executor);
    EXPECT_TRUE(pairs.empty()) << "taken, and nothing moved since";
}

TEST(BroadPhase, APairPassedByIsOfferedAgainOnlyWhenAProxyOfItMoves) {
    BroadPhase bp;
    Executor executor(1);
    const std::int32_t a = bp.createProxy(box(0, 0, 1, 1), 0, false);
    bp.createProxy(box(0.5, 0, 1.5, 1), 1, false);
    const PairSet known;
    std::vector<ShapePair> pairs;
    int asked = 0;
    const auto passBy = [&](std::uint32_t, std::uint32_t) {
        ++asked;
        return Offer::PassBy;
    };
    bp.findNewPairs(pairs, known, passBy, executor);
    EXPECT_TRUE(pairs.empty());
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(bp.moveCount(), 0u) << "passed by: no proxy is asked again";
    bp.findNewPairs(pairs, known, passBy, executor);
    EXPECT_EQ(asked, 1) << "nothing moved: not offered";
    bp.moveProxy(a, box(0.1, 0, 1.1, 1));
    bp.findNewPairs(pairs, known, passBy, executor);
    EXPECT_EQ(asked, 2) << "a proxy of the pair moved: offered again";
}

TEST(BroadPhase, ProxiesMovedTogetherAreQueriedAsIfMovedAlone) {
    // 40 proxies on a row, each moved onto its right neighbour's place: with all moved at once the tree is
    // rebuilt, with one moved it is reinserted; the pairs found are the overlaps either way.
    for (const bool all : {false, true}) {
        BroadPhase bp;
        Executor executor(1);
        std::vector<std::int32_t> keys;
        for (std::uint32_t i = 0; i < 40; ++i) keys.push_back(bp.createProxy(box(2.0 * i, 0, 2.0 * i + 1, 1), i, false));
        const PairSet known;
        const auto take = [](std::uint32_t, std::uint32_t) { return true; };
        std::vector<ShapePair> pairs;
        bp.findNewPairs(pairs, known, take, executor);
        ASSERT_TRUE(pairs.empty());
        std::vector<std::int32_t> moving;
        std::vector<Aabb> boxes;
        for (std::uint32_t i = 0; i < (all ? 40u : 1u); ++i) {
            moving.push_back(keys[i]);
            boxes.push_back(box(2.0 * i + 0.5, 0, 2.0 * i + 2.5, 1));  // reaches the next proxy's box
        }
        bp.moveProxies(moving, boxes);
        EXPECT_EQ(bp.moveCount(), moving.size());
        bp.findNewPairs(pairs, known, take, executor);
        std::vector<ShapePair> expected;
        for (std::uint32_t i = 0; i + 1 < 40 && i < moving.size(); ++i) expected.emplace_back(i, i + 1);
        EXPECT_EQ(pairs, expected) << (all ? "all moved" : "one moved");
        EXPECT_EQ(bp.fatBox(keys[0]).upper, Vec2(2.5, 1.0));
    }
}

// 600 static boxes and 60 movable ones that jump about, round after round: the pairs found are exactly the
// overlaps of a moved proxy with any other (static pairs never), checked against all pairs tried. Enough rounds pass
// for the static boxes' four-wide tree to be built (BroadPhase::staticWideTree); then a static proxy is moved, one
// is created and one destroyed (each makes that tree stale), and a copy is assigned back after a different future.
TEST(BroadPhase, NewPairsAreTheBruteForceOverlapsWhileStaticBoxesChange) {
    std::uint64_t state = 12345;
    const auto uniform = [&state](double lo, double hi) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return lo + (hi - lo) * static_cast<double>(state >> 11) / 9007199254740992.0;
    };
    const auto randomBox = [&](double size) {
        const double x = uniform(0.0, 60.0), y = uniform(0.0, 30.0);
        return box(x, y, x + uniform(0.1, size), y + uniform(0.1, size));
    };
    BroadPhase bp;
    Executor executor(1);
    struct Proxy {
        std::int32_t key;
        bool isStatic;
    };
    std::vector<Proxy> proxies;  // by shape
    for (std::uint32_t i = 0; i < 600; ++i) proxies.push_back({bp.createProxy(randomBox(1.5), i, true), true});
    for (std::uint32_t i = 600; i < 660; ++i) proxies.push_back({bp.createProxy(randomBox(2.0), i, false), false});
    const PairSet known;
    const auto take = [](std::uint32_t, std::uint32_t) { return true; };
    std::vector<ShapePair> pairs;
    bp.findNewPairs(pairs, known, take, executor);
    const auto round = [&](const std::vector<std::uint32_t>& movedShapes, const char* what) {
        std::vector<ShapePair> expected;
        for (const std::uint32_t a : movedShapes)
            for (std::uint32_t b = 0; b < proxies.size(); ++b) {
                if (b == a || (proxies[a].isStatic && proxies[b].isStatic)) continue;
                if (proxies[b].key < 0) continue;  // destroyed
                if (bp.fatBox(proxies[a].key).overlaps(bp.fatBox(proxies[b].key)))
                    expected.emplace_back(std::min(a, b), std::max(a, b));
            }
        std::sort(expected.begin(), expected.end());
        expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
        bp.findNewPairs(pairs, known, take, executor);
        EXPECT_EQ(pairs, expected) << what;
        EXPECT_FALSE(expected.empty()) << what << ": a round that tries nothing";
    };
    const auto jump = [&](int rounds, const char* what) {
        for (int r = 0; r < rounds; ++r) {
            std::vector<std::uint32_t> moved;
            for (std::uint32_t i = 600; i < 660; i += 1 + static_cast<std::uint32_t>(uniform(0.0, 2.0))) {
                bp.moveProxy(proxies[i].key, randomBox(2.0));
                moved.push_back(i);
            }
            round(moved, what);
        }
    };
    jump(20, "the static tree's own queries, then the wide tree's");
    bp.moveProxy(proxies[7].key, box(25.0, 10.0, 35.0, 20.0));
    round({7}, "a static proxy moved");
    jump(10, "after a static move");
    proxies.push_back({bp.createProxy(box(20.0, 10.0, 40.0, 20.0), 660, true), true});
    round({660}, "a large static proxy created");
    jump(10, "after a static creation");
    bp.destroyProxy(proxies[660].key);
    proxies[660].key = -1;
    jump(10, "after a static destruction");
    BroadPhase saved = bp;
    const std::vector<Proxy> savedProxies = proxies;
    bp.moveProxy(proxies[8].key, box(0.0, 0.0, 62.0, 32.0));  // meets every movable box
    round({8}, "a static proxy over everything");
    jump(10, "after it");
    bp = saved;  // back to before it, then another future with the same number of static changes
    proxies = savedProxies;
    bp.moveProxy(proxies[9].key, box(10.0, 5.0, 20.0, 15.0));
    round({9}, "restored, another static move");
    jump(10, "restored");
}

}  // namespace
}  // namespace physim
