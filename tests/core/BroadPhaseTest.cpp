// Broad phase against brute force: exactly the pairs whose world boxes overlap (touching counts, the paper's
// AABB test), each once with first < second, sorted, never two static bodies; for scattered scenes, stacks in a
// column or a row, far from the origin, with dead slots, with large boxes among small ones, and for a scratch
// reused over a moving scene (the order kept between calls). Exact comparison: both sides test the same boxes.

#include "BroadPhase.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace physim {
namespace {

std::vector<BodyPair> bruteForce(const std::vector<BodyData>& bodies) {
    std::vector<BodyPair> out;
    for (std::uint32_t i = 0; i < bodies.size(); ++i)
        for (std::uint32_t j = i + 1; j < bodies.size(); ++j) {
            const BodyData &a = bodies[i], &b = bodies[j];
            if (!a.alive || !b.alive || (!a.movable() && !b.movable())) continue;
            if (computeAabb(a.shape, a.xf).overlaps(computeAabb(b.shape, b.xf))) out.emplace_back(i, j);
        }
    return out;
}

BodyData body(const Geometry& shape, const Vec2& p, double angle, BodyType type) {
    BodyData b;
    b.alive = true;
    b.type = type;
    b.shape = shape;
    b.xf = {p, Rotation::fromAngle(angle)};
    b.angle = angle;
    return b;
}

void expectMatchesBruteForce(std::vector<BodyData>& bodies) {
    std::vector<BodyPair> pairs;
    std::vector<std::uint32_t> scratch;
    findCandidatePairs(bodies, pairs, scratch);
    EXPECT_EQ(pairs, bruteForce(bodies));
    for (const BodyPair& p : pairs) EXPECT_LT(p.first, p.second);
}

TEST(BroadPhase, RandomScenesMatchBruteForce) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int scene = 0; scene < 20; ++scene) {
        std::vector<BodyData> bodies;
        const double side = 5.0 + 20.0 * u(rng);
        const Vec2 far = scene % 4 == 0 ? Vec2(1e7, -3e6) : Vec2::Zero();
        for (int i = 0; i < 400; ++i) {
            const BodyType type = u(rng) < 0.2 ? BodyType::Static : (u(rng) < 0.1 ? BodyType::Kinematic : BodyType::Dynamic);
            const Geometry shape = u(rng) < 0.5 ? Geometry{makeCircle(0.1 + 0.5 * u(rng))}
                                                : Geometry{makeBox(0.1 + u(rng), 0.05 + 0.3 * u(rng))};
            bodies.push_back(body(shape, far + Vec2(side * u(rng), side * u(rng)), 6.3 * u(rng), type));
            if (u(rng) < 0.05) bodies.back().alive = false;  // a destroyed body's slot
        }
        expectMatchesBruteForce(bodies);
    }
}

TEST(BroadPhase, ColumnsRowsAndTouchingBoxes) {
    // A vertical stack and a horizontal row of 200 touching unit boxes on a 100 m wide ground whose top is
    // y = -0.5: the stack meets the ground with its first box, the row with the 51 boxes over x in [-50, 50].
    for (const bool column : {true, false}) {
        std::vector<BodyData> bodies;
        bodies.push_back(body(makeBox(50.0, 50.0), {0.0, -50.5}, 0.0, BodyType::Static));
        for (int i = 0; i < 200; ++i)
            bodies.push_back(body(makeBox(0.5, 0.5), column ? Vec2(0.0, i) : Vec2(i, 0.0), 0.0, BodyType::Dynamic));
        std::vector<BodyPair> pairs;
        std::vector<std::uint32_t> scratch;
        findCandidatePairs(bodies, pairs, scratch);
        EXPECT_EQ(pairs, bruteForce(bodies));
        EXPECT_EQ(pairs.size(), column ? 200u : 250u);
    }
}

TEST(BroadPhase, LargeBoxesAmongSmallOnes) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int scene = 0; scene < 10; ++scene) {
        std::vector<BodyData> bodies;
        bodies.push_back(body(makeBox(30.0, 0.5), {15.0, -0.5}, 0.0, BodyType::Static));   // ground
        bodies.push_back(body(makeBox(0.5, 30.0), {-0.5, 15.0}, 0.0, BodyType::Static));   // wall
        bodies.push_back(body(makeBox(20.0, 0.2), {15.0, 12.0}, 0.3, BodyType::Kinematic)); // tilted beam
        for (int i = 0; i < 500; ++i) {
            const bool big = u(rng) < 0.1;
            const double size = big ? 2.0 + 8.0 * u(rng) : 0.1 + 0.4 * u(rng);
            bodies.push_back(body(makeBox(size, 0.5 * size), {30.0 * u(rng), 30.0 * u(rng)}, 6.3 * u(rng),
                                  u(rng) < 0.1 ? BodyType::Static : BodyType::Dynamic));
        }
        expectMatchesBruteForce(bodies);
    }
}

TEST(BroadPhase, ReusedScratchFollowsAMovingScene) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<BodyData> bodies;
    for (int i = 0; i < 300; ++i)
        bodies.push_back(body(u(rng) < 0.5 ? Geometry{makeCircle(0.3)} : Geometry{makeBox(0.4, 0.2)},
                              {20.0 * u(rng), 20.0 * u(rng)}, 0.0, BodyType::Dynamic));
    std::vector<BodyPair> pairs;
    std::vector<std::uint32_t> scratch;
    for (int step = 0; step < 60; ++step) {
        for (BodyData& b : bodies) {  // small moves: last call's order stays nearly sorted
            b.xf.p += Vec2(0.2 * (u(rng) - 0.5), 0.2 * (u(rng) - 0.5));
            b.angle += 0.1;
            b.xf.q = Rotation::fromAngle(b.angle);
        }
        if (step % 7 == 3) bodies[static_cast<std::size_t>(u(rng) * 300)].alive = false;     // destroyed
        if (step % 11 == 5) bodies.push_back(body(makeCircle(2.0), {10.0, 10.0}, 0.0, BodyType::Dynamic));
        if (step % 13 == 6) bodies[static_cast<std::size_t>(u(rng) * 300)].alive = true;      // slot reused
        if (step % 17 == 8)                                                                   // shuffled
            for (BodyData& b : bodies) b.xf.p = {20.0 * u(rng), 20.0 * u(rng)};
        findCandidatePairs(bodies, pairs, scratch);
        ASSERT_EQ(pairs, bruteForce(bodies)) << "step " << step;
    }
}

TEST(BroadPhase, AnyScratchContentGivesTheRightPairs) {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<BodyData> bodies;
    for (int i = 0; i < 200; ++i)
        bodies.push_back(body(makeCircle(0.4), {10.0 * u(rng), 10.0 * u(rng)}, 0.0, BodyType::Dynamic));
    std::vector<BodyPair> pairs;
    // An order of the right length that repeats slot 0 and so misses slot 199: counting alone would trust it.
    std::vector<std::uint32_t> scratch = {200};
    for (std::uint32_t i = 0; i < 199; ++i) scratch.push_back(i);
    scratch.push_back(0);
    findCandidatePairs(bodies, pairs, scratch);
    EXPECT_EQ(pairs, bruteForce(bodies));
    // A stale count with out-of-range slots.
    scratch = {100000, 3, 3, 7, 9999, 1};
    findCandidatePairs(bodies, pairs, scratch);
    EXPECT_EQ(pairs, bruteForce(bodies));
    std::vector<std::uint32_t> empty;
    findCandidatePairs(bodies, pairs, empty);
    EXPECT_EQ(pairs, bruteForce(bodies));
}

TEST(BroadPhase, NeverPairsTwoStaticBodies) {
    std::vector<BodyData> bodies;
    for (int i = 0; i < 10; ++i) bodies.push_back(body(makeBox(1.0, 1.0), {0.1 * i, 0.0}, 0.0, BodyType::Static));
    std::vector<BodyPair> pairs;
    std::vector<std::uint32_t> scratch;
    findCandidatePairs(bodies, pairs, scratch);
    EXPECT_TRUE(pairs.empty());
    bodies.push_back(body(makeCircle(0.5), {0.0, 0.0}, 0.0, BodyType::Kinematic));
    findCandidatePairs(bodies, pairs, scratch);
    EXPECT_EQ(pairs.size(), 10u);
}

}  // namespace
}  // namespace physim
