// Kinematic bodies and locked rotation (issue #4), default settings at 60 Hz.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;

TEST(Kinematic, MovesByItsVelocityAndPushesDynamicBodies) {
    World world;
    BodyDef k;
    k.type = BodyType::Kinematic;
    k.shape = makeBox(0.5, 0.5);
    k.velocity = {1.0, 0.0};
    const BodyId pusher = world.createBody(k);
    BodyDef d;
    d.shape = makeBox(0.5, 0.5);
    d.position = {1.2, 0.0};
    d.useGravity = false;
    const BodyId pushed = world.createBody(d);
    for (int i = 0; i < 120; ++i) world.step(kDt);
    // Exactly its velocity times the time: gravity and the contact did not touch it (1e-9: rounding).
    EXPECT_NEAR(world.position(pusher).x(), 2.0, 1e-9);
    EXPECT_NEAR(world.position(pusher).y(), 0.0, 1e-12);
    EXPECT_EQ(world.velocity(pusher), Vec2(1.0, 0.0));
    // The dynamic box was pushed ahead of it: at least at the pusher's speed, no overlap beyond the slop.
    EXPECT_GE(world.position(pushed).x(), world.position(pusher).x() + 1.0 - 2 * world.settings().linearSlop);
    EXPECT_GE(world.velocity(pushed).x(), 1.0 - 1e-6);
}

TEST(FixedRotation, ContactsDoNotTurnALockedBody) {
    World world;
    test::addGround(world, 5.0);
    BodyDef box;
    box.shape = makeBox(0.5, 0.5);
    box.position = {0.0, 2.0};
    box.angle = 0.3;  // lands on a corner: free, it would tip onto a face
    const BodyId id = world.createBody(box);
    world.setFixedRotation(id, true);
    EXPECT_EQ(world.inverseInertia(id), 0.0);
    for (int i = 0; i < 120; ++i) world.step(kDt);
    EXPECT_EQ(world.angle(id), 0.3);
    world.setFixedRotation(id, false);
    EXPECT_GT(world.inverseInertia(id), 0.0);
    for (int i = 0; i < 300; ++i) world.step(kDt);
    EXPECT_NE(world.angle(id), 0.3) << "unlocked, it tips";
}

}  // namespace
}  // namespace physim
