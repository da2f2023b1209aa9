// Prismatic (slider) joints against analytic answers: a block on a frictionless inclined axis accelerates at
// g sin(theta), limits hold it, the motor saturates at its force cap, the spring's period is 1 / hertz for the
// slider's effective mass; the reaction; bad input refused with the world unchanged.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace physim {
namespace {

constexpr double kG = 9.81;
constexpr double kDt = 1.0 / 60.0;

// A 0.4 m square block (1 kg/m^2: 0.16 kg) that collides with nothing, at `at`.
BodyId addBlock(World& world, const Vec2& at, double angle = 0.0) {
    BodyDef d;
    d.shape = makeBox(0.2, 0.2);
    d.position = at;
    d.angle = angle;
    d.collides = false;
    return world.createBody(d);
}

struct Slider {
    World world;
    BodyId ground, block;
    JointId joint;
};

void build(Slider& s, const PrismaticJointDef& extra, const Vec2& gravity = {0.0, -kG}) {
    s.world.setSettings(test::awakeSettings(gravity));
    s.ground = test::addStaticPivot(s.world);
    s.block = addBlock(s.world, {1.0, 2.0}, 0.3);
    PrismaticJointDef def = extra;
    def.bodyA = s.ground;
    def.bodyB = s.block;
    def.anchor = {1.0, 2.0};
    s.joint = s.world.createPrismaticJoint(def);
}

// Along a frictionless axis inclined theta below the horizontal, gravity's component g sin(theta) is all that
// acts: the speed after t is g sin(theta) t, and the block neither leaves the line nor turns.
TEST(PrismaticJoint, BlockOnAnInclinedAxisAcceleratesAtGSinTheta) {
    const double theta = 30.0 * M_PI / 180.0;
    Slider s;
    PrismaticJointDef def;
    def.axis = {2.0 * std::cos(theta), -2.0 * std::sin(theta)};  // any length: stored as a unit vector
    build(s, def);
    const int steps = 60;
    for (int i = 0; i < steps; ++i) s.world.step(kDt);
    const double t = steps * kDt, a = kG * std::sin(theta);
    // Symplectic Euler integrates a constant acceleration's speed exactly; the rows add rounding only.
    EXPECT_NEAR(s.world.jointSpeed(s.joint), a * t, 1e-9 * a * t);
    // Its position lags the exact a t^2 / 2 by a t h / 2 (h the substep): the scheme's first-order term.
    const double h = kDt / s.world.settings().substeps;
    EXPECT_NEAR(s.world.jointTranslation(s.joint), 0.5 * a * t * (t + h), 1e-9);
    const Vec2 axis(std::cos(theta), -std::sin(theta));
    const Vec2 moved = s.world.position(s.block) - Vec2(1.0, 2.0);
    // The anchor stays on the axis but for the soft row's give under the normal force, g cos(theta) / (2 pi f)^2
    // = 1.5e-5 m at f = 120 Hz, the jointHertz the 480 Hz substep allows.
    EXPECT_NEAR(cross(axis, moved), -kG * std::cos(theta) / std::pow(2 * M_PI * 120.0, 2), 1e-7);
    EXPECT_NEAR(s.world.angle(s.block), 0.3, 1e-9) << "no turn relative to the static body";
    // The reaction is the normal force: g cos(theta) m, across the axis, upward.
    const double m = s.world.mass(s.block);
    const Vec2 F = s.world.jointReactionForce(s.joint);
    EXPECT_NEAR(F.dot(axis), 0.0, 1e-9);
    EXPECT_NEAR(F.dot(perp(axis)), m * kG * std::cos(theta), 1e-9 * m * kG);
    EXPECT_NEAR(s.world.jointReactionTorque(s.joint), 0.0, 1e-9);
    EXPECT_EQ(s.world.jointType(s.joint), JointType::Prismatic);
}

// A block hanging on a vertical axis rests on its lower limit, pushed up with its weight; thrown up, it stops at
// the upper one.
TEST(PrismaticJoint, LimitsHoldTheBlockAtTheLimit) {
    Slider s;
    PrismaticJointDef def;
    def.axis = {0.0, 1.0};
    def.enableLimit = true;
    def.lowerTranslation = -0.5;
    def.upperTranslation = 0.25;
    build(s, def);
    for (int i = 0; i < 120; ++i) s.world.step(kDt);
    // The soft limit row gives under the weight by g / (2 pi f)^2 = 1.7e-5 m, f = 120 Hz the jointHertz.
    EXPECT_NEAR(s.world.jointTranslation(s.joint), -0.5, 3e-5);
    const double m = s.world.mass(s.block);
    EXPECT_NEAR(s.world.jointReactionForce(s.joint).y(), m * kG, 1e-6 * m * kG) << "the limit carries the weight";

    s.world.setVelocity(s.block, {0.0, 6.0});  // would rise 6^2 / (2 g) = 1.8 m from -0.5
    double highest = -1.0;
    for (int i = 0; i < 60; ++i) {
        s.world.step(kDt);
        highest = std::max(highest, s.world.jointTranslation(s.joint));
    }
    // Speculative: the row stops the block at the limit within the substep it would cross it.
    EXPECT_LT(highest, 0.25 + 1e-6);
    EXPECT_GT(highest, 0.25 - 1e-3);

    s.world.setPrismaticLimits(s.joint, false, 0.0, 0.0);
    for (int i = 0; i < 30; ++i) s.world.step(kDt);
    EXPECT_LT(s.world.jointTranslation(s.joint), -0.6) << "limits off: it falls through";
}

// A motor pushing along a horizontal axis at its cap F: the block accelerates at F / m, and jointMotorForce reads F;
// once at the motor's speed, it holds it with no force.
TEST(PrismaticJoint, MotorSaturatesAtMaxMotorForce) {
    Slider s;
    PrismaticJointDef def;
    def.axis = {1.0, 0.0};
    def.enableMotor = true;
    def.motorSpeed = 2.0;
    def.maxMotorForce = 0.4;
    build(s, def);
    const double m = s.world.mass(s.block), a = def.maxMotorForce / m;  // 2.5 m/s^2: 0.8 s to 2 m/s
    for (int i = 0; i < 30; ++i) s.world.step(kDt);
    EXPECT_NEAR(s.world.jointSpeed(s.joint), a * 0.5, 1e-9);
    EXPECT_NEAR(s.world.jointMotorForce(s.joint), def.maxMotorForce, 1e-9);
    for (int i = 0; i < 60; ++i) s.world.step(kDt);
    EXPECT_NEAR(s.world.jointSpeed(s.joint), 2.0, 1e-9);
    EXPECT_NEAR(s.world.jointMotorForce(s.joint), 0.0, 1e-9);

    // Lifting against gravity on a vertical axis at a steady speed: the motor's force is the weight.
    Slider up;
    def.axis = {0.0, 1.0};
    def.motorSpeed = 0.5;
    def.maxMotorForce = 10.0;
    build(up, def);
    for (int i = 0; i < 60; ++i) up.world.step(kDt);
    const double mu = up.world.mass(up.block);
    EXPECT_NEAR(up.world.jointSpeed(up.joint), 0.5, 1e-9);
    EXPECT_NEAR(up.world.jointMotorForce(up.joint), mu * kG, 1e-9 * mu * kG);
    up.world.setPrismaticMotor(up.joint, true, 0.5, 0.5 * mu * kG);  // too weak now: falls at g / 2
    for (int i = 0; i < 60; ++i) up.world.step(kDt);
    EXPECT_NEAR(up.world.jointMotorForce(up.joint), 0.5 * mu * kG, 1e-9);
    EXPECT_THROW(up.world.jointMotorTorque(up.joint), std::invalid_argument) << "a slider's motor is a force";
}

// Undamped, the spring along the axis oscillates at `hertz` for the slider's effective mass: between a block and a
// static body, the block's mass; between two free blocks of m1 and m2, m1 m2 / (m1 + m2).
TEST(PrismaticJoint, SpringPeriodIsOneOverHertzForTheEffectiveMass) {
    for (const bool twoBodies : {false, true}) {
        World world;
        world.setSettings(test::awakeSettings({0.0, 0.0}));
        BodyId a;
        if (twoBodies) {
            BodyDef d;
            d.shape = makeBox(0.5, 0.2);  // 0.4 kg against the block's 0.16 kg
            d.collides = false;
            a = world.createBody(d);
        } else {
            a = test::addStaticPivot(world);
        }
        const BodyId b = addBlock(world, {1.0, 0.0});
        PrismaticJointDef def;
        def.bodyA = a;
        def.bodyB = b;
        def.anchor = {1.0, 0.0};
        // Two bodies: along the line of their centres, so the spring turns neither and the effective mass is the
        // reduced mass exactly.
        def.axis = twoBodies ? Vec2(1.0, 0.0) : Vec2(1.0, 1.0);
        def.enableSpring = true;
        def.hertz = 2.0;
        def.targetTranslation = 0.1;  // starts 0.1 m from its rest
        const JointId j = world.createPrismaticJoint(def);
        std::vector<double> crossings;
        double last = world.jointTranslation(j) - 0.1;
        for (int i = 1; i * kDt < 5.0; ++i) {
            world.step(kDt);
            const double now = world.jointTranslation(j) - 0.1;
            if (last < 0.0 && now >= 0.0) crossings.push_back(i * kDt - kDt * now / (now - last));
            last = now;
        }
        ASSERT_GE(crossings.size(), 8u);
        const double period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
        // The implicit spring's phase error is (omega h)^2 / 12 ~ 1e-4 at the 1/480 s substep; crossings are
        // interpolated within a 1/60 s frame of a 0.5 s period (error ~1e-4 of it).
        EXPECT_NEAR(period * def.hertz, 1.0, 2e-3) << (twoBodies ? "two free bodies" : "against a static body");
    }
}

// Between two free bodies turning together, with the motor pushing them apart along the turning axis: no outside
// force or torque, so the joint keeps the total momentum and the angular momentum about the origin; its rows' lever
// arms (the axis turning with A, B's anchor off A's centre) must be right for the latter.
TEST(PrismaticJoint, TwoFreeBodiesKeepTheirMomentumAndAngularMomentum) {
    World world;
    world.setSettings(test::awakeSettings({0.0, 0.0}));
    BodyDef d;
    d.shape = makeBox(0.6, 0.15);
    d.collides = false;
    const BodyId a = world.createBody(d);
    const BodyId b = addBlock(world, {0.8, 0.3}, 0.2);
    PrismaticJointDef def;
    def.bodyA = a;
    def.bodyB = b;
    def.anchor = {0.5, 0.1};
    def.axis = {1.0, 0.4};
    def.enableMotor = true;
    def.motorSpeed = 1.5;
    def.maxMotorForce = 2.0;
    const JointId j = world.createPrismaticJoint(def);
    const BodyId bodies[2] = {a, b};
    for (const BodyId id : bodies) {  // turning together at 1 rad/s about the origin
        world.setAngularVelocity(id, 1.0);
        world.setVelocity(id, cross(1.0, world.centerOfMass(id)));
    }
    auto momentum = [&] {
        Vec2 p = Vec2::Zero();
        for (const BodyId id : bodies) p += world.mass(id) * world.velocity(id);
        return p;
    };
    auto angularMomentum = [&] {
        double L = 0.0;
        for (const BodyId id : bodies)
            L += world.mass(id) * cross(world.centerOfMass(id), world.velocity(id)) +
                 world.inertia(id) * world.angularVelocity(id);
        return L;
    };
    const Vec2 p0 = momentum();
    const double L0 = angularMomentum();
    for (int i = 0; i < 120; ++i) world.step(kDt);
    EXPECT_GT(world.jointTranslation(j), 0.5) << "the motor pushed them apart";
    EXPECT_NEAR(world.angle(b) - world.angle(a), 0.2, 1e-6) << "no relative turn";
    // Each row's impulses are equal and opposite at one point (or pure opposite torques): exact but for rounding
    // over 960 substeps of impulses about 1e-3 N s.
    EXPECT_LT((momentum() - p0).norm(), 1e-12);
    EXPECT_NEAR(angularMomentum(), L0, 1e-10);
}

TEST(PrismaticJoint, BadInputIsRefusedNamingTheValueAndLeavesTheWorldUnchanged) {
    World world;
    const BodyId ground = test::addStaticPivot(world);
    const BodyId block = addBlock(world, {1.0, 0.0});
    auto refused = [&](PrismaticJointDef def, const std::string& name) {
        if (def.bodyA.isNull()) def.bodyA = ground;
        if (def.bodyB.isNull()) def.bodyB = block;
        try {
            world.createPrismaticJoint(def);
            ADD_FAILURE() << "accepted: " << name;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
        EXPECT_EQ(world.jointCount(), 0u) << name;
    };
    const double nan = std::nan("");
    PrismaticJointDef d;
    d.anchor = {nan, 0.0};
    refused(d, "anchor");
    d = {};
    d.axis = {0.0, nan};
    refused(d, "axis");
    d = {};
    d.axis = {0.0, 0.0};
    refused(d, "axis");
    d = {};
    d.enableLimit = true;
    d.lowerTranslation = 1.0;
    d.upperTranslation = 0.5;
    refused(d, "lowerTranslation");
    d = {};
    d.maxMotorForce = -1.0;
    refused(d, "maxMotorForce");
    d = {};
    d.hertz = nan;
    refused(d, "hertz");
    d = {};
    d.bodyA = block;
    refused(d, "two different bodies");
    EXPECT_EQ(world.awakeBodyCount(), 1u);

    PrismaticJointDef good;
    good.bodyA = ground;
    good.bodyB = block;
    const JointId j = world.createPrismaticJoint(good);
    EXPECT_THROW(world.setPrismaticLimits(j, true, 1.0, 0.0), std::invalid_argument);
    EXPECT_THROW(world.setPrismaticMotor(j, true, nan, 1.0), std::invalid_argument);
    EXPECT_THROW(world.setPrismaticSpring(j, true, -1.0, 0.0, 0.0), std::invalid_argument);
    EXPECT_THROW(world.setWheelMotor(j, true, 1.0, 1.0), std::invalid_argument) << "not a wheel joint";
    EXPECT_THROW(world.jointAngle(j), std::invalid_argument);
}

}  // namespace
}  // namespace physim
