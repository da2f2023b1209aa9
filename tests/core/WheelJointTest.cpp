// Wheel joints against analytic answers: a wheel hanging on its suspension sags by m g / k, its motor spins it up at
// T / I and jointMotorTorque reads T, it turns freely with the motor off, and its anchor stays on the axis; bad input;
// the car climbing a 10 degree slope with its driven wheel rolling (omega r against the travel speed).

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

// A chassis and its wheel free in space, turning together, the suspension displaced and the motor spinning the
// wheel: every row's impulses are internal, so the momentum and the angular momentum about the origin stay.
TEST(WheelJoint, FreeChassisAndWheelKeepTheirMomentumAndAngularMomentum) {
    World world;
    world.setSettings(test::awakeSettings({0.0, 0.0}));
    BodyDef d;
    d.shape = makeBox(1.0, 0.25);
    d.collides = false;
    const BodyId chassis = world.createBody(d);
    d.shape = makeCircle(0.3);
    d.position = {0.7, -0.6};
    const BodyId wheel = world.createBody(d);
    WheelJointDef def;
    def.bodyA = chassis;
    def.bodyB = wheel;
    def.anchor = {0.7, -0.5};  // 0.1 m off the wheel's centre: its rows turn it too
    def.axis = {0.2, 1.0};
    def.hertz = 3.0;
    def.enableMotor = true;
    def.motorSpeed = -8.0;
    def.maxMotorTorque = 0.3;
    world.createWheelJoint(def);
    const BodyId bodies[2] = {chassis, wheel};
    for (const BodyId id : bodies) {
        world.setAngularVelocity(id, 0.5);
        world.setVelocity(id, cross(0.5, world.centerOfMass(id)) + Vec2(0.0, id == wheel ? 1.0 : 0.0));
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
    // Exact but for rounding over 960 substeps.
    EXPECT_LT((momentum() - p0).norm(), 1e-12);
    EXPECT_NEAR(angularMomentum(), L0, 1e-10);
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

// The car: a 120 kg chassis on two 10 kg wheels of 0.3 m (wheel joints, 5 Hz springs, the rear motor
// capped at T), climbing a 10 degree slope of a static box at the default 40 Hz. The chassis collides with nothing
// (the wheels meet only the ground). Speeds come from displacements over each step (what a viewer measures).
struct Car {
    World world;
    BodyId chassis, rear, front;
    JointId drive;
    double slope = 10.0 * M_PI / 180.0, radius = 0.3;
    Vec2 along, normal;

    explicit Car(double maxTorque, double motorSpeed = -10.0) {
        world.setSettings(test::awakeSettings());
        along = {std::cos(slope), std::sin(slope)};
        normal = perp(along);
        test::addStaticBox(world, -0.5 * normal + 40.0 * along, 60.0, 0.5, slope);
        const Vec2 c = 2.0 * along + (radius + 0.71) * normal;
        BodyDef cd;
        cd.shape = makeBox(1.0, 0.25);
        cd.density = 120.0;  // 2 m x 0.5 m: 120 kg
        cd.position = c;
        cd.angle = slope;
        cd.collides = false;
        chassis = world.createBody(cd);
        BodyDef wd;
        wd.shape = makeCircle(radius);
        wd.density = 10.0 / (M_PI * radius * radius);
        BodyId wheels[2];
        JointId joints[2];
        for (int k = 0; k < 2; ++k) {
            wd.position = c + (k == 0 ? -0.7 : 0.7) * along - 0.7 * normal;
            wheels[k] = world.createBody(wd);
            WheelJointDef j;
            j.bodyA = chassis;
            j.bodyB = wheels[k];
            j.anchor = wd.position;
            j.axis = normal;
            j.hertz = 5.0;
            j.dampingRatio = 0.7;
            j.enableMotor = k == 0;
            j.motorSpeed = motorSpeed;  // rad/s, clockwise: uphill
            j.maxMotorTorque = maxTorque;
            joints[k] = world.createWheelJoint(j);
        }
        rear = wheels[0];
        front = wheels[1];
        drive = joints[0];
    }
};

// The car's run at `hz` (40: the default) from rest: the worst |omega r / v - 1| of the driven wheel from `from` s on, and the travel
// speed at `from` and at the end (from each step's displacements).
struct CarRun {
    double worstRoll = 0.0, speedFrom = 0.0, speedEnd = 0.0;
};

CarRun drive(Car& car, double from, double seconds, double hz = 40.0) {
    const double dt = 1.0 / hz;
    CarRun run;
    Vec2 p = car.world.position(car.chassis);
    double turned = car.world.angle(car.rear);
    const int first = static_cast<int>(std::lround(from / dt)), last = static_cast<int>(std::lround(seconds / dt));
    for (int i = 1; i <= last; ++i) {
        car.world.step(dt);
        const Vec2 now = car.world.position(car.chassis);
        const double angle = car.world.angle(car.rear);
        const double v = (now - p).dot(car.along) / dt, wr = -(angle - turned) / dt * car.radius;
        p = now;
        turned = angle;
        if (i >= first) run.worstRoll = std::max(run.worstRoll, std::abs(wr / v - 1.0));
        if (i == first) run.speedFrom = v;
        run.speedEnd = v;
    }
    return run;
}

// Rolling uphill under the motor's cap T: a = (T / r - M g sin(slope)) / (M + 2 I / r^2), M the car's mass and I
// a wheel's, while the rear tyre's friction allows T / r (here 267 N against 0.4 x its ~700 N load).
TEST(WheelJoint, CarClimbsTheSlopeWithItsDrivenWheelRolling) {
    const double T = 80.0;
    Car car(T);
    const double M = car.world.mass(car.chassis) + car.world.mass(car.rear) + car.world.mass(car.front);
    const double I = car.world.inertia(car.rear), r = car.radius;
    const double a = (T / r - M * 9.81 * std::sin(car.slope)) / (M + 2.0 * I / (r * r));  // 0.188 m/s^2
    // From 2 s (the suspension settled) to 8 s: 0.36 to 1.5 m/s.
    const CarRun run = drive(car, 2.0, 8.0);
    // The bar, omega r within 1% of the travel speed (measured: 0.29% at 1.5 m/s, the contacts' creep).
    EXPECT_LT(run.worstRoll, 0.01);
    // The acceleration (measured: 1.3% above; 0.25% at 240 Hz): the same per-step contact geometry, within 2%.
    EXPECT_NEAR((run.speedEnd - run.speedFrom) / 6.0 / a, 1.0, 0.02);
    EXPECT_NEAR(car.world.jointMotorTorque(car.drive), -T, 1e-9) << "the motor pulls at its cap throughout";
}

// Beyond 1.6 m/s, to 2.26 m/s by 12 s: the bar holds at the default 40 Hz as at 240 Hz. The contact rows
// measure the wheel's separation from its centre, not from its contact point, which turns with the wheel
// (r (1 - cos(omega dt)), 9 mm per step at 10 rad/s and 40 Hz) and made the wheel seem to lift within the step:
// its grip came and went, and it slipped 4% (src/core/RoundedRows.hpp).
TEST(WheelJoint, CarAboveTwoMetresPerSecondRollsAtFortyHz) {
    Car fine(80.0);
    // Measured 0.08% at 240 Hz.
    EXPECT_LT(drive(fine, 2.0, 12.0, 240.0).worstRoll, 0.01) << "the issue's bar, omega r within 1%, at 240 Hz";
    Car coarse(80.0);
    // Measured 0.07% by 12 s.
    const CarRun run = drive(coarse, 2.0, 12.0);
    EXPECT_LT(run.worstRoll, 0.01) << "the issue's bar at 40 Hz";
    EXPECT_GT(run.speedEnd, 2.0);
}

// The 4 m/s: with the motor's speed raised to 15 rad/s (4.5 m/s rolling), the same torque takes the car
// from 0.36 m/s at 2 s to 4.3 m/s by 23 s (a = 0.188 m/s^2, above), its driven wheel still rolling within 1% at
// 40 Hz (measured 0.07%; the tyre's friction allows the motor's 267 N at the ground, as above).
TEST(WheelJoint, CarRollsAtFortyHzToFourMetresPerSecond) {
    Car car(80.0, -15.0);
    const CarRun run = drive(car, 2.0, 23.0);
    EXPECT_GT(run.speedEnd, 3.9);
    EXPECT_LT(run.worstRoll, 0.01) << "the issue's bar at 40 Hz";
}

}  // namespace
}  // namespace physim
