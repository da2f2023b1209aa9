// WideBoxTree against brute force: a query reports every leaf whose double box meets the query box (touching counts,
// as Aabb::overlaps), each once, and nothing that misses by more than float rounding (boxes are kept in floats
// rounded outwards, so a leaf a few ulps away may come too: the tolerance is 1e-6 of the coordinates' size, ten
// float ulps). Degenerate inputs (coincident boxes, boxes spaced geometrically) keep the height under 64.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "WideBoxTree.hpp"

namespace physim {
namespace {

bool meets(const Aabb& a, const Aabb& b) {
    return a.lower.x() <= b.upper.x() && b.lower.x() <= a.upper.x() && a.lower.y() <= b.upper.y() &&
           b.lower.y() <= a.upper.y();
}

Aabb widened(const Aabb& b, double scale) {
    const double pad = 1e-6 * scale;
    return Aabb{b.lower - Vec2(pad, pad), b.upper + Vec2(pad, pad)};
}

// Checks one query: every leaf that meets is reported once; every one reported meets within the tolerance.
void expectMatches(const WideBoxTree& tree, const std::vector<Aabb>& boxes, const Aabb& query, double scale) {
    std::vector<std::uint32_t> found;
    tree.query(query, [&](std::uint32_t i) { found.push_back(i); });
    std::sort(found.begin(), found.end());
    ASSERT_TRUE(std::adjacent_find(found.begin(), found.end()) == found.end()) << "a leaf reported twice";
    for (std::uint32_t i = 0; i < boxes.size(); ++i) {
        const bool reported = std::binary_search(found.begin(), found.end(), i);
        if (meets(boxes[i], query)) {
            EXPECT_TRUE(reported) << "leaf " << i << " meets the query but was not reported";
        }
        if (reported) {
            EXPECT_TRUE(meets(widened(boxes[i], scale), query)) << "leaf " << i << " is far from the query";
        }
    }
}

WideBoxTree built(const std::vector<Aabb>& boxes) {
    WideBoxTree tree;
    for (std::uint32_t i = 0; i < boxes.size(); ++i) tree.addLeaf(boxes[i], i);
    tree.build();
    return tree;
}

TEST(WideBoxTree, RandomBoxesMatchBruteForce) {
    for (const std::size_t count : {0u, 1u, 2u, 3u, 4u, 5u, 16u, 17u, 300u, 3000u}) {
        std::mt19937 rng(static_cast<unsigned>(count) + 7);
        std::uniform_real_distribution<double> pos(-100.0, 100.0), size(0.0, 5.0);
        std::vector<Aabb> boxes;
        for (std::size_t i = 0; i < count; ++i) {
            const Vec2 c(pos(rng), pos(rng));
            boxes.push_back(Aabb{c, c + Vec2(size(rng), size(rng))});
        }
        const WideBoxTree tree = built(boxes);
        EXPECT_LT(tree.height(), 64);
        for (int q = 0; q < 400; ++q) {
            const Vec2 c(pos(rng), pos(rng));
            const Aabb query{c, c + Vec2(4.0 * size(rng), 4.0 * size(rng))};
            expectMatches(tree, boxes, query, 200.0);
        }
        // Boxes touching a leaf's edge exactly count, as Aabb::overlaps.
        for (std::size_t i = 0; i < std::min<std::size_t>(count, 50); ++i) {
            const Aabb& b = boxes[i];
            expectMatches(tree, boxes, Aabb{Vec2(b.upper.x(), b.lower.y()), Vec2(b.upper.x() + 1.0, b.lower.y())},
                          200.0);
        }
    }
}

TEST(WideBoxTree, CoincidentBoxesAndPointBoxes) {
    std::vector<Aabb> boxes(5000, Aabb{Vec2(1.0, 1.0), Vec2(2.0, 2.0)});
    for (int i = 0; i < 500; ++i) boxes.push_back(Aabb{Vec2(0.1 * i, 3.0), Vec2(0.1 * i, 3.0)});  // zero size
    const WideBoxTree tree = built(boxes);
    EXPECT_LT(tree.height(), 64);
    expectMatches(tree, boxes, Aabb{Vec2(1.5, 1.5), Vec2(1.5, 1.5)}, 10.0);
    expectMatches(tree, boxes, Aabb{Vec2(0.0, 2.5), Vec2(20.0, 3.0)}, 60.0);
    expectMatches(tree, boxes, Aabb{Vec2(2.0, 2.0), Vec2(5.0, 5.0)}, 10.0);
}

// Centres spaced geometrically: the heuristic cuts one leaf off at a time, which the halving depth bounds.
TEST(WideBoxTree, SkewedBoxesKeepTheHeightBounded) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 20000; ++i) {
        const double x = std::pow(1.002, i);
        boxes.push_back(Aabb{Vec2(x, 0.0), Vec2(x + 1e-3 * x, 1.0)});
    }
    const WideBoxTree tree = built(boxes);
    EXPECT_LT(tree.height(), 64);
    for (const double x : {1.0, 10.0, 1e3, 1e10, 2e17})
        expectMatches(tree, boxes, Aabb{Vec2(x, 0.5), Vec2(1.5 * x, 0.5)}, 2.0 * x);
}

TEST(WideBoxTree, LargeAndTinyCoordinates) {
    std::vector<Aabb> boxes = {Aabb{Vec2(1e30, -1e30), Vec2(1.0000001e30, 1e30)},
                               Aabb{Vec2(1e-30, 1e-30), Vec2(2e-30, 2e-30)}, Aabb{Vec2(-3.0, -3.0), Vec2(-2.0, -2.0)},
                               Aabb{Vec2(-1e300, 5.0), Vec2(1e300, 6.0)}, Aabb{Vec2(1e39, 1e39), Vec2(1e40, 1e40)}};
    const WideBoxTree tree = built(boxes);
    // Each box queried by itself, and by a box touching it from outside: both must report it.
    for (const Aabb& b : boxes) {
        std::vector<std::uint32_t> found;
        tree.query(b, [&](std::uint32_t i) { found.push_back(i); });
        EXPECT_EQ(std::count(found.begin(), found.end(), &b - boxes.data()), 1);
        found.clear();
        tree.query(Aabb{b.upper, b.upper + b.upper.cwiseAbs()}, [&](std::uint32_t i) { found.push_back(i); });
        EXPECT_EQ(std::count(found.begin(), found.end(), &b - boxes.data()), 1);
    }
}

TEST(WideBoxTree, CallbackStopsTheQuery) {
    std::vector<Aabb> boxes;
    for (int i = 0; i < 100; ++i) boxes.push_back(Aabb{Vec2(i, 0.0), Vec2(i + 1.0, 1.0)});
    const WideBoxTree tree = built(boxes);
    int calls = 0;
    tree.query(Aabb{Vec2(-1.0, -1.0), Vec2(200.0, 2.0)}, [&](std::uint32_t) { return ++calls < 3; });
    EXPECT_EQ(calls, 3);
    const double nan = std::nan("");
    tree.query(Aabb{Vec2(nan, 0.0), Vec2(200.0, 2.0)}, [&](std::uint32_t) { return ++calls < 100; });
    EXPECT_EQ(calls, 3);  // a NaN box meets nothing
}

TEST(WideBoxTree, RebuildReplacesTheLeaves) {
    WideBoxTree tree;
    tree.addLeaf(Aabb{Vec2(0.0, 0.0), Vec2(1.0, 1.0)}, 7);
    tree.build();
    tree.clear();
    tree.addLeaf(Aabb{Vec2(5.0, 5.0), Vec2(6.0, 6.0)}, 9);
    tree.build();
    std::vector<std::uint32_t> found;
    tree.query(Aabb{Vec2(-10.0, -10.0), Vec2(10.0, 10.0)}, [&](std::uint32_t i) { found.push_back(i); });
    EXPECT_EQ(found, std::vector<std::uint32_t>{9});
    tree.clear();
    tree.build();
    EXPECT_EQ(tree.height(), 0);
    tree.query(Aabb{Vec2(-10.0, -10.0), Vec2(10.0, 10.0)}, [&](std::uint32_t i) { found.push_back(i); });
    EXPECT_EQ(found.size(), 1u);
}

}  // namespace
}  // namespace physim
