// Statistics and debug drawing's resting contacts, against hand-computed answers.

#include <physim/core/World.hpp>
#include "support/Scenes.hpp"
#include <physim/framework/DebugDraw.hpp>
#include "Stats.hpp"

#include <gtest/gtest.h>

namespace physim {
namespace {

// A 2 kg disc at (1, 3) moving at (3, 4) m/s and spinning at 2 rad/s: kinetic m v^2 / 2 + I w^2 / 2 with
// I = m r^2 / 2, potential m g y (g = 9.81 down, zero at the origin), momentum and angular momentum about the
// origin. The static ground adds none of them. 1e-12: a few roundings of numbers of order 10.
TEST(Stats, CountsBodiesAndSumsEnergy) {
    World world;
    test::addStaticBox(world, Vec2::Zero(), 5.0, 0.5);
    BodyDef disc;
    disc.shape = makeCircle(0.5);
    disc.position = {1.0, 3.0};
    disc.velocity = {3.0, 4.0};
    disc.angularVelocity = 2.0;
    const BodyId id = world.createBody(disc);
    world.setMass(id, 2.0);
    const WorldStats s = computeStats(world);
    EXPECT_EQ(s.bodies, 2u);
    EXPECT_EQ(s.awake, 1u);
    EXPECT_EQ(s.asleep, 0u);
    EXPECT_EQ(s.immovable, 1u);
    const double I = 0.5 * 2.0 * 0.25;
    EXPECT_NEAR(s.kinetic, 0.5 * 2.0 * 25.0 + 0.5 * I * 4.0, 1e-12);
    EXPECT_NEAR(s.potential, 2.0 * 9.81 * 3.0, 1e-12);
    EXPECT_NEAR(world.kineticEnergy(id), s.kinetic, 1e-12);
    // Momentum m v; angular momentum about the origin: x cross m v + I w = (1 * 8 - 3 * 6) + I * 2.
    EXPECT_NEAR(s.momentum.x(), 6.0, 1e-12);
    EXPECT_NEAR(s.momentum.y(), 8.0, 1e-12);
    EXPECT_NEAR(s.angularMomentum, (1.0 * 8.0 - 3.0 * 6.0) + I * 2.0, 1e-12);
    world.setAwake(id, false);
    EXPECT_EQ(computeStats(world).asleep, 1u);
}

TEST(Stats, StepTimesAverageTheLastSteps) {
    StepTimes times(2);
    StepProfile p;
    p.secondsOf(Stage::Solve) = 1.0;
    p.ran[static_cast<std::size_t>(Stage::Solve)] = true;
    times.record(p);
    p.secondsOf(Stage::Solve) = 3.0;
    times.record(p);
    EXPECT_DOUBLE_EQ(times.mean().secondsOf(Stage::Solve), 2.0);
    p.secondsOf(Stage::Solve) = 5.0;
    times.record(p);  // the first falls out of the window of 2
    EXPECT_DOUBLE_EQ(times.mean().secondsOf(Stage::Solve), 4.0);
    EXPECT_TRUE(times.mean().didRun(Stage::Solve));
    EXPECT_FALSE(times.mean().didRun(Stage::Continuous));
    EXPECT_NE(formatStats(WorldStats{}, times).find("solve"), std::string::npos);
    EXPECT_THROW(StepTimes(0), std::invalid_argument);
}

// A box that fell asleep on the ground: the world no longer lists its contact (World::contacts() holds awake
// bodies' only, from the step that puts them to sleep on), but debug drawing still finds it, with the same
// manifold the step had when the box was awake.
TEST(DebugDraw, RestingContactsOfSleepingBodies) {
    World world;
    test::addGround(world, 5.0);
    BodyDef box;
    box.shape = makeBox(0.5, 0.5);
    box.position = {0.0, 0.5};
    const BodyId id = world.createBody(box);
    world.step(1.0 / 60.0);
    ASSERT_EQ(world.contacts().size(), 1u);
    const Manifold awake = world.contacts().front();
    EXPECT_TRUE(restingContacts(world).empty()) << "awake contacts are the step's own";
    for (int i = 0; i < 120 && world.isAwake(id); ++i) world.step(1.0 / 60.0);
    ASSERT_FALSE(world.isAwake(id));
    EXPECT_TRUE(world.contacts().empty()) << "asleep, the world lists no contact for the pair";
    world.step(1.0 / 60.0);
    EXPECT_TRUE(world.contacts().empty()) << "and the step skips it";
    const std::vector<Manifold> resting = restingContacts(world);
    ASSERT_EQ(resting.size(), 1u);
    EXPECT_EQ(resting[0].pointCount, 2);
    EXPECT_EQ(resting[0].bodyA, awake.bodyA);
    EXPECT_EQ(resting[0].bodyB, awake.bodyB);
    EXPECT_LT((resting[0].normal - awake.normal).norm(), 1e-12) << "the normal points the same way";
    EXPECT_EQ(computeStats(world).restingContacts, 1u);
    EXPECT_EQ(computeStats(world).contacts, 0u);
}

}  // namespace
}  // namespace physim
