// Narrow phase against hand-worked answers for every shape pair: separated, touching, overlapping, deep,
// rotated, edge-edge (two points), vertex-edge (one point), and A/B symmetry.
// Tolerance: 1e-12 m for O(1) m inputs: each answer is a handful of floating-point operations from the exact
// value (rotations by pi/4 round sqrt(2)/2 once). Touching cases use exactly representable positions, so the
// contact is exact and the flag must be true.

#include "physim/core/Collide.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace physim {
namespace {

constexpr double kTol = 1e-12;

Transform at(double x, double y, double angle = 0.0) { return {{x, y}, Rotation::fromAngle(angle)}; }

void expectVecNear(const Vec2& actual, const Vec2& expected, double tol = kTol) {
    EXPECT_NEAR(actual.x(), expected.x(), tol) << "actual (" << actual.transpose() << ")";
    EXPECT_NEAR(actual.y(), expected.y(), tol) << "actual (" << actual.transpose() << ")";
}

// Swapping the shapes reverses the normal and keeps the depth and the point count.
void expectSymmetric(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
    const Colliding ab = computeColliding(a, xa, b, xb);
    const Colliding ba = computeColliding(b, xb, a, xa);
    ASSERT_EQ(ab.collision, ba.collision);
    EXPECT_NEAR(ab.penetration, ba.penetration, kTol);
    expectVecNear(ba.normal, -ab.normal);
    EXPECT_EQ(ab.collidingPoints.contactCount, ba.collidingPoints.contactCount);
}

// --- circle-circle ------------------------------------------------------------------------------------

TEST(CollideCircles, SeparatedTouchingOverlapping) {
    const Geometry c = makeCircle(1.0);
    EXPECT_FALSE(computeColliding(c, at(0, 0), c, at(3, 0)).collision);

    const Colliding touch = computeColliding(c, at(0, 0), c, at(2, 0));
    EXPECT_TRUE(touch.collision);
    EXPECT_EQ(touch.penetration, 0.0);
    expectVecNear(touch.collidingPoints.pointA, {1.0, 0.0});

    const Colliding hit = computeColliding(makeCircle(1.0), at(0, 0), makeCircle(0.5), at(0, 1.25));
    EXPECT_TRUE(hit.collision);
    EXPECT_NEAR(hit.penetration, 0.25, kTol);
    EXPECT_NEAR(hit.overlap, 0.25, kTol);
    expectVecNear(hit.normal, {0.0, 1.0});
    ASSERT_EQ(hit.collidingPoints.contactCount, 1);
    expectVecNear(hit.collidingPoints.pointA, {0.0, 0.875});  // midway between y = 1 and y = 0.75
    expectSymmetric(makeCircle(1.0), at(0, 0), makeCircle(0.5), at(0.3, 1.2));
}

TEST(CollideCircles, ConcentricCirclesHaveAUnitNormal) {
    const Colliding c = computeColliding(makeCircle(1.0), at(2, 2), makeCircle(0.5), at(2, 2));
    ASSERT_TRUE(c.collision);
    EXPECT_NEAR(c.normal.norm(), 1.0, kTol);
    EXPECT_NEAR(c.penetration, 1.5, kTol);  // any direction needs the sum of the radii
    EXPECT_TRUE(std::isfinite(c.collidingPoints.pointA.x()) && std::isfinite(c.collidingPoints.pointA.y()));
}

// --- polygon-circle -----------------------------------------------------------------------------------

TEST(CollidePolygonCircle, FaceRegion) {
    const Colliding c = computeColliding(makeBox(1.0, 1.0), at(0, 0), makeCircle(0.5), at(0.2, 1.25));
    ASSERT_TRUE(c.collision);
    EXPECT_NEAR(c.penetration, 0.25, kTol);
    expectVecNear(c.normal, {0.0, 1.0});
    expectVecNear(c.collidingPoints.pointA, {0.2, 0.875});
    EXPECT_FALSE(computeColliding(makeBox(1.0, 1.0), at(0, 0), makeCircle(0.5), at(0.2, 1.5 + 1e-9)).collision);
    EXPECT_TRUE(computeColliding(makeBox(1.0, 1.0), at(0, 0), makeCircle(0.5), at(0.2, 1.5)).collision);
}

TEST(CollidePolygonCircle, VertexRegion) {
    // Centre 0.5 m from the corner (1, 1) along (0.6, 0.8).
    const Colliding c = computeColliding(makeBox(1.0, 1.0), at(0, 0), makeCircle(1.0), at(1.3, 1.4));
    ASSERT_TRUE(c.collision);
    EXPECT_NEAR(c.penetration, 0.5, kTol);
    expectVecNear(c.normal, {0.6, 0.8});
    expectVecNear(c.collidingPoints.pointA, Vec2(1.0, 1.0) + 0.25 * Vec2(0.6, 0.8) - 0.5 * Vec2(0.6, 0.8));
    // Within reach of both faces' lines but not of the corner: no contact.
    EXPECT_FALSE(computeColliding(makeBox(1.0, 1.0), at(0, 0), makeCircle(0.45), at(1.3, 1.4)).collision);
}

TEST(CollidePolygonCircle, CentreInsideUsesTheNearestFace) {
    const Colliding c = computeColliding(makeBox(1.0, 1.0), at(0, 0), makeCircle(0.1), at(0.5, 0.2));
    ASSERT_TRUE(c.collision);
    expectVecNear(c.normal, {1.0, 0.0});
    EXPECT_NEAR(c.penetration, 0.6, kTol);  // 0.5 to the right face plus the radius
    // Centre exactly at the centre of a square: every face is nearest; any is fine but it must be a unit normal.
    const Colliding mid = computeColliding(makeBox(1.0, 1.0), at(0, 0), makeCircle(0.1), at(0, 0));
    EXPECT_NEAR(mid.normal.norm(), 1.0, kTol);
    EXPECT_NEAR(mid.penetration, 1.1, kTol);
}

TEST(CollidePolygonCircle, RotatedPolygonAndSwappedOrder) {
    // A 2 x 2 square turned 45 degrees has a corner at (0, sqrt 2); the circle overlaps it by 0.2 m.
    const double top = std::sqrt(2.0);
    const Colliding c = computeColliding(makeBox(1.0, 1.0), at(0, 0, M_PI / 4), makeCircle(0.5), at(0, top + 0.3));
    ASSERT_TRUE(c.collision);
    EXPECT_NEAR(c.penetration, 0.2, kTol);
    expectVecNear(c.normal, {0.0, 1.0});
    // Circle first: the normal runs from the circle to the polygon.
    const Colliding r = computeColliding(makeCircle(0.5), at(0, top + 0.3), makeBox(1.0, 1.0), at(0, 0, M_PI / 4));
    expectVecNear(r.normal, {0.0, -1.0});
    expectVecNear(r.collidingPoints.pointA, c.collidingPoints.pointA);
    expectSymmetric(makeBox(1.0, 0.5), at(0, 0, 0.3), makeCircle(0.4), at(0.9, 0.6));
}

// --- polygon-polygon ----------------------------------------------------------------------------------

TEST(CollidePolygons, SeparatedAndTouching) {
    const Geometry box = makeBox(1.0, 1.0);
    EXPECT_FALSE(computeColliding(box, at(0, 0), box, at(0, 2.5)).collision);
    EXPECT_FALSE(computeColliding(box, at(0, 0), box, at(2.1, 2.1)).collision);  // only the corners' gap
    const Colliding touch = computeColliding(box, at(0, 0), box, at(0.5, 2));
    ASSERT_TRUE(touch.collision);
    EXPECT_EQ(touch.penetration, 0.0);
    expectVecNear(touch.normal, {0.0, 1.0});
    EXPECT_EQ(touch.collidingPoints.contactCount, 2);
}

TEST(CollidePolygons, EdgeAgainstEdgeGivesTwoClippedPoints) {
    const Polygon a = makeBox(1.0, 1.0), b = makeBox(0.5, 0.5);
    const Manifold m = collide(a, at(0, 0), b, at(0.2, 1.4));
    ASSERT_EQ(m.pointCount, 2);
    expectVecNear(m.normal, {0.0, 1.0});
    // B's bottom edge spans x in [-0.3, 0.7] at y = 0.9, A's top face is y = 1: points midway, at y = 0.95.
    const double xs[2] = {m.points[0].point.x(), m.points[1].point.x()};
    EXPECT_NEAR(std::min(xs[0], xs[1]), -0.3, kTol);
    EXPECT_NEAR(std::max(xs[0], xs[1]), 0.7, kTol);
    for (int i = 0; i < 2; ++i) {
        EXPECT_NEAR(m.points[i].point.y(), 0.95, kTol);
        EXPECT_NEAR(m.points[i].separation, -0.1, kTol);
    }
    EXPECT_NE(m.points[0].id, m.points[1].id);

    // B wider than A: B's edge is clipped to A's top face, x in [-1, 1].
    const Manifold wide = collide(a, at(0, 0), makeBox(3.0, 0.5), at(0.5, 1.4));
    ASSERT_EQ(wide.pointCount, 2);
    EXPECT_NEAR(std::abs(wide.points[0].point.x() - wide.points[1].point.x()), 2.0, kTol);

    const Colliding c = computeColliding(a, at(0, 0), b, at(0.2, 1.4));
    EXPECT_NEAR(c.penetration, 0.1, kTol);
    EXPECT_NEAR(c.overlap, 0.1, kTol);
    expectSymmetric(a, at(0, 0), b, at(0.2, 1.4));
}

TEST(CollidePolygons, VertexAgainstEdgeGivesOnePoint) {
    // A unit square turned 45 degrees reaches sqrt(0.5) below its centre; its corner sinks 0.1 m into A.
    const double reach = std::sqrt(0.5);
    const Colliding c = computeColliding(makeBox(1.0, 1.0), at(0, 0), makeBox(0.5, 0.5), at(0.3, 1.0 + reach - 0.1, M_PI / 4));
    ASSERT_TRUE(c.collision);
    ASSERT_EQ(c.collidingPoints.contactCount, 1);
    EXPECT_NEAR(c.penetration, 0.1, kTol);
    expectVecNear(c.normal, {0.0, 1.0});
    expectVecNear(c.collidingPoints.pointA, {0.3, 0.95});
}

TEST(CollidePolygons, TiltedBoxOnGroundTouchesAtOneCorner) {
    // A 1 x 1 box tilted by 0.2 rad resting with its lowest corner 0.01 m inside the ground's top face y = 0.
    const double angle = 0.2;
    const Vec2 corner = Rotation::fromAngle(angle).apply({-0.5, -0.5});
    const Transform xb{{0.0, -corner.y() - 0.01}, Rotation::fromAngle(angle)};
    const Colliding c = computeColliding(makeBox(5.0, 0.5), at(0, -0.5), makeBox(0.5, 0.5), xb);
    ASSERT_EQ(c.collidingPoints.contactCount, 1);
    EXPECT_NEAR(c.penetration, 0.01, kTol);
    expectVecNear(c.normal, {0.0, 1.0});
    expectVecNear(c.collidingPoints.pointA, {corner.x(), -0.005});
}

TEST(CollidePolygons, DeepOverlapAndContainmentPushTheShortWay) {
    // B (1 x 1) wholly inside A (4 x 4), nearer A's right face: out through it, 2 - 0.7 = 1.3 m.
    const Polygon big = makeBox(2.0, 2.0), small = makeBox(0.5, 0.5);
    const Colliding c = computeColliding(big, at(0, 0), small, at(1.2, 0.3));
    ASSERT_TRUE(c.collision);
    EXPECT_NEAR(c.penetration, 1.3, kTol);
    expectVecNear(c.normal, {1.0, 0.0});
    // The same pair in the other order: A inside B, the normal still from A to B (A leaves to the left).
    const Colliding r = computeColliding(small, at(1.2, 0.3), big, at(0, 0));
    EXPECT_NEAR(r.penetration, 1.3, kTol);
    expectVecNear(r.normal, {-1.0, 0.0});
    expectSymmetric(big, at(0, 0), small, at(1.2, 0.3));
    // B's projection contains A's on x: the y axis still wins when it is the shorter way out.
    const Colliding y = computeColliding(makeBox(0.5, 0.5), at(0, 0), makeBox(3.0, 0.5), at(0.1, -0.8));
    EXPECT_NEAR(y.penetration, 0.2, kTol);
    expectVecNear(y.normal, {0.0, -1.0});
}

TEST(CollidePolygons, RotatingThePairRotatesTheAnswer) {
    const Polygon a = makeBox(1.0, 0.5), b = makePolygon({{0, -0.4}, {0.5, 0.3}, {-0.4, 0.2}});
    const Colliding flat = computeColliding(a, at(0, 0), b, at(0.3, 0.8));
    ASSERT_TRUE(flat.collision);
    for (const double angle : {0.3, M_PI / 2, 2.5, -1.0}) {
        const Rotation q = Rotation::fromAngle(angle);
        const Vec2 offset(5.0, -3.0);
        const Colliding turned = computeColliding(a, {offset, q}, b, {offset + q.apply({0.3, 0.8}), q});
        ASSERT_TRUE(turned.collision);
        EXPECT_NEAR(turned.penetration, flat.penetration, kTol);
        expectVecNear(turned.normal, q.apply(flat.normal));
        ASSERT_EQ(turned.collidingPoints.contactCount, flat.collidingPoints.contactCount);
        expectVecNear(turned.collidingPoints.pointA, offset + q.apply(flat.collidingPoints.pointA), 1e-11);
    }
}

TEST(CollidePolygons, FeatureIdsStayWhileTheSameFeaturesTouch) {
    const Polygon ground = makeBox(5.0, 0.5), box = makeBox(0.5, 0.5);
    const Manifold m0 = collide(ground, at(0, -0.5), box, at(0.0, 0.495));
    const Manifold m1 = collide(ground, at(0, -0.5), box, at(0.01, 0.4952, 1e-6));
    ASSERT_EQ(m0.pointCount, 2);
    ASSERT_EQ(m1.pointCount, 2);
    EXPECT_EQ(m0.points[0].id, m1.points[0].id);
    EXPECT_EQ(m0.points[1].id, m1.points[1].id);
    // Same-size boxes stacked: both faces tie; the first shape's face stays the reference.
    const Manifold s0 = collide(box, at(0, 0), box, at(0, 0.995));
    const Manifold s1 = collide(box, at(0, 0), box, at(0, 0.995, 1e-7));
    ASSERT_EQ(s1.pointCount, 2);
    EXPECT_EQ(s0.points[0].id, s1.points[0].id);
    EXPECT_EQ(s0.points[1].id, s1.points[1].id);
}

TEST(CollidePolygons, FarFromTheOriginGivesTheSameAnswer) {
    const Polygon a = makeBox(1.0, 1.0), b = makeBox(0.5, 0.5);
    const Colliding near = computeColliding(a, at(0, 0), b, at(0.2, 1.4, 0.1));
    const Colliding far = computeColliding(a, at(1e6, -1e6), b, at(1e6 + 0.2, -1e6 + 1.4, 0.1));
    // Positions near 1e6 m carry about 1e-10 m of rounding.
    EXPECT_NEAR(far.penetration, near.penetration, 1e-9);
    expectVecNear(far.normal, near.normal, 1e-9);
}

}  // namespace
}  // namespace physim
