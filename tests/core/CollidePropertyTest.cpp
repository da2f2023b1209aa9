// Randomised narrow-phase checks of circles and sharp polygons against brute-force references that share no code
// with the narrow phase (tests/support/CollideReference.hpp: exact touching tests, penetration as the minimum over
// sampled and refined directions, contact points within penetration / 2 of both shapes), with its tolerances:
// 1e-9 m for identities the narrow phase computes directly, 1e-7 m against the sampled minimum, and
// kReferenceFaceTolerance (1e-4 m, src/core/Manifolds.hpp) where two facing polygon edges tie.
// Fixed seeds; 12 000 pairs per test keeps the suite fast under AddressSanitizer too.

#include "support/CollideReference.hpp"

#include "physim/core/Collide.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace physim {
namespace {

using namespace testing::reference;

constexpr int kPairs = 12000;

class RandomShapes : public RandomDraws {
public:
    using RandomDraws::RandomDraws;

    Geometry shape() {
        switch (std::uniform_int_distribution<int>(0, 3)(rng_)) {
            case 0: return makeCircle(uniform(0.1, 1.5), {uniform(-0.3, 0.3), uniform(-0.3, 0.3)});
            case 1: return makeBox(uniform(0.05, 1.5), uniform(0.05, 1.5));
            default: return polygon();
        }
    }

private:
    // Points on an ellipse at sorted random angles: convex, 3 to 8 vertices, sometimes long and thin.
    Polygon polygon() {
        for (;;) {
            const int count = std::uniform_int_distribution<int>(3, Polygon::maxVertices)(rng_);
            std::vector<double> angles(count);
            for (double& t : angles) t = uniform(0.0, 2.0 * M_PI);
            std::sort(angles.begin(), angles.end());
            const double rx = uniform(0.1, 1.5), ry = uniform(0.1, 1.5);
            const Vec2 offset(uniform(-0.3, 0.3), uniform(-0.3, 0.3));
            std::vector<Vec2> pts;
            for (double t : angles) pts.emplace_back(offset.x() + rx * std::cos(t), offset.y() + ry * std::sin(t));
            try {
                return makePolygon(pts);
            } catch (const std::invalid_argument&) {
                // near-coincident or collinear draw: draw again
            }
        }
    }
};

TEST(CollideProperty, MatchesBruteForceReference) {
    RandomShapes random(20240512);
    int colliding = 0, twoPoints = 0, facingTies = 0;
    for (int k = 0; k < kPairs; ++k) {
        const Geometry ga = random.shape(), gb = random.shape();
        const Transform xa = random.transform(1.0), xb = random.transform(1.0);
        SCOPED_TRACE("pair " + std::to_string(k));
        PairOutcome outcome;
        ASSERT_NO_FATAL_FAILURE(checkAgainstReference(ga, xa, gb, xb, outcome));
        colliding += outcome.colliding;
        twoPoints += outcome.twoPoints;
        facingTies += outcome.facingTie;
    }
    // The draw must exercise the interesting cases, not just misses.
    EXPECT_GT(colliding, kPairs / 4);
    EXPECT_GT(twoPoints, 50);
    EXPECT_LT(facingTies, kPairs / 1000) << "ties between facing edges should be rare in random draws";
}

TEST(CollideProperty, SwappingTheShapesReversesTheNormal) {
    RandomShapes random(7);
    int exactFlips = 0, colliding = 0;
    for (int k = 0; k < kPairs; ++k) {
        const Geometry ga = random.shape(), gb = random.shape();
        const Transform xa = random.transform(1.0), xb = random.transform(1.0);
        SCOPED_TRACE("pair " + std::to_string(k));
        ASSERT_NO_FATAL_FAILURE(checkSwapReversesNormal(ga, xa, gb, xb, colliding, exactFlips));
    }
    EXPECT_GT(exactFlips, colliding - colliding / 100);
}

TEST(CollideProperty, NeverNaNForFiniteAndDegenerateInputs) {
    RandomShapes random(99);
    // Scaled shapes: micrometre to kilometre, near and very far from the origin, all placements.
    checkScaledPairsAreSane(random, kPairs, [&] { return random.shape(); });
    // Coincident placements and shared features: ties in every choice the narrow phase makes.
    checkEveryPlacementIsSane(
        {makeCircle(1.0), makeBox(1.0, 1.0), makeBox(1e-3, 10.0), makePolygon({{0, 0}, {1, 0}, {0, 1}}),
         makeCircle(1.0, {0.5, 0.0})},
        {{}, {{0, 0}, Rotation::fromAngle(M_PI / 4)}, {{1, 1}, {}}, {{2, 0}, {}}, {{1, 0}, Rotation::fromAngle(M_PI)},
         {{0.5, 0.5}, {}}, {{1e-300, 0}, {}}, {{0, 2}, Rotation::fromAngle(M_PI / 2)}});
}

}  // namespace
}  // namespace physim
