// What a scene does not use costs nothing: every effect available but unused runs nothing, each runs once
// something uses it; user force callbacks; bodies that collide with nothing; gravity scale.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kG = 9.81;

void expectNoEffect(const World& world, const char* why) {
    for (std::size_t e = 0; e < StepProfile::effectCount; ++e)
        EXPECT_FALSE(world.profile().effectRan[e]) << effectName(static_cast<Effect>(e)) << ": " << why;
}

TEST(EffectStages, EffectsAvailableButUnusedRunNothing) {
    World world;
    BodyDef d;
    d.attracting = true;  // one attracting body: nobody to pull
    const BodyId a = world.createBody(d);
    d.attracting = false;
    d.position = {5.0, 0.0};
    d.drag.linear = 1.0;
    const BodyId b = world.createBody(d);
    SpringJointDef spring;
    spring.bodyA = a;
    spring.bodyB = b;
    spring.stiffness = 1.0;
    const JointId s = world.createSpringJoint(spring);
    const ForceCallbackId callback = world.addForceCallback([](World&, double) {});
    world.step(kDt);
    for (const Effect e : {Effect::Drag, Effect::Springs, Effect::Callbacks})
        EXPECT_TRUE(world.profile().didRun(e)) << effectName(e);
    EXPECT_FALSE(world.profile().didRun(Effect::Gravitation)) << "one attracting body";
    // Take each away: the counts fall to zero and nothing runs, though every effect was used before.
    world.setDrag(b, DragDef{});
    world.destroyJoint(s);
    world.removeForceCallback(callback);
    world.setAttracting(a, false);
    world.step(kDt);
    expectNoEffect(world, "nothing in the world uses it");
    EXPECT_TRUE(world.profile().didRun(Stage::Forces)) << "gravity still acts";
    EXPECT_FALSE(world.profile().didRun(Stage::Solve)) << "no joints, no contacts";
}

TEST(EffectStages, WorldAsleepRunsNoEffect) {
    World world;
    test::addGround(world, 5.0);
    BodyDef box;
    box.shape = makeBox(0.5, 0.5);
    box.position = {0.0, 0.5};
    box.drag.dragCoefficient = 1.0;
    world.createBody(box);
    for (int i = 0; i < 120; ++i) world.step(kDt);
    EXPECT_EQ(world.awakeBodyCount(), 0u);
    expectNoEffect(world, "a sleeping body's drag does nothing");
    for (std::size_t s = 0; s < StepProfile::stageCount; ++s)
        EXPECT_FALSE(world.profile().ran[s]) << stageName(static_cast<Stage>(s));
}

TEST(ForceCallbacks, ActLikeForcesAppliedJustBeforeTheStep) {
    // A callback pushing with F each step moves a body exactly as applyForce(F) before each step does.
    auto run = [](bool callback) {
        World world;
        const BodyId b = world.createBody(BodyDef{});
        if (callback) world.addForceCallback([b](World& w, double) { w.applyForce(b, {2.0, 0.0}); });
        for (int i = 0; i < 60; ++i) {
            if (!callback) world.applyForce(b, {2.0, 0.0});
            world.step(kDt);
        }
        EXPECT_EQ(world.profile().didRun(Effect::Callbacks), callback);
        return world.position(b);
    };
    EXPECT_EQ(run(true), run(false));
}

TEST(ForceCallbacks, RunInOrderWithTheStepAndRefuseReentry) {
    World world;
    const BodyId b = world.createBody(BodyDef{});
    std::vector<int> calls;
    double seen = 0.0;
    world.addForceCallback([&](World&, double dt) {
        calls.push_back(1);
        seen = dt;
    });
    const ForceCallbackId second = world.addForceCallback([&](World&, double) { calls.push_back(2); });
    world.step(kDt);
    EXPECT_EQ(calls, (std::vector<int>{1, 2}));
    EXPECT_EQ(seen, kDt);
    world.removeForceCallback(second);
    EXPECT_EQ(world.forceCallbackCount(), 1u);
    EXPECT_THROW(world.removeForceCallback(second), std::invalid_argument) << "already removed";
    EXPECT_THROW(world.addForceCallback(ForceCallback{}), std::invalid_argument) << "empty";

    // From inside a callback: stepping again or changing the callbacks is refused; forces and bodies are not.
    int refused = 0;
    const ForceCallbackId nested = world.addForceCallback([&](World& w, double dt) {
        try {
            w.step(dt);
        } catch (const std::logic_error&) {
            ++refused;
        }
        try {
            w.addForceCallback([](World&, double) {});
        } catch (const std::logic_error&) {
            ++refused;
        }
        w.applyTorque(b, 1.0);
        w.createBody(BodyDef{});
    });
    world.step(kDt);
    EXPECT_EQ(refused, 2);
    EXPECT_EQ(world.bodyCount(), 2u);
    EXPECT_GT(world.angularVelocity(b), 0.0) << "the torque acted in this step";
    world.removeForceCallback(nested);

    // A callback that throws: the step does not happen, the world is unchanged and can step again.
    const ForceCallbackId throwing = world.addForceCallback([](World&, double) { throw std::runtime_error("user"); });
    const auto steps = world.stepCount();
    EXPECT_THROW(world.step(kDt), std::runtime_error);
    EXPECT_EQ(world.stepCount(), steps);
    world.removeForceCallback(throwing);
    world.step(kDt);
    EXPECT_EQ(world.stepCount(), steps + 1);
}

TEST(Collides, BodiesThatTouchNothingPassThroughAndRunNoContactStage) {
    WorldSettings s;
    s.gravity = Vec2::Zero();
    World world(s);
    BodyDef d;
    d.collides = false;
    d.velocity = {1.0, 0.0};
    const BodyId a = world.createBody(d);
    d.position = {2.0, 0.0};
    d.velocity = {-1.0, 0.0};
    const BodyId b = world.createBody(d);
    EXPECT_FALSE(world.collides(a));
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        EXPECT_FALSE(world.profile().didRun(Stage::BroadPhase));
        EXPECT_FALSE(world.profile().didRun(Stage::NarrowPhase));
        EXPECT_FALSE(world.profile().didRun(Stage::Continuous)) << "fast for its size, but it hits nothing";
    }
    EXPECT_NEAR(world.position(a).x(), 2.0, 1e-9) << "passed straight through b";
    EXPECT_NEAR(world.velocity(b).x(), -1.0, 0.0);

    // Colliding again: they meet and bounce (restitution 1) instead.
    world.setTransform(a, {0.0, 0.0}, 0.0);
    world.setTransform(b, {2.0, 0.0}, 0.0);
    world.setVelocity(a, {1.0, 0.0});
    world.setVelocity(b, {-1.0, 0.0});
    world.setMaterial(a, 1.0, 0.0, 0.0);
    world.setMaterial(b, 1.0, 0.0, 0.0);
    world.setCollides(a, true);
    world.setCollides(b, true);
    for (int i = 0; i < 120; ++i) world.step(kDt);
    EXPECT_LT(world.position(a).x(), 0.0) << "a bounced back";
    EXPECT_TRUE(world.collides(b));
    world.setCollides(a, false);
    EXPECT_FALSE(world.collides(a));
}

// A step keeps no boxes for bodies that touch nothing (no proxy reads them): bounds computes them where asked, and
// a body set to collide again gets its proxies where it is now. Exact: the same computeAabb at the same pose.
TEST(Collides, ABodyThatTouchesNothingHasItsBoundsWhereItIs) {
    World world;
    BodyDef d;
    d.collides = false;
    d.shape = makeBox(0.5, 0.25);
    d.angularVelocity = 3.0;
    const BodyId body = world.createBody(d);
    ShapeDef part;
    part.geometry = Circle{{1.0, 0.0}, 0.3};
    world.createShape(body, part);
    const Vec2 start = world.position(body);
    for (int i = 0; i < 60; ++i) world.step(kDt);
    ASSERT_LT(world.position(body).y(), start.y() - 1.0) << "it fell and turned";
    const Transform xf = world.transform(body);
    const std::vector<ShapeId> shapes = world.shapes(body);
    Aabb all = computeAabb(world.geometry(shapes.front()), xf);
    for (const ShapeId shape : shapes) {
        const Aabb box = computeAabb(world.geometry(shape), xf);
        EXPECT_EQ(world.bounds(shape).lower, box.lower);
        EXPECT_EQ(world.bounds(shape).upper, box.upper);
        all = Aabb::merged(all, box);
    }
    EXPECT_EQ(world.bounds(body).lower, all.lower);
    EXPECT_EQ(world.bounds(body).upper, all.upper);

    world.setCollides(body, true);
    const Vec2 here = world.position(body);
    EXPECT_EQ(world.overlapAabb({here, here}).size(), 1u) << "its box's proxy is where it is now";
    EXPECT_TRUE(world.overlapAabb({start, start}).empty()) << "not where it was";
}

TEST(EffectStages, RotationLockedEverywhereDoesNoRotationWork) {
    // Boxes stacked off-centre: their contacts have lever arms, so free boxes would topple. All locked: no contact row
    // carries angular terms, no box turns by a single bit, and the stack still rests on its contacts. Sleep off: the
    // rows must run every step.
    WorldSettings settings;
    settings.enableSleep = false;
    World world(settings);
    test::addGround(world, 5.0);
    std::vector<BodyId> boxes;
    for (int i = 0; i < 4; ++i) {
        boxes.push_back(test::addBox(world, {0.3 * i, 0.5 + 1.0 * i}, 0.5, 0.5));
        world.setFixedRotation(boxes.back(), true);
    }
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        ASSERT_EQ(world.profile().turningRows, 0u) << "step " << i;
    }
    EXPECT_EQ(world.profile().manifolds, 4u) << "the stack touches: ground and three box-on-box contacts";
    for (const BodyId b : boxes) {
        EXPECT_EQ(world.angle(b), 0.0);
        EXPECT_EQ(world.angularVelocity(b), 0.0);
    }
    // Four soft contacts under a column of four hold it about 4^2 g / (2 (2 pi 120 Hz)^2) = 0.14 mm low (measured
    // 0.14 mm); 1 mm leaves room for rounding of that estimate and still catches a box that slid off or sank in.
    EXPECT_NEAR(world.position(boxes.back()).y(), 3.5, 1e-3) << "the top box rests at its stacked height";
    // Free the top box: only its own contact turns (it sits on the one below, so one row), the rest stay lean.
    world.setFixedRotation(boxes.back(), false);
    world.step(kDt);
    EXPECT_EQ(world.profile().turningRows, 1u);
    EXPECT_GT(world.profile().manifolds, 1u);
}

TEST(GravityScale, ScalesTheWorldsGravityPerBody) {
    World world;
    BodyDef d;
    d.gravityScale = 0.5;
    const BodyId half = world.createBody(d);
    d.gravityScale = -1.0;
    d.position = {5.0, 0.0};
    const BodyId up = world.createBody(d);
    for (int i = 0; i < 60; ++i) world.step(kDt);
    // Velocity under a constant acceleration is exact in semi-implicit Euler: v = a t to rounding.
    EXPECT_NEAR(world.velocity(half).y(), -0.5 * kG * 1.0, 1e-12);
    EXPECT_NEAR(world.velocity(up).y(), kG * 1.0, 1e-12);
    EXPECT_EQ(world.gravityScale(half), 0.5);
    world.setGravityScale(half, 0.0);
    world.step(kDt);
    EXPECT_NEAR(world.velocity(half).y(), -0.5 * kG, 1e-12) << "scale 0: weightless";
    EXPECT_THROW(world.setGravityScale(half, NAN), std::invalid_argument);
    d.gravityScale = INFINITY;
    EXPECT_THROW(world.createBody(d), std::invalid_argument);
}

}  // namespace
}  // namespace physim
