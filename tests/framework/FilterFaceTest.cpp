// Collision filters and the pre-solve hook from the paper's face: a CollisionShape's filter goes to its Object's
// body shape (and a part's to its shape), RigidBody::setFilter sets every shape before and after the object joins a
// simulation, and a Simulation's world takes a pre-solve hook (a one-way platform).
// Tolerances: a resting box sits within the linear slop (5 mm) of the face under it; 0.02 m (4 slops) where it
// comes to rest after a fall.

#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>

#include <gtest/gtest.h>

#include <memory>

namespace physim {
namespace {

const sf::Color kColor(40, 160, 90);

Filter filterOf(std::uint64_t category, std::uint64_t mask, std::int32_t group = 0) {
    Filter f;
    f.categoryBits = category;
    f.maskBits = mask;
    f.groupIndex = group;
    return f;
}

Object& addGround(Simulation& sim) {
    Object& ground = sim.spawn<Object>(RectangleShape({20.0, 1.0}), kColor);
    ground.setPosition({0.0, -0.5});  // top face at y = 0
    ground.rb.setMass(0.0);
    return ground;
}

TEST(FilterFace, ShapeFiltersReachTheWorld) {
    Simulation sim;
    RectangleShape main({1.0, 1.0});
    main.setFilter(filterOf(2, 5, -1));
    RectangleShape part({0.5, 0.5});
    part.setFilter(filterOf(8, 3));
    auto made = std::make_unique<Object>(main, kColor);
    made->addShape(part, Material{}, {1.0, 0.0});
    Object& object = static_cast<Object&>(sim.addEntity(std::move(made)));
    const std::vector<ShapeId> shapes = object.rb.shapeIds();
    ASSERT_EQ(shapes.size(), 2u);
    EXPECT_EQ(sim.world().filter(shapes[0]), filterOf(2, 5, -1));
    EXPECT_EQ(sim.world().filter(shapes[1]), filterOf(8, 3));
    EXPECT_EQ(object.rb.filter(), filterOf(2, 5, -1));
    // RigidBody::setFilter, attached: every shape, at once in the world.
    object.rb.setFilter(filterOf(4, 4));
    EXPECT_EQ(sim.world().filter(shapes[0]), filterOf(4, 4));
    EXPECT_EQ(sim.world().filter(shapes[1]), filterOf(4, 4));
}

TEST(FilterFace, BodyFilterSetBeforeJoiningMakesABoxFallThroughTheGround) {
    Simulation sim;
    Object& ground = addGround(sim);
    ground.rb.setFilter(filterOf(1, ~std::uint64_t{0}));
    auto ghost = std::make_unique<Object>(Vec2(1.0, 1.0));
    ghost->setPosition({-2.0, 0.5});
    ghost->rb.setFilter(filterOf(2, ~std::uint64_t{1}));  // not the ground's category
    EXPECT_EQ(ghost->rb.filter(), filterOf(2, ~std::uint64_t{1}));
    Object& fallen = static_cast<Object&>(sim.addEntity(std::move(ghost)));
    Object& solid = sim.spawn<Object>(Vec2(1.0, 1.0));
    solid.setPosition({2.0, 0.5});
    for (int i = 0; i < 60; ++i) sim.world().step(1.0 / 60.0);
    EXPECT_LT(fallen.getPosition().y(), -3.0);  // 1 s of free fall: 4.9 m
    EXPECT_NEAR(solid.getPosition().y(), 0.5, 0.02);
}

TEST(FilterFace, SimulationWorldTakesAPreSolveHookForAOneWayPlatform) {
    Simulation sim;
    addGround(sim);
    Object& platform = sim.spawn<Object>(RectangleShape({4.0, 0.2}), kColor);
    platform.setPosition({0.0, 2.0});  // top face at y = 2.1
    platform.rb.setMass(0.0);
    Object& box = sim.spawn<Object>(Vec2(0.5, 0.5));
    box.setPosition({0.0, 0.25});
    box.rb.setVelocity({0.0, 7.0});  // its bottom rises to 49 / 19.62 = 2.5 m, clear of the top
    const ShapeId top = platform.rb.shapeIds()[0];
    // The platform's contacts act only on what lies above it: the normal from it to the other shape points up.
    sim.world().setPreSolve([top](const Manifold& m) {
        if (m.shapeA == top) return m.normal.y() > 0.7;
        if (m.shapeB == top) return -m.normal.y() > 0.7;
        return true;
    });
    for (int i = 0; i < 180; ++i) sim.world().step(1.0 / 60.0);
    EXPECT_NEAR(box.getPosition().y() - 0.25, 2.1, sim.world().settings().linearSlop);
}

}  // namespace
}  // namespace physim
