// World's joint geometry getters (drawing and inspection): a Wheel or Prismatic joint's axis turns with body A, the
// limits read back as set (Revolute in rad, Prismatic and Wheel in m), a Pulley's ground anchors are its definition's,
// jointBodies gives A then B; kinds without the item are refused with std::invalid_argument.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace physim {
namespace {

struct Pair {
    World world{[] {
        WorldSettings s;
        s.gravity = Vec2::Zero();
        return s;
    }()};
    BodyId a, b;
    Pair() {
        BodyDef d;
        d.shape = makeBox(0.5, 0.5);
        d.position = {0.0, 0.0};
        a = world.createBody(d);
        d.position = {2.0, 1.0};
        b = world.createBody(d);
    }
};

TEST(JointGeometry, WheelAndPrismaticAxisTurnsWithBodyA) {
    Pair s;
    WheelJointDef w;
    w.bodyA = s.a;
    w.bodyB = s.b;
    w.anchor = {2.0, 1.0};
    w.axis = {0.0, 3.0};  // any length: read back as a unit vector
    const JointId wheel = s.world.createWheelJoint(w);
    PrismaticJointDef p;
    p.bodyA = s.a;
    p.bodyB = s.b;
    p.anchor = {2.0, 1.0};
    p.axis = {1.0, 1.0};
    const JointId slider = s.world.createPrismaticJoint(p);
    // 1e-12: a unit vector through one rotation, a few roundings of 1.
    EXPECT_NEAR(s.world.jointAxis(wheel).x(), 0.0, 1e-12);
    EXPECT_NEAR(s.world.jointAxis(wheel).y(), 1.0, 1e-12);
    EXPECT_NEAR(s.world.jointAxis(slider).x(), std::sqrt(0.5), 1e-12);
    s.world.setTransform(s.a, {0.0, 0.0}, M_PI / 2);  // A turns a quarter: its axes with it
    EXPECT_NEAR(s.world.jointAxis(wheel).x(), -1.0, 1e-12);
    EXPECT_NEAR(s.world.jointAxis(wheel).y(), 0.0, 1e-12);
    EXPECT_NEAR(s.world.jointAxis(slider).x(), -std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(s.world.jointAxis(slider).y(), std::sqrt(0.5), 1e-12);
}

TEST(JointGeometry, LimitsOfRevolutePrismaticWheelReadBackAsSet) {
    Pair s;
    RevoluteJointDef r;
    r.bodyA = s.a;
    r.bodyB = s.b;
    r.anchor = {1.0, 0.5};
    const JointId pin = s.world.createRevoluteJoint(r);
    EXPECT_FALSE(s.world.jointLimits(pin).enabled);
    s.world.setJointLimits(pin, true, -0.5, 0.25);
    const JointLimits rl = s.world.jointLimits(pin);
    EXPECT_TRUE(rl.enabled);
    EXPECT_EQ(rl.lower, -0.5);
    EXPECT_EQ(rl.upper, 0.25);
    PrismaticJointDef p;
    p.bodyA = s.a;
    p.bodyB = s.b;
    p.enableLimit = true;
    p.lowerTranslation = -1.0;
    p.upperTranslation = 2.0;
    const JointLimits pl = s.world.jointLimits(s.world.createPrismaticJoint(p));
    EXPECT_TRUE(pl.enabled);
    EXPECT_EQ(pl.lower, -1.0);
    EXPECT_EQ(pl.upper, 2.0);
    WheelJointDef w;
    w.bodyA = s.a;
    w.bodyB = s.b;
    const JointId wheel = s.world.createWheelJoint(w);
    s.world.setWheelLimits(wheel, true, -0.1, 0.2);
    EXPECT_EQ(s.world.jointLimits(wheel).lower, -0.1);
    EXPECT_EQ(s.world.jointLimits(wheel).upper, 0.2);
}

TEST(JointGeometry, PulleyGroundAnchorsAndJointBodies) {
    Pair s;
    PulleyJointDef p;
    p.bodyA = s.a;
    p.bodyB = s.b;
    p.groundAnchorA = {0.0, 3.0};
    p.groundAnchorB = {2.0, 4.0};
    const JointId pulley = s.world.createPulleyJoint(p);
    const auto [ga, gb] = s.world.jointPulleyGroundAnchors(pulley);
    EXPECT_EQ(ga, Vec2(0.0, 3.0));
    EXPECT_EQ(gb, Vec2(2.0, 4.0));
    const auto [a, b] = s.world.jointBodies(pulley);
    EXPECT_EQ(a, s.a);
    EXPECT_EQ(b, s.b);
    MouseJointDef m;  // a joint to a world point: B twice
    m.body = s.b;
    m.maxForce = 10.0;
    const auto [ma, mb] = s.world.jointBodies(s.world.createMouseJoint(m));
    EXPECT_EQ(ma, s.b);
    EXPECT_EQ(mb, s.b);
}

TEST(JointGeometry, KindsWithoutTheItemAreRefusedWheelPrismaticPulley) {
    Pair s;
    WeldJointDef w;
    w.bodyA = s.a;
    w.bodyB = s.b;
    const JointId weld = s.world.createWeldJoint(w);
    EXPECT_THROW(s.world.jointAxis(weld), std::invalid_argument);
    EXPECT_THROW(s.world.jointLimits(weld), std::invalid_argument);
    EXPECT_THROW(s.world.jointPulleyGroundAnchors(weld), std::invalid_argument);
    EXPECT_THROW(s.world.jointBodies(JointId{}), std::invalid_argument);
}

}  // namespace
}  // namespace physim
