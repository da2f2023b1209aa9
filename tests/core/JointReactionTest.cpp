// Joint reactions (World::jointReactionForce, jointReactionTorque) against statics and a swing: whatever holds a
// body at rest pushes with its weight, and a cantilever's weld or motor holds its moment; a pendulum released from
// the horizontal pulls three times its weight at the bottom.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace physim {
namespace {

constexpr double kG = 9.81;
constexpr double kDt = 1.0 / 60.0;

World quietWorld() { return World(test::awakeSettings()); }

BodyId body(World& world, const Geometry& shape, const Vec2& at) {
    BodyDef d;
    d.shape = shape;
    d.position = at;
    d.collides = false;
    return world.createBody(d);
}

void run(World& world, double seconds) {
    for (int i = 0; i * kDt < seconds; ++i) world.step(kDt);
}

// The force holding a weight m g up: (0, m g), to a part in 1e-6 of it once at rest.
void expectHoldsWeight(const Vec2& force, double m, const char* what) {
    EXPECT_NEAR(force.x(), 0.0, 1e-6 * m * kG) << what;
    EXPECT_NEAR(force.y(), m * kG, 1e-6 * m * kG) << what;
}

// A bob (a 5 cm disc) at `at` on a rod from a static pivot at the origin.
struct RodPendulum {
    World world = quietWorld();
    BodyId pivot = test::addStaticPivot(world);
    BodyId bob;
    JointId rod;

    explicit RodPendulum(const Vec2& at) : bob(body(world, makeCircle(0.05), at)) {
        DistanceJointDef def;
        def.bodyA = pivot;
        def.bodyB = bob;
        rod = world.createDistanceJoint(def);
    }
};

TEST(JointReaction, ZeroBeforeTheFirstStep) {
    RodPendulum p({0.0, -1.0});
    World& world = p.world;
    const JointId j = p.rod;
    EXPECT_EQ(world.jointReactionForce(j), Vec2::Zero());
    EXPECT_EQ(world.jointReactionTorque(j), 0.0);
    EXPECT_THROW(world.jointReactionForce(JointId{}), std::invalid_argument);
}

// A bob hanging still under its pivot: the rod's tension is the bob's weight, along the rod.
TEST(JointReaction, PendulumRodAtRestHoldsTheWeight) {
    RodPendulum p({0.0, -1.0});
    World& world = p.world;
    const BodyId bob = p.bob;
    const JointId j = p.rod;
    run(world, 1.0);
    expectHoldsWeight(world.jointReactionForce(j), world.mass(bob), "rod");
    EXPECT_EQ(world.jointReactionTorque(j), 0.0);
}

// Released from the horizontal, a bob on a rod of length L pulls T = 3 m g cos(theta) at angle theta from the
// vertical (m g cos + m v^2 / L, v^2 = 2 g L cos), 3 m g at the bottom. There it turns 0.074 rad per 1/60 s step,
// so some step ends within 0.037 rad of it, where T falls short by under 1e-3; 5e-3 leaves room for the soft rod.
TEST(JointReaction, PendulumPullsThreeTimesItsWeightAtTheBottom) {
    RodPendulum p({1.0, 0.0});
    World& world = p.world;
    const BodyId bob = p.bob;
    const JointId j = p.rod;
    double largest = 0.0;
    for (int i = 0; i * kDt < 1.0; ++i) {
        world.step(kDt);
        largest = std::max(largest, world.jointReactionForce(j).norm());
    }
    const double m = world.mass(bob);
    EXPECT_NEAR(largest / (3.0 * m * kG), 1.0, 5e-3);
}

// A disc hanging from a pin at its top: the pin holds its weight and, free to turn, no torque.
TEST(JointReaction, RevolutePinHoldsAHangingBody) {
    World world = quietWorld();
    const BodyId pivot = test::addStaticPivot(world);
    const BodyId disc = body(world, makeCircle(0.2), {0.0, -0.2});
    RevoluteJointDef pin;
    pin.bodyA = pivot;
    pin.bodyB = disc;
    pin.anchor = Vec2::Zero();
    const JointId j = world.createRevoluteJoint(pin);
    run(world, 1.0);
    expectHoldsWeight(world.jointReactionForce(j), world.mass(disc), "pin");
    EXPECT_EQ(world.jointReactionTorque(j), 0.0);
}

// A horizontal beam of length L reaching to +x from a wall at the origin, to be held there by a joint. The hold
// carries its weight m g and the moment of that weight about the end, m g L / 2 (counter-clockwise), to 1e-4 of it:
// the soft hold lets the beam droop by some 1e-5 rad, which moves its centre of mass in by L (1 - cos), about 1e-10 L.
struct Cantilever {
    World world = quietWorld();
    double length = 2.0;  // m
    BodyId wall = test::addStaticPivot(world);
    BodyId beam = body(world, makeBox(0.5 * length, 0.05), {0.5 * length, 0.0});

    // A weld's or pin's definition joining the beam to the wall at the origin.
    template <class Def>
    Def hold() const {
        Def def;
        def.bodyA = wall;
        def.bodyB = beam;
        def.anchor = Vec2::Zero();
        return def;
    }

    // Runs a second and checks that the hold `j` (a `what`) carries the weight and the moment.
    void expectHeldBy(JointId j, const char* what) {
        run(world, 1.0);
        expectHoldsWeight(world.jointReactionForce(j), world.mass(beam), what);
        EXPECT_NEAR(world.jointReactionTorque(j) / (world.mass(beam) * kG * 0.5 * length), 1.0, 1e-4) << what;
    }
};

TEST(JointReaction, WeldHoldsACantilever) {
    Cantilever c;
    c.expectHeldBy(c.world.createWeldJoint(c.hold<WeldJointDef>()), "weld");
}

TEST(JointReaction, RevoluteMotorHoldsACantilever) {
    Cantilever c;
    RevoluteJointDef pin = c.hold<RevoluteJointDef>();
    pin.enableMotor = true;
    pin.motorSpeed = 0.0;
    pin.maxMotorTorque = 1000.0;  // far above the beam's moment
    const JointId j = c.world.createRevoluteJoint(pin);
    c.expectHeldBy(j, "pin");
    // The pin's torque is all the motor's (no limit is on).
    EXPECT_EQ(c.world.jointMotorTorque(j), c.world.jointReactionTorque(j));
}

// A mouse joint holding a body still against gravity: its (capped, soft) pull is the body's weight.
TEST(JointReaction, MouseJointHoldsTheWeight) {
    World world = quietWorld();
    const BodyId box = body(world, makeBox(0.2, 0.2), {0.0, 0.0});
    MouseJointDef grab;
    grab.body = box;
    grab.target = Vec2::Zero();
    grab.maxForce = 1000.0 * world.mass(box) * kG;
    const JointId j = world.createMouseJoint(grab);
    run(world, 5.0);
    expectHoldsWeight(world.jointReactionForce(j), world.mass(box), "mouse");
}

// A body hanging still from a spring to a point, stretched to where k x = m g: the spring's force is the weight.
TEST(JointReaction, SpringAtRestHoldsTheWeight) {
    World world = quietWorld();
    const double k = 50.0, rest = 1.0;
    const BodyId ball = body(world, makeCircle(0.1), {0.0, 0.0});
    const double m = world.mass(ball);
    world.setTransform(ball, {0.0, -(rest + m * kG / k)}, 0.0);
    SpringJointDef spring;
    spring.bodyB = ball;
    spring.localAnchorA = Vec2::Zero();  // the world point
    spring.restLength = rest;
    spring.stiffness = k;
    spring.damping = 1.0;
    const JointId j = world.createSpringJoint(spring);
    run(world, 2.0);
    expectHoldsWeight(world.jointReactionForce(j), m, "spring");
    EXPECT_EQ(world.jointReactionTorque(j), 0.0);
}

}  // namespace
}  // namespace physim
