// BroadPhase's pair finding: pairs with a contact are not reported again, a pair the caller declines is offered
// again by the next call although nothing moved, and proxies moved together are queried like proxies moved alone.

#include "BroadPhase.hpp"
#include "Executor.hpp"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace physim
