// World stepping: free fall against the analytic answer, stage skipping, handles, bad input.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace physim {
namespace {

constexpr double kG = 9.81;

World fallingWorld(double y0, BodyId& id) {
    World world;
    BodyDef def;
    def.position = {0.0, y0};
    def.shape = makeCircle(0.1);
    id = world.createBody(def);
    return world;
}

// Semi-implicit Euler under constant g gives y_n = y0 - g h^2 n (n + 1) / 2, so its error against the exact
// y(t) = y0 - g t^2 / 2 is exactly g h t / 2 (one substep's lead in velocity), where h = dt / substeps is the
// interval the integrator really steps by (every substep is one Euler step). Tolerance: 1e-9 m, rounding of
// about a thousand additions of O(1) numbers, far below the O(0.1 m) error being checked.
TEST(WorldFreeFall, MatchesAnalyticWithKnownEulerError) {
    for (const double dt : {1.0 / 40.0, 1.0 / 60.0, 1.0 / 240.0}) {
        BodyId id;
        World world = fallingWorld(100.0, id);
        const int steps = static_cast<int>(std::lround(2.0 / dt));
        for (int i = 0; i < steps; ++i) world.step(dt);
        const double t = steps * dt;
        const double exact = 100.0 - 0.5 * kG * t * t;
        const double y = world.position(id).y();
        const double h = dt / world.settings().substeps;
        EXPECT_NEAR(y - exact, -0.5 * kG * h * t, 1e-9) << "dt = " << dt;
        EXPECT_NEAR(world.velocity(id).y(), -kG * t, 1e-9) << "dt = " << dt;
        EXPECT_EQ(world.position(id).x(), 0.0);
    }
}

TEST(WorldFreeFall, ErrorIsFirstOrderInDt) {
    auto errorAt = [](double dt) {
        BodyId id;
        World world = fallingWorld(0.0, id);
        const int steps = static_cast<int>(std::lround(1.0 / dt));
        for (int i = 0; i < steps; ++i) world.step(dt);
        return std::abs(world.position(id).y() + 0.5 * kG);
    };
    // Halving dt halves the error (first-order method); 1e-6 relative covers rounding.
    EXPECT_NEAR(errorAt(1.0 / 80.0) / errorAt(1.0 / 160.0), 2.0, 2e-6);
}

TEST(WorldStages, SingleFallingBodySkipsCollisionStages) {
    BodyId id;
    World world = fallingWorld(10.0, id);
    world.step(1.0 / 60.0);
    const StepProfile& p = world.profile();
    EXPECT_TRUE(p.didRun(Stage::Forces));
    EXPECT_FALSE(p.didRun(Stage::BroadPhase)) << "one body has nothing to collide with";
    EXPECT_FALSE(p.didRun(Stage::NarrowPhase));
    EXPECT_FALSE(p.didRun(Stage::Continuous));
    EXPECT_FALSE(p.didRun(Stage::Solve));
    EXPECT_TRUE(p.didRun(Stage::Integrate));
}

TEST(WorldStages, StaticOnlyWorldRunsNothing) {
    World world;
    BodyDef def;
    def.type = BodyType::Static;
    def.shape = makeBox(1.0, 1.0);
    world.createBody(def);
    def.position = {0.5, 0.0};
    world.createBody(def);  // overlapping statics: never a pair
    world.step(1.0 / 60.0);
    for (std::size_t s = 0; s < StepProfile::stageCount; ++s) EXPECT_FALSE(world.profile().ran[s]) << s;
}

TEST(WorldStages, SeparatedBodiesStopAtBroadPhase) {
    World world;
    BodyDef def;
    def.shape = makeCircle(0.5);
    world.createBody(def);
    def.position = {10.0, 0.0};
    world.createBody(def);
    world.step(1.0 / 60.0);
    EXPECT_TRUE(world.profile().didRun(Stage::BroadPhase));
    EXPECT_EQ(world.profile().candidatePairs, 0u);
    EXPECT_FALSE(world.profile().didRun(Stage::NarrowPhase));
    EXPECT_FALSE(world.profile().didRun(Stage::Solve));
}

TEST(WorldBodies, StaleHandleIsRejected) {
    World world;
    const BodyId a = world.createBody(BodyDef{});
    world.destroyBody(a);
    const BodyId b = world.createBody(BodyDef{});  // reuses the slot with a new generation
    EXPECT_EQ(a.index, b.index);
    EXPECT_NE(a, b);
    EXPECT_FALSE(world.contains(a));
    EXPECT_TRUE(world.contains(b));
    EXPECT_THROW(world.position(a), std::invalid_argument);
    EXPECT_EQ(world.bodyCount(), 1u);
}

TEST(WorldBodies, StaticBodyIsImmovable) {
    World world;
    BodyDef def;
    def.type = BodyType::Static;
    def.shape = makeBox(1.0, 0.5);
    const BodyId id = world.createBody(def);
    EXPECT_EQ(world.mass(id), 0.0);
    EXPECT_EQ(world.inverseMass(id), 0.0);
    EXPECT_EQ(world.inverseInertia(id), 0.0);
    world.applyForce(id, {100.0, 100.0});
    world.step(0.1);
    EXPECT_EQ(world.position(id), Vec2(0.0, 0.0));
}

TEST(WorldBodies, MassAndInertiaFromDensity) {
    World world;
    BodyDef def;
    def.density = 2.0;
    def.shape = makeBox(1.0, 0.5);  // 2 m x 1 m
    const BodyId box = world.createBody(def);
    EXPECT_NEAR(world.mass(box), 4.0, 1e-12);
    EXPECT_NEAR(world.inertia(box), 4.0 * (4.0 + 1.0) / 12.0, 1e-12);  // m (w^2 + h^2) / 12
    def.shape = makeCircle(0.5);
    const BodyId disc = world.createBody(def);
    EXPECT_NEAR(world.mass(disc), 2.0 * M_PI * 0.25, 1e-12);
    EXPECT_NEAR(world.inertia(disc), 0.5 * world.mass(disc) * 0.25, 1e-12);  // m r^2 / 2
}

TEST(WorldBadInput, NamesTheValueAndLeavesStateUnchanged) {
    World world;
    BodyDef def;
    def.density = -1.0;
    try {
        world.createBody(def);
        FAIL() << "negative density accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("density"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("-1"), std::string::npos) << e.what();
    }
    EXPECT_EQ(world.bodyCount(), 0u);

    const BodyId id = world.createBody(BodyDef{});
    EXPECT_THROW(world.setVelocity(id, {NAN, 0.0}), std::invalid_argument);
    EXPECT_EQ(world.velocity(id), Vec2(0.0, 0.0));
    EXPECT_THROW(world.applyForce(id, {INFINITY, 0.0}), std::invalid_argument);
    def = BodyDef{};
    def.restitution = 1.5;
    EXPECT_THROW(world.createBody(def), std::invalid_argument);
    def = BodyDef{};
    def.shape = Circle{Vec2::Zero(), 0.0};
    EXPECT_THROW(world.createBody(def), std::invalid_argument);
    EXPECT_THROW(world.step(0.0), std::invalid_argument);
    EXPECT_THROW(world.step(-0.01), std::invalid_argument);
    EXPECT_THROW(world.step(1e-300), std::invalid_argument) << "below a nanosecond: the substep's inverses overflow";
    EXPECT_THROW(world.step(NAN), std::invalid_argument);
    EXPECT_THROW(world.step(5.0), std::invalid_argument) << "5 s per step is a unit mistake";
    EXPECT_EQ(world.stepCount(), 0u);
}

}  // namespace
}  // namespace physim
