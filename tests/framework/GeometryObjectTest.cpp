// An Object of any shape kind, from the two pieces that take any Geometry: GeometryShape (the collision shape)
// and Mesh::GeometryMesh (what is drawn). Checked against the paper's wrappers: the same geometry makes the same
// body and the same motion, to the bit.

#include <physim/core/GeometryShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace physim {
namespace {

const sf::Color kColor(40, 160, 90);

TEST(GeometryObject, MeshIsTheGeometrysOutlineFilled) {
    const Geometry kinds[] = {makeCircle(0.5, {0.2, 0.0}), makePolygon({{0.0, 0.0}, {2.0, 0.0}, {0.0, 1.0}})};
    for (const Geometry& g : kinds) {
        const Mesh mesh = Mesh::GeometryMesh(g, kColor);
        const std::vector<Vec2> points = outline(g, Transform{});
        ASSERT_EQ(mesh.shape().getPointCount(), points.size());
        for (std::size_t i = 0; i < points.size(); ++i)
            EXPECT_EQ(mesh.shape().getPoint(i),
                      sf::Vector2f(static_cast<float>(points[i].x()), static_cast<float>(points[i].y())));
        EXPECT_EQ(mesh.shape().getFillColor(), kColor);
    }
    EXPECT_THROW(Mesh::GeometryMesh(Circle{Vec2::Zero(), 0.0}, kColor), std::invalid_argument);
}

// A tilted box dropped on a floor, made from GeometryShape or from the paper's RectangleShape.
struct Drop {
    double mass, inertia;
    Vec2 position;
    double angle;
};

Drop drop(bool anyKind) {
    Simulation sim;
    Object& floor = sim.spawn<Object>(Vec2(8.0, 1.0));
    floor.rb.setMass(0.0);
    floor.setPosition({0.0, -1.0});
    Object& box = anyKind ? sim.spawn<Object>(Mesh::GeometryMesh(makeBox(0.5, 0.25), kColor),
                                              GeometryShape(makeBox(0.5, 0.25)))
                          : sim.spawn<Object>(Mesh::RectangleMesh({1.0, 0.5}, kColor), RectangleShape({1.0, 0.5}));
    box.setPosition({0.1, 1.0});
    box.setRotation(0.3);
    for (int i = 0; i < 120; ++i) sim.fixedStep();
    EXPECT_EQ(box.shape->getPosition(), box.getPosition()) << "the shape follows the body";
    return {box.rb.mass(), box.rb.inertia(), box.getPosition(), box.getRotation()};
}

TEST(GeometryObject, MovesAsThePapersWrapperDoes) {
    const Drop any = drop(true), paper = drop(false);
    EXPECT_EQ(any.mass, paper.mass);
    EXPECT_EQ(any.inertia, paper.inertia);
    EXPECT_EQ(any.position, paper.position);
    EXPECT_EQ(any.angle, paper.angle);
    EXPECT_LT(any.position.y(), 0.0) << "it fell onto the floor";
}

}  // namespace
}  // namespace physim
