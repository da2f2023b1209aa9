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

}  // namespace
}  // namespace physim
