// The framework's face of surface materials: RigidBody's rolling resistance and tangent speed, kept before the body
// joins a simulation and passed to the world's shapes after.

#include "physim/core/CircleShape.hpp"
#include "physim/core/RectangleShape.hpp"
#include "physim/core/World.hpp"
#include "physim/framework/Object.hpp"
#include "physim/framework/Simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace physim {
namespace {

TEST(RigidBodyRollingResistanceTangentSpeed, KeptBeforeAttachAndSetOnTheWorldAfter) {
    Simulation sim;
    auto& belt = sim.spawn<Object>(RectangleShape({10.0, 0.4}), sf::Color::White);
    belt.rb.setMass(0.0);
    belt.setPosition({0.0, -0.2});
    belt.rb.setTangentSpeed(1.5);  // attached: on the world's shape
    EXPECT_EQ(sim.world().tangentSpeed(belt.rb.bodyId()), 1.5);
    auto ball = std::make_unique<Object>(CircleShape(0.3), sf::Color::Red);
    ball->rb.setRollingResistance(0.2);  // before attach: kept in the body's definition
    EXPECT_EQ(ball->rb.rollingResistance(), 0.2);
    EXPECT_THROW(ball->rb.setRollingResistance(-1.0), std::invalid_argument);
    EXPECT_THROW(ball->rb.setTangentSpeed(NAN), std::invalid_argument);
    Object& b = sim.addEntity(std::move(ball));
    EXPECT_EQ(sim.world().rollingResistance(b.rb.bodyId()), 0.2);
    EXPECT_EQ(b.rb.rollingResistance(), 0.2);
    EXPECT_EQ(belt.rb.tangentSpeed(), 1.5);
    b.rb.setTangentSpeed(-0.5);
    EXPECT_EQ(sim.world().tangentSpeed(sim.world().shapes(b.rb.bodyId())[0]), -0.5);
}

TEST(RigidBodyRollingResistanceTangentSpeed, PartsKeepTheirOwnMaterial) {
    Simulation sim;
    auto body = std::make_unique<Object>(RectangleShape({1.0, 0.2}), sf::Color::White);
    Material tread;
    tread.rollingResistance = 0.3;
    tread.tangentSpeed = 0.7;
    body->addShape(CircleShape(0.2), tread, {0.6, 0.0});
    tread.tangentSpeed = NAN;
    EXPECT_THROW(body->addShape(CircleShape(0.2), tread, {-0.6, 0.0}), std::invalid_argument);
    Object& o = sim.addEntity(std::move(body));
    const std::vector<ShapeId> ids = o.rb.shapeIds();
    ASSERT_EQ(ids.size(), 2u);
    EXPECT_EQ(sim.world().rollingResistance(ids[0]), 0.0);  // the first shape: the body's own
    EXPECT_EQ(sim.world().rollingResistance(ids[1]), 0.3);
    EXPECT_EQ(sim.world().tangentSpeed(ids[1]), 0.7);
}

}  // namespace
}  // namespace physim
