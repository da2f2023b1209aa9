// Distance joints: a pendulum against the exact period, the rod keeping its length, no energy gain, bad input.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace physim {
namespace {

constexpr double kG = 9.81;
constexpr double kDt = 1.0 / 60.0;

struct Pendulum {
    World world;
    BodyId pivot, bob;
    JointId rod;
};

// A point-like bob (5 cm disc, anchored at its centre so the rod exerts no torque on it) on a 1 m rod from a
// static pivot at the origin, released at rest `degrees` from the vertical.
void build(Pendulum& p, double degrees, double length = 1.0) {
    BodyDef pivot;
    pivot.type = BodyType::Static;
    pivot.shape = makeCircle(0.01);
    p.pivot = p.world.createBody(pivot);
    BodyDef bob;
    bob.shape = makeCircle(0.05);
    const double a = degrees * M_PI / 180.0;
    bob.position = {length * std::sin(a), -length * std::cos(a)};
    p.bob = p.world.createBody(bob);
    DistanceJointDef rod;
    rod.bodyA = p.pivot;
    rod.bodyB = p.bob;
    p.rod = p.world.createDistanceJoint(rod);  // length from the anchors: `length`
}

// Period from the times the bob crosses x = 0 moving right (linear interpolation between steps).
double measuredPeriod(Pendulum& p, int crossings) {
    std::vector<double> times;
    double t = 0.0, x = p.world.position(p.bob).x();
    while (static_cast<int>(times.size()) < crossings + 1 && t < 60.0) {
        p.world.step(kDt);
        t += kDt;
        const double nx = p.world.position(p.bob).x();
        if (x < 0.0 && nx >= 0.0) times.push_back(t - kDt * nx / (nx - x));
        x = nx;
    }
    return (times.back() - times.front()) / crossings;
}

// The exact period of a simple pendulum: T = 4 sqrt(L / g) K(sin(theta0 / 2)), K the complete elliptic
// integral of the first kind. Tolerance 0.1%: the integrator's 1/240 s substep is 0.2% of the period and
// symplectic Euler's phase error is of second order in it (measured: 7e-6 at 10 degrees up to 1.5e-4 at 150).
TEST(DistanceJoint, PendulumPeriodMatchesTheEllipticIntegral) {
    for (const double degrees : {10.0, 45.0, 90.0, 150.0}) {
        Pendulum p;
        build(p, degrees);
        const double exact = 4.0 * std::sqrt(1.0 / kG) * std::comp_ellint_1(std::sin(degrees * M_PI / 360.0));
        EXPECT_NEAR(measuredPeriod(p, 5) / exact, 1.0, 1e-3) << degrees << " degrees";
    }
}

TEST(DistanceJoint, RodKeepsItsLengthAndAddsNoEnergy) {
    Pendulum p;
    build(p, 90.0);
    const double m = p.world.mass(p.bob);
    auto energy = [&] {
        return 0.5 * m * p.world.velocity(p.bob).squaredNorm() + m * kG * p.world.position(p.bob).y();
    };
    const double e0 = energy();  // = 0: released at rest at the pivot's height
    double worstStretch = 0.0, worstEnergyError = 0.0;
    for (int i = 0; i < 1200; ++i) {  // 20 s, about 10 swings
        p.world.step(kDt);
        worstStretch = std::max(worstStretch, std::abs(p.world.position(p.bob).norm() - 1.0));
        worstEnergyError = std::max(worstEnergyError, std::abs(energy() - e0));
    }
    // The rod-wise speed target keeps the length to second order and the position pass removes the rest:
    // 1 mm is far below what a swing shows.
    EXPECT_LT(worstStretch, 1e-3);
    // Semi-implicit Euler is symplectic: its energy error oscillates with amplitude of order m g v h (v the
    // fastest speed, sqrt(2 g L), h the 1/240 s substep) and does not grow. The bound is that scale, over ten
    // swings (measured: 0.31 of it, no growth).
    const double h = kDt / WorldSettings{}.substeps;
    EXPECT_LT(worstEnergyError, m * kG * std::sqrt(2 * kG * 1.0) * h);
    EXPECT_TRUE(p.world.profile().didRun(Stage::Solve)) << "joints need the solve stage even without contacts";
}

TEST(DistanceJoint, BadInputAndLifetime) {
    Pendulum p;
    build(p, 30.0);
    DistanceJointDef d;
    d.bodyA = p.bob;
    d.bodyB = p.bob;
    EXPECT_THROW(p.world.createDistanceJoint(d), std::invalid_argument) << "same body";
    BodyDef wall;
    wall.type = BodyType::Static;
    wall.position = {3.0, 0.0};
    d.bodyA = p.pivot;
    d.bodyB = p.world.createBody(wall);
    EXPECT_THROW(p.world.createDistanceJoint(d), std::invalid_argument) << "two immovable bodies";
    d.bodyB = p.bob;
    d.localAnchorA = {NAN, 0.0};
    EXPECT_THROW(p.world.createDistanceJoint(d), std::invalid_argument);
    d.localAnchorA = Vec2::Zero();
    d.length = INFINITY;
    EXPECT_THROW(p.world.createDistanceJoint(d), std::invalid_argument);
    EXPECT_EQ(p.world.jointCount(), 1u);
    EXPECT_NEAR(p.world.jointLength(p.rod), 1.0, 1e-12);

    p.world.destroyBody(p.bob);  // the rod goes with it
    EXPECT_EQ(p.world.jointCount(), 0u);
    EXPECT_FALSE(p.world.contains(p.rod));
    EXPECT_THROW(p.world.jointLength(p.rod), std::invalid_argument);
}

TEST(DistanceJoint, HangingChainSleepsAndWakesWhole) {
    World world;
    BodyDef pivot;
    pivot.type = BodyType::Static;
    pivot.shape = makeCircle(0.01);
    BodyId previous = world.createBody(pivot);
    std::vector<BodyId> links;
    for (int i = 1; i <= 5; ++i) {
        BodyDef link;
        link.shape = makeCircle(0.04);
        link.position = {0.0, -0.1 * i};
        const BodyId id = world.createBody(link);
        DistanceJointDef d;
        d.bodyA = previous;
        d.bodyB = id;
        world.createDistanceJoint(d);
        links.push_back(id);
        previous = id;
    }
    for (int i = 0; i < 180; ++i) world.step(kDt);
    for (const BodyId id : links) EXPECT_FALSE(world.isAwake(id)) << "a still chain sleeps";
    world.setVelocity(links.back(), {1.0, 0.0});
    world.step(kDt);
    for (const BodyId id : links) EXPECT_TRUE(world.isAwake(id)) << "pushing its end wakes the whole chain";
    EXPECT_NEAR(world.position(links.back()).norm(), 0.5, 0.01);
}

}  // namespace
}  // namespace physim
