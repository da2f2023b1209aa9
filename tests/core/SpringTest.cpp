// Springs against their analytic answers: a mass on a Hooke spring (period, damped decay and frequency), two
// bodies on one spring (the reduced mass), torque from an off-centre anchor; the soft distance joint's static
// stretch and the soft rope's; lifetime and bad input.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace physim {
namespace {

constexpr double kG = 9.81;
constexpr double kDt = 1.0 / 60.0;

WorldSettings weightless() {
    WorldSettings s;
    s.gravity = Vec2::Zero();
    s.enableSleep = false;
    return s;
}

BodyId ball(World& world, const Vec2& at, double density = 1.0) {
    BodyDef d;
    d.shape = makeCircle(0.05);
    d.density = density;
    d.position = at;
    return world.createBody(d);
}

// Times at which x(t) crosses zero upwards, interpolated between steps.
template <class X>
std::vector<double> upCrossings(World& world, X x, double seconds) {
    std::vector<double> times;
    double last = x();
    for (int i = 1; i * kDt <= seconds; ++i) {
        world.step(kDt);
        const double now = x();
        if (last < 0.0 && now >= 0.0) times.push_back(i * kDt - kDt * now / (now - last));
        last = now;
    }
    return times;
}

// Symplectic Euler's frequency for x'' = -w^2 x at substep h: 2 asin(w h / 2) / h = w (1 + (w h)^2 / 24 + ...).
// Its period error is far below the 1e-4 the tests allow at these w h (the crossings are interpolated within a
// 1/60 s frame from a 1 s or longer period: error below 1e-5).

TEST(Spring, MassOnASpringToAPointOscillatesWithPeriodTwoPiRootMOverK) {
    World world(weightless());
    const BodyId b = ball(world, {0.3, 0.0});  // 0.3 m from its rest position: the spring is stretched
    const double m = world.mass(b);
    SpringJointDef s;
    s.bodyB = b;
    s.localAnchorA = {0.0, 0.0};  // a world point
    s.restLength = 0.0;
    s.stiffness = m * 4.0 * M_PI * M_PI;  // 1 Hz
    world.createSpringJoint(s);
    const auto times = upCrossings(world, [&] { return world.position(b).x(); }, 10.5);
    ASSERT_GE(times.size(), 10u);
    EXPECT_NEAR((times.back() - times.front()) / (times.size() - 1), 1.0, 1e-4);
    EXPECT_TRUE(world.profile().didRun(Effect::Springs));
    EXPECT_FALSE(world.profile().didRun(Stage::Solve)) << "a spring is a force, not a constraint row";
}

TEST(Spring, DampedSpringDecaysAsExpOfMinusCtOverTwoMAtTheDampedFrequency) {
    World world(weightless());
    const BodyId b = ball(world, {0.3, 0.0});
    const double m = world.mass(b);
    const double omega = 2.0 * M_PI * 2.0, zeta = 0.05;  // 2 Hz, 5% of critical
    SpringJointDef s;
    s.bodyB = b;
    s.restLength = 0.0;
    s.stiffness = m * omega * omega;
    s.damping = 2.0 * zeta * m * omega;
    world.createSpringJoint(s);
    // x(t) = A exp(-zeta w t) cos(w_d t + phi): successive maxima shrink by exp(-zeta w T_d), T_d = 2 pi / w_d.
    const double omegaD = omega * std::sqrt(1.0 - zeta * zeta);
    std::vector<double> peaks, peakTimes;
    double x0 = world.position(b).x(), x1 = x0;
    for (int i = 1; i * kDt <= 3.0; ++i) {
        world.step(kDt);
        const double x2 = world.position(b).x();
        if (i >= 2 && x1 > x0 && x1 >= x2) {
            // Parabola through the three samples: the peak's height and time.
            const double curvature = x0 - 2 * x1 + x2, offset = 0.5 * (x0 - x2) / curvature;
            peaks.push_back(x1 - 0.25 * (x0 - x2) * offset);
            peakTimes.push_back((i - 1 + offset) * kDt);
        }
        x0 = x1;
        x1 = x2;
    }
    ASSERT_GE(peaks.size(), 5u);
    const int n = static_cast<int>(peaks.size()) - 1;
    const double period = (peakTimes.back() - peakTimes.front()) / n;
    // Peak times from a parabola through 1/60 s samples of a 0.5 s period: 1e-3 covers that fit; the
    // integrator's own error (h w)^2 / 24 is 7e-6.
    EXPECT_NEAR(period / (2 * M_PI / omegaD), 1.0, 1e-3);
    // The decay per period: explicit damping at substep h is exact to first order in zeta w h (0.3%), and the
    // fitted peaks carry the same 1e-3.
    const double decay = std::pow(peaks.back() / peaks.front(), 1.0 / n);
    EXPECT_NEAR(decay / std::exp(-zeta * omega * 2 * M_PI / omegaD), 1.0, 5e-3);
}

TEST(Spring, TwoBodiesOscillateWithTheReducedMassAndKeepTheirMomentum) {
    World world(weightless());
    const BodyId a = ball(world, {-0.6, 0.0}, 1.0);
    const BodyId b = ball(world, {0.6, 0.0}, 3.0);
    const double ma = world.mass(a), mb = world.mass(b), mu = ma * mb / (ma + mb);
    SpringJointDef s;
    s.bodyA = a;
    s.bodyB = b;
    s.restLength = 1.0;  // stretched by 0.2 m
    s.stiffness = mu * 4.0 * M_PI * M_PI;  // 1 Hz for the reduced mass
    const JointId spring = world.createSpringJoint(s);
    EXPECT_EQ(world.jointType(spring), JointType::Spring);
    EXPECT_NEAR(world.jointLength(spring), 1.0, 0.0);
    const Vec2 centre0 = (ma * world.position(a) + mb * world.position(b)) / (ma + mb);
    const auto times = upCrossings(
        world, [&] { return world.position(b).x() - world.position(a).x() - 1.0; }, 10.5);
    ASSERT_GE(times.size(), 9u);
    EXPECT_NEAR((times.back() - times.front()) / (times.size() - 1), 1.0, 1e-4);
    const Vec2 momentum = ma * world.velocity(a) + mb * world.velocity(b);
    EXPECT_LT(momentum.norm(), 1e-12) << "the spring's force and reaction are equal and opposite";
    const Vec2 centre = (ma * world.position(a) + mb * world.position(b)) / (ma + mb);
    EXPECT_LT((centre - centre0).norm(), 1e-12);
}

TEST(Spring, OffCentreAnchorTurnsTheBody) {
    // A rod hung by one end on a spring to a point above it turns to hang below the anchor.
    WorldSettings settings;
    settings.enableSleep = false;
    World world(settings);
    BodyDef d;
    d.shape = makeBox(0.5, 0.05);
    d.drag.angular = 0.05;  // settles the swing
    d.drag.linear = 0.5;
    const BodyId rod = world.createBody(d);
    SpringJointDef s;
    s.bodyB = rod;
    s.localAnchorA = {0.5, 1.0};
    s.localAnchorB = {0.5, 0.0};  // its right end
    s.restLength = 0.5;
    s.stiffness = 200.0;
    s.damping = 2.0;
    const JointId spring = world.createSpringJoint(s);
    for (int i = 0; i < 1200; ++i) world.step(kDt);
    // At rest the centre of mass hangs straight below the anchor, the spring holding the weight: stretched by
    // m g / k below its rest length.
    const auto [top, end] = world.jointAnchors(spring);
    EXPECT_NEAR(top.x(), 0.5, 1e-12);
    EXPECT_NEAR(world.centerOfMass(rod).x(), 0.5, 1e-4);
    const double m = world.mass(rod);
    EXPECT_NEAR((top - end).norm(), 0.5 + m * kG / 200.0, 1e-4);
    EXPECT_NEAR(std::abs(std::remainder(world.angle(rod), M_PI)), M_PI / 2, 1e-3) << "the rod hangs vertically";
}

// A soft distance joint is a spring of `hertz` for the mass it holds: hanging still, it stretches by g / w^2.
TEST(SoftDistanceJoint, HangingMassStretchesByGOverOmegaSquared) {
    World world;
    BodyDef pivot;
    pivot.type = BodyType::Static;
    pivot.shape = makeCircle(0.01);
    const BodyId p = world.createBody(pivot);
    const BodyId b = ball(world, {0.0, -1.0});
    DistanceJointDef d;
    d.bodyA = p;
    d.bodyB = b;
    d.hertz = 3.0;
    d.dampingRatio = 1.0;
    world.createDistanceJoint(d);
    for (int i = 0; i < 300; ++i) world.step(kDt);
    const double omega = 2 * M_PI * 3.0;
    // The soft step's fixed point balances gravity at exactly this stretch (its spring is implicit, so there is
    // no substep error at rest); 1e-6 m covers what is left of the settling after 5 s at critical damping.
    EXPECT_NEAR(-world.position(b).y() - 1.0, kG / (omega * omega), 1e-6);
    EXPECT_FALSE(world.isAwake(b)) << "at rest it sleeps like any other joint";
}

// The soft rope: n links of a soft distance joint. Link j from the top holds the n - j + 1 balls below it; the
// top one pulls a ball against the fixed pivot (effective mass m), the others join two balls (m / 2), so the
// rope stretches by g / w^2 (n + 2 (1 + 2 + ... + n - 1)) = n^2 g / w^2.
TEST(SoftDistanceJoint, SoftRopeStretchesByNSquaredGOverOmegaSquared) {
    WorldSettings settings;
    settings.enableSleep = false;  // a creeping rope falls asleep 0.4% short of its rest (measured)
    World world(settings);
    BodyDef pivot;
    pivot.type = BodyType::Static;
    pivot.shape = makeCircle(0.01);
    BodyId previous = world.createBody(pivot);
    constexpr int n = 8;
    constexpr double link = 0.2, hertz = 10.0;
    BodyId last;
    for (int i = 1; i <= n; ++i) {
        BodyDef d;
        d.shape = makeCircle(0.05);
        d.position = {0.0, -link * i};
        d.collides = false;  // the balls touch nothing: the rope is its links
        last = world.createBody(d);
        DistanceJointDef j;
        j.bodyA = previous;
        j.bodyB = last;
        j.hertz = hertz;
        world.createDistanceJoint(j);
        previous = last;
    }
    for (int i = 0; i < 1200; ++i) world.step(kDt);
    const double omega = 2 * M_PI * hertz;
    // Exact at rest, as above; after 20 s the slowest mode has settled to 1e-12 m (measured).
    EXPECT_NEAR(-world.position(last).y() - n * link, n * n * kG / (omega * omega), 1e-9);
    EXPECT_FALSE(world.profile().didRun(Stage::BroadPhase)) << "bodies that collide with nothing";
}

TEST(Spring, LifetimeAndBadInput) {
    World world(weightless());
    const BodyId a = ball(world, {0.0, 0.0});
    const BodyId b = ball(world, {1.0, 0.0});
    BodyDef still;
    still.type = BodyType::Static;
    const BodyId wall = world.createBody(still);
    SpringJointDef s;
    s.bodyA = a;
    s.bodyB = b;
    s.stiffness = 10.0;
    const JointId spring = world.createSpringJoint(s);
    EXPECT_NEAR(world.jointLength(spring), 1.0, 1e-12) << "rest length from the anchors";
    auto expectBad = [&](SpringJointDef bad, const char* name) {
        try {
            world.createSpringJoint(bad);
            ADD_FAILURE() << "accepted " << name;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
        }
    };
    SpringJointDef bad = s;
    bad.stiffness = 0.0;
    expectBad(bad, "stiffness");
    bad = s;
    bad.damping = -1.0;
    expectBad(bad, "damping");
    bad = s;
    bad.localAnchorB = {NAN, 0.0};
    expectBad(bad, "anchor B");
    bad = s;
    bad.restLength = INFINITY;
    expectBad(bad, "restLength");
    bad = s;
    bad.bodyA = b;
    expectBad(bad, "two different bodies");
    bad = s;
    bad.bodyB = wall;
    bad.bodyA = BodyId{};
    expectBad(bad, "dynamic body");
    world.step(kDt);
    EXPECT_TRUE(world.profile().didRun(Effect::Springs));
    world.destroyBody(a);  // the spring goes with it
    EXPECT_FALSE(world.contains(spring));
    EXPECT_EQ(world.jointCount(), 0u);
    world.step(kDt);
    EXPECT_FALSE(world.profile().didRun(Effect::Springs)) << "no spring left";
}

}  // namespace
}  // namespace physim
