// The paper's face of the new kinds: SegmentShape, CapsuleShape, ChainShape and rounded PolygonShapes (their
// queries, meshes and Objects), and compound Objects (several shapes, each with its own place and material).
// Checked against closed forms written here (areas, centres, the parallel axis theorem) and brute-force distances.

#include <physim/core/CapsuleShape.hpp>
#include <physim/core/ChainShape.hpp>
#include <physim/core/CircleShape.hpp>
#include <physim/core/PolygonShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/core/SegmentShape.hpp>
#include <physim/framework/DebugDraw.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace physim {
namespace {

const sf::Color kColor(40, 160, 90);
// Closed forms of a few operations on O(1) m: rounding only.
constexpr double kTol = 1e-12;
// Meshes are in float (SFML): 1e-6 m at these sizes.
constexpr double kFloatTol = 1e-6;

Vec2 toVec(const sf::Vector2f& p) { return {p.x, p.y}; }

// Distance from p to the segment a-b, by projection (not the engine's code).
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
    return (p - (a + t * d)).norm();
}

// Distance from p to a convex polygon's boundary (the nearest edge), for points outside it.
double distanceToPolygon(const Vec2& p, const std::vector<Vec2>& v) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < v.size(); ++i) best = std::min(best, distanceToSegment(p, v[i], v[(i + 1) % v.size()]));
    return best;
}

TEST(SegmentShapeFace, TypeSizePointsAndStaticObject) {
    const SegmentShape s({-1.0, 0.0}, {2.0, 1.0});
    EXPECT_EQ(s.getType(), ShapeType::SEGMENT);
    EXPECT_EQ(s.getSize(), Vec2(3.0, 1.0));
    EXPECT_EQ(s.point1(), Vec2(-1.0, 0.0));
    EXPECT_EQ(s.getMassProperties().area, 0.0);
    EXPECT_THROW(SegmentShape({1.0, 1.0}, {1.0, 1.0}), std::invalid_argument);
    EXPECT_THROW(SegmentShape({NAN, 0.0}, {1.0, 1.0}), std::invalid_argument);
    Simulation sim;
    Object& wall = sim.spawn<Object>(s, kColor);
    EXPECT_EQ(sim.world().type(wall.rb.bodyId()), BodyType::Static) << "no area, no mass: static";
}

// A segment's mesh is a band kLineWidth wide along it (a filled outline of two points would draw nothing).
TEST(SegmentShapeFace, MeshIsABandAlongTheLine) {
    const Vec2 a(-1.0, 0.0), b(2.0, 1.0);
    for (const Mesh& mesh :
         {Mesh::ShapeMesh(SegmentShape(a, b), kColor), Mesh::GeometryMesh(makeSegment(a, b), kColor)}) {
        ASSERT_EQ(mesh.band().getVertexCount(), 6u) << "two triangles";
        for (std::size_t i = 0; i < 6; ++i) {
            const Vec2 p = toVec(mesh.band()[i].position);
            EXPECT_NEAR(distanceToSegment(p, a, b), 0.5 * Mesh::kLineWidth, kFloatTol);
            EXPECT_EQ(mesh.band()[i].color, kColor);
        }
    }
}

TEST(CapsuleShapeFace, MassIsARectangleAndTwoHalfDiscs) {
    const double length = 1.2, r = 0.3;
    const CapsuleShape c(length, r);
    EXPECT_EQ(c.getType(), ShapeType::CAPSULE);
    EXPECT_NEAR((c.getSize() - Vec2(length + 2 * r, 2 * r)).norm(), 0.0, kTol);
    EXPECT_EQ(c.center1(), Vec2(-0.6, 0.0));
    EXPECT_EQ(c.radius(), r);
    const MassProperties m = c.getMassProperties();
    EXPECT_NEAR(m.area, 2 * r * length + M_PI * r * r, kTol);
    EXPECT_NEAR(m.centroid.norm(), 0.0, kTol);
    EXPECT_THROW(CapsuleShape(0.0, 0.3), std::invalid_argument);
    EXPECT_THROW(CapsuleShape({0, 0}, {1, 0}, -0.1), std::invalid_argument);
}

// The mesh's outline runs counter-clockwise around the capsule with round ends: every point at the radius from
// the segment between the centres.
TEST(CapsuleShapeFace, MeshOutlineHasRoundEnds) {
    const Vec2 c1(-0.5, 0.2), c2(0.7, -0.1);
    const double r = 0.25;
    const Mesh mesh = Mesh::ShapeMesh(CapsuleShape(c1, c2, r), kColor);
    const std::size_t n = mesh.shape().getPointCount();
    ASSERT_GE(n, 20u) << "arcs, not a box";
    double area2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 p = toVec(mesh.shape().getPoint(i)), q = toVec(mesh.shape().getPoint((i + 1) % n));
        EXPECT_NEAR(distanceToSegment(p, c1, c2), r, kFloatTol);
        area2 += cross(p, q);
    }
    EXPECT_GT(area2, 0.0) << "counter-clockwise";
    // The polygon's area approaches the capsule's from inside (chords cut the arcs): within 1%.
    EXPECT_NEAR(0.5 * area2 / (2 * r * (c2 - c1).norm() + M_PI * r * r), 1.0, 1e-2);
}

TEST(RoundedPolygonFace, RadiusSizeAndMeshCorners) {
    const std::vector<Vec2> core{{-0.5, -0.25}, {0.5, -0.25}, {0.5, 0.25}, {-0.5, 0.25}};
    const double r = 0.1;
    const PolygonShape p(core, r);
    EXPECT_EQ(p.getType(), ShapeType::POLYGON);
    EXPECT_EQ(p.radius(), r);
    EXPECT_EQ(PolygonShape(core).radius(), 0.0);
    EXPECT_NEAR((p.getSize() - Vec2(1.0 + 2 * r, 0.5 + 2 * r)).norm(), 0.0, kTol);
    // Area of a rectangle w x h grown by r: w h + 2 r (w + h) + pi r^2.
    EXPECT_NEAR(p.getMassProperties().area, 0.5 + 2 * r * 1.5 + M_PI * r * r, kTol);
    const Mesh mesh = Mesh::ShapeMesh(p, kColor);
    ASSERT_GT(mesh.shape().getPointCount(), 8u) << "arcs at the corners";
    for (std::size_t i = 0; i < mesh.shape().getPointCount(); ++i)
        EXPECT_NEAR(distanceToPolygon(toVec(mesh.shape().getPoint(i)), core), r, kFloatTol);
    EXPECT_THROW(PolygonShape(core, -0.1), std::invalid_argument);
    EXPECT_THROW(PolygonShape(core, NAN), std::invalid_argument);
}

TEST(ChainShapeFace, PiecesBoundsAndMesh) {
    const std::vector<Vec2> points{{-2.0, 1.0}, {-1.0, 0.2}, {0.0, 0.0}, {1.0, 0.2}, {2.0, 1.0}};
    const ChainShape open(points);
    EXPECT_EQ(open.getType(), ShapeType::CHAIN);
    EXPECT_EQ(open.pieces().size(), 4u);
    EXPECT_EQ(ChainShape(points, true).pieces().size(), 5u) << "a loop joins the last point to the first";
    EXPECT_EQ(open.getSize(), Vec2(4.0, 1.0));
    ChainShape placed = open;
    placed.setTransform({10.0, 0.0}, 0.0);
    EXPECT_EQ(placed.getBounds().lower, Vec2(8.0, 0.0));
    EXPECT_EQ(placed.getBounds().upper, Vec2(12.0, 1.0)) << "every piece, not the first alone";
    // A circle touching the fourth piece only: satCollision finds it through all the pieces.
    CircleShape ball(0.2);
    ball.setTransform({11.5, 0.6 + 0.15}, 0.0);
    EXPECT_TRUE(placed.satCollision(ball).collision);
    EXPECT_TRUE(ball.satCollision(placed).collision);
    ball.setTransform({11.5, 2.0}, 0.0);
    EXPECT_FALSE(placed.satCollision(ball).collision);
    // Its mesh: a band along every piece, kLineWidth wide, on the solid side (below this ground): its vertices on
    // the polyline or a band's width below it (further at mitred corners, never nearer).
    const Mesh mesh = Mesh::ShapeMesh(open, kColor);
    ASSERT_EQ(mesh.band().getVertexCount(), 6u * 4u);
    const Mesh centred = Mesh::LineMesh(points, false, Mesh::kLineWidth, kColor);
    ASSERT_EQ(centred.band().getVertexCount(), 6u * 4u);
    const auto nearest = [&](const Vec2& p) {
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k + 1 < points.size(); ++k)
            best = std::min(best, distanceToSegment(p, points[k], points[k + 1]));
        return best;
    };
    int onLine = 0;
    for (std::size_t i = 0; i < mesh.band().getVertexCount(); ++i) {
        const Vec2 p = toVec(mesh.band()[i].position);
        const double d = nearest(p);
        if (d < kFloatTol) ++onLine;
        else {
            EXPECT_GE(d, Mesh::kLineWidth - kFloatTol);
            EXPECT_LE(d, 2.0 * Mesh::kLineWidth);
            const double curveY = 0.8 * std::max(std::abs(p.x()) - 1.0, 0.0) + 0.2 * std::min(std::abs(p.x()), 1.0);
            EXPECT_LT(p.y(), curveY) << "below the ground line";
        }
        // LineMesh centres it: half the width either side.
        const double c = nearest(toVec(centred.band()[i].position));
        EXPECT_GE(c, 0.5 * Mesh::kLineWidth - kFloatTol);
        EXPECT_LE(c, Mesh::kLineWidth);
    }
    EXPECT_EQ(onLine, 12) << "half of each piece's six vertices on the line";
    EXPECT_THROW(ChainShape({{0.0, 0.0}}), std::invalid_argument);
    EXPECT_THROW(ChainShape({{0.0, 0.0}, {0.0, 0.0}}), std::invalid_argument);
}

// A ChainShape Object is static ground made with World::createChain: one shape per piece; a disc dropped into its
// valley lands on it and rolls to and fro, its centre one radius from the curve.
TEST(ChainShapeFace, ObjectIsStaticGroundADiscRestsOn) {
    Simulation sim;
    std::vector<Vec2> valley;
    for (int i = 0; i <= 40; ++i) {
        const double x = -2.0 + 0.1 * i;
        valley.push_back({x, 0.25 * x * x});
    }
    Object& ground = sim.spawn<Object>(ChainShape(valley), kColor);
    EXPECT_EQ(sim.world().type(ground.rb.bodyId()), BodyType::Static);
    EXPECT_EQ(ground.rb.shapeIds().size(), 40u);
    Object& disc = sim.spawn<Object>(CircleShape(0.2), kColor);
    disc.setPosition({0.3, 0.3});
    for (int i = 0; i < 40; ++i) sim.fixedStep();  // 1 s: landed
    for (int i = 0; i < 400; ++i) {
        sim.fixedStep();
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k + 1 < valley.size(); ++k)
            nearest = std::min(nearest, distanceToSegment(disc.getPosition(), valley[k], valley[k + 1]));
        // One radius from the curve, within 1 cm (the solver's slop, about 5 mm, and a bounce on landing).
        ASSERT_NEAR(nearest, 0.2, 1e-2) << "step " << i;
    }
}

// A box asleep on chain ground (a body whose shapes are all chain pieces): the debug drawing's resting contacts
// and the window's framing go through every shape of every body.
TEST(ChainShapeFace, RestingContactsAndViewBoundsSeeChainGround) {
    Simulation sim;
    sim.spawn<Object>(ChainShape({{-3.0, 0.0}, {-1.0, 0.0}, {1.0, 0.0}, {3.0, 0.0}}), kColor);
    Object& box = sim.spawn<Object>(RectangleShape({0.5, 0.5}), kColor);
    box.setPosition({0.2, 0.25});
    for (int i = 0; i < 400 && box.rb.isAwake(); ++i) sim.fixedStep();
    ASSERT_FALSE(box.rb.isAwake()) << "asleep on the chain";
    for (int i = 0; i < 3; ++i) sim.fixedStep();  // the step no longer computes its contacts
    const std::vector<Manifold> resting = restingContacts(sim.world());
    ASSERT_FALSE(resting.empty());
    for (const Manifold& m : resting) EXPECT_NEAR(std::abs(m.normal.y()), 1.0, kTol) << "flat ground";
    const std::optional<Aabb> framed = sim.viewBounds();
    ASSERT_TRUE(framed.has_value());
    EXPECT_EQ(framed->lower.x(), -3.0) << "the chain's ends";
    EXPECT_EQ(framed->upper.x(), 3.0);
}

// A hammer: a light handle and a heavy head, one body. Its mass, centre of mass and inertia follow from the
// parts (parallel axis theorem), the same before and after it joins the world.
TEST(CompoundObject, MassCentreAndInertiaFromAllShapes) {
    const double handleDensity = 1.0, headDensity = 8.0;
    const Vec2 handleSize(0.1, 1.0), headSize(0.4, 0.2);
    const Vec2 headAt(0.0, 0.6);
    Simulation sim;
    auto hammer = std::make_unique<Object>(RectangleShape(handleSize), kColor);
    hammer->rb.setDensity(handleDensity);
    Material steel;
    steel.density = headDensity;
    steel.staticFriction = 0.9;
    hammer->addShape(RectangleShape(headSize), steel, headAt);

    const double m1 = handleDensity * handleSize.x() * handleSize.y();
    const double m2 = headDensity * headSize.x() * headSize.y();
    const Vec2 centre = (m2 * headAt) / (m1 + m2);
    const auto boxInertia = [](double m, const Vec2& size) { return m * size.squaredNorm() / 12.0; };
    const double inertia = boxInertia(m1, handleSize) + m1 * centre.squaredNorm() + boxInertia(m2, headSize) +
                           m2 * (headAt - centre).squaredNorm();
    // Before it joins the world: the framework's sum; after: the world's (World::createShape).
    EXPECT_NEAR(hammer->rb.mass(), m1 + m2, kTol);
    EXPECT_NEAR((hammer->getCenterOfMass() - centre).norm(), 0.0, kTol);
    EXPECT_NEAR(hammer->rb.inertia(), inertia, kTol);
    Object& added = sim.addEntity(std::move(hammer));
    EXPECT_EQ(added.rb.shapeIds().size(), 2u);
    EXPECT_NEAR(added.rb.mass(), m1 + m2, kTol);
    EXPECT_NEAR((added.getCenterOfMass() - centre).norm(), 0.0, kTol);
    EXPECT_NEAR(added.rb.inertia(), inertia, kTol);
    EXPECT_EQ(sim.world().staticFriction(added.rb.shapeIds()[1]), 0.9) << "the head's own material";
    EXPECT_EQ(sim.world().density(added.rb.shapeIds()[1]), headDensity);
    // A part added after the object joined the world counts at once.
    Material light;
    light.density = 2.0;
    added.addShape(CircleShape(0.05), light, {0.0, -0.55});
    EXPECT_NEAR(added.rb.mass(), m1 + m2 + 2.0 * M_PI * 0.05 * 0.05, kTol);
}

// Each part's collision shape follows the body at its offset and angle; the paper's queries see every part.
TEST(CompoundObject, PartsFollowTheBodyAndCollide) {
    Simulation sim;
    Object& l = sim.spawn<Object>(RectangleShape({1.0, 0.2}), kColor);
    Object::Part& upright = l.addShape(CapsuleShape(0.6, 0.1), Material{}, {0.4, 0.4}, M_PI / 2);
    l.setPosition({1.0, 2.0});
    l.setRotation(M_PI / 2);
    // The capsule's origin at offset (0.4, 0.4) turned a quarter: (-0.4, 0.4) from the body origin.
    EXPECT_NEAR((upright.shape->getPosition() - Vec2(0.6, 2.4)).norm(), 0.0, kTol);
    EXPECT_NEAR(upright.shape->getRotation(), M_PI, kTol);
    Object& probe = sim.spawn<Object>(CircleShape(0.05), kColor);
    probe.rb.setMass(0.0);
    probe.setPosition({0.6, 2.4});  // inside the upright only
    EXPECT_TRUE(upright.shape->satCollision(*probe.shape).collision);
    EXPECT_FALSE(l.shape->satCollision(*probe.shape).collision);
    EXPECT_TRUE(l.rb.checkDiscreteCollision(l.getPosition(), probe.rb)) << "any of the body's shapes";
    EXPECT_THROW(l.addShape(nullptr, Material{}), std::invalid_argument);
    Material bad;
    bad.restitution = 2.0;
    EXPECT_THROW(l.addShape(CircleShape(0.1), bad), std::invalid_argument);
}

// A compound body falls and lands as one: the parts keep their places (rigid), the body comes to rest on the
// floor on its wide part.
TEST(CompoundObject, FallsAndRestsAsOneBody) {
    Simulation sim;
    Object& floor = sim.spawn<Object>(Vec2(8.0, 1.0));
    floor.rb.setMass(0.0);
    floor.setPosition({0.0, -0.5});
    Object& t = sim.spawn<Object>(RectangleShape({1.0, 0.2}), kColor);
    t.addShape(RectangleShape({0.2, 0.6}), Material{}, {0.0, 0.4});
    t.setPosition({0.0, 1.0});
    for (int i = 0; i < 200; ++i) sim.fixedStep();
    // Resting on its base: the base's centre 0.1 m above the floor (within 5 mm of solver slop).
    EXPECT_NEAR(t.getPosition().y(), 0.1, 5e-3);
    EXPECT_NEAR(t.getRotation(), 0.0, 1e-3);
    EXPECT_NEAR((t.parts()[0]->shape->getPosition() - t.getPosition() - Vec2(0.0, 0.4)).norm(), 0.0, 1e-3);
}

}  // namespace
}  // namespace physim
