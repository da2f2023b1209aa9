// Revolute (pin) and weld joints: a physical pendulum on a pin against its small-angle period, the pin keeping
// its point, limits, the motor's speed and torque cap, a welded beam; bad input.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace physim {
namespace {

constexpr double kG = 9.81;
constexpr double kDt = 1.0 / 60.0;

// A bar of length L (m) and thickness w hanging from a pin at its top end, released `degrees` from the vertical.
struct BarPendulum {
    World world;
    BodyId pivot, bar;
    JointId pin;
    double length = 1.0, thickness = 0.05;
};

void build(BarPendulum& p, double degrees, const RevoluteJointDef& extra = {}) {
    WorldSettings s;
    s.enableSleep = false;
    p.world.setSettings(s);
    p.pivot = test::addStaticPivot(p.world);
    BodyDef d;
    d.shape = makeBox(0.5 * p.thickness, 0.5 * p.length);
    d.collides = false;
    const double a = degrees * M_PI / 180.0;
    d.angle = a;
    d.position = {0.5 * p.length * std::sin(a), -0.5 * p.length * std::cos(a)};
    p.bar = p.world.createBody(d);
    RevoluteJointDef pin = extra;
    pin.bodyA = p.pivot;
    pin.bodyB = p.bar;
    pin.anchor = Vec2::Zero();
    p.pin = p.world.createRevoluteJoint(pin);
}

// A physical pendulum's small-angle period: T = 2 pi sqrt(I_pivot / (m g d)), I_pivot = m (L^2 + w^2) / 12 + m d^2,
// d = L / 2; the first amplitude correction multiplies it by 1 + theta0^2 / 16.
TEST(RevoluteJoint, PendulumOnAPinHasTheSmallAnglePeriod) {
    BarPendulum p;
    const double degrees = 3.0, theta0 = degrees * M_PI / 180.0;
    build(p, degrees);
    const double L = p.length, w = p.thickness, d = 0.5 * L;
    const double exact = 2 * M_PI * std::sqrt(((L * L + w * w) / 12 + d * d) / (kG * d)) * (1 + theta0 * theta0 / 16);
    std::vector<double> times;
    double last = p.world.angle(p.bar);
    for (int i = 1; i * kDt < 12.0; ++i) {
        p.world.step(kDt);
        const double now = p.world.angle(p.bar);
        if (last > 0.0 && now <= 0.0) times.push_back(i * kDt - kDt * now / (now - last));
        last = now;
    }
    ASSERT_GE(times.size(), 6u);
    const double period = (times.back() - times.front()) / (times.size() - 1);
    // Interpolated crossings within a 1/60 s frame of a 1.6 s period and symplectic Euler's second-order phase
    // error at the 1/480 s substep are both below 1e-4; the next amplitude term (11 theta0^4 / 3072) is 3e-7.
    EXPECT_NEAR(period / exact, 1.0, 2e-4);
    // The pin keeps its point: the bar's top end stays at the pivot, but for the soft point row's give under the
    // bar's weight, g / (2 pi jointHertz)^2 = 1.7e-5 m at the 120 Hz the 480 Hz substep allows.
    const auto [onA, onB] = p.world.jointAnchors(p.pin);
    EXPECT_LT((onB - onA).norm(), 1.5 * kG / std::pow(2 * M_PI * 120.0, 2));
    EXPECT_EQ(p.world.jointType(p.pin), JointType::Revolute);
    EXPECT_NEAR(p.world.jointAngle(p.pin), p.world.angle(p.bar) - 3.0 * M_PI / 180.0, 1e-12)
        << "the joint angle is relative to the angle at creation";
}

TEST(RevoluteJoint, PinAddsNoEnergyOverManySwings) {
    BarPendulum p;
    build(p, 90.0);
    const double m = p.world.mass(p.bar), I = p.world.inertia(p.bar);
    auto energy = [&] {
        return 0.5 * m * p.world.velocity(p.bar).squaredNorm() + 0.5 * I * std::pow(p.world.angularVelocity(p.bar), 2) +
               m * kG * p.world.centerOfMass(p.bar).y();
    };
    const double e0 = energy();
    double worst = 0.0;
    for (int i = 0; i < 1200; ++i) {
        p.world.step(kDt);
        worst = std::max(worst, std::abs(energy() - e0));
    }
    // As for the distance joint (JointTest): symplectic Euler's bounded error, of order m g v h with v the bar's
    // fastest centre speed sqrt(3 g L / 4) (bar released horizontal), and no growth.
    const double h = kDt / 8;
    EXPECT_LT(worst, m * kG * std::sqrt(3.0 * kG * p.length / 4.0) * h);
}

TEST(RevoluteJoint, LimitsHoldTheAngleInside) {
    BarPendulum p;
    RevoluteJointDef limits;
    limits.enableLimit = true;
    limits.lowerAngle = -0.25;
    limits.upperAngle = 0.25;
    build(p, 0.0, limits);
    // Swinging about the pin at 6 rad/s (its centre moving with it) it would rise to about 100 degrees.
    auto swing = [&] {
        p.world.setTransform(p.bar, {0.0, -0.5}, 0.0);
        p.world.setAngularVelocity(p.bar, 6.0);
        p.world.setVelocity(p.bar, {3.0, 0.0});
    };
    swing();
    double lowest = 0.0, highest = 0.0;
    for (int i = 0; i < 300; ++i) {
        p.world.step(kDt);
        lowest = std::min(lowest, p.world.jointAngle(p.pin));
        highest = std::max(highest, p.world.jointAngle(p.pin));
    }
    // Speculative while apart: the bar stops at the limit within its substep; the soft push-out then holds it to
    // a small fraction of a degree.
    EXPECT_NEAR(highest, 0.25, 5e-3);
    EXPECT_NEAR(lowest, -0.25, 5e-3);
    p.world.setJointLimits(p.pin, false, 0.0, 0.0);
    swing();
    highest = 0.0;
    for (int i = 0; i < 60; ++i) {
        p.world.step(kDt);
        highest = std::max(highest, p.world.jointAngle(p.pin));
    }
    EXPECT_GT(highest, 1.5) << "limits off: it swings past";
}

TEST(RevoluteJoint, MotorReachesItsSpeedWithinItsTorque) {
    // A wheel on an axle (no gravity): the motor spins it up at maxTorque / I, then holds motorSpeed.
    WorldSettings s;
    s.gravity = Vec2::Zero();
    World world(s);
    const BodyId axle = test::addStaticPivot(world);
    BodyDef d;
    d.shape = makeCircle(0.5);
    const BodyId wheel = world.createBody(d);
    RevoluteJointDef j;
    j.bodyA = axle;
    j.bodyB = wheel;
    j.enableMotor = true;
    j.motorSpeed = 4.0;
    j.maxMotorTorque = 0.1;
    const JointId motor = world.createRevoluteJoint(j);
    const double I = world.inertia(wheel), alpha = j.maxMotorTorque / I;  // 0.255 rad/s^2 for this wheel
    const int steps = 60;
    for (int i = 0; i < steps; ++i) world.step(kDt);
    EXPECT_NEAR(world.angularVelocity(wheel), alpha * steps * kDt, 1e-9) << "torque-limited spin-up: exact";
    // Saturated, the motor applies its whole cap (1e-12 N m: the cap times h over h, rounded).
    EXPECT_NEAR(world.jointMotorTorque(motor), j.maxMotorTorque, 1e-12);
    EXPECT_THROW(world.jointMotorForce(motor), std::invalid_argument) << "a revolute motor applies a torque";
    world.setJointMotor(motor, true, 4.0, 100.0);
    world.step(kDt);
    EXPECT_NEAR(world.angularVelocity(wheel), 4.0, 1e-9) << "a strong motor holds its speed";
    EXPECT_LT(world.velocity(wheel).norm(), 1e-12) << "the pin holds the centre";
}

TEST(WeldJoint, WeldedBeamHoldsItsPose) {
    // A 1 m beam welded at its left end to a static wall: a cantilever. The weld is as stiff as the rod, so the
    // beam sags only by the soft constraint's compliance: small, and it does not creep.
    World world;
    const BodyId wall = test::addStaticPivot(world);
    BodyDef d;
    d.shape = makeBox(0.5, 0.05);
    d.position = {0.5, 0.0};
    const BodyId beam = world.createBody(d);
    WeldJointDef weld;
    weld.bodyA = wall;
    weld.bodyB = beam;
    weld.anchor = Vec2::Zero();
    const JointId j = world.createWeldJoint(weld);
    EXPECT_EQ(world.jointType(j), JointType::Weld);
    for (int i = 0; i < 120; ++i) world.step(kDt);
    const double sag = world.angle(beam);
    for (int i = 0; i < 600; ++i) world.step(kDt);
    // The soft angle row at jointHertz (capped at a quarter of the 480 Hz substep rate) holds the beam's weight
    // torque m g L / 2 at an angle of about that torque over I_end (2 pi 120)^2: 2e-5 rad; 1e-3 rad bounds it.
    EXPECT_LT(std::abs(world.angle(beam)), 1e-3);
    EXPECT_NEAR(world.angle(beam), sag, 1e-6) << "no creep";
    EXPECT_LT((world.jointAnchors(j).first - world.jointAnchors(j).second).norm(), 1e-4);
}

TEST(RevoluteJoint, BadInput) {
    BarPendulum p;
    build(p, 0.0);
    RevoluteJointDef j;
    j.bodyA = p.bar;
    j.bodyB = p.bar;
    EXPECT_THROW(p.world.createRevoluteJoint(j), std::invalid_argument) << "same body";
    j.bodyA = p.pivot;
    j.anchor = {0.0, NAN};
    EXPECT_THROW(p.world.createRevoluteJoint(j), std::invalid_argument);
    j.anchor = Vec2::Zero();
    j.lowerAngle = 1.0;
    j.upperAngle = -1.0;
    EXPECT_THROW(p.world.createRevoluteJoint(j), std::invalid_argument);
    j.lowerAngle = j.upperAngle = 0.0;
    j.maxMotorTorque = -1.0;
    EXPECT_THROW(p.world.createRevoluteJoint(j), std::invalid_argument);
    EXPECT_THROW(p.world.setJointMotor(p.pin, true, NAN, 1.0), std::invalid_argument);
    EXPECT_THROW(p.world.setJointLimits(p.pin, true, 0.5, 0.4), std::invalid_argument);
    BodyDef still;
    still.type = BodyType::Static;
    WeldJointDef w;
    w.bodyA = p.pivot;
    w.bodyB = p.world.createBody(still);
    EXPECT_THROW(p.world.createWeldJoint(w), std::invalid_argument) << "two immovable bodies";
    DistanceJointDef rod;
    rod.bodyA = p.pivot;
    rod.bodyB = p.bar;
    const JointId distance = p.world.createDistanceJoint(rod);
    EXPECT_THROW(p.world.jointAngle(distance), std::invalid_argument);
    EXPECT_THROW(p.world.setJointMotor(distance, true, 1.0, 1.0), std::invalid_argument);
    p.world.destroyBody(p.bar);
    EXPECT_FALSE(p.world.contains(p.pin));
}

}  // namespace
}  // namespace physim
