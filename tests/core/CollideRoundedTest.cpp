// Hand-worked manifolds of the new kinds: where the points go, how deep, and that feature ids stay while the same
// features touch (warm starting keys points by id). Tolerance 1e-12 m: the values are sums and products of O(1)
// inputs.

#include "physim/core/Collide.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace physim {
namespace {

constexpr double kTol = 1e-12;

Transform at(double x, double y, double angle = 0.0) { return {{x, y}, Rotation::fromAngle(angle)}; }

std::vector<std::uint32_t> ids(const Manifold& m) {
    std::vector<std::uint32_t> out;
    for (int i = 0; i < m.pointCount; ++i) out.push_back(m.points[i].id);
    std::sort(out.begin(), out.end());
    return out;
}

// A capsule lying 0.01 m deep on flat ground: one point under each centre, midway between the surfaces.
TEST(CollideCapsule, LyingOnGroundTouchesUnderBothCentres) {
    const Capsule capsule = makeCapsule({-0.5, 0.0}, {0.5, 0.0}, 0.2);
    const std::vector<Geometry> grounds = {makeBox(5.0, 0.5), makeRoundedBox(4.9, 0.4, 0.1)};
    for (const Geometry& ground : grounds) {
        const Manifold m = collide(ground, at(0.0, -0.5), capsule, at(0.0, 0.19));
        ASSERT_EQ(m.pointCount, 2);
        EXPECT_NEAR((m.normal - Vec2(0.0, 1.0)).norm(), 0.0, kTol);
        const double xs[2] = {m.points[0].point.x(), m.points[1].point.x()};
        EXPECT_NEAR(std::min(xs[0], xs[1]), -0.5, kTol);
        EXPECT_NEAR(std::max(xs[0], xs[1]), 0.5, kTol);
        for (int i = 0; i < 2; ++i) {
            EXPECT_NEAR(m.points[i].point.y(), -0.005, kTol);
            EXPECT_NEAR(m.points[i].separation, -0.01, kTol);
        }
    }
    const Manifold onSegment = collide(makeSegment({-5.0, 0.0}, {5.0, 0.0}), at(0.0, 0.0), capsule, at(0.2, 0.19));
    ASSERT_EQ(onSegment.pointCount, 2);
    EXPECT_NEAR(onSegment.points[0].separation, -0.01, kTol);
}

// A circle against a capsule's round end: the normal runs along the line between the centres.
TEST(CollideCapsule, CircleAtTheEndPushesAlongTheCentres) {
    const Capsule capsule = makeCapsule({-0.5, 0.0}, {0.5, 0.0}, 0.2);
    // Centres 0.4 apart along (0.6, 0.8), radii 0.2 + 0.3: 0.1 deep.
    const Colliding c = computeColliding(capsule, at(0, 0), makeCircle(0.3), at(0.5 + 0.24, 0.32));
    ASSERT_TRUE(c.collision);
    EXPECT_NEAR((c.normal - Vec2(0.6, 0.8)).norm(), 0.0, kTol);
    EXPECT_NEAR(c.penetration, 0.1, kTol);
}

// Two crossing segments (zero area each) still collide: the short way out is the smaller of the four pushes.
TEST(CollideSegment, CrossingSegmentsPushTheShortWay) {
    const Segment a = makeSegment({-1.0, 0.0}, {1.0, 0.0});
    const Segment b = makeSegment({0.3, -0.1}, {0.3, 2.0});
    const Colliding c = computeColliding(a, at(0, 0), b, at(0, 0));
    ASSERT_TRUE(c.collision);
    EXPECT_NEAR(c.penetration, 0.1, kTol);  // move b up by 0.1 (its lower end is 0.1 below a)
    EXPECT_NEAR((c.normal - Vec2(0.0, 1.0)).norm(), 0.0, kTol);
    // Collinear and apart: no contact, though every face normal of either sees no gap.
    EXPECT_FALSE(computeColliding(a, at(0, 0), makeSegment({1.5, 0.0}, {3.0, 0.0}), at(0, 0)).collision);
    EXPECT_TRUE(computeColliding(a, at(0, 0), makeCapsule({1.5, 0.0}, {3.0, 0.0}, 0.6), at(0, 0)).collision);
}

// A rounded box resting on a rounded box, nudged (a hair of turn, a slide): the same two ids, whichever face the
// routine takes as the reference.
TEST(CollideRounded, FeatureIdsStayWhileTheSameFeaturesTouch) {
    const Polygon ground = makeRoundedBox(5.0, 0.4, 0.1), box = makeRoundedBox(0.4, 0.4, 0.1);
    const Manifold m0 = collide(ground, at(0, -0.5), box, at(0.0, 0.495));
    ASSERT_EQ(m0.pointCount, 2);
    for (const Transform& nudged : {at(0.01, 0.4952, 1e-6), at(-0.02, 0.495, -1e-7), at(0.0, 0.4951, 1e-9)}) {
        const Manifold m1 = collide(ground, at(0, -0.5), box, nudged);
        ASSERT_EQ(m1.pointCount, 2);
        EXPECT_EQ(ids(m0), ids(m1));
    }
    // Same-size rounded boxes stacked: both faces tie.
    const Manifold s0 = collide(box, at(0, 0), box, at(0, 0.995));
    for (double angle : {1e-7, -1e-7, 1e-9}) {
        const Manifold s1 = collide(box, at(0, 0), box, at(0, 0.995, angle));
        ASSERT_EQ(s1.pointCount, 2);
        EXPECT_EQ(ids(s0), ids(s1));
    }
}

// A rounded box's corner against flat ground: one point, at the corner arc's lowest point.
TEST(CollideRounded, TiltedRoundedBoxTouchesWithItsCornerArc) {
    const Polygon box = makeRoundedBox(0.5, 0.3, 0.1);
    const double angle = 0.4;
    const Rotation q = Rotation::fromAngle(angle);
    // The core's lowest corner sits at height 0.09 above the ground's top: its arc reaches 0.01 below.
    double lowest = 0.0;
    Vec2 corner;
    for (int i = 0; i < box.count; ++i)
        if (q.apply(box.vertices[i]).y() < lowest) {
            lowest = q.apply(box.vertices[i]).y();
            corner = q.apply(box.vertices[i]);
        }
    const Transform xf{{0.0, 0.09 - lowest}, q};
    const Manifold m = collide(makeBox(5.0, 0.5), at(0.0, -0.5), box, xf);
    ASSERT_EQ(m.pointCount, 1);
    EXPECT_NEAR(m.points[0].separation, -0.01, kTol);
    EXPECT_NEAR(m.points[0].point.x(), corner.x(), kTol);
    EXPECT_NEAR(m.points[0].point.y(), -0.005, kTol);
}

}  // namespace
}  // namespace physim
