// The revolute joint's rotary spring: a disc pinned at its centre oscillates at the spring's frequency, critical
// damping settles it without overshoot, the spring's torque is the reaction; bad input.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"
#include "support/ThrowsNaming.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 40.0;  // the framework's default step

struct PinnedDisc {
    World world;
    BodyId pivot, disc;
    JointId pin;
};

// A disc of radius 0.5 m pinned at its centre to a static point: the joint's effective inertia is the disc's own.
// No gravity: it would only load the pin.
void build(PinnedDisc& p, double hertz, double dampingRatio, double target) {
    p.world.setSettings(test::awakeSettings(Vec2::Zero()));
    p.pivot = test::addStaticPivot(p.world);
    BodyDef d;
    d.shape = makeCircle(0.5);
    d.collides = false;
    p.disc = p.world.createBody(d);
    RevoluteJointDef pin;
    pin.bodyA = p.pivot;
    pin.bodyB = p.disc;
    pin.enableSpring = true;
    pin.springHertz = hertz;
    pin.springDampingRatio = dampingRatio;
    pin.springTargetAngle = target;
    p.pin = p.world.createRevoluteJoint(pin);
}

// Undamped, 2 Hz, released 0.3 rad from its target. The spring is implicit in each 1/320 s substep: its period is
// the spring's to second order in omega h = 0.039, (omega h)^2 / 2 = 8e-4; crossings interpolated within the 1/40 s
// step add less. 2e-3 leaves room for both.
TEST(RevoluteSpring, DiscOscillatesAtTheSpringFrequency) {
    PinnedDisc p;
    build(p, 2.0, 0.0, 0.3);
    std::vector<double> down;
    double last = -0.3;
    for (int i = 1; i * kDt < 3.0; ++i) {
        p.world.step(kDt);
        const double now = p.world.angle(p.disc) - 0.3;
        if (last > 0.0 && now <= 0.0) down.push_back(i * kDt - kDt * now / (now - last));
        last = now;
    }
    ASSERT_GE(down.size(), 5u);
    const double period = (down.back() - down.front()) / (down.size() - 1);
    EXPECT_NEAR(period / 0.5, 1.0, 2e-3) << period;
    // The pin holds the centre: the spring only turns the disc.
    EXPECT_LT(p.world.position(p.disc).norm(), 1e-12);
}

// Critically damped, the angle rises monotonically towards its target and never passes it, and settles there
// (exp(-omega t) after 3 s at 2 Hz: 4e-17).
TEST(RevoluteSpring, CriticalDampingDoesNotOvershoot) {
    PinnedDisc p;
    build(p, 2.0, 1.0, 0.5);
    double last = 0.0;
    for (int i = 0; i < 120; ++i) {
        p.world.step(kDt);
        const double now = p.world.angle(p.disc);
        EXPECT_LE(now, 0.5) << "step " << i;
        EXPECT_GE(now, last - 1e-15) << "step " << i;
        last = now;
    }
    EXPECT_NEAR(p.world.angle(p.disc), 0.5, 1e-9);
    EXPECT_NEAR(p.world.jointAngle(p.pin), 0.5, 1e-9);
}

// Held off its target by a motor, the spring's torque is k (angle - target), k = I (2 pi f)^2: the motor, capped
// below it, gives way until the spring's torque equals its cap, and the reaction torque (spring plus motor) is 0.
TEST(RevoluteSpring, TorqueIsStiffnessTimesAngle) {
    PinnedDisc p;
    build(p, 1.0, 1.0, 0.0);
    const double k = p.world.inertia(p.disc) * std::pow(2 * M_PI * 1.0, 2);
    const double cap = 0.1 * k;  // holds the disc 0.1 rad from its target
    p.world.setJointMotor(p.pin, true, 1.0, cap);
    for (int i = 0; i < 400; ++i) p.world.step(kDt);
    EXPECT_NEAR(p.world.jointAngle(p.pin), 0.1, 1e-9);
    EXPECT_NEAR(p.world.jointMotorTorque(p.pin), cap, 1e-9 * cap);
    EXPECT_NEAR(p.world.jointReactionTorque(p.pin), 0.0, 1e-9 * cap);
    // Turned off, the spring lets go: the motor spins the disc up.
    p.world.setJointSpring(p.pin, false, 1.0, 1.0);
    for (int i = 0; i < 40; ++i) p.world.step(kDt);
    EXPECT_NEAR(p.world.angularVelocity(p.disc), 1.0, 1e-9);
}

TEST(RevoluteSpring, BadInputIsRefusedByName) {
    PinnedDisc p;
    build(p, 1.0, 1.0, 0.0);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    using physim::testing::expectThrowsNaming;
    expectThrowsNaming([&] { p.world.setJointSpring(p.pin, true, -1.0, 1.0); }, "springHertz");
    expectThrowsNaming([&] { p.world.setJointSpring(p.pin, true, 1.0, nan); }, "springDampingRatio");
    RevoluteJointDef bad;
    bad.bodyA = p.pivot;
    bad.bodyB = p.disc;
    bad.springTargetAngle = nan;
    expectThrowsNaming([&] { p.world.createRevoluteJoint(bad); }, "springTargetAngle");
    bad.springTargetAngle = 0.0;
    bad.springHertz = nan;
    expectThrowsNaming([&] { p.world.createRevoluteJoint(bad); }, "springHertz");
    EXPECT_EQ(p.world.jointCount(), 1u);
}

}  // namespace
}  // namespace physim
