// First contact: a box dropped on static ground comes to rest on it, at the right height, without creeping.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

namespace physim {
namespace {

TEST(RestingContact, BoxSettlesOnGround) {
    WorldSettings settings;
    settings.enableSleep = false;  // this test looks at the resting contact itself, every step
    World world(settings);
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.shape = makeBox(10.0, 0.5);
    ground.position = {0.0, -0.5};  // top at y = 0
    world.createBody(ground);
    BodyDef box;
    box.shape = makeBox(0.5, 0.5);
    box.position = {0.0, 3.0};
    const BodyId id = world.createBody(box);

    const double dt = 1.0 / 60.0;
    for (int i = 0; i < 180; ++i) world.step(dt);  // 3 s: falls 2.5 m in ~0.7 s, then settles
    const double settledY = world.position(id).y();
    // Resting overlap is bounded by the solver's allowed slop (5 mm) plus one step of gravity's push.
    EXPECT_GT(settledY, 0.5 - 2 * world.settings().linearSlop);
    EXPECT_LT(settledY, 0.5 + 1e-6);
    for (int i = 0; i < 600; ++i) world.step(dt);  // 10 more seconds
    EXPECT_NEAR(world.position(id).y(), settledY, 1e-4) << "no sinking or creeping";
    EXPECT_LT(world.velocity(id).norm(), 1e-3);
    EXPECT_EQ(world.contacts().size(), 1u);
    EXPECT_EQ(world.contacts()[0].pointCount, 2);
    EXPECT_TRUE(world.profile().didRun(Stage::Solve));
}

TEST(RestingContact, ImpulseIsAppliedOncePerPair) {
    // Head-on: two equal circles, perfectly elastic, in free space. Resolving the pair twice (the paper's
    // program's bug) would reverse the exchange; once gives a clean swap of velocities.
    WorldSettings s;
    s.gravity = Vec2::Zero();
    World world(s);
    BodyDef def;
    def.shape = makeCircle(0.5);
    def.restitution = 1.0;
    def.position = {-0.499, 0.0};
    def.velocity = {2.0, 0.0};
    const BodyId a = world.createBody(def);
    def.position = {0.499, 0.0};
    def.velocity = {-2.0, 0.0};
    const BodyId b = world.createBody(def);
    world.step(1.0 / 60.0);
    // Momentum is conserved exactly up to rounding; elastic exchange reverses both velocities.
    EXPECT_NEAR(world.velocity(a).x() + world.velocity(b).x(), 0.0, 1e-12);
    EXPECT_NEAR(world.velocity(a).x(), -2.0, 1e-9);
    EXPECT_NEAR(world.velocity(b).x(), 2.0, 1e-9);
}

}  // namespace
}  // namespace physim
