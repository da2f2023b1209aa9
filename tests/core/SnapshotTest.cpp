// Snapshots and restores (World::snapshot, World::restore, World::stateHash): a run restored to an earlier snapshot
// and stepped again gives, bit for bit, the states the first run had (equal state hashes, exact comparison: the
// step is deterministic, so anything short of identical bits is a state the snapshot missed). Checked on a scene
// that uses every kind of shape and joint, sleep and islands, sensors, filters and the pre-solve hook, drag,
// gravitation, force callbacks and continuous detection; on one and two threads; into another world.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "physim/core/World.hpp"
#include "support/EverythingScene.hpp"
#include "support/Scenes.hpp"

namespace physim {
namespace {

constexpr double kDt = 1.0 / 40.0;

void run(World& world, int steps) {
    for (int i = 0; i < steps; ++i) world.step(kDt);
}

WorldSettings sleepy(int threads) {
    WorldSettings s;
    s.enableSleep = true;
    s.threads = threads;
    return s;
}

// Takes a snapshot after `before` steps, runs `after` more, restores, runs `after` again: both hashes must agree,
// and must differ from the snapshot's (the scene moved).
void expectReplays(World& world, int before, int after) {
    run(world, before);
    const WorldSnapshot s = world.snapshot();
    EXPECT_EQ(s.stepCount(), static_cast<std::uint64_t>(before));
    EXPECT_EQ(s.stateHash(), world.stateHash());
    run(world, after);
    const std::uint64_t first = world.stateHash();
    EXPECT_NE(first, s.stateHash()) << "the scene stood still: the test would prove nothing";
    world.restore(s);
    EXPECT_EQ(world.stateHash(), s.stateHash());
    EXPECT_EQ(world.stepCount(), static_cast<std::uint64_t>(before));
    run(world, after);
    EXPECT_EQ(world.stateHash(), first);
}

TEST(Snapshot, RestoreReplaysTheDeterminismSceneBitForBit) {
    World world(test::awakeSettings());
    test::buildDeterminismScene(world);
    expectReplays(world, 150, 200);
}

TEST(Snapshot, RestoreReplaysEverythingBitForBit) {
    for (const int threads : {1, 2}) {
        World world(sleepy(threads));
        test::buildEverything(world);
        expectReplays(world, 60, 160);
    }
}

// One run straight through on one thread; another on two threads, restored midway into a third world on one
// thread: the same states, since results depend on neither the thread count nor which world holds them.
TEST(Snapshot, RestoreIntoAnotherWorldOnOtherThreads) {
    World straight(sleepy(1));
    test::buildEverything(straight);
    run(straight, 200);

    WorldSnapshot midway;
    {
        World first(sleepy(2));
        test::buildEverything(first);
        run(first, 80);
        midway = first.snapshot();
    }  // the snapshot outlives its world
    World second(sleepy(1));
    second.restore(midway);
    run(second, 120);
    EXPECT_EQ(second.stateHash(), straight.stateHash());
    EXPECT_EQ(second.bodyCount(), straight.bodyCount());
    EXPECT_EQ(second.jointCount(), straight.jointCount());
}

TEST(Snapshot, TheSnapshotNeverChanges) {
    World world(sleepy(1));
    test::buildEverything(world);
    run(world, 30);
    const WorldSnapshot s = world.snapshot();
    const WorldSnapshot copy = s;  // shares it
    const std::uint64_t hash = s.stateHash();
    run(world, 50);
    world.restore(s);
    run(world, 50);
    const std::uint64_t once = world.stateHash();
    world.restore(copy);
    EXPECT_EQ(world.stateHash(), hash);
    run(world, 50);
    EXPECT_EQ(world.stateHash(), once);
    EXPECT_GT(s.bytes(), world.bodyCount() * sizeof(double));
}

TEST(Snapshot, RestoreRefusesBadInputAndLeavesTheWorld) {
    World world(sleepy(1));
    test::buildEverything(world);
    run(world, 10);
    const std::uint64_t hash = world.stateHash();
    EXPECT_THROW(world.restore(WorldSnapshot{}), std::invalid_argument);
    EXPECT_EQ(world.stateHash(), hash);
    EXPECT_TRUE(WorldSnapshot{}.empty());
    EXPECT_EQ(WorldSnapshot{}.bytes(), 0u);

    const WorldSnapshot s = world.snapshot();
    bool threw = false;
    world.addForceCallback([&](World& w, double) {
        try {
            w.restore(s);
        } catch (const std::logic_error&) {
            threw = true;
        }
        EXPECT_THROW((void)w.snapshot(), std::logic_error);
    });
    world.step(kDt);
    EXPECT_TRUE(threw);
}

// The hash sees every body's state: nudging one body by one ulp changes it.
TEST(Snapshot, StateHashSeesOneUlp) {
    World world(test::awakeSettings());
    const std::vector<BodyId> ids = test::buildDeterminismScene(world);
    run(world, 20);
    const std::uint64_t before = world.stateHash();
    const Vec2 v = world.velocity(ids[5]);
    world.setVelocity(ids[5], Vec2(std::nextafter(v.x(), 1e9), v.y()));
    EXPECT_NE(world.stateHash(), before);
}

}  // namespace
}  // namespace physim
