// Gravitation between bodies: a circular two-body orbit over 100 orbits (radius, energy, angular momentum),
// Barnes-Hut against direct summation on a random cluster, determinism across thread counts and lane builds,
// attracting bodies never sleeping; settings and bad input.

#include "physim/core/World.hpp"

#include "effects/BarnesHut.hpp"
#include "support/WideCodes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <random>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;

WorldSettings space(int threads = 1) {
    WorldSettings s;
    s.gravity = Vec2::Zero();
    s.threads = threads;
    return s;
}

struct Binary {
    World world{space()};
    BodyId a, b;
    double ma = 0.0, mb = 0.0, G = 1.0, r = 1.0;
};

// Two point-like bodies (collide = false) of masses 1 and 3 (kg, via density) a distance r apart, on the circular
// orbit about their centre of mass: relative speed sqrt(G (ma + mb) / r).
void build(Binary& s) {
    GravitationSettings g;
    g.G = s.G;
    s.world.setGravitation(g);
    BodyDef d;
    d.shape = makeCircle(0.01);
    d.collides = false;
    d.attracting = true;
    const double area = M_PI * 0.01 * 0.01;
    d.density = 1.0 / area;
    s.a = s.world.createBody(d);
    d.density = 3.0 / area;
    d.position = {s.r, 0.0};
    s.b = s.world.createBody(d);
    s.ma = s.world.mass(s.a);
    s.mb = s.world.mass(s.b);
    const double M = s.ma + s.mb, v = std::sqrt(s.G * M / s.r);
    // Centre of mass at rest: A moves down at v mb / M, B up at v ma / M.
    s.world.setVelocity(s.a, {0.0, -v * s.mb / M});
    s.world.setVelocity(s.b, {0.0, v * s.ma / M});
}

double energy(const Binary& s) {
    const double r = (s.world.position(s.b) - s.world.position(s.a)).norm();
    return 0.5 * s.ma * s.world.velocity(s.a).squaredNorm() + 0.5 * s.mb * s.world.velocity(s.b).squaredNorm() -
           s.G * s.ma * s.mb / r;
}

double angularMomentum(const Binary& s) {
    return s.ma * cross(s.world.position(s.a), s.world.velocity(s.a)) +
           s.mb * cross(s.world.position(s.b), s.world.velocity(s.b));
}

TEST(Gravitation, CircularTwoBodyOrbitStaysCircularForAHundredOrbits) {
    Binary s;
    build(s);
    const double omega = std::sqrt(s.G * (s.ma + s.mb) / (s.r * s.r * s.r));  // 2 rad/s: a period of pi s
    const double h = kDt / s.world.settings().substeps;
    const double e0 = energy(s), l0 = angularMomentum(s);
    const int steps = static_cast<int>(std::ceil(100 * 2 * M_PI / omega / kDt));
    double worstRadius = 0.0, worstEnergy = 0.0, worstMomentum = 0.0, firstEnergy = 0.0, lastEnergy = 0.0;
    for (int i = 0; i < steps; ++i) {
        s.world.step(kDt);
        const double r = (s.world.position(s.b) - s.world.position(s.a)).norm();
        const double dE = std::abs(energy(s) / e0 - 1.0);
        worstRadius = std::max(worstRadius, std::abs(r / s.r - 1.0));
        worstEnergy = std::max(worstEnergy, dE);
        worstMomentum = std::max(worstMomentum, std::abs(angularMomentum(s) / l0 - 1.0));
        if (i < steps / 10) firstEnergy = std::max(firstEnergy, dE);
        if (i >= steps - steps / 10) lastEnergy = std::max(lastEnergy, dE);
    }
    // Every substep is a symplectic Euler step of h = 1/480 s. For central pairwise forces it keeps the angular
    // momentum exactly (each kick is parallel to the separation, each drift parallel to the velocity): only
    // rounding is left, 1e-16 per substep over 150 000 substeps (measured 1.2e-14). Its energy error is bounded
    // and does not grow: of first order in omega h (4.2e-3 here) in general, but on a circular orbit the
    // first-order term (h / 2) p . grad V vanishes, leaving (omega h)^2 (measured 1.0 (omega h)^2). The orbit it
    // follows is the exact circle's neighbour of eccentricity of order omega h / 2 (measured radius error 2.1e-3).
    EXPECT_LT(worstMomentum, 1e-11);
    EXPECT_LT(worstEnergy, 2 * (omega * h) * (omega * h));
    EXPECT_LT(worstRadius, omega * h);
    EXPECT_LT(lastEnergy, 2.0 * firstEnergy + 1e-12) << "no drift: the last ten orbits' error is the first ten's";
    EXPECT_TRUE(s.world.profile().didRun(Effect::Gravitation));
    EXPECT_FALSE(s.world.profile().didRun(Stage::BroadPhase)) << "bodies that touch nothing";
    EXPECT_TRUE(s.world.isAwake(s.a)) << "attracting bodies never sleep";
}

TEST(Gravitation, MomentumIsKeptAndTheCentreOfMassDoesNotMove) {
    Binary s;
    build(s);
    for (int i = 0; i < 600; ++i) s.world.step(kDt);
    const Vec2 p = s.ma * s.world.velocity(s.a) + s.mb * s.world.velocity(s.b);
    EXPECT_LT(p.norm(), 1e-12);
}

// A random cluster: uniform in a disc of radius 1, masses in [0.5, 1.5].
void cluster(std::size_t n, std::vector<Vec2>& positions, std::vector<double>& masses, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    positions.clear();
    masses.clear();
    while (positions.size() < n) {
        const Vec2 p(2 * u(rng) - 1, 2 * u(rng) - 1);
        if (p.squaredNorm() > 1.0) continue;
        positions.push_back(p);
        masses.push_back(0.5 + u(rng));
    }
}

// Each body's error |a_tree - a_direct|, relative to its force (rel) and to the sum of the magnitudes of its pulls,
// sum_j |a_ij| (abs: the scale of the sum without its cancellations), both sorted.
struct TreeErrors {
    std::vector<double> rel, abs;
};

TreeErrors treeErrors(const std::vector<Vec2>& positions, const std::vector<double>& masses, double theta,
                      double eps2) {
    BarnesHutTree tree;
    tree.build(positions, masses);
    std::vector<Vec2> a;
    tree.accelerations(1.0, eps2, theta, a);
    TreeErrors e;
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const Vec2 exact = directAcceleration(positions, masses, i, 1.0, eps2);
        double scale = 0.0;
        for (std::size_t j = 0; j < positions.size(); ++j)
            if (j != i) scale += pull(positions[i], positions[j], masses[j], 1.0, eps2).norm();
        const double error = (a[i] - exact).norm();
        e.rel.push_back(error / exact.norm());
        e.abs.push_back(error / scale);
    }
    std::sort(e.rel.begin(), e.rel.end());
    std::sort(e.abs.begin(), e.abs.end());
    return e;
}

TEST(BarnesHut, ForcesMatchDirectSummationWithinTheOpeningAngleBound) {
    std::vector<Vec2> positions;
    std::vector<double> masses;
    cluster(2000, positions, masses, 7);
    const double eps2 = 1e-4;
    // One accepted cell of width s < theta r stands for masses spread over it; its monopole's first neglected
    // (quadrupole) term is at most about (s / r)^2 / 2 < theta^2 / 2 of that cell's pull, and the cells' errors
    // add at most linearly: each body's error stays below theta^2 / 2 of sum_j |a_ij|. A random cluster's cells
    // are nearly uniform (a uniform square has no quadrupole), so the test holds the tree to a quarter of that,
    // theta^2 / 8 (measured for 500 to 8000 bodies: at most 0.008 at theta 0.5, 0.0016 at 0.25; the groups' shared
    // test opens more cells than each body's own would). A tree that summed cells at their geometric centre
    // instead of their centre of mass would be off at first order.
    for (const double theta : {0.5, 0.25}) {
        const TreeErrors e = treeErrors(positions, masses, theta, eps2);
        EXPECT_LT(e.abs.back(), theta * theta / 8) << "theta " << theta;
    }
    // Relative to the net force (which cancels near the cluster's centre) the typical body is within 2% at
    // theta 0.5 (measured 0.53%), and halving theta shrinks that by more than the quadrupole's factor of 4.
    const TreeErrors half = treeErrors(positions, masses, 0.5, eps2);
    const TreeErrors quarter = treeErrors(positions, masses, 0.25, eps2);
    EXPECT_LT(half.rel[half.rel.size() / 2], 0.02);
    EXPECT_LT(quarter.rel[quarter.rel.size() / 2], half.rel[half.rel.size() / 2] / 4);
    const TreeErrors exact = treeErrors(positions, masses, 0.0, eps2);
    EXPECT_LT(exact.rel.back(), 1e-12) << "theta 0 opens every cell: the direct sum, in another order";
}

TEST(BarnesHut, CoincidentPointsAndTinyClusters) {
    std::vector<Vec2> positions(20, Vec2(1.0, 1.0));
    std::vector<double> masses(20, 1.0);
    positions.push_back({2.0, 1.0});
    masses.push_back(1.0);
    BarnesHutTree tree;
    tree.build(positions, masses);
    std::vector<Vec2> a;
    tree.accelerations(1.0, 0.0, 0.5, a);
    EXPECT_NEAR(a[20].x(), -20.0, 1e-12) << "20 unit masses 1 m away";
    EXPECT_EQ(a[0].y(), 0.0);
    EXPECT_NEAR(a[0].x(), 1.0, 1e-12) << "coincident, unsoftened: no NaN, only the far point pulls";
}

// The four-lane sums are built three times (Wide.hpp); each build gives every body the same bits.
TEST(BarnesHut, EveryBuildOfTheLanesGivesTheSameBits) {
    std::vector<Vec2> positions;
    std::vector<double> masses;
    cluster(1000, positions, masses, 5);
    BarnesHutTree tree;
    tree.build(positions, masses);
    std::vector<std::vector<Vec2>> results;
    for (const WideCode code : test::runnableWideCodes()) {
        std::vector<Vec2> a(positions.size(), Vec2::Constant(NAN));
        for (std::size_t g = 0; g < tree.groupCount(); ++g)
            tree.groupAccelerations(g, 1.0, 1e-4, 0.5, a.data() + tree.groupBegin(g), code);
        results.push_back(a);
    }
    for (const Vec2& a : results[0]) ASSERT_TRUE(std::isfinite(a.x()) && std::isfinite(a.y())) << "every body has one";
    for (std::size_t c = 1; c < results.size(); ++c)
        for (std::size_t k = 0; k < positions.size(); ++k) ASSERT_EQ(results[c][k], results[0][k]) << c << " " << k;
}

// The world picks the tree above GravitationSettings::directBelow; a run is the same for any thread count.
TEST(Gravitation, TreeRunIsTheSameOnAnyThreadCount) {
    std::vector<Vec2> positions;
    std::vector<double> masses;
    cluster(600, positions, masses, 3);
    auto run = [&](int threads, std::size_t directBelow) {
        World world(space(threads));
        GravitationSettings g;
        g.G = 1e-3;
        g.softening = 0.02;
        g.directBelow = directBelow;
        world.setGravitation(g);
        std::vector<BodyId> ids;
        for (std::size_t i = 0; i < positions.size(); ++i) {
            BodyDef d;
            d.shape = makeCircle(0.005);
            d.collides = false;
            d.attracting = true;
            d.density = masses[i] / (M_PI * 0.005 * 0.005);
            d.position = positions[i];
            ids.push_back(world.createBody(d));
        }
        for (int i = 0; i < 30; ++i) world.step(kDt);
        std::vector<Vec2> out;
        for (const BodyId id : ids) out.push_back(world.position(id));
        return out;
    };
    const auto tree1 = run(1, 256), tree4 = run(4, 256);
    for (std::size_t i = 0; i < tree1.size(); ++i) ASSERT_EQ(tree1[i], tree4[i]) << i;
    // Against the direct sum: the bodies' displacements over the half second differ by the tree's force error,
    // a few per cent of the typical force (measured: 0.53% median at theta 0.5; the ratio 0.3%).
    const auto direct = run(1, 100000);
    double deviation = 0.0, displacement = 0.0;
    for (std::size_t i = 0; i < tree1.size(); ++i) {
        deviation += (tree1[i] - direct[i]).squaredNorm();
        displacement += (direct[i] - positions[i]).squaredNorm();
    }
    std::printf("rms deviation / rms displacement %g\n", std::sqrt(deviation / displacement));
    EXPECT_LT(std::sqrt(deviation / displacement), 0.03);
    EXPECT_GT(deviation, 0.0) << "it did use the tree";
}

TEST(Gravitation, OneAttractingBodyRunsNoStageAndSettingsAreChecked) {
    World world(space());
    BodyDef d;
    d.attracting = true;
    const BodyId a = world.createBody(d);
    world.step(kDt);
    EXPECT_FALSE(world.profile().didRun(Effect::Gravitation)) << "it takes two";
    d.position = {3.0, 0.0};
    const BodyId b = world.createBody(d);
    EXPECT_EQ(world.attractingCount(), 2u);
    world.step(kDt);
    EXPECT_TRUE(world.profile().didRun(Effect::Gravitation));
    EXPECT_GT(world.velocity(a).x(), 0.0) << "pulled towards b";
    world.setAttracting(b, false);
    EXPECT_FALSE(world.attracting(b));
    world.step(kDt);
    EXPECT_FALSE(world.profile().didRun(Effect::Gravitation));
    world.setAttracting(b, true);
    world.destroyBody(b);
    EXPECT_EQ(world.attractingCount(), 1u);

    GravitationSettings g;
    g.G = -1.0;
    EXPECT_THROW(world.setGravitation(g), std::invalid_argument);
    g = {};
    g.softening = NAN;
    EXPECT_THROW(world.setGravitation(g), std::invalid_argument);
    g = {};
    g.theta = 1.5;
    EXPECT_THROW(world.setGravitation(g), std::invalid_argument);
    EXPECT_EQ(world.gravitation().G, GravitationSettings{}.G) << "refused settings change nothing";
}

}  // namespace
}  // namespace physim
