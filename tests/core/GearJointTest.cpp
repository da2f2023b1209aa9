// Gear joints: a gear train keeps its ratio over many turns, a rack and pinion its rolling (x = R theta), a gear
// between a carrier's angle and a planet's relative angle its sum; a geared joint's destruction takes the gear with
// it; bad input refused with the world unchanged.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;

BodyId addDisc(World& world, const Vec2& at, double radius) {
    BodyDef d;
    d.shape = makeCircle(radius);
    d.position = at;
    d.collides = false;
    return world.createBody(d);
}

JointId pin(World& world, BodyId a, BodyId b, const Vec2& at, double motorSpeed = 0.0, double maxTorque = 0.0) {
    RevoluteJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.anchor = at;
    def.enableMotor = maxTorque > 0.0;
    def.motorSpeed = motorSpeed;
    def.maxMotorTorque = maxTorque;
    return world.createRevoluteJoint(def);
}

// Two meshed gears of radii 0.5 and 1 m on pins, the small one driven: theta1 + 2 theta2 stays 0 (ratio r2 / r1 = 2).
TEST(GearJoint, GearTrainKeepsItsRatioOverManyTurns) {
    World world;
    world.setSettings(test::awakeSettings());
    const BodyId ground = test::addStaticPivot(world);
    const BodyId small = addDisc(world, {0.0, 0.0}, 0.5), large = addDisc(world, {1.5, 0.0}, 1.0);
    const JointId j1 = pin(world, ground, small, {0.0, 0.0}, 5.0, 10.0), j2 = pin(world, ground, large, {1.5, 0.0});
    GearJointDef def;
    def.joint1 = j1;
    def.joint2 = j2;
    def.ratio = 2.0;
    const JointId gear = world.createGearJoint(def);
    EXPECT_EQ(world.jointType(gear), JointType::Gear);
    double worstUnderLoad = 0.0;
    for (int i = 0; i < 60; ++i) {  // the motor spins the train up within 0.3 s
        world.step(kDt);
        worstUnderLoad = std::max(worstUnderLoad, std::abs(world.jointAngle(j1) + 2.0 * world.jointAngle(j2)));
    }
    // While the motor's torque (10 N m) passes through the gear, the soft row gives by its load over its stiffness,
    // about tau / (I_eff (2 pi 120 Hz)^2) ~ 1e-4 rad; it comes back once the load goes.
    EXPECT_LT(worstUnderLoad, 1e-3);
    for (int i = 0; i < 1200; ++i) world.step(kDt);  // 20 s more at 5 rad/s: 100 rad, 16 turns
    const double theta1 = world.jointAngle(j1), theta2 = world.jointAngle(j2);
    EXPECT_GT(theta1, 100.0);
    // The bar: the ratio to 1e-6 after many turns, in angle and in speed.
    EXPECT_LT(std::abs(theta1 + 2.0 * theta2), 1e-6 * std::abs(theta1));
    const double w1 = world.angularVelocity(small), w2 = world.angularVelocity(large);
    EXPECT_NEAR(w2 / w1, -0.5, 1e-6 * 0.5);
}

// A free gear train (no motor) turning as the gear requires keeps its kinetic energy: the gear does no work.
TEST(GearJoint, FreeGearTrainKeepsItsEnergy) {
    World world;
    world.setSettings(test::awakeSettings({0.0, 0.0}));
    const BodyId ground = test::addStaticPivot(world);
    const BodyId small = addDisc(world, {0.0, 0.0}, 0.5), large = addDisc(world, {1.5, 0.0}, 1.0);
    GearJointDef def;
    def.joint1 = pin(world, ground, small, {0.0, 0.0});
    def.joint2 = pin(world, ground, large, {1.5, 0.0});
    def.ratio = 2.0;
    world.createGearJoint(def);
    world.setAngularVelocity(small, 6.0);
    world.setAngularVelocity(large, -3.0);
    auto energy = [&] {
        return 0.5 * world.inertia(small) * std::pow(world.angularVelocity(small), 2) +
               0.5 * world.inertia(large) * std::pow(world.angularVelocity(large), 2);
    };
    const double e0 = energy();
    for (int i = 0; i < 600; ++i) world.step(kDt);
    // The row's velocity error stays at rounding: nothing to take or give.
    EXPECT_NEAR(energy() / e0, 1.0, 1e-9);
    EXPECT_NEAR(world.angularVelocity(large), -3.0, 1e-9);
}

// A pinion of radius R on a pin over a rack on a horizontal slider: ratio -1 / R makes the rack travel R theta.
TEST(GearJoint, RackAndPinionRollsWithoutSlip) {
    World world;
    world.setSettings(test::awakeSettings());
    const BodyId ground = test::addStaticPivot(world);
    const double R = 0.5;
    const BodyId pinion = addDisc(world, {0.0, 0.0}, R);
    BodyDef d;
    d.shape = makeBox(2.0, 0.1);
    d.position = {0.0, -R - 0.1};
    d.collides = false;
    const BodyId rack = world.createBody(d);
    const JointId turn = pin(world, ground, pinion, {0.0, 0.0}, -3.0, 20.0);
    PrismaticJointDef slide;
    slide.bodyA = ground;
    slide.bodyB = rack;
    slide.anchor = {0.0, -R - 0.1};
    slide.axis = {1.0, 0.0};
    const JointId rail = world.createPrismaticJoint(slide);
    GearJointDef def;
    def.joint1 = turn;
    def.joint2 = rail;
    def.ratio = -1.0 / R;
    world.createGearJoint(def);
    for (int i = 0; i < 600; ++i) world.step(kDt);  // 10 s at -3 rad/s: 4.8 turns, the rack 15 m
    const double theta = world.jointAngle(turn), x = world.jointTranslation(rail);
    EXPECT_LT(theta, -29.0);
    EXPECT_LT(std::abs(x - R * theta), 1e-6 * std::abs(x));
    EXPECT_NEAR(world.jointSpeed(rail), R * world.angularVelocity(pinion), 1e-6 * 1.5);
}

// The pinion's motor at its cap T accelerating the rack (mass m) through the gear: T = (I / R + m R) a for the
// rack's acceleration a, and the gear's reaction on the rack is the force that accelerates it, m a along the rail.
TEST(GearJoint, RackReactionIsTheForceThatAcceleratesIt) {
    World world;
    world.setSettings(test::awakeSettings());
    const BodyId ground = test::addStaticPivot(world);
    const double R = 0.5, T = 3.0;
    const BodyId pinion = addDisc(world, {0.0, 0.0}, R);
    BodyDef d;
    d.shape = makeBox(2.0, 0.1);
    d.position = {0.0, -R - 0.1};
    d.collides = false;
    const BodyId rack = world.createBody(d);
    GearJointDef def;
    def.joint1 = pin(world, ground, pinion, {0.0, 0.0}, -1000.0, T);
    PrismaticJointDef slide;
    slide.bodyA = ground;
    slide.bodyB = rack;
    slide.anchor = {0.0, -R - 0.1};
    def.joint2 = world.createPrismaticJoint(slide);
    def.ratio = -1.0 / R;
    const JointId gear = world.createGearJoint(def);
    for (int i = 0; i < 60; ++i) world.step(kDt);
    const double m = world.mass(rack), a = T / (world.inertia(pinion) / R + m * R);
    // Symplectic Euler keeps a constant acceleration's speed exact; the soft row's lag is constant, so its impulse
    // per substep is m a h to rounding.
    EXPECT_NEAR(world.velocity(rack).x(), -a * 1.0, 1e-6 * a);
    const Vec2 F = world.jointReactionForce(gear);
    EXPECT_NEAR(F.x(), -m * a, 1e-6 * m * a);
    EXPECT_NEAR(F.y(), 0.0, 1e-9);
}

// A carrier on a pin and a planet pinned to the carrier: the gear between the carrier's angle and the planet's angle
// relative to it acts on those two bodies alone (the carrier is each joint's shared body).
TEST(GearJoint, GearOnACarrierAndItsPlanet) {
    World world;
    world.setSettings(test::awakeSettings({0.0, 0.0}));
    const BodyId ground = test::addStaticPivot(world);
    BodyDef d;
    d.shape = makeBox(1.0, 0.1);
    d.position = {0.5, 0.0};
    d.collides = false;
    const BodyId carrier = world.createBody(d);
    const BodyId planet = addDisc(world, {1.0, 0.0}, 0.25);
    const JointId arm = pin(world, ground, carrier, {0.0, 0.0}, 2.0, 50.0);
    const JointId axle = pin(world, carrier, planet, {1.0, 0.0});
    GearJointDef def;
    def.joint1 = arm;
    def.joint2 = axle;
    def.ratio = -0.25;  // the planet turns 4 times the carrier's angle relative to it
    world.createGearJoint(def);
    for (int i = 0; i < 1200; ++i) world.step(kDt);  // 20 s at 2 rad/s: 6.4 turns
    const double carrierAngle = world.jointAngle(arm), planetAngle = world.jointAngle(axle);
    EXPECT_GT(carrierAngle, 39.0);
    EXPECT_LT(std::abs(carrierAngle - 0.25 * planetAngle), 1e-6 * carrierAngle);
}

TEST(GearJoint, DestroyingAGearedJointDestroysTheGear) {
    World world;
    const BodyId ground = test::addStaticPivot(world);
    const BodyId a = addDisc(world, {0.0, 0.0}, 0.5), b = addDisc(world, {2.0, 0.0}, 0.5);
    const JointId j1 = pin(world, ground, a, {0.0, 0.0}), j2 = pin(world, ground, b, {2.0, 0.0});
    GearJointDef def;
    def.joint1 = j1;
    def.joint2 = j2;
    const JointId gear = world.createGearJoint(def);
    EXPECT_EQ(world.jointCount(), 3u);
    world.destroyJoint(j2);
    EXPECT_FALSE(world.contains(gear));
    EXPECT_TRUE(world.contains(j1));
    EXPECT_EQ(world.jointCount(), 1u);
    // Through a body: destroying the static ground removes both pins and the gear on them.
    const JointId j3 = pin(world, ground, b, {2.0, 0.0});
    def.joint2 = j3;
    world.createGearJoint(def);
    EXPECT_EQ(world.jointCount(), 3u);
    world.destroyBody(ground);
    EXPECT_EQ(world.jointCount(), 0u);
    world.step(kDt);
}

TEST(GearJoint, BadInputIsRefusedNamingTheValueAndLeavesTheWorldUnchanged) {
    World world;
    const BodyId ground = test::addStaticPivot(world);
    const BodyId a = addDisc(world, {0.0, 0.0}, 0.5), b = addDisc(world, {2.0, 0.0}, 0.5);
    const BodyId c = addDisc(world, {4.0, 0.0}, 0.5);
    const JointId j1 = pin(world, ground, a, {0.0, 0.0}), j2 = pin(world, ground, b, {2.0, 0.0});
    DistanceJointDef rod;
    rod.bodyA = ground;
    rod.bodyB = c;
    const JointId distance = world.createDistanceJoint(rod);
    const JointId j3 = pin(world, b, c, {3.0, 0.0});
    PrismaticJointDef slide;  // its axis on a moving body
    slide.bodyA = a;
    slide.bodyB = c;
    const JointId loose = world.createPrismaticJoint(slide);
    const JointId gone = pin(world, ground, c, {4.0, 0.0});
    world.destroyJoint(gone);
    const std::size_t joints = world.jointCount();
    auto refused = [&](JointId first, JointId second, double ratio, const std::string& name) {
        GearJointDef def;
        def.joint1 = first;
        def.joint2 = second;
        def.ratio = ratio;
        try {
            world.createGearJoint(def);
            ADD_FAILURE() << "accepted: " << name;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
        EXPECT_EQ(world.jointCount(), joints) << name;
    };
    refused(j1, j2, 0.0, "ratio");
    refused(j1, j2, std::nan(""), "ratio");
    refused(j1, j2, INFINITY, "ratio");
    refused(j1, distance, 1.0, "distance joint");
    refused(gone, j2, 1.0, "joint1 (index");
    refused(j1, JointId{}, 1.0, "joint2");
    refused(j1, j1, 1.0, "two different joints");
    refused(j1, j3, 1.0, "more than two bodies");
    refused(j1, loose, 1.0, "bodyA is not static");
}

}  // namespace
}  // namespace physim
