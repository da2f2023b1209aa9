// The shared kernel's distance and time of impact for the kinds beyond the circle and the sharp polygon: segments,
// capsules, chain segments (two-sided in the kernel) and rounded polygons, built by hand as kernel::Shape values
// (tests/support/KernelShapes.hpp). The reference shares no code with the kernel: the distance between two cores
// (point, segment or convex polygon) from point-segment distances, proper edge crossings and point-in-polygon
// tests, minus both radii, and, over a motion, that distance sampled densely with refinement where it comes near.
// Tolerances: the kernel and the reference compute the same exact distance in different orders, so they agree to
// 1e-12 m (rounding at metre scale); over a motion, as in TimeOfImpactTest.cpp, the exact method promises a gap
// below kToiTolerance at a hit and at least tolerance / 2 before it.

#include "KernelBridge.hpp"

#include "support/DenseSampling.hpp"
#include "support/KernelShapes.hpp"
#include "support/RandomBatch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

namespace physim {
namespace {

using testing::kernelBox;
using testing::kernelCapsule;
using testing::kernelChainSegment;
using testing::kernelCircle;
using testing::kernelRounded;
using testing::kernelSegment;

// --- The reference: a shape placed in the world as its core's points and its radius.

struct Placed {
    std::vector<Vec2> core;  ///< 1 point (circle), 2 (segment) or a counter-clockwise convex polygon
    double radius;
};

Placed place(const kernel::Shape& s, const Transform& xf) {
    Placed p{{}, s.radius};
    for (int i = 0; i < s.count; ++i) p.core.push_back(xf.apply(Vec2(s.vertices[i].x, s.vertices[i].y)));
    return p;
}

double toSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 e = b - a;
    const double s = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    return (p - (a + s * e)).norm();
}

// The core's edges: none for a point, the segment once, a polygon's closed loop.
std::vector<std::pair<Vec2, Vec2>> edges(const std::vector<Vec2>& core) {
    std::vector<std::pair<Vec2, Vec2>> e;
    if (core.size() == 2) e.emplace_back(core[0], core[1]);
    if (core.size() > 2)
        for (std::size_t i = 0; i < core.size(); ++i) e.emplace_back(core[i], core[(i + 1) % core.size()]);
    return e;
}

bool crossProperly(const std::pair<Vec2, Vec2>& a, const std::pair<Vec2, Vec2>& b) {
    const double o1 = cross(a.second - a.first, b.first - a.first), o2 = cross(a.second - a.first, b.second - a.first);
    const double o3 = cross(b.second - b.first, a.first - b.first), o4 = cross(b.second - b.first, a.second - b.first);
    return o1 * o2 < 0.0 && o3 * o4 < 0.0;
}

bool strictlyInside(const Vec2& p, const std::vector<Vec2>& polygon) {
    if (polygon.size() < 3) return false;
    for (const auto& [a, b] : edges(polygon))
        if (!(cross(b - a, p - a) > 0.0)) return false;
    return true;
}

// Distance between the cores: 0 when edges cross or one holds the other; otherwise the closest points of disjoint
// convex sets include a vertex of one, so the least vertex-to-edge (or point-to-point) distance.
double coreDistance(const Placed& a, const Placed& b) {
    const auto ea = edges(a.core), eb = edges(b.core);
    for (const auto& x : ea)
        for (const auto& y : eb)
            if (crossProperly(x, y)) return 0.0;
    if (strictlyInside(b.core[0], a.core) || strictlyInside(a.core[0], b.core)) return 0.0;
    double d = INFINITY;
    for (const Vec2& p : a.core)
        for (const auto& [s, e] : eb) d = std::min(d, toSegment(p, s, e));
    for (const Vec2& p : b.core)
        for (const auto& [s, e] : ea) d = std::min(d, toSegment(p, s, e));
    if (a.core.size() == 1 && b.core.size() == 1) d = (a.core[0] - b.core[0]).norm();
    return d;
}

double referenceDistance(const Placed& a, const Placed& b) {
    return std::max(0.0, coreDistance(a, b) - a.radius - b.radius);
}

// How far p lies outside the core (0 on or inside it): for a point on the placed shape's surface, its radius.
double fromCore(const Vec2& p, const Placed& s) {
    return coreDistance(Placed{{p}, 0.0}, Placed{s.core, 0.0});
}

kernel::Xf toXf(const Transform& xf) { return {{xf.p.x(), xf.p.y()}, {xf.q.c, xf.q.s}}; }

// Every kind, the new ones in several sizes: the distance, its witness points on both surfaces and its normal.
std::vector<kernel::Shape> everyKind() {
    std::vector<Vec2> pentagon;
    for (int k = 0; k < 5; ++k) pentagon.emplace_back(0.3 * std::cos(0.4 * M_PI * k), 0.2 * std::sin(0.4 * M_PI * k));
    return {kernelCircle(0.1),
            kernelCircle(0.05, {0.1, -0.05}),
            kernelBox(0.2, 0.1),
            kernelSegment({-0.4, 0.0}, {0.4, 0.1}),
            kernelChainSegment({0.3, 0.2}, {-0.3, -0.1}),
            kernelCapsule({-0.2, 0.0}, {0.25, 0.05}, 0.06),
            kernelBox(0.15, 0.05, 0.04),
            kernelRounded(kernel::kPolygon, pentagon, 0.02),
            kernelRounded(kernel::kPolygon, {{-0.1, -0.1}, {0.2, 0.0}, {0.0, 0.15}}, 0.1)};
}

TEST(ShapeDistanceKinds, SegmentCapsuleChainAndRoundedMatchTheReference) {
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::vector<kernel::Shape> shapes = everyKind();
    int apart = 0, overlapping = 0;
    for (int trial = 0; trial < 8000; ++trial) {
        const kernel::Shape& a = shapes[trial % shapes.size()];
        const kernel::Shape& b = shapes[(trial / shapes.size()) % shapes.size()];
        const Transform xa{{0.1 * u(rng), 0.1 * u(rng)}, Rotation::fromAngle(3.2 * u(rng))};
        const Transform xb{{0.8 * u(rng), 0.8 * u(rng)}, Rotation::fromAngle(3.2 * u(rng))};
        const Placed pa = place(a, xa), pb = place(b, xb);
        const double reference = referenceDistance(pa, pb);
        const kernel::Distance d = kernel::shapeDistance(a, toXf(xa), b, toXf(xb));
        ASSERT_NEAR(d.distance, reference, 1e-12) << "trial " << trial << ", kinds " << a.kind << " " << b.kind;
        if (reference == 0.0) {
            ++overlapping;
            continue;
        }
        ++apart;
        const Vec2 pointA(d.pointA.x, d.pointA.y), pointB(d.pointB.x, d.pointB.y), normal(d.normal.x, d.normal.y);
        EXPECT_NEAR((pointB - pointA).norm(), d.distance, 1e-12) << trial;
        EXPECT_NEAR(normal.norm(), 1.0, 1e-12) << trial;
        EXPECT_NEAR(normal.dot(pointB - pointA), d.distance, 1e-12) << trial;
        EXPECT_NEAR(fromCore(pointA, pa), a.radius, 1e-12) << "witness on a's surface: " << trial;
        EXPECT_NEAR(fromCore(pointB, pb), b.radius, 1e-12) << "witness on b's surface: " << trial;
    }
    // The placements' design: both outcomes common for every pair of kinds.
    EXPECT_GT(apart, 3000);
    EXPECT_GT(overlapping, 1000);
}

// Closed forms, including the case a polygon's separating axes miss: two segments on one line, apart only along it.
TEST(ShapeDistanceKinds, SegmentsCapsulesAndRoundedBoxesInClosedForm) {
    const kernel::Xf origin{{0.0, 0.0}, {1.0, 0.0}};
    const kernel::Shape unit = kernelSegment({0.0, 0.0}, {1.0, 0.0});
    EXPECT_NEAR(kernel::shapeDistance(unit, origin, unit, {{2.0, 0.0}, {1.0, 0.0}}).distance, 1.0, 1e-15);
    EXPECT_NEAR(kernel::shapeDistance(unit, origin, unit, {{-0.5, 0.0}, {-1.0, 0.0}}).distance, 0.5, 1e-15);  // turned: [-1.5, -0.5]
    EXPECT_EQ(kernel::shapeDistance(unit, origin, unit, {{0.5, 0.0}, {1.0, 0.0}}).distance, 0.0);  // overlapping
    // Crossing at right angles: 0; the same segment lifted 0.3 m above the other's end: 0.3.
    const kernel::Rot quarter{0.0, 1.0};
    EXPECT_EQ(kernel::shapeDistance(unit, origin, unit, {{0.5, -0.5}, quarter}).distance, 0.0);
    EXPECT_NEAR(kernel::shapeDistance(unit, origin, unit, {{1.0, 0.3}, quarter}).distance, 0.3, 1e-15);
    // A circle on a segment's line beyond its end: the gap to the end, not 0.
    EXPECT_NEAR(kernel::shapeDistance(unit, origin, kernelCircle(0.1), {{1.5, 0.0}, {1.0, 0.0}}).distance, 0.4, 1e-15);
    // Parallel capsules of radius 0.05, 0.3 m between their centre lines.
    const kernel::Shape capsule = kernelCapsule({-0.5, 0.0}, {0.5, 0.0}, 0.05);
    const kernel::Distance d = kernel::shapeDistance(capsule, origin, capsule, {{0.2, 0.3}, {1.0, 0.0}});
    EXPECT_NEAR(d.distance, 0.2, 1e-15);
    EXPECT_NEAR(d.normal.y, 1.0, 1e-15);
    EXPECT_NEAR(d.pointA.y, 0.05, 1e-15);
    EXPECT_NEAR(d.pointB.y, 0.25, 1e-15);
    // A rounded box's corner is a quarter circle: against a circle on its diagonal, the centres' distance less the
    // core corner's and both radii.
    const kernel::Shape rounded = kernelBox(0.2, 0.2, 0.05);
    EXPECT_NEAR(kernel::shapeDistance(rounded, origin, kernelCircle(0.1), {{1.0, 1.0}, {1.0, 0.0}}).distance,
                0.8 * std::sqrt(2.0) - 0.15, 1e-15);
    // A rounded box against a sharp one, face to face 0.5 m apart between cores.
    EXPECT_NEAR(kernel::shapeDistance(rounded, origin, kernelBox(0.1, 0.1), {{0.8, 0.05}, {1.0, 0.0}}).distance,
                0.5 - 0.05, 1e-15);
}

// --- Over a motion: the true distance sampled densely, refined where it comes near (tests/support/DenseSampling.hpp,
// as TimeOfImpactTest.cpp, with the reference distance): the sampling's error bound is tolerance / 20.
testing::DenseSampling sampleMotion(const kernel::Shape& a, const Sweep& sa, const kernel::Shape& b, const Sweep& sb,
                                    double tol) {
    return testing::sampleDistance(testing::closingSpeedBound(sa, a.boundingRadius, sb, b.boundingRadius), tol,
                                   [&](double t) { return referenceDistance(place(a, sa.at(t)), place(b, sb.at(t))); });
}

// What the exact method answered on a set of pairs, against dense sampling of the reference distance.
struct Tally {
    int tested = 0, hits = 0, separated = 0, failed = 0, overlaps = 0, nearMisses = 0;
    double leastHitGap = INFINITY;
};

// At a hit the shapes are apart (no overlap) by less than the tolerance, the hit comes no later than the first
// sampled pose within half the tolerance (never past the contact), and some pose comes within the tolerance plus
// the sampling's error bound (no phantom); without a hit no sampled pose comes within half the tolerance (never
// tunnels). Pairs that start within the tolerance are left out.
Tally checkAgainstSampling(const std::vector<testing::KernelPair>& pairs) {
    const double tol = kToiTolerance;
    Tally n;
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        const testing::KernelPair& p = pairs[i];
        if (referenceDistance(place(p.a, p.sa.at(0.0)), place(p.b, p.sb.at(0.0))) < tol) continue;
        ++n.tested;
        const kernel::Toi r = kernel::timeOfImpact(p.a, testing::kernelMotion(p.sa), p.b,
                                                   testing::kernelMotion(p.sb), tol, 100);
        const testing::DenseSampling truth = sampleMotion(p.a, p.sa, p.b, p.sb, tol);
        n.overlaps += truth.firstOverlap < INFINITY;
        n.nearMisses += truth.minimum >= tol && truth.minimum <= 3.0 * tol;
        EXPECT_NE(r.state, kernel::kTouching) << "pair " << i << " starts apart";
        if (r.state == kernel::kHit) {
            ++n.hits;
            const double gap = referenceDistance(place(p.a, p.sa.at(r.t)), place(p.b, p.sb.at(r.t)));
            n.leastHitGap = std::min(n.leastHitGap, gap);
            EXPECT_GT(gap, 0.0) << "overlapping at its time: pair " << i;
            EXPECT_LT(gap, tol + 1e-12) << "pair " << i;
            EXPECT_LE(r.t, truth.firstBelowHalf) << "past the contact: pair " << i;
            EXPECT_LE(truth.minimum, tol + 0.05 * tol) << "phantom hit: pair " << i << " at t = " << r.t;
        } else {
            n.failed += r.state == kernel::kFailed;
            n.separated += r.state == kernel::kSeparated;
            EXPECT_EQ(truth.firstOverlap, INFINITY) << "tunnelled: pair " << i << ", state " << r.state;
            EXPECT_EQ(truth.firstBelowHalf, INFINITY) << "pair " << i << ", state " << r.state;
        }
    }
    std::cout << n.tested << " pairs: " << n.hits << " hit (" << n.overlaps << " overlap when sampled), "
              << n.separated << " separated, " << n.failed << " failed; " << n.nearMisses
              << " near misses (closest 1 to 3 tolerances); least gap at a hit " << n.leastHitGap / tol
              << " tolerances\n";
    return n;
}

// A circle, a box, a capsule and a rounded box, each fired at 1 to 20 m per motion and spinning up to 6 rad, at a
// segment, a thin capsule, a rounded pentagon and a chain segment, still or spinning up to 17 rad
// (testing::roundedKindsPairs). Most of these pairs would tunnel without the exact method: the sampled motion
// overlaps.
TEST(TimeOfImpactKinds, FastBodiesNeverTunnelThroughSegmentCapsuleChainOrRounded) {
    const Tally n = checkAgainstSampling(testing::roundedKindsPairs(1600, 31));
    EXPECT_EQ(n.failed, 0);
    EXPECT_GT(n.tested, 1400);
    EXPECT_GT(n.overlaps, 500) << "the set's design: many pairs that would tunnel";
    EXPECT_GT(n.separated, 200) << "and many that pass by";
}

// Every kind against every kind, spinning up to 17 rad and moving up to 8 m, placed to graze at a random moment t*
// (testing::placeGrazing, spinningPairs' rule, on kernel shapes): b is put `gap` from a along their closest-point
// normal at t*, and in three pairs of four b's motion along that normal is set so that the gap's rate is zero
// there (a graze, or a hit just after). Gaps: overlaps of 1 mm and 10 um, then 0.2 to 20 tolerances; the fourth
// pair has a random gap up to 0.5 m. Near misses are where loose bounds for a radius would give phantom hits or
// run out of iterations.
std::vector<testing::KernelPair> grazingPairs(int count, unsigned seed) {
    testing::PairDraws draw(seed);
    std::vector<kernel::Shape> shapes = everyKind();
    shapes.push_back(kernelSegment({-1.0, 0.0}, {1.0, 0.0}));
    shapes.push_back(kernelCapsule({-1.0, 0.0}, {1.0, 0.0}, 0.005));
    shapes.push_back(kernelBox(1.0, 0.005, 0.01));
    std::vector<testing::KernelPair> pairs;
    while (static_cast<int>(pairs.size()) < count) {
        const int i = static_cast<int>(pairs.size());
        testing::KernelPair p;
        p.a = shapes[static_cast<std::size_t>(draw.unit() * shapes.size())];
        p.b = shapes[static_cast<std::size_t>(draw.unit() * shapes.size())];
        auto distance = [&](const Transform& xa, const Transform& xb) {
            const kernel::Distance d = kernel::shapeDistance(p.a, toXf(xa), p.b, toXf(xb));
            return DistanceOutput{d.distance, Vec2(d.normal.x, d.normal.y), Vec2(d.pointA.x, d.pointA.y),
                                  Vec2(d.pointB.x, d.pointB.y)};
        };
        if (!testing::placeGrazing(draw, i, p.a.boundingRadius, p.b.boundingRadius, p.sa, p.sb, distance)) continue;
        if (referenceDistance(place(p.a, p.sa.at(0.0)), place(p.b, p.sb.at(0.0))) < kToiTolerance) continue;
        pairs.push_back(p);
    }
    return pairs;
}

TEST(TimeOfImpactKinds, SpinningSegmentCapsuleChainAndRoundedGrazeWithoutPhantomHits) {
    const Tally n = checkAgainstSampling(grazingPairs(1200, 19));
    EXPECT_EQ(n.failed, 0);
    EXPECT_GT(n.nearMisses, 80) << "the set's design: many near misses";
    EXPECT_GT(n.overlaps, 300) << "and many contacts";
}

// A shape turns with its core's reach, the farthest vertex from the body origin (the radius turns onto itself), as
// a circle with its centre's; a sharp polygon's is its bounding radius, as before.
TEST(TimeOfImpactKinds, SegmentCapsuleAndRoundedTurnWithTheirCoresReach) {
    EXPECT_NEAR(kernel::turningReach(kernelCapsule({-0.3, 0.0}, {0.3, 0.4}, 0.2)), 0.5, 1e-15);
    EXPECT_NEAR(kernel::turningReach(kernelBox(0.3, 0.4, 0.1)), 0.5, 1e-15);
    EXPECT_NEAR(kernel::turningReach(kernelSegment({0.0, 0.0}, {0.0, -2.0})), 2.0, 1e-15);
    EXPECT_EQ(kernel::turningReach(kernelBox(0.3, 0.4)), kernelBox(0.3, 0.4).boundingRadius);
}

// A capsule spinning about its centre like a propeller, 1 m long, radius 5 cm, and a ball beside it: its round
// end sweeps a circle of radius 0.55 m, so a ball 0.1 m outside that (surface to surface) is never hit and one
// 0.1 m inside is, where the end's surface first reaches it (analytic angle).
TEST(TimeOfImpactKinds, SpinningCapsuleMatchesTheAnalyticAngle) {
    const kernel::Shape capsule = kernelCapsule({-0.5, 0.0}, {0.5, 0.0}, 0.05);
    const kernel::Shape ball = kernelCircle(0.05);
    const kernel::Motion spinning{{0.0, 0.0}, {0.0, 0.0}, 0.0, M_PI / 2};
    // Ball centre at distance 0.7 from the pivot: apart by 0.1 m at the closest.
    const kernel::Motion farBall{{0.0, 0.7}, {0.0, 0.7}, 0.0, 0.0};
    EXPECT_EQ(kernel::timeOfImpact(capsule, spinning, ball, farBall, kToiTolerance, 100).state, kernel::kSeparated);
    // Ball centre at (0.3, 0.4) (0.5 from the pivot, at 53.13 degrees): the capsule's centre line, at angle phi,
    // comes within 0.1 m of it when 0.5 sin(53.13 deg - phi) = 0.1.
    const kernel::Motion nearBall{{0.3, 0.4}, {0.3, 0.4}, 0.0, 0.0};
    const kernel::Toi r = kernel::timeOfImpact(capsule, spinning, ball, nearBall, kToiTolerance, 100);
    ASSERT_EQ(r.state, kernel::kHit);
    const double phi = std::atan2(0.4, 0.3) - std::asin(0.1 / 0.5), exact = phi / (M_PI / 2);
    const double closingRate = std::sqrt(0.25 - 0.01) * (M_PI / 2);  // m per unit t at the contact
    EXPECT_LE(r.t, exact + 1e-12);
    EXPECT_LE(exact - r.t, kToiTolerance / closingRate * 1.01) << "1% for the curvature of the gap in t";
}

}  // namespace
}  // namespace physim
