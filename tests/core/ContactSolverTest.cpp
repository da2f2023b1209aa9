// The contact rows' rotation-free form against the full rows: a row whose bodies cannot turn (zero inverse inertia,
// not spinning, so unturned since the step began) skips its angular terms. Those terms are products with zero there,
// so both forms must give the same impulses and velocities exactly, through solve and relax passes, speculative
// points, bounces and friction, on random rows. Exact comparison: the skipped terms add only zeros.

#include "ContactSolver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace physim {
namespace {

// A row between two rotation-locked bodies (B may be immovable), with random geometry, warm-start impulses and
// material; the normal mass matrix as prepareContact builds it for zero inverse inertia.
ContactConstraint randomLockedRow(std::mt19937& rng, bool immovableB) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    ContactConstraint c;
    c.indexA = 0;
    c.indexB = immovableB ? kNullIndex : 1;
    const double angle = 3.14159265358979 * u(rng);
    c.normal = {std::cos(angle), std::sin(angle)};
    c.invMassA = 1.0 + 0.5 * u(rng);
    c.invMassB = immovableB ? 0.0 : 1.0 + 0.9 * u(rng);
    c.invIA = c.invIB = 0.0;
    c.staticFriction = u(rng) > 0.0 ? 0.6 : 0.0;
    c.dynamicFriction = 0.5 * c.staticFriction;
    c.restitution = u(rng) > 0.0 ? 0.5 + 0.5 * u(rng) : 0.0;
    c.normalAcceleration = 10.0 * u(rng);
    c.sliding = u(rng) > 0.0;
    c.pointCount = u(rng) > -0.5 ? 2 : 1;
    for (int i = 0; i < c.pointCount; ++i) {
        ContactConstraintPoint& p = c.points[i];
        p.anchorA = {u(rng), u(rng)};
        p.anchorB = {u(rng), u(rng)};
        p.rnA = cross(p.anchorA, c.normal);
        p.rnB = cross(p.anchorB, c.normal);
        p.ndA = c.normal.dot(p.anchorA);
        p.ndB = c.normal.dot(p.anchorB);
        p.baseSeparation = 0.01 * u(rng) - (p.ndB - p.ndA);
        p.normalImpulse = u(rng) > 0.0 ? std::abs(u(rng)) : 0.0;  // some start at zero: they may bounce
        p.normalMass = 1.0 / (c.invMassA + c.invMassB);
    }
    c.tangentImpulse = 0.1 * u(rng);
    c.tangentMass = 1.0 / (c.invMassA + c.invMassB);
    c.frictionAnchorA = c.points[0].anchorA;
    c.frictionAnchorB = c.points[0].anchorB;
    c.rtA = cross(c.frictionAnchorA, perp(c.normal));
    c.rtB = cross(c.frictionAnchorB, perp(c.normal));
    const double lin = c.invMassA + c.invMassB;
    c.k11 = c.k22 = c.k12 = lin;  // no angular part: K is singular, so two points go one at a time...
    c.invDet = 0.0;
    if (c.pointCount == 2 && u(rng) > 0.0) {
        c.k12 = 0.5 * lin;  // ...or, to reach the block path too, a regular K (any K is the same in both forms)
        c.invDet = 1.0 / (c.k11 * c.k22 - c.k12 * c.k12);
    }
    return c;
}

TEST(ContactSolver, RowsWithoutTurningBodiesMatchTheFullRowsExactly) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int met = 0, slid = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const bool immovableB = trial % 4 == 0;
        ContactConstraint lean = randomLockedRow(rng, immovableB);
        ContactConstraint full = lean;
        lean.turns = false;
        full.turns = true;
        std::vector<SolverBody> leanStates(2), fullStates(2);
        for (int b = 0; b < 2; ++b) {
            leanStates[b].v = {3.0 * u(rng), 3.0 * u(rng)};
            leanStates[b].dp = {0.01 * u(rng), 0.01 * u(rng)};
        }
        fullStates = leanStates;
        ContactPass pass;
        pass.h = 1.0 / 480.0;
        pass.invH = 480.0;
        pass.softness = makeSoftness(120.0, 10.0, pass.h);
        pass.maxPushVelocity = 3.0;
        pass.restitutionThreshold = 1.0;
        pass.slipSpeed = 0.03;
        for (int sub = 0; sub < 4; ++sub) {
            pass.substep = sub;
            warmStartContacts(&lean, &lean + 1, leanStates.data());
            warmStartContacts(&full, &full + 1, fullStates.data());
            for (const bool bias : {true, false}) {
                pass.useBias = bias;
                solveContacts(&lean, &lean + 1, leanStates.data(), pass);
                solveContacts(&full, &full + 1, fullStates.data(), pass);
            }
        }
        for (int b = 0; b < 2; ++b) {
            EXPECT_EQ(leanStates[b].v.x(), fullStates[b].v.x()) << "trial " << trial << " body " << b;
            EXPECT_EQ(leanStates[b].v.y(), fullStates[b].v.y()) << "trial " << trial << " body " << b;
            EXPECT_EQ(fullStates[b].w, 0.0) << "a locked body turned, trial " << trial;
            EXPECT_EQ(leanStates[b].dp, fullStates[b].dp) << "trial " << trial;
        }
        for (int i = 0; i < lean.pointCount; ++i) {
            EXPECT_EQ(lean.points[i].normalImpulse, full.points[i].normalImpulse) << "trial " << trial;
            EXPECT_EQ(lean.points[i].maxNormalImpulse, full.points[i].maxNormalImpulse) << "trial " << trial;
            met += lean.points[i].engaged && lean.restitution > 0.0 ? 1 : 0;
        }
        EXPECT_EQ(lean.tangentImpulse, full.tangentImpulse) << "trial " << trial;
        EXPECT_EQ(lean.sliding, full.sliding) << "trial " << trial;
        slid += lean.sliding ? 1 : 0;
        if (::testing::Test::HasFailure()) break;
    }
    // The random rows reached the paths that matter: points meeting with restitution (the bounce path) and sliding
    // faces.
    EXPECT_GT(met, 100);
    EXPECT_GT(slid, 100);
}

}  // namespace
}  // namespace physim
