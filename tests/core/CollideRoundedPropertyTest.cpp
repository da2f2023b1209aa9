// Randomised narrow-phase checks for every pair of the kinds circle, polygon, rounded polygon, segment and capsule
// against brute-force references that share no code with the narrow phase (tests/support/CollideReference.hpp:
// every kind a core grown by a radius; exact touching tests, penetration as the minimum over sampled and refined
// directions of support_A(d) + support_B(-d), contact points within penetration / 2 of both shapes), with its
// tolerances, as CollidePropertyTest.cpp: 1e-9 m for what the narrow phase computes directly, 1e-7 m against the
// sampled minimum, kReferenceFaceTolerance (1e-4 m) where two facing edges tie. Chain segments are one-sided and
// have tests of their own (ChainSegmentTest.cpp).

#include "Manifolds.hpp"  // collideGeometries with a margin (internal: src/core is on this program's include path)

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

constexpr int kKinds = 5;  // circle, polygon, rounded polygon, segment, capsule
const char* const kKindNames[kKinds] = {"circle", "polygon", "rounded polygon", "segment", "capsule"};

class RandomShapes : public RandomDraws {
public:
    using RandomDraws::RandomDraws;

    int kind() { return std::uniform_int_distribution<int>(0, kKinds - 1)(rng_); }
    Geometry shape(int kind) {
        const Vec2 offset(uniform(-0.3, 0.3), uniform(-0.3, 0.3));
        switch (kind) {
            case 0: return makeCircle(uniform(0.1, 1.5), offset);
            case 1: return polygon(0.0);
            case 2: return polygon(uniform(0.02, 0.6));
            case 3: return makeSegment(offset + Vec2(uniform(-1.5, 1.5), uniform(-1.5, 1.5)),
                                       offset + Vec2(uniform(-1.5, 1.5), uniform(-1.5, 1.5)));
            default: return makeCapsule(offset + Vec2(uniform(-1.2, 1.2), uniform(-1.2, 1.2)),
                                        offset + Vec2(uniform(-1.2, 1.2), uniform(-1.2, 1.2)), uniform(0.05, 0.8));
        }
    }

private:
    // A box (a third of the draws) or points on an ellipse at sorted random angles; grown by radius when > 0.
    Polygon polygon(double radius) {
        for (;;) {
            std::vector<Vec2> pts;
            const double rx = uniform(0.05, 1.3), ry = uniform(0.05, 1.3);
            if (uniform(0.0, 1.0) < 1.0 / 3.0) {
                pts = {{-rx, -ry}, {rx, -ry}, {rx, ry}, {-rx, ry}};
            } else {
                const int count = std::uniform_int_distribution<int>(3, Polygon::maxVertices)(rng_);
                std::vector<double> angles(count);
                for (double& t : angles) t = uniform(0.0, 2.0 * M_PI);
                std::sort(angles.begin(), angles.end());
                const Vec2 offset(uniform(-0.3, 0.3), uniform(-0.3, 0.3));
                for (double t : angles) pts.push_back(offset + Vec2(rx * std::cos(t), ry * std::sin(t)));
            }
            try {
                return radius > 0.0 ? makeRoundedPolygon(pts, radius) : makePolygon(pts);
            } catch (const std::invalid_argument&) {
                // near-coincident or collinear draw: draw again
            }
        }
    }
};

TEST(CollidePropertyRoundedSegmentCapsule, EveryPairOfKindsMatchesBruteForceReference) {
    RandomShapes random(52);
    int colliding[kKinds][kKinds] = {}, drawn[kKinds][kKinds] = {};
    int twoPoints = 0, facingTies = 0;
    for (int k = 0; k < 4 * kPairs; ++k) {
        const int ka = random.kind(), kb = random.kind();
        const Geometry ga = random.shape(ka), gb = random.shape(kb);
        const Transform xa = random.transform(1.0), xb = random.transform(1.0);
        SCOPED_TRACE("pair " + std::to_string(k) + ": " + kKindNames[ka] + " and " + kKindNames[kb]);
        ++drawn[ka][kb];
        PairOutcome outcome;
        ASSERT_NO_FATAL_FAILURE(checkAgainstReference(ga, xa, gb, xb, outcome));
        colliding[ka][kb] += outcome.colliding;
        twoPoints += outcome.twoPoints;
        facingTies += outcome.facingTie;
    }
    // Every ordered pair of kinds must be drawn and collide often enough to mean something.
    for (int i = 0; i < kKinds; ++i)
        for (int j = 0; j < kKinds; ++j)
            EXPECT_GT(colliding[i][j], drawn[i][j] / 10) << kKindNames[i] << " and " << kKindNames[j];
    EXPECT_GT(twoPoints, 500);
    EXPECT_LT(facingTies, 4 * kPairs / 1000) << "ties between facing edges should be rare in random draws";
}

// Apart but within the margin: a speculative manifold whose separation is the gap; beyond it nothing. (Two radius-0
// polygons keep their separating-axis routine, whose separation is a lower bound of the gap at a corner.)
TEST(CollidePropertyRoundedSegmentCapsule, SpeculativeSeparationIsTheGap) {
    RandomShapes random(5252);
    int speculative = 0;
    for (int k = 0; k < kPairs; ++k) {
        const int ka = random.kind(), kb = random.kind();
        const Geometry ga = random.shape(ka), gb = random.shape(kb);
        const Transform xa = random.transform(1.5), xb = random.transform(1.5);
        const double apart = gap(place(ga, xa), place(gb, xb));
        if (apart <= 1e-6) continue;
        constexpr double margin = 0.2;
        const NarrowResult r = collideGeometries(ga, xa, gb, xb, margin);
        SCOPED_TRACE("pair " + std::to_string(k) + ": " + kKindNames[ka] + " and " + kKindNames[kb]);
        const bool polygons = ka == 1 && kb == 1;
        if (apart > margin + kExact) {
            if (!polygons) {
                EXPECT_EQ(r.manifold.pointCount, 0);
            }
            continue;
        }
        if (apart < margin - kExact) {
            ASSERT_GT(r.manifold.pointCount, 0);
            ++speculative;
            double deepest = r.manifold.points[0].separation;
            for (int i = 1; i < r.manifold.pointCount; ++i)
                deepest = std::min(deepest, r.manifold.points[i].separation);
            if (polygons) {
                EXPECT_LE(r.separation, apart + kExact);
            } else {
                EXPECT_NEAR(r.separation, apart, kExact);
                EXPECT_NEAR(deepest, apart, kExact);
            }
        }
    }
    EXPECT_GT(speculative, 500);
}

TEST(CollidePropertyRoundedSegmentCapsule, SwappingTheShapesReversesTheNormal) {
    RandomShapes random(77);
    int exactFlips = 0, colliding = 0;
    for (int k = 0; k < kPairs; ++k) {
        const int ka = random.kind(), kb = random.kind();
        const Geometry ga = random.shape(ka), gb = random.shape(kb);
        const Transform xa = random.transform(1.0), xb = random.transform(1.0);
        SCOPED_TRACE("pair " + std::to_string(k) + ": " + kKindNames[ka] + " and " + kKindNames[kb]);
        ASSERT_NO_FATAL_FAILURE(checkSwapReversesNormal(ga, xa, gb, xb, colliding, exactFlips));
    }
    EXPECT_GT(exactFlips, colliding - colliding / 100);
}

// A segment, capsule or rounded polygon scaled from micrometres to kilometres and placed far from the origin, and
// every kind (chain pieces too) in coincident placements that tie every choice: never NaN, at most two points.
TEST(CollidePropertyRoundedSegmentCapsule, NeverNaNForFiniteAndDegenerateInputs) {
    RandomShapes random(999);
    checkScaledPairsAreSane(random, kPairs, [&] { return random.shape(random.kind()); });
    const std::vector<Geometry> shapes = {
        makeCircle(1.0), makeBox(1.0, 1.0), makeRoundedBox(1.0, 1.0, 0.5), makeRoundedBox(1e-3, 10.0, 1e-3),
        makeSegment({-1, 0}, {1, 0}), makeSegment({0, 0}, {0, 1}), makeCapsule({-1, 0}, {1, 0}, 0.5),
        makeCapsule({0, 0}, {0, 1e-3}, 1.0), makeRoundedPolygon({{0, 0}, {1, 0}, {0, 1}}, 0.1),
        ChainSegment{{-2, 0}, makeSegment({-1, 0}, {1, 0}), {2, 0}},
        ChainSegment{{-1, 0}, makeSegment({-1, 0}, {1, 0}), {2, 1}},
        ChainSegment{{-2, 1}, makeSegment({-1, 0}, {1, 0}), {1, 0}}};
    const std::vector<Transform> poses = {
        {}, {{0, 0}, Rotation::fromAngle(M_PI / 4)}, {{1, 1}, {}}, {{2, 0}, {}}, {{1, 0}, Rotation::fromAngle(M_PI)},
        {{0.5, 0.5}, {}}, {{1e-300, 0}, {}}, {{0, 2}, Rotation::fromAngle(M_PI / 2)}, {{0, 1.5}, {}}};
    checkEveryPlacementIsSane(shapes, poses);
}

}  // namespace
}  // namespace physim
