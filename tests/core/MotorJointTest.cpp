// Motor joints: a body driven to its target pose and held there against gravity; capped by maxForce and maxTorque,
// it accelerates at (F - m g) / m and turns at maxTorque / I; moving the target; bad input.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"
#include "support/ThrowsNaming.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace physim {
namespace {

constexpr double kG = 9.81;
constexpr double kDt = 1.0 / 40.0;

struct Driven {
    World world;
    BodyId ground, box;
    JointId motor;
};

// A 2 kg box of 1 m x 0.5 m at the origin, driven relative to a static ground point at (0, 0).
void build(Driven& s, const MotorJointDef& extra) {
    s.world.setSettings(test::awakeSettings());
    s.ground = test::addStaticPivot(s.world);
    BodyDef d;
    d.shape = makeBox(0.5, 0.25);
    d.density = 4.0;
    d.collides = false;
    s.box = s.world.createBody(d);
    MotorJointDef m = extra;
    m.bodyA = s.ground;
    m.bodyB = s.box;
    s.motor = s.world.createMotorJoint(m);
}

// Strong enough, the joint removes 30% of the pose error per substep (320 per second at 40 Hz), so after 2 s the
// error is gone to rounding: B's origin on the target within 1e-9 m and rad, and its pull the box's weight.
TEST(MotorJoint, MovesABodyToItsTargetPoseAndHoldsItAgainstGravity) {
    Driven s;
    MotorJointDef m;
    m.linearOffset = {2.0, 1.0};
    m.angularOffset = 0.5;
    m.maxForce = 1000.0;
    m.maxTorque = 1000.0;
    build(s, m);
    for (int i = 0; i < 80; ++i) s.world.step(kDt);
    EXPECT_NEAR((s.world.position(s.box) - Vec2(2.0, 1.0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR(s.world.angle(s.box), 0.5, 1e-9);
    EXPECT_NEAR(s.world.jointAngle(s.motor), 0.0, 1e-9);
    const double weight = s.world.mass(s.box) * kG;
    EXPECT_NEAR(s.world.jointReactionForce(s.motor).x(), 0.0, 1e-9 * weight);
    EXPECT_NEAR(s.world.jointReactionForce(s.motor).y(), weight, 1e-9 * weight);
    EXPECT_NEAR(s.world.jointMotorForce(s.motor), weight, 1e-9 * weight);
    EXPECT_NEAR(s.world.jointMotorTorque(s.motor), 0.0, 1e-9);

    // A new target: the box follows it.
    s.world.setMotorJointOffsets(s.motor, {-1.0, 3.0}, -0.25);
    for (int i = 0; i < 80; ++i) s.world.step(kDt);
    EXPECT_NEAR((s.world.position(s.box) - Vec2(-1.0, 3.0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR(s.world.angle(s.box), -0.25, 1e-9);
}

// Too weak for the pose, the joint pushes with its whole maxForce F towards a target straight above, so the box
// rises at (F - m g) / m, and turns at maxTorque / I. Both passes clamp the accumulated impulse to F h, so each
// substep adds exactly (F / m - g) h: the test asks for 1e-9 relative.
TEST(MotorJoint, CappedByMaxForceAndMaxTorque) {
    Driven s;
    MotorJointDef m;
    m.linearOffset = {0.0, 1000.0};
    m.angularOffset = 1000.0;
    m.maxForce = 1.5 * 2.0 * kG;  // 1.5 times the weight of the 2 kg box
    m.maxTorque = 0.1;
    build(s, m);
    const double mass = s.world.mass(s.box), inertia = s.world.inertia(s.box);
    ASSERT_NEAR(mass, 2.0, 1e-12);
    for (int i = 0; i < 20; ++i) s.world.step(kDt);
    const Vec2 v1 = s.world.velocity(s.box);
    const double w1 = s.world.angularVelocity(s.box);
    for (int i = 0; i < 40; ++i) s.world.step(kDt);
    const double a = (s.world.velocity(s.box).y() - v1.y()) / (40 * kDt);
    const double alpha = (s.world.angularVelocity(s.box) - w1) / (40 * kDt);
    const double expected = (m.maxForce - mass * kG) / mass;
    EXPECT_NEAR(a / expected, 1.0, 1e-9) << a << " m/s^2 against " << expected;
    EXPECT_NEAR(s.world.velocity(s.box).x(), 0.0, 1e-12);
    EXPECT_NEAR(alpha / (m.maxTorque / inertia), 1.0, 1e-9);
    EXPECT_NEAR(s.world.jointMotorForce(s.motor), m.maxForce, 1e-9 * m.maxForce);
    EXPECT_NEAR(s.world.jointMotorTorque(s.motor), m.maxTorque, 1e-12);
}

// Between two free bodies in zero gravity, one spinning: the joint's forces are equal and opposite, so the pair's
// momentum stays zero (to rounding: 1e-12 of the speeds' scale), and B settles on A's turning frame: its angle to
// 1e-9 rad, its point within a lag of the target's curving path, which leaves each substep's straight step by
// about w^2 r h^2 / 2 (5e-6 m at the 1/320 s substep, w 1 rad/s, r about 1 m) and loses 30% of it a substep: 1e-4 m.
TEST(MotorJoint, BetweenTwoBodiesKeepsTheirMomentumAndFollowsTheTurningFrame) {
    World world(test::awakeSettings(Vec2::Zero()));
    BodyDef d;
    d.shape = makeBox(0.5, 0.5);
    d.collides = false;
    d.angularVelocity = 1.0;
    const BodyId a = world.createBody(d);
    d.angularVelocity = 0.0;
    d.shape = makeCircle(0.25);
    d.position = {3.0, 0.0};
    const BodyId b = world.createBody(d);
    MotorJointDef m;
    m.bodyA = a;
    m.bodyB = b;
    m.linearOffset = {1.0, 0.0};
    m.angularOffset = 0.5;
    m.maxForce = 1e4;
    m.maxTorque = 1e4;
    const JointId motor = world.createMotorJoint(m);
    for (int i = 0; i < 80; ++i) {
        world.step(kDt);
        const Vec2 momentum = world.mass(a) * world.velocity(a) + world.mass(b) * world.velocity(b);
        ASSERT_LT(momentum.norm(), 1e-12) << "step " << i;
    }
    EXPECT_LT((world.position(b) - world.transform(a).apply(Vec2(1.0, 0.0))).norm(), 1e-4);
    EXPECT_NEAR(world.angle(b) - world.angle(a), 0.5, 1e-9);
    EXPECT_NEAR(world.jointAngle(motor), 0.0, 1e-9);
}

TEST(MotorJoint, BadInputLeavesTheWorldUnchanged) {
    Driven s;
    build(s, MotorJointDef{});
    const double nan = std::numeric_limits<double>::quiet_NaN();
    using physim::testing::expectThrowsNaming;
    MotorJointDef m;
    m.bodyA = s.ground;
    m.bodyB = s.box;
    auto tryDef = [&](MotorJointDef bad, const char* name) {
        expectThrowsNaming([&] { s.world.createMotorJoint(bad); }, name);
    };
    MotorJointDef bad = m;
    bad.linearOffset = {nan, 0.0};
    tryDef(bad, "linearOffset");
    bad = m;
    bad.angularOffset = nan;
    tryDef(bad, "angularOffset");
    bad = m;
    bad.maxForce = -1.0;
    tryDef(bad, "maxForce");
    bad = m;
    bad.maxTorque = nan;
    tryDef(bad, "maxTorque");
    bad = m;
    bad.correctionFactor = 1.5;
    tryDef(bad, "correctionFactor");
    EXPECT_EQ(s.world.jointCount(), 1u);
    expectThrowsNaming([&] { s.world.setMotorJointOffsets(s.motor, {0.0, nan}, 0.0); }, "linearOffset");
    expectThrowsNaming([&] { s.world.setMotorJointOffsets(s.motor, {0.0, 0.0}, nan); }, "angularOffset");
    EXPECT_EQ(s.world.jointAnchors(s.motor).first, Vec2::Zero()) << "the target is unchanged";
    EXPECT_EQ(s.world.jointType(s.motor), JointType::Motor);
}

}  // namespace
}  // namespace physim
