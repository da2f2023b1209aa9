// Sensors (physim/core/Sensor.hpp): begin and end events with their times within the step, against the analytic
// times of the motion; a sensor never pushes; filters; destruction mid-overlap; bad input. 60 Hz, 8 substeps.

#include "physim/core/Collide.hpp"
#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;

WorldSettings noGravity() {
    WorldSettings s;
    s.gravity = Vec2::Zero();
    return s;
}

BodyId staticSensor(World& world, const Geometry& shape, const Vec2& at) {
    BodyDef d;
    d.type = BodyType::Static;
    d.position = at;
    d.shape = shape;
    d.isSensor = true;
    return world.createBody(d);
}

BodyId ball(World& world, const Vec2& at, const Vec2& velocity, double radius) {
    BodyDef d;
    d.position = at;
    d.velocity = velocity;
    d.shape = makeCircle(radius);
    return world.createBody(d);
}

// Events of a run with the world time at which each happened (the step's start plus its time within the step).
struct Timed {
    SensorEvent event;
    double at = 0.0;  // s
};
struct Log {
    std::vector<Timed> begin, end;
    void record(const World& world, double stepStart) {
        for (const SensorEvent& e : world.sensorEvents().begin) begin.push_back({e, stepStart + e.time});
        for (const SensorEvent& e : world.sensorEvents().end) end.push_back({e, stepStart + e.time});
    }
};

Log run(World& world, int steps, double dt = kDt) {
    Log log;
    for (int i = 0; i < steps; ++i) {
        world.step(dt);
        log.record(world, i * dt);
    }
    return log;
}

// The solver's semi-implicit Euler with substep h puts a body falling from rest at y0 on the parabola
// y(t) = y0 - g t^2 / 2 - g h t / 2 at every substep (v_k = k g h, y_k = y0 - g h^2 k (k + 1) / 2), the path the
// Sensors stage follows over each step. The time at which it has fallen by `drop`:
double substepFallTime(double drop, double g, double h) {
    const double b = 0.5 * g * h, a = 0.5 * g;
    return (-b + std::sqrt(b * b + 4.0 * a * drop)) / (2.0 * a);
}

TEST(Sensor, BallFallingThroughStaticBoxBeginsAndEndsAtTheAnalyticTimes) {
    World world;  // g = 9.81 down
    const double g = 9.81, h = kDt / 8.0, r = 0.1, y0 = 2.0, half = 0.25;
    const BodyId gate = staticSensor(world, makeBox(1.0, half), {0.0, 0.0});
    const BodyId b = ball(world, {0.0, y0}, Vec2::Zero(), r);
    const Log log = run(world, 60);
    ASSERT_EQ(log.begin.size(), 1u);
    ASSERT_EQ(log.end.size(), 1u);
    EXPECT_EQ(log.begin[0].event.sensorBody, gate);
    EXPECT_EQ(log.begin[0].event.visitorBody, b);
    EXPECT_EQ(log.begin[0].event.visitorShape, world.shapes(b).front());
    const double in = substepFallTime(y0 - r - half, g, h), out = substepFallTime(y0 + r + half, g, h);
    // The path the stage follows is the substeps' parabola exactly (constant force); what remains is the
    // advancement's stop within kSensorTolerance (1e-6 m at ~5 m/s: 2e-7 s) and rounding: 1e-6 s.
    EXPECT_NEAR(log.begin[0].at, in, 1e-6);
    EXPECT_NEAR(log.end[0].at, out, 1e-6);
    // Against the exact free fall sqrt(2 d / g): the integrator runs ahead by about h / 2 (1.0 ms here), no more
    // than one substep.
    EXPECT_NEAR(log.begin[0].at, std::sqrt(2.0 * (y0 - r - half) / g), h);
    EXPECT_NEAR(log.end[0].at, std::sqrt(2.0 * (y0 + r + half) / g), h);
    EXPECT_GE(log.begin[0].event.fraction, 0.0);
    EXPECT_LE(log.begin[0].event.fraction, 1.0);
    EXPECT_TRUE(world.sensorOverlaps(world.shapes(gate).front()).empty());
}

TEST(Sensor, NeverPushesItsVisitor) {
    // The same ball with and without a sensor in its way (and a dynamic sensor body beside it): the same motion,
    // bit for bit, since nothing the solver does depends on a sensor.
    auto trajectory = [](bool withSensors) {
        World world;
        const BodyId b = ball(world, {0.0, 2.0}, {0.3, 0.0}, 0.1);
        if (withSensors) {
            staticSensor(world, makeBox(1.0, 0.25), {0.0, 0.0});
            BodyDef d;  // a dynamic sensor the ball falls into
            d.position = {0.05, 1.0};
            d.shape = makeBox(0.3, 0.3);
            d.isSensor = true;
            d.useGravity = false;
            world.createBody(d);
        }
        BodyDef ground;
        ground.type = BodyType::Static;
        ground.position = {0.0, -1.0};
        ground.shape = makeBox(5.0, 0.1);
        world.createBody(ground);
        std::vector<Vec2> path;
        for (int i = 0; i < 90; ++i) {
            world.step(kDt);
            path.push_back(world.position(b));
        }
        return path;
    };
    const std::vector<Vec2> without = trajectory(false), with = trajectory(true);
    ASSERT_EQ(without.size(), with.size());
    for (std::size_t i = 0; i < with.size(); ++i) {
        EXPECT_EQ(with[i].x(), without[i].x()) << "step " << i;
        EXPECT_EQ(with[i].y(), without[i].y()) << "step " << i;
    }
}

TEST(Sensor, KinematicSensorSweepingOverBodiesReportsEachAtTheAnalyticTimes) {
    World world(noGravity());
    const double a = 0.25, b = 0.1, v = 2.0, x0 = -1.0;
    BodyDef k;
    k.type = BodyType::Kinematic;
    k.position = {x0, 0.0};
    k.velocity = {v, 0.0};
    k.shape = makeBox(a, a);
    k.isSensor = true;
    const BodyId sweeper = world.createBody(k);
    const std::vector<double> xs = {0.5, 1.0, 1.5};
    std::vector<BodyId> boxes;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        BodyDef d;
        d.type = i == 2 ? BodyType::Static : BodyType::Dynamic;  // a moving sensor sees static shapes too
        d.position = {xs[i], 0.0};
        d.shape = makeBox(b, b);
        boxes.push_back(world.createBody(d));
    }
    const Log log = run(world, 90);
    ASSERT_EQ(log.begin.size(), xs.size());
    ASSERT_EQ(log.end.size(), xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
        // Each list is in the order of the visitors' slots, and the boxes were made in order of x.
        EXPECT_EQ(log.begin[i].event.visitorBody, boxes[i]);
        EXPECT_EQ(log.begin[i].event.sensorBody, sweeper);
        // A kinematic body moves at constant velocity, so its path is exact: what remains is the advancement's
        // stop within kSensorTolerance (1e-6 m at 2 m/s: 5e-7 s).
        EXPECT_NEAR(log.begin[i].at, (xs[i] - b - a - x0) / v, 1e-6) << i;
        EXPECT_NEAR(log.end[i].at, (xs[i] + b + a - x0) / v, 1e-6) << i;
        // Nothing pushed: the boxes are where they were made.
        EXPECT_EQ(world.position(boxes[i]).x(), xs[i]);
        EXPECT_EQ(world.position(boxes[i]).y(), 0.0);
    }
}

TEST(Sensor, FastBulletCrossingThinGateInOneStepIsReportedWithEntryAndExitTimes) {
    for (const CollisionDetection mode : {CollisionDetection::Discrete, CollisionDetection::ContinuousExact}) {
        World world(noGravity());
        const double r = 0.05, v = 200.0, x0 = 0.2, gateX = 1.0, half = 0.01;
        staticSensor(world, makeBox(half, 1.0), {gateX, 0.0});
        BodyDef d;
        d.position = {x0, 0.0};
        d.velocity = {v, 0.0};
        d.shape = makeCircle(r);
        d.collisionDetection = mode;
        const BodyId bullet = world.createBody(d);
        world.step(kDt);  // the bullet moves 3.3 m: from before the gate to far past it
        const SensorEvents& e = world.sensorEvents();
        ASSERT_EQ(e.begin.size(), 1u);
        ASSERT_EQ(e.end.size(), 1u);
        // Constant velocity: exact path; the advancement stops within kSensorTolerance (1e-6 m / 200 m/s = 5e-9 s).
        EXPECT_NEAR(e.begin[0].time, (gateX - half - r - x0) / v, 1e-8);
        EXPECT_NEAR(e.end[0].time, (gateX + half + r - x0) / v, 1e-8);
        EXPECT_NEAR(e.begin[0].fraction * kDt, e.begin[0].time, 1e-15);
        // The gate stopped nothing, continuous detection included.
        EXPECT_NEAR(world.position(bullet).x(), x0 + v * kDt, 1e-12);
        EXPECT_EQ(world.velocity(bullet).x(), v);
    }
}

TEST(Sensor, FiltersDecideWhatASensorSeesAndSensorsDoNotSeeSensors) {
    World world(noGravity());
    BodyDef s;
    s.type = BodyType::Static;
    s.shape = makeBox(1.0, 1.0);
    s.isSensor = true;
    s.filter.maskBits = 1;  // sees category 1 only
    const BodyId gate = world.createBody(s);
    BodyDef grouped = s;  // inside the first: sensors do not see sensors
    grouped.filter.groupIndex = -3;
    grouped.position = {0.5, 0.0};
    grouped.shape = makeBox(0.2, 0.2);
    const BodyId groupedGate = world.createBody(grouped);
    auto visitor = [&](double x, std::uint64_t category, std::int32_t group) {
        BodyDef d;
        d.position = {x, 0.0};
        d.shape = makeCircle(0.1);
        d.filter.categoryBits = category;
        d.filter.groupIndex = group;
        return world.createBody(d);
    };
    const BodyId plain = visitor(-0.5, 1, 0);
    visitor(0.0, 2, 0);                             // not in the gate's mask
    const BodyId inGroup = visitor(0.5, 1, -3);     // seen by the gate; its shared negative group hides it from the other
    BodyDef still;                                  // static: a static sensor does not see it
    still.type = BodyType::Static;
    still.position = {-0.2, 0.5};
    still.shape = makeBox(0.1, 0.1);
    world.createBody(still);
    world.step(kDt);
    const SensorEvents& e = world.sensorEvents();
    ASSERT_EQ(e.begin.size(), 2u);
    EXPECT_EQ(e.begin[0].sensorBody, gate);
    EXPECT_EQ(e.begin[0].visitorBody, plain);
    EXPECT_EQ(e.begin[0].fraction, 0.0);  // inside from the start
    EXPECT_EQ(e.begin[1].sensorBody, gate);
    EXPECT_EQ(e.begin[1].visitorBody, inGroup);
    EXPECT_TRUE(world.sensorOverlaps(world.shapes(groupedGate).front()).empty());
    EXPECT_EQ(world.sensorOverlaps(world.shapes(gate).front()).size(), 2u);
    // A visitor that stops being seen without moving (its body stops colliding) ends at fraction 0.
    world.setCollides(plain, false);
    world.step(kDt);
    ASSERT_EQ(world.sensorEvents().end.size(), 1u);
    EXPECT_EQ(world.sensorEvents().end[0].visitorBody, plain);
    EXPECT_EQ(world.sensorEvents().end[0].fraction, 0.0);
}

TEST(Sensor, DestroyingTheVisitorOrTheSensorMidOverlapEndsItSilently) {
    World world(noGravity());
    const BodyId gate = staticSensor(world, makeBox(1.0, 1.0), {0.0, 0.0});
    const BodyId a = ball(world, {0.0, 0.0}, Vec2::Zero(), 0.1);
    const BodyId b = ball(world, {0.5, 0.0}, Vec2::Zero(), 0.1);
    world.step(kDt);
    EXPECT_EQ(world.sensorEvents().begin.size(), 2u);
    EXPECT_EQ(world.sensorCount(), 1u);
    world.destroyBody(a);  // no end event: the id is gone, as a destroyed body's contacts end without events
    world.step(kDt);
    EXPECT_TRUE(world.sensorEvents().end.empty());
    ASSERT_EQ(world.sensorOverlaps(world.shapes(gate).front()).size(), 1u);
    EXPECT_EQ(world.sensorOverlaps(world.shapes(gate).front())[0], world.shapes(b).front());
    // A new body in the freed slot is a new visitor: it begins.
    const BodyId c = ball(world, {-0.5, 0.0}, Vec2::Zero(), 0.1);
    world.step(kDt);
    ASSERT_EQ(world.sensorEvents().begin.size(), 1u);
    EXPECT_EQ(world.sensorEvents().begin[0].visitorBody, c);
    world.destroyBody(gate);
    EXPECT_EQ(world.sensorCount(), 0u);
    world.step(kDt);
    EXPECT_TRUE(world.sensorEvents().begin.empty());
    EXPECT_TRUE(world.sensorEvents().end.empty());
    EXPECT_FALSE(world.profile().didRun(Stage::Sensors));  // no sensor: the stage costs nothing
}

TEST(Sensor, SetSensorTurnsAShapeIntoASensorAndBack) {
    World world;
    BodyDef floor;
    floor.type = BodyType::Static;
    floor.shape = makeBox(2.0, 0.1);
    const BodyId ground = world.createBody(floor);
    const BodyId b = ball(world, {0.0, 0.2}, Vec2::Zero(), 0.1);
    for (int i = 0; i < 30; ++i) world.step(kDt);
    EXPECT_NEAR(world.position(b).y(), 0.2, 0.01);  // resting on the floor
    const ShapeId floorShape = world.shapes(ground).front();
    world.setSensor(floorShape, true);
    EXPECT_TRUE(world.isSensor(floorShape));
    world.step(kDt);
    EXPECT_EQ(world.sensorEvents().begin.size(), 1u);  // the ball, inside it from the start of the step
    for (int i = 0; i < 30; ++i) world.step(kDt);
    EXPECT_LT(world.position(b).y(), -0.5);  // fell through
    // A ball sinking into the sensor floor: made solid again, the floor pushes it back out and holds it.
    const BodyId c = ball(world, {1.0, 0.2}, Vec2::Zero(), 0.1);
    for (int i = 0; i < 5; ++i) world.step(kDt);
    EXPECT_LT(world.position(c).y(), 0.2 - 0.01);
    world.setSensor(floorShape, false);
    EXPECT_EQ(world.sensorCount(), 0u);
    EXPECT_FALSE(world.isSensor(floorShape));
    for (int i = 0; i < 60; ++i) world.step(kDt);
    EXPECT_NEAR(world.position(c).y(), 0.2, 0.01);
}

TEST(Sensor, BadInputIsRefusedNamingTheValueAndTheWorldIsUnchanged) {
    World world(noGravity());
    const BodyId gate = staticSensor(world, makeBox(1.0, 1.0), {0.0, 0.0});
    const BodyId b = ball(world, {3.0, 0.0}, Vec2::Zero(), 0.1);
    const ShapeId plain = world.shapes(b).front();
    const ShapeId sensor = world.shapes(gate).front();
    world.destroyBody(gate);
    const std::size_t shapes = world.shapeCount();
    for (auto call : {+[](World& w, ShapeId id) { w.setSensor(id, false); },
                      +[](World& w, ShapeId id) { (void)w.isSensor(id); },
                      +[](World& w, ShapeId id) { (void)w.sensorOverlaps(id); }}) {
        try {
            call(world, sensor);
            ADD_FAILURE() << "a destroyed sensor was accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("index " + std::to_string(sensor.index)), std::string::npos)
                << e.what();
        }
    }
    try {
        (void)world.sensorOverlaps(plain);
        ADD_FAILURE() << "a shape that is no sensor was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("not a sensor"), std::string::npos) << e.what();
    }
    EXPECT_EQ(world.shapeCount(), shapes);
    EXPECT_EQ(world.sensorCount(), 0u);
    EXPECT_FALSE(world.isSensor(plain));
}

// Kinematic visitors of every kind with area (and a segment), turning, cross static sensors of every kind along
// random lines at 2 to 60 m/s. A kinematic body moves along a straight line at constant speed and turn, so its pose
// at any time is known in closed form; the reference samples that motion 64 times a step and asks the narrow phase
// (collide(), not the distance code the stage walks with) whether the shapes touch. Every entry and exit must be
// reported, each within its sampling interval, widened by kSensorTolerance / speed (5e-7 s) and rounding.
TEST(Sensor, CrossingTimesMatchABruteForceSweepOverShapeKinds) {
    const std::vector<Geometry> sensors = {makeBox(0.3, 0.1, {0.0, 0.0}, 0.4), makeCircle(0.25),
                                           makeCapsule({-0.3, 0.0}, {0.3, 0.1}, 0.08),
                                           makeRoundedBox(0.2, 0.15, 0.05)};
    const std::vector<Geometry> visitors = {makeCircle(0.1), makeBox(0.15, 0.05),
                                            makeCapsule({-0.1, 0.0}, {0.1, 0.0}, 0.05),
                                            makeRoundedBox(0.1, 0.1, 0.03), makeSegment({-0.15, 0.0}, {0.15, 0.0})};
    std::mt19937 rng(54);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    constexpr int kSteps = 30, kSamples = 64;
    int crossings = 0;
    for (int trial = 0; trial < 60; ++trial) {
        World world(noGravity());
        const Geometry& sensorShape = sensors[trial % sensors.size()];
        const Geometry& visitorShape = visitors[(trial / sensors.size()) % visitors.size()];
        staticSensor(world, sensorShape, Vec2::Zero());
        const double heading = 2.0 * M_PI * u(rng), speed = 2.0 + 58.0 * u(rng) * u(rng);
        const Vec2 dir(std::cos(heading), std::sin(heading)), side(-dir.y(), dir.x());
        // Starts 0.5 s of travel away (at least 1 m), aimed within 0.2 m of the sensor's centre.
        const Vec2 start = -std::max(1.0, 0.5 * speed) * dir + (0.4 * u(rng) - 0.2) * side;
        const double spin = 6.0 * u(rng) - 3.0, angle0 = 2.0 * M_PI * u(rng);
        BodyDef k;
        k.type = BodyType::Kinematic;
        k.position = start;
        k.angle = angle0;
        k.velocity = speed * dir;
        k.angularVelocity = spin;
        k.shape = visitorShape;
        world.createBody(k);
        const Log log = run(world, kSteps);

        // The reference: touching at each sample time, and the intervals of the changes.
        const double dtSample = kDt / kSamples;
        auto touching = [&](double t) {
            const Transform xf{start + t * speed * dir, Rotation::fromAngle(angle0 + t * spin)};
            return collide(sensorShape, Transform{}, visitorShape, xf).pointCount > 0;
        };
        std::vector<std::pair<double, double>> entries, exits;  // (last sample before, first sample after)
        bool was = touching(0.0);
        ASSERT_FALSE(was);
        for (int j = 1; j <= kSteps * kSamples; ++j) {
            const bool is = touching(j * dtSample);
            if (is != was) (is ? entries : exits).emplace_back((j - 1) * dtSample, j * dtSample);
            was = is;
        }
        ASSERT_EQ(log.begin.size(), entries.size()) << "trial " << trial;
        ASSERT_EQ(log.end.size(), exits.size()) << "trial " << trial;
        const double slack = 1e-6;
        for (std::size_t i = 0; i < entries.size(); ++i) {
            EXPECT_GE(log.begin[i].at, entries[i].first - slack) << "trial " << trial;
            EXPECT_LE(log.begin[i].at, entries[i].second + slack) << "trial " << trial;
        }
        for (std::size_t i = 0; i < exits.size(); ++i) {
            EXPECT_GE(log.end[i].at, exits[i].first - slack) << "trial " << trial;
            EXPECT_LE(log.end[i].at, exits[i].second + slack) << "trial " << trial;
        }
        crossings += static_cast<int>(entries.size());
    }
    EXPECT_GE(crossings, 55);  // nearly every line crosses
}

}  // namespace
}  // namespace physim
