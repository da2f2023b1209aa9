// The paper's CollisionShape API (section 5.2): types, sizes, bounds, the AABB test and satCollision, for
// circles, rectangles and polygons, and for a GeometryShape (any kind). Tolerance 1e-12 m: closed forms evaluated with a few operations on O(1) m.

#include "physim/core/CircleShape.hpp"
#include "physim/core/GeometryShape.hpp"
#include "physim/core/PolygonShape.hpp"
#include "physim/core/RectangleShape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace physim {
namespace {

constexpr double kTol = 1e-12;

TEST(CollisionShapeApi, TypesAndSizes) {
    const CircleShape c(0.5);
    const RectangleShape r({2.0, 1.0});
    const PolygonShape p({{0, 0}, {0, 2}, {3, 0}});  // clockwise in, counter-clockwise kept
    EXPECT_EQ(c.getType(), ShapeType::CIRCLE);
    EXPECT_EQ(r.getType(), ShapeType::RECTANGLE);
    EXPECT_EQ(p.getType(), ShapeType::POLYGON);
    EXPECT_EQ(c.getSize().norm(), 0.5);  // the paper: the vector's length is the radius
    EXPECT_EQ(r.getSize(), Vec2(2.0, 1.0));
    EXPECT_EQ(p.getSize(), Vec2(3.0, 2.0));
    EXPECT_EQ(p.vertices().size(), 3u);
    EXPECT_GT(cross(p.vertices()[1] - p.vertices()[0], p.vertices()[2] - p.vertices()[1]), 0.0);
}

TEST(CollisionShapeApi, MassPropertiesPerUnitDensity) {
    EXPECT_NEAR(CircleShape(0.5).getMassProperties().area, M_PI * 0.25, kTol);
    const MassProperties box = RectangleShape({2.0, 1.0}).getMassProperties();
    EXPECT_NEAR(box.area, 2.0, kTol);
    EXPECT_NEAR(box.secondMoment, 2.0 * 5.0 / 12.0, kTol);
    EXPECT_EQ(box.centroid, Vec2(0.0, 0.0));  // rotates about its centre
    const MassProperties tri = PolygonShape({{0, 0}, {3, 0}, {0, 3}}).getMassProperties();
    EXPECT_NEAR(tri.area, 4.5, kTol);
    EXPECT_NEAR((tri.centroid - Vec2(1.0, 1.0)).norm(), 0.0, kTol);  // kept as given: not at the origin
}

TEST(CollisionShapeApi, BadSizesThrowNamingTheValue) {
    EXPECT_THROW(CircleShape(0.0), std::invalid_argument);
    EXPECT_THROW(CircleShape(-1.0), std::invalid_argument);
    EXPECT_THROW(CircleShape(NAN), std::invalid_argument);
    try {
        RectangleShape({-2.0, 1.0});
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("rectangle width"), std::string::npos) << e.what();
    }
    EXPECT_THROW(PolygonShape({{0, 0}, {1, 1}}), std::invalid_argument);
    EXPECT_THROW(PolygonShape({{0, 0}, {2, 0}, {1, 0.2}, {2, 2}, {0, 2}}), std::invalid_argument);
    CircleShape c(1.0);
    EXPECT_THROW(c.setTransform({INFINITY, 0.0}, 0.0), std::invalid_argument);
}

TEST(CollisionShapeApi, RotatedRectangleTurnsAboutItsCentre) {
    RectangleShape r({2.0, 1.0});
    r.setTransform({3.0, 4.0}, M_PI / 2);
    const Aabb b = r.getBounds();
    // 2 x 1 turned a quarter turn about (3, 4): 1 wide and 2 tall, still centred on (3, 4).
    EXPECT_NEAR((b.lower - Vec2(2.5, 3.0)).norm(), 0.0, kTol);
    EXPECT_NEAR((b.upper - Vec2(3.5, 5.0)).norm(), 0.0, kTol);
}

TEST(CollisionShapeApi, AabbTestIsConservativeAndSatIsExact) {
    // A square turned 45 degrees near a circle: the boxes overlap, the shapes do not.
    RectangleShape r({2.0, 2.0});
    r.setTransform({0.0, 0.0}, M_PI / 4);
    CircleShape c(0.2);
    c.setTransform({1.0, 1.0}, 0.0);
    EXPECT_TRUE(r.aabbCollision(c));
    EXPECT_FALSE(r.satCollision(c).collision);
    c.setTransform({0.6, 0.6}, 0.0);
    const Colliding hit = r.satCollision(c);
    ASSERT_TRUE(hit.collision);
    EXPECT_NEAR(hit.normal.x(), std::sqrt(0.5), kTol);
    EXPECT_NEAR(hit.normal.y(), std::sqrt(0.5), kTol);
    // Face at distance 1 from the centre along the normal; the circle's near side at 0.6 sqrt 2 - 0.2.
    EXPECT_NEAR(hit.penetration, 1.0 - (0.6 * std::sqrt(2.0) - 0.2), kTol);
    c.setTransform({5.0, 0.0}, 0.0);
    EXPECT_FALSE(r.aabbCollision(c));
}

TEST(CollisionShapeApi, BoxRestingOnARotatedPolygonFace) {
    // A triangle with a face along y = 0 (its top) turned and placed; a box sits flat on that face.
    PolygonShape ground({{-2, -1}, {2, -1}, {0, 0}});
    RectangleShape box({0.5, 0.5});
    ground.setTransform({0.0, 0.0}, 0.0);
    box.setTransform({0.0, 0.2}, 0.0);  // bottom at y = -0.05: overlaps the triangle's tip region
    const Colliding c = ground.satCollision(box);
    ASSERT_TRUE(c.collision);
    EXPECT_GT(c.penetration, 0.0);
    EXPECT_NEAR(c.normal.norm(), 1.0, kTol);
    const Colliding r = box.satCollision(ground);
    EXPECT_NEAR(r.penetration, c.penetration, kTol);
    EXPECT_NEAR((r.normal + c.normal).norm(), 0.0, kTol);
}

// A GeometryShape holding a kind answers every query as that kind's paper-style wrapper does, to the bit (both
// reach the same Geometry); only its type and, for a circle, its size differ.
TEST(CollisionShapeApi, GeometryShapeAnswersAsThePapersWrappers) {
    const GeometryShape box(makeBox(1.0, 0.5));
    const GeometryShape disc(makeCircle(0.5));
    const RectangleShape rect({2.0, 1.0});
    const CircleShape circle(0.5);
    EXPECT_EQ(box.getType(), ShapeType::GEOMETRY);
    EXPECT_EQ(box.getSize(), rect.getSize());
    EXPECT_EQ(disc.getSize(), Vec2(1.0, 1.0)) << "the bounding box's size, as for a polygon";
    EXPECT_EQ(box.getMassProperties().secondMoment, rect.getMassProperties().secondMoment);
    EXPECT_EQ(disc.getMassProperties().secondMoment, circle.getMassProperties().secondMoment);

    GeometryShape movedBox = box;
    RectangleShape movedRect = rect;
    GeometryShape movedDisc = disc;
    CircleShape movedCircle = circle;
    movedBox.setTransform({0.3, 0.1}, 0.4);
    movedRect.setTransform({0.3, 0.1}, 0.4);
    movedDisc.setTransform({1.2, 0.6}, 0.0);
    movedCircle.setTransform({1.2, 0.6}, 0.0);
    const Colliding any = movedBox.satCollision(movedDisc);
    const Colliding paper = movedRect.satCollision(movedCircle);
    ASSERT_TRUE(paper.collision);
    EXPECT_EQ(any.collision, paper.collision);
    EXPECT_EQ(any.penetration, paper.penetration);
    EXPECT_EQ(any.normal, paper.normal);
    EXPECT_EQ(any.collidingPoints.pointA, paper.collidingPoints.pointA);
    EXPECT_EQ(movedBox.getBounds().lower, movedRect.getBounds().lower);
    EXPECT_EQ(movedBox.getBounds().upper, movedRect.getBounds().upper);

    const auto copy = movedBox.clone();
    EXPECT_EQ(copy->getType(), ShapeType::GEOMETRY);
    EXPECT_EQ(copy->getPosition(), Vec2(0.3, 0.1));
    EXPECT_EQ(copy->geometry().index(), box.geometry().index());
}

TEST(CollisionShapeApi, GeometryShapeRejectsWhatValidateRejects) {
    EXPECT_THROW(GeometryShape(Circle{Vec2::Zero(), -1.0}), std::invalid_argument);
    Polygon twoPoints = makeBox(1.0, 1.0);
    twoPoints.count = 2;
    EXPECT_THROW(GeometryShape{twoPoints}, std::invalid_argument);
}

}  // namespace
}  // namespace physim
