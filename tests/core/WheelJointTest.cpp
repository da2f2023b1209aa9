// Wheel joints against analytic answers: a wheel hanging on its suspension sags by m g / k, its motor spins it up at
// T / I and jointMotorTorque reads T, it turns freely with the motor off, and its anchor stays on the axis; bad input.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace physim {
namespace {

constexpr double kG = 9.81;
constexpr double kDt = 1.0 / 60.0;

struct HangingWheel {
    World world;
    BodyId chassis, wheel;
    JointId joint;
};

// A 0.3 m wheel (1 kg/m^2) under a static chassis point, on a vertical suspension.
void build(HangingWheel& s, const WheelJointDef& extra, const Vec2& gravity = {0.0, -kG}) {
    s.world.setSettings(test::awakeSettings(gravity));
    s.chassis = test::addStaticPivot(s.world, {0.0, 1.0});
    BodyDef d;
    d.shape = makeCircle(0.3);
    d.collides = false;
    s.wheel = s.world.createBody(d);
    WheelJointDef def = extra;
    def.bodyA = s.chassis;
    def.bodyB = s.wheel;
    def.anchor = Vec2::Zero();
    def.axis = {0.0, 1.0};
    s.joint = s.world.createWheelJoint(def);
}

// The suspension is a spring of k = m (2 pi hertz)^2 for the wheel's mass against the static chassis: at rest it
// has sagged by m g / k = g / (2 pi hertz)^2, and it carries the weight.
TEST(WheelJoint, WheelOnItsSuspensionSagsByMgOverK) {
    HangingWheel s;
    WheelJointDef def;
    def.hertz = 4.0;
    def.dampingRatio = 1.0;
    build(s, def);
    for (int i = 0; i < 300; ++i) s.world.step(kDt);
    const double m = s.world.mass(s.wheel), k = m * std::pow(2.0 * M_PI * def.hertz, 2);
    // The implicit spring's rest is the spring law's exactly; 5 s of critical damping at 4 Hz leave e^-125.
    EXPECT_NEAR(s.world.jointTranslation(s.joint), -m * kG / k, 1e-6 * m * kG / k);
    EXPECT_NEAR(s.world.jointSpeed(s.joint), 0.0, 1e-9);
    EXPECT_NEAR(s.world.jointReactionForce(s.joint).y(), m * kG, 1e-6 * m * kG);
    EXPECT_NEAR(s.world.position(s.wheel).x(), 0.0, 1e-9) << "the anchor stays on the axis";
    EXPECT_EQ(s.world.jointType(s.joint), JointType::Wheel);

    s.world.setWheelSpring(s.joint, true, 2.0, 1.0);  // half the frequency: four times the sag
    for (int i = 0; i < 600; ++i) s.world.step(kDt);
    EXPECT_NEAR(s.world.jointTranslation(s.joint), -4.0 * m * kG / k, 1e-5 * m * kG / k);
}

// The motor at its torque cap T spins the wheel up at T / I (I the wheel's, the chassis static) and
// jointMotorTorque reads T; at the motor's speed it holds it with no torque.
TEST(WheelJoint, MotorSpinsTheWheelUpAtTOverI) {
    HangingWheel s;
    WheelJointDef def;
    def.enableMotor = true;
    def.motorSpeed = -20.0;
    def.maxMotorTorque = 0.05;
    build(s, def, {0.0, 0.0});
    const double I = s.world.inertia(s.wheel), alpha = def.maxMotorTorque / I;  // 3.9 rad/s^2: 5.1 s to 20 rad/s
    for (int i = 0; i < 60; ++i) s.world.step(kDt);
    EXPECT_NEAR(s.world.angularVelocity(s.wheel), -alpha * 1.0, 1e-9 * alpha);
    EXPECT_NEAR(s.world.jointMotorTorque(s.joint), -def.maxMotorTorque, 1e-9);
    EXPECT_NEAR(s.world.jointReactionTorque(s.joint), -def.maxMotorTorque, 1e-9);
    for (int i = 0; i < 300; ++i) s.world.step(kDt);
    EXPECT_NEAR(s.world.angularVelocity(s.wheel), -20.0, 1e-9);
    EXPECT_NEAR(s.world.jointMotorTorque(s.joint), 0.0, 1e-9);

    // Motor off: the wheel turns freely, keeping its spin.
    s.world.setWheelMotor(s.joint, false, 0.0, 0.0);
    for (int i = 0; i < 60; ++i) s.world.step(kDt);
    EXPECT_NEAR(s.world.angularVelocity(s.wheel), -20.0, 1e-9);
    EXPECT_THROW(s.world.jointMotorForce(s.joint), std::invalid_argument) << "a wheel's motor is a torque";
}

// Limits on the suspension's travel: with the spring off, the wheel falls to its lower limit and rests there.
TEST(WheelJoint, LimitsStopTheSuspension) {
    HangingWheel s;
    WheelJointDef def;
    def.enableSpring = false;
    def.enableLimit = true;
    def.lowerTranslation = -0.2;
    def.upperTranslation = 0.1;
    build(s, def);
    for (int i = 0; i < 120; ++i) s.world.step(kDt);
    // The soft limit row gives under the weight by g / (2 pi 120 Hz)^2 = 1.7e-5 m.
    EXPECT_NEAR(s.world.jointTranslation(s.joint), -0.2, 3e-5);
    s.world.setWheelLimits(s.joint, false, 0.0, 0.0);
    for (int i = 0; i < 30; ++i) s.world.step(kDt);
    EXPECT_LT(s.world.jointTranslation(s.joint), -0.5);
}

TEST(WheelJoint, BadInputIsRefusedNamingTheValueAndLeavesTheWorldUnchanged) {
    World world;
    const BodyId chassis = test::addStaticPivot(world);
    BodyDef d;
    d.shape = makeCircle(0.3);
    const BodyId wheel = world.createBody(d);
    auto refused = [&](WheelJointDef def, const std::string& name) {
        if (def.bodyA.isNull()) def.bodyA = chassis;
        if (def.bodyB.isNull()) def.bodyB = wheel;
        try {
            world.createWheelJoint(def);
            ADD_FAILURE() << "accepted: " << name;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
        EXPECT_EQ(world.jointCount(), 0u) << name;
    };
    const double nan = std::nan("");
    WheelJointDef w;
    w.anchor = {0.0, nan};
    refused(w, "anchor");
    w = {};
    w.axis = {0.0, 0.0};
    refused(w, "axis");
    w = {};
    w.hertz = -1.0;
    refused(w, "hertz");
    w = {};
    w.dampingRatio = nan;
    refused(w, "dampingRatio");
    w = {};
    w.lowerTranslation = 0.1;
    w.upperTranslation = -0.1;
    refused(w, "lowerTranslation");
    w = {};
    w.maxMotorTorque = -2.0;
    refused(w, "maxMotorTorque");
    w = {};
    w.bodyA = wheel;
    refused(w, "two different bodies");

    WheelJointDef good;
    good.bodyA = chassis;
    good.bodyB = wheel;
    const JointId j = world.createWheelJoint(good);
    EXPECT_THROW(world.setWheelSpring(j, true, nan, 1.0), std::invalid_argument);
    EXPECT_THROW(world.setWheelLimits(j, true, 1.0, 0.0), std::invalid_argument);
    EXPECT_THROW(world.setPrismaticMotor(j, true, 1.0, 1.0), std::invalid_argument) << "not a prismatic joint";
}

}  // namespace
}  // namespace physim
