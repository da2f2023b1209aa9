// Sleeping: islands at rest stop being simulated (and cost no integration or narrow phase), and wake when
// touched, pushed, given a velocity, or when what they rest on goes away.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;

struct Pile {
    World world;
    BodyId ground, bottom, top;
};

// Two 1 m boxes stacked on static ground, settled for `seconds`.
void build(Pile& p, double seconds, const WorldSettings& settings = {}) {
    p.world.setSettings(settings);
    BodyDef g;
    g.type = BodyType::Static;
    g.shape = makeBox(10.0, 0.5);
    g.position = {0.0, -0.5};
    p.ground = p.world.createBody(g);
    BodyDef b;
    b.shape = makeBox(0.5, 0.5);
    b.position = {0.0, 0.5};
    p.bottom = p.world.createBody(b);
    b.position = {0.0, 1.5};
    p.top = p.world.createBody(b);
    for (int i = 0; i < static_cast<int>(seconds / kDt); ++i) p.world.step(kDt);
}

TEST(Sleep, RestingPileFallsAsleepAndCostsNothing) {
    Pile p;
    build(p, 3.0);  // settles within a second; then timeToSleep (0.5 s) below the tolerances
    ASSERT_FALSE(p.world.isAwake(p.bottom));
    ASSERT_FALSE(p.world.isAwake(p.top));
    const Vec2 before = p.world.position(p.top);
    for (int i = 0; i < 600; ++i) p.world.step(kDt);
    EXPECT_EQ(p.world.position(p.top), before) << "a sleeping body does not move at all";
    EXPECT_EQ(p.world.profile().manifolds, 0u) << "sleeping pairs skip the narrow phase";
    EXPECT_EQ(p.world.awakeBodyCount(), 0u);
    for (std::size_t s = 0; s < StepProfile::stageCount; ++s)
        EXPECT_FALSE(p.world.profile().ran[s]) << "a world asleep runs no stage: " << stageName(static_cast<Stage>(s));
}

TEST(Sleep, FallingBodyNeverSleeps) {
    World world;
    BodyDef ball;
    ball.shape = makeCircle(0.1);
    ball.velocity = {0.0, 10.0};  // up, through its apex (speed ~0 for an instant) and down again
    const BodyId id = world.createBody(ball);
    for (int i = 0; i < 180; ++i) {
        world.step(kDt);
        ASSERT_TRUE(world.isAwake(id)) << "step " << i;
    }
}

TEST(Sleep, TouchWakesTheWholeIsland) {
    Pile p;
    build(p, 3.0);
    ASSERT_FALSE(p.world.isAwake(p.bottom));
    BodyDef ball;
    ball.shape = makeCircle(0.2);
    ball.position = {0.0, 3.0};
    const BodyId id = p.world.createBody(ball);
    bool wokeTogether = false;
    for (int i = 0; i < 60 && !wokeTogether; ++i) {
        p.world.step(kDt);
        wokeTogether = p.world.isAwake(p.top) && p.world.isAwake(p.bottom);
        // The bottom box wakes in the same step as the top one: the wake runs through the pile.
        ASSERT_EQ(p.world.isAwake(p.top), p.world.isAwake(p.bottom)) << "step " << i;
    }
    EXPECT_TRUE(wokeTogether);
    EXPECT_TRUE(p.world.isAwake(id));
}

TEST(Sleep, SettingMotionWakesABody) {
    Pile p;
    build(p, 3.0);
    p.world.setVelocity(p.top, {1.0, 0.0});
    EXPECT_TRUE(p.world.isAwake(p.top));
    p.world.setAwake(p.top, false);
    EXPECT_EQ(p.world.velocity(p.top), Vec2::Zero()) << "put to sleep, it stops";
    p.world.applyForce(p.top, {0.0, 1.0});
    EXPECT_TRUE(p.world.isAwake(p.top));
    p.world.setAwake(p.top, false);
    p.world.applyLinearImpulse(p.top, {0.0, 1.0});
    EXPECT_TRUE(p.world.isAwake(p.top));
    p.world.setAwake(p.top, false);
    p.world.setTransform(p.top, {0.0, 5.0}, 0.0);
    EXPECT_TRUE(p.world.isAwake(p.top));
}

TEST(Sleep, RemovingTheSupportWakesWhatRestedOnIt) {
    Pile p;
    build(p, 3.0);
    ASSERT_FALSE(p.world.isAwake(p.top));
    p.world.destroyBody(p.bottom);
    EXPECT_TRUE(p.world.isAwake(p.top));
    for (int i = 0; i < 60; ++i) p.world.step(kDt);
    EXPECT_NEAR(p.world.position(p.top).y(), 0.5, 0.01) << "fell onto the ground";
}

TEST(Sleep, DisabledPerWorldAndPerBody) {
    WorldSettings off;
    off.enableSleep = false;
    Pile p;
    build(p, 3.0, off);
    EXPECT_TRUE(p.world.isAwake(p.top));
    EXPECT_TRUE(p.world.isAwake(p.bottom));
    EXPECT_FALSE(p.world.profile().didRun(Stage::Sleep));

    // A body that may not sleep keeps its whole island awake; once allowed, the island sleeps.
    Pile q;
    q.world.setSettings({});
    build(q, 0.0);
    q.world.setAllowSleep(q.top, false);
    for (int i = 0; i < 180; ++i) q.world.step(kDt);
    EXPECT_TRUE(q.world.isAwake(q.top));
    EXPECT_TRUE(q.world.isAwake(q.bottom)) << "it touches the top box";
    q.world.setAllowSleep(q.top, true);
    for (int i = 0; i < 60; ++i) q.world.step(kDt);
    EXPECT_FALSE(q.world.isAwake(q.top));
    EXPECT_FALSE(q.world.isAwake(q.bottom));
}

TEST(Sleep, BadSettingsAreRejected) {
    WorldSettings s;
    s.timeToSleep = 0.0;
    EXPECT_THROW(World{s}, std::invalid_argument);
    s = WorldSettings{};
    s.sleepLinearTolerance = -1.0;
    EXPECT_THROW(World{s}, std::invalid_argument);
}

// A settled pile sleeps within 2 s of coming to rest, and then costs nothing. Islands persist (merged as contacts
// begin, split only when one is about to sleep), so the moment the last body of a 210-box pyramid stays below the
// tolerances, its island's clock runs: it sleeps timeToSleep (0.5 s) after that, to the step. "At rest" is the
// last step in which any body moved faster than the tolerances.
TEST(Sleep, ASettledPyramidSleepsWithinTwoSecondsOfComingToRest) {
    World world;
    BodyDef g;
    g.type = BodyType::Static;
    g.shape = makeBox(30.0, 0.5);
    g.position = {0.0, -0.5};
    world.createBody(g);
    std::vector<BodyId> boxes;
    const int n = 20;
    for (int i = 0; i < n; ++i)
        for (int j = i; j < n; ++j) {
            BodyDef d;
            d.shape = makeBox(0.5, 0.5);
            d.position = {(i + 1) * 0.5 + (j - i) - 0.5 * n, 0.5 + i};
            boxes.push_back(world.createBody(d));
        }
    const WorldSettings& s = world.settings();
    double lastMoving = 0.0, asleep = -1.0;
    for (int step = 1; step <= 20 * 60 && asleep < 0.0; ++step) {
        world.step(kDt);
        for (const BodyId id : boxes)
            if (world.velocity(id).norm() > s.sleepLinearTolerance ||
                std::abs(world.angularVelocity(id)) > s.sleepAngularTolerance)
                lastMoving = step * kDt;
        if (world.awakeBodyCount() == 0) asleep = step * kDt;
    }
    RecordProperty("at_rest_s", std::to_string(lastMoving));
    RecordProperty("asleep_s", std::to_string(asleep));
    ASSERT_GT(asleep, 0.0) << "never slept";
    EXPECT_LE(asleep - lastMoving, 2.0);
    EXPECT_NEAR(asleep - lastMoving, s.timeToSleep, 1.5 * kDt);
    world.step(kDt);
    EXPECT_FALSE(world.profile().didRun(Stage::BroadPhase));
    EXPECT_FALSE(world.profile().didRun(Stage::NarrowPhase));
    EXPECT_FALSE(world.profile().didRun(Stage::Solve));
}

}  // namespace
}  // namespace physim

namespace physim {
namespace {

// BodyDef::awake = false: a dynamic body starts asleep and stays put, not simulated (its velocity is kept, no
// gravity acts), until a body striking it wakes it; then it falls like any other. Where the world does not sleep,
// the flag does nothing.
TEST(Sleep, ABodyCreatedAsleepWaitsUntilStruck) {
    World w;
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.shape = makeBox(10.0, 0.5);
    ground.position = {0.0, -0.5};
    w.createBody(ground);
    BodyDef waiting;
    waiting.shape = makeBox(0.5, 0.5);
    waiting.position = {0.0, 3.0};  // in the air: awake, it would fall
    waiting.awake = false;
    const BodyId still = w.createBody(waiting);
    EXPECT_FALSE(w.isAwake(still));
    for (int k = 0; k < 40; ++k) w.step(1.0 / 40.0);
    EXPECT_EQ(w.position(still), Vec2(0.0, 3.0)) << "asleep: not simulated";
    BodyDef ball;
    ball.shape = makeCircle(0.2);
    ball.position = {0.0, 5.0};
    w.createBody(ball);  // falls onto it
    for (int k = 0; k < 80; ++k) w.step(1.0 / 40.0);
    EXPECT_TRUE(w.isAwake(still) || w.position(still).y() < 1.0);
    EXPECT_LT(w.position(still).y(), 0.6) << "struck awake, it fell to the ground";

    WorldSettings noSleep;
    noSleep.enableSleep = false;
    World awake(noSleep);
    const BodyId b = awake.createBody(waiting);
    EXPECT_TRUE(awake.isAwake(b));
}

}  // namespace
}  // namespace physim

namespace physim {
namespace {

// An 8 m ram of 512 kg at 40 m/s strikes a sleeping 0.2 m box: the box wakes as soon as the ram's speculative
// points reach it, within the same step, so the blow is the same as on an awake box at rest: both bodies' velocities
// equal those of the same scene without sleep, to rounding (1e-12). Asleep, the box would stand as immovable and
// stop the ram dead (it did: the ram left at -0.06 m/s).
TEST(Sleep, ASleeperStruckHardMovesAsIfAwake) {
    auto run = [](bool sleep) {
        WorldSettings s;
        s.gravity = Vec2::Zero();
        s.enableSleep = sleep;
        World w(s);
        BodyDef ram;
        ram.shape = makeBox(4.0, 4.0);
        ram.position = {-20.0, 0.0};
        ram.velocity = {40.0, 0.0};
        ram.density = 8.0;
        const BodyId r = w.createBody(ram);
        BodyDef box;
        box.shape = makeBox(0.2, 0.2);
        box.position = {30.0, 0.0};
        box.awake = false;
        const BodyId b = w.createBody(box);
        for (int k = 0; k < 75; ++k) w.step(1.0 / 60.0);
        return std::make_pair(w.velocity(r), w.velocity(b));
    };
    const auto [ramAsleep, boxAsleep] = run(true);
    const auto [ramAwake, boxAwake] = run(false);
    ASSERT_GT(boxAwake.x(), 30.0);  // struck: it leaves ahead of the ram
    EXPECT_NEAR((ramAsleep - ramAwake).norm(), 0.0, 1e-12);
    EXPECT_NEAR((boxAsleep - boxAwake).norm(), 0.0, 1e-12);
}

// Two discs on a rod (an awake island of two), made touching a sleeping box (an island of one) and pushing it:
// touching begins at once and links the islands, and the box, merged into the larger awake island, is simulated
// (it moves off) rather than counted awake and left standing.
TEST(Sleep, AnAwakeIslandTouchingASleeperSimulatesIt) {
    WorldSettings s;
    s.gravity = Vec2::Zero();
    World w(s);
    BodyDef box;
    box.shape = makeBox(0.5, 0.5);
    box.position = {3.0, 0.0};
    box.awake = false;
    const BodyId b = w.createBody(box);
    BodyDef disc;
    disc.shape = makeCircle(0.25);
    disc.velocity = {0.5, 0.0};
    disc.position = {2.25, 0.0};  // touching the box's face at x = 2.5
    const BodyId front = w.createBody(disc);
    disc.position = {1.25, 0.0};
    const BodyId back = w.createBody(disc);
    DistanceJointDef rod;
    rod.bodyA = back;
    rod.bodyB = front;
    rod.localAnchorA = {0.0, 0.0};
    rod.localAnchorB = {0.0, 0.0};
    w.createDistanceJoint(rod);
    for (int k = 0; k < 120; ++k) w.step(1.0 / 60.0);
    EXPECT_GT(w.position(b).x(), 3.1) << "pushed, the box moved on";
    EXPECT_TRUE(w.isAwake(b));
}

}  // namespace
}  // namespace physim
