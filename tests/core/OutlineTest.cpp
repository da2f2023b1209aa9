// outline(): the boundary points the framework draws, for every kind. Tolerance 1e-12 m (a rotation and a
// translation of O(1) m values).

#include "physim/core/Geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace physim {
namespace {

constexpr double kTol = 1e-12;

// Twice the signed area of the closed path: positive when counter-clockwise.
double twiceSignedArea(const std::vector<Vec2>& points) {
    double sum = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) sum += cross(points[i], points[(i + 1) % points.size()]);
    return sum;
}

TEST(Outline, APolygonIsItsPlacedVerticesCounterClockwise) {
    const Polygon box = makeBox(1.0, 0.5, Vec2(0.2, 0.1), 0.3);
    const Transform xf{Vec2(3.0, -2.0), Rotation::fromAngle(0.7)};
    const std::vector<Vec2> points = outline(box, xf);
    ASSERT_EQ(points.size(), static_cast<std::size_t>(box.count));
    for (int i = 0; i < box.count; ++i)
        EXPECT_LT((points[static_cast<std::size_t>(i)] - xf.apply(box.vertices[i])).norm(), kTol);
    EXPECT_GT(twiceSignedArea(points), 0.0);
}

TEST(Outline, ACircleIsARingOfPointsOnItsPlacedBoundary) {
    const Circle c = makeCircle(0.5, Vec2(0.3, -0.1));
    const Transform xf{Vec2(-1.0, 4.0), Rotation::fromAngle(-1.2)};
    const std::vector<Vec2> points = outline(c, xf);
    ASSERT_GE(points.size(), 16u);
    const Vec2 center = xf.apply(c.center);
    for (const Vec2& p : points) EXPECT_NEAR((p - center).norm(), 0.5, kTol);
    EXPECT_GT(twiceSignedArea(points), 0.0);
}

// transformed() moves every point of a shape: its outline at the origin is the original's outline placed by the
// same transform, and it stays a valid shape of its kind (outward unit normals for a polygon, the same mass).
TEST(Outline, ATransformedShapeIsTheShapePlaced) {
    const Transform xf{{1.5, -0.7}, Rotation::fromAngle(0.9)};
    const Transform origin{};
    const std::vector<Geometry> kinds = {makeCircle(0.3, {0.2, 0.1}), makeRoundedBox(0.4, 0.2, 0.05),
                                         makeSegment({-1.0, 0.0}, {1.0, 0.5}),
                                         makeCapsule({-0.5, 0.0}, {0.5, 0.2}, 0.1),
                                         makeChain({{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.5}})[1]};
    for (const Geometry& g : kinds) {
        const Geometry moved = transformed(g, xf);
        EXPECT_EQ(moved.index(), g.index());
        EXPECT_NO_THROW(validate(moved));
        const std::vector<Vec2> expected = outline(g, xf), got = outline(moved, origin);
        ASSERT_EQ(got.size(), expected.size());
        for (std::size_t i = 0; i < got.size(); ++i) EXPECT_NEAR((got[i] - expected[i]).norm(), 0.0, kTol);
        EXPECT_NEAR(computeMassProperties(moved).area, computeMassProperties(g).area, kTol);
        EXPECT_NEAR(computeMassProperties(moved).secondMoment, computeMassProperties(g).secondMoment, kTol);
    }
}

}  // namespace
}  // namespace physim
