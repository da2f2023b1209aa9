// Contact forces a user reads (ContactPoint::normalImpulse, tangentImpulse): each point's impulse over the whole
// step, so impulse / dt is the mean force. Checked against statics (a resting box carries m g, a stack's bottom
// contact the stack's weight), Coulomb's kinetic friction (mu m g while a box slides) and momentum balance across
// a bounce; a sleeping box's contact keeps its last step's values.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kG = 9.81;

BodyId addGround(World& world, double friction = 0.6, double restitution = 0.0) {
    BodyDef g;
    g.type = BodyType::Static;
    g.shape = makeBox(20.0, 0.5);
    g.position = {0.0, -0.5};  // top face at y = 0
    g.staticFriction = g.dynamicFriction = friction;
    g.restitution = restitution;
    return world.createBody(g);
}

BodyId addBox(World& world, Vec2 at, double friction = 0.6) {
    BodyDef b;
    b.shape = makeBox(0.5, 0.5);  // 1 m, 1 kg
    b.position = at;
    b.staticFriction = b.dynamicFriction = friction;
    return world.createBody(b);
}

// The normal and tangent impulses of a manifold's points, summed, N s.
double normalSum(const Manifold& m) {
    double sum = 0.0;
    for (int p = 0; p < m.pointCount; ++p) sum += m.points[p].normalImpulse;
    return sum;
}
double tangentSum(const Manifold& m) {
    double sum = 0.0;
    for (int p = 0; p < m.pointCount; ++p) sum += m.points[p].tangentImpulse;
    return sum;
}

// The listed contact between bodies a and b (either order); fails the test if there is none.
Manifold contactBetween(const std::vector<Manifold>& list, BodyId a, BodyId b) {
    for (const Manifold& m : list)
        if ((m.bodyA == a && m.bodyB == b) || (m.bodyA == b && m.bodyB == a)) return m;
    ADD_FAILURE() << "no contact between bodies " << a.index << " and " << b.index;
    return Manifold{};
}

// A 1 kg box settled on the ground: its points' impulses over the step sum to m g dt whatever the substeps and
// passes (before, they held the last substep's, m g dt / substeps). 1e-9 relative: once settled, each substep's
// impulse is m g h to rounding (the soft contact's settling decays by orders of magnitude per second, and after 5 s
// what is left moves the box by far less than a nanometre per second); the sum of 8 rounded terms is off by a few
// 1e-16 relative, so 1e-9 leaves room for any remaining settling and no room for a lost substep (1/8 off).
TEST(ContactForce, RestingBoxCarriesItsWeightAtAnySubsteps) {
    for (const int substeps : {1, 4, 8})
        for (const int relax : {0, 1, 2}) {
            WorldSettings s;
            s.enableSleep = false;
            s.substeps = substeps;
            s.relaxIterations = relax;
            World world(s);
            const BodyId ground = addGround(world);
            const BodyId box = addBox(world, {0.0, 0.5});
            for (int i = 0; i < 300; ++i) world.step(kDt);
            const Manifold m = contactBetween(world.contacts(), ground, box);
            ASSERT_EQ(m.pointCount, 2);
            const double weight = world.mass(box) * kG;
            EXPECT_NEAR(normalSum(m) / kDt, weight, 1e-9 * weight) << substeps << " substeps, " << relax << " relax";
            // Balanced on a flat face, the two corners carry half each (the box is symmetric): 1e-3 relative, as
            // the sum is exact but the split is the solver's, which takes the corners one at a time (first one,
            // then the other, by substep) and leaves them unequal by up to 1e-4 of the weight (measured).
            EXPECT_NEAR(m.points[0].normalImpulse / kDt, weight / 2, 1e-3 * weight);
            EXPECT_NEAR(tangentSum(m), 0.0, 1e-9 * weight * kDt) << "no friction at rest on level ground";
        }
}

// A box that fell asleep on the ground keeps reporting the weight from the last step that solved its contact:
// World::contacts() lists awake bodies' contacts only, World::sleepingContacts() the rest. 1e-6 relative: the box
// falls asleep once its speed stayed under the sleep threshold a while, not when it is at rest to rounding, so the
// last step's impulse still holds what is left of the settling (measured near 1e-12).
TEST(ContactForce, SleepingBoxStillReportsItsWeight) {
    World world;
    const BodyId ground = addGround(world);
    const BodyId box = addBox(world, {0.0, 0.5});
    int steps = 0;
    while (world.isAwake(box) && steps < 600) {
        world.step(kDt);
        ++steps;
    }
    ASSERT_FALSE(world.isAwake(box)) << "the box did not fall asleep in 10 s";
    world.step(kDt);  // a step that skips the sleeping pair
    EXPECT_TRUE(world.contacts().empty());
    const std::vector<Manifold> sleeping = world.sleepingContacts();
    ASSERT_EQ(sleeping.size(), 1u);
    const Manifold m = contactBetween(sleeping, ground, box);
    ASSERT_EQ(m.pointCount, 2);
    const double weight = world.mass(box) * kG;
    EXPECT_NEAR(normalSum(m) / kDt, weight, 1e-6 * weight);
    world.setVelocity(box, {0.0, 0.0});  // wakes it: its contact is the step's again, and leaves sleepingContacts
    world.step(kDt);
    EXPECT_TRUE(world.sleepingContacts().empty());
    EXPECT_NEAR(normalSum(contactBetween(world.contacts(), ground, box)) / kDt, weight, 1e-6 * weight);
}

// A box sliding on level ground with friction coefficient mu (static = dynamic, so the sticking bound never
// differs): Coulomb's kinetic friction is mu N = mu m g against the motion, so every step while it slides the
// friction impulse over the step is -mu m g dt along the motion, and the box's speed falls by mu g dt. Checked
// from the slide's second half second on: friction's torque about the centre first pitches the box a little onto
// its front corner, a transient that leaves the load off m g by 1e-5 at first and decays by 1e-8 in 20 steps.
// Then 1e-9 relative: each substep's friction impulse sits on its bound mu N_k, and the N_k sum to m g dt to
// rounding as at rest (the box's normal speed stays zero).
TEST(ContactForce, SlidingBoxFeelsKineticFriction) {
    constexpr double mu = 0.3;
    WorldSettings s;
    s.enableSleep = false;
    World world(s);
    const BodyId ground = addGround(world, mu);
    const BodyId box = addBox(world, {0.0, 0.5}, mu);
    for (int i = 0; i < 120; ++i) world.step(kDt);  // settle at rest first
    world.setVelocity(box, {4.0, 0.0});             // slides 4 / (mu g) = 1.36 s
    const double weight = world.mass(box) * kG;
    for (int i = 0; i < 30; ++i) world.step(kDt);
    int checked = 0;
    for (int i = 30; i < 60; ++i) {  // still sliding after a second (4 - mu g t > 1 m/s)
        const double before = world.velocity(box).x();
        world.step(kDt);
        const Manifold m = contactBetween(world.contacts(), ground, box);
        // The tangent is perp(normal) = (-ny, nx), on body B; the friction on the box points against +x.
        const double sign = m.bodyB == box ? 1.0 : -1.0;
        const double along = sign * tangentSum(m) * -m.normal.y();  // the box's friction impulse along +x
        EXPECT_NEAR(along / kDt, -mu * weight, 1e-9 * weight) << "step " << i;
        EXPECT_NEAR(normalSum(m) / kDt, weight, 1e-9 * weight) << "step " << i;
        // Momentum: the box's speed changes by its friction impulse / m (nothing else acts along x).
        EXPECT_NEAR(world.velocity(box).x() - before, along / world.mass(box), 1e-12) << "step " << i;
        ++checked;
    }
    EXPECT_EQ(checked, 30);
}

// A joint-free stack of five 1 kg boxes settled on the ground: the ground's contact carries the whole stack, 5 m g,
// and the contact under box k the boxes above it and itself. 1e-6 relative: a stack's soft contacts settle more
// slowly than one box's (each contact's push-out is shared with its neighbours), so after 10 s a little of the
// settling is still in the impulses, far below the one box's share (20%) that a wrong sum would lose.
TEST(ContactForce, StackBottomCarriesTheWholeStack) {
    WorldSettings s;
    s.enableSleep = false;
    World world(s);
    const BodyId ground = addGround(world);
    std::vector<BodyId> boxes;
    for (int k = 0; k < 5; ++k) boxes.push_back(addBox(world, {0.0, 0.5 + 1.0 * k}));
    for (int i = 0; i < 600; ++i) world.step(kDt);
    const double weight = world.mass(boxes[0]) * kG;
    EXPECT_NEAR(normalSum(contactBetween(world.contacts(), ground, boxes[0])) / kDt, 5 * weight, 1e-6 * 5 * weight);
    for (int k = 1; k < 5; ++k) {
        const double carried = (5 - k) * weight;
        EXPECT_NEAR(normalSum(contactBetween(world.contacts(), boxes[k - 1], boxes[k])) / kDt, carried,
                    1e-6 * carried)
            << "under box " << k;
    }
}

// A ball dropped with restitution bounces within one step, by a blow the solver deals outside its rows'
// accumulated impulses. The step's normal impulse is still all the momentum the contact passed: every step,
// m (v1 - v0) = m g dt + J n for the ball (a circle: nothing turns it), bounce steps included. 1e-9 N s: rounding of
// a few N s of momentum.
TEST(ContactForce, ImpulseBalancesMomentumThroughBounces) {
    for (const int substeps : {1, 4, 8}) {
        WorldSettings s;
        s.enableSleep = false;
        s.substeps = substeps;
        World world(s);
        const BodyId ground = addGround(world, 0.6, 0.7);  // a pair's restitution is the smaller of the two
        BodyDef b;
        b.shape = makeCircle(0.25);
        b.position = {0.0, 2.0};
        b.restitution = 0.7;
        const BodyId ball = world.createBody(b);
        const double m = world.mass(ball);
        int touching = 0, bounces = 0;
        double largest = 0.0;
        for (int i = 0; i < 240; ++i) {
            const Vec2 before = world.velocity(ball);
            world.step(kDt);
            Vec2 impulse = Vec2::Zero();  // on the ball
            for (const Manifold& c : world.contacts()) {
                if (c.bodyA != ball && c.bodyB != ball) continue;
                const double sign = c.bodyB == ball ? 1.0 : -1.0;
                impulse += sign * normalSum(c) * c.normal;
                ++touching;
            }
            largest = std::max(largest, impulse.norm());
            if (before.y() < -1.0 && world.velocity(ball).y() > 1.0) ++bounces;  // past the 1 m/s threshold
            const Vec2 change = m * (world.velocity(ball) - before);
            EXPECT_NEAR(change.y(), -m * kG * kDt + impulse.y(), 1e-9) << substeps << " substeps, step " << i;
            EXPECT_NEAR(change.x(), impulse.x(), 1e-9);
        }
        EXPECT_GT(touching, 10) << "the ball bounced and came to rest";
        EXPECT_GT(largest, 2.0 * m * kG * kDt) << "some step held a bounce, not only resting weight";
        EXPECT_GE(bounces, 3) << "the ball bounced (0.7 of its speed each time), it did not only land";
        (void)ground;
    }
}

}  // namespace
}  // namespace physim
