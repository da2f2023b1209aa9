// Joints from the paper's face: RigidBody::join and Object::join make a world joint between two entities' bodies,
// the first entity's body as A.

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace physim {
namespace {

const sf::Color kColor(40, 160, 90);

TEST(JointFace, ObjectsJoinedByAPinSwingAsAPendulum) {
    Simulation sim;
    Object& pivot = sim.spawn<Object>(CircleShape(0.05), kColor);
    pivot.rb.setMass(0.0);  // static
    Object& bob = sim.spawn<Object>(CircleShape(0.1), kColor);
    bob.setPosition({1.0, 0.0});
    RevoluteJointDef pin;
    pin.anchor = Vec2::Zero();
    const JointId j = pivot.join(bob, pin);
    World& world = sim.world();
    ASSERT_TRUE(world.contains(j));
    EXPECT_EQ(world.jointType(j), JointType::Revolute);
    const auto [a, b] = world.jointAnchors(j);
    EXPECT_EQ(a, Vec2::Zero());
    EXPECT_EQ(b, Vec2::Zero());
    // Released from the horizontal, the bob stays on its circle of radius 1 m about the pin (1e-3 m: the pin is
    // soft in the solve pass, exact only in the relax pass).
    for (int i = 0; i < 120; ++i) world.step(1.0 / 60.0);
    EXPECT_NEAR(world.position(bob.rb.bodyId()).norm(), 1.0, 1e-3);
    EXPECT_LT(world.position(bob.rb.bodyId()).y(), -0.5) << "it swung down";
}

TEST(JointFace, JoiningNeedsBothBodiesInTheSimulation) {
    Simulation sim;
    Object& added = sim.spawn<Object>(CircleShape(0.1), kColor);
    Object loose(CircleShape(0.1), kColor);
    DistanceJointDef rod;
    EXPECT_THROW(added.join(loose, rod), std::logic_error);
    EXPECT_THROW(loose.rb.join(added.rb, rod), std::logic_error);
    EXPECT_EQ(sim.world().jointCount(), 0u);
}

// A pulley from the paper's face: two bobs of 2 kg and 1 kg over two fixed points accelerate at
// (m1 - m2) g / (m1 + m2) = g / 3, the Atwood machine's closed form.
TEST(JointFace, ObjectsJoinedByAPulleyAccelerateAsAnAtwoodMachine) {
    Simulation sim;
    Object& heavy = sim.spawn<Object>(CircleShape(0.1), kColor);
    Object& light = sim.spawn<Object>(CircleShape(0.1), kColor);
    heavy.setPosition({-1.0, 0.0});
    light.setPosition({1.0, 0.0});
    heavy.rb.setMass(2.0);
    light.rb.setMass(1.0);
    PulleyJointDef rope;
    rope.groundAnchorA = {-1.0, 2.0};
    rope.groundAnchorB = {1.0, 2.0};
    const JointId j = heavy.join(light, rope);
    World& world = sim.world();
    ASSERT_TRUE(world.contains(j));
    EXPECT_EQ(world.jointType(j), JointType::Pulley);
    const double g = -world.settings().gravity.y();
    for (int i = 0; i < 20; ++i) world.step(1.0 / 40.0);
    // 0.5%: the bar for the pulley (the rope is rigid in the relax pass; what is left is the soft solve's).
    EXPECT_NEAR(-world.velocity(heavy.rb.bodyId()).y() / 0.5, g / 3.0, 0.005 * g / 3.0);
}

// Prismatic, wheel and motor joints from the paper's face: each is made between the two bodies, in that order.
TEST(JointFace, ObjectsJoinBySliderWheelAndMotorJoints) {
    Simulation sim;
    Object& base = sim.spawn<Object>(CircleShape(0.1), kColor);
    base.rb.setMass(0.0);  // static
    Object& slider = sim.spawn<Object>(CircleShape(0.1), kColor);
    Object& wheel = sim.spawn<Object>(CircleShape(0.1), kColor);
    Object& follower = sim.spawn<Object>(CircleShape(0.1), kColor);
    World& world = sim.world();
    const JointId p = base.join(slider, PrismaticJointDef{});
    const JointId w = slider.join(wheel, WheelJointDef{});
    const JointId m = base.join(follower, MotorJointDef{});
    EXPECT_EQ(world.jointType(p), JointType::Prismatic);
    EXPECT_EQ(world.jointType(w), JointType::Wheel);
    EXPECT_EQ(world.jointType(m), JointType::Motor);
    EXPECT_EQ(world.joints().size(), 3u);
}

}  // namespace
}  // namespace physim
