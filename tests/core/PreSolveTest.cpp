// The pre-solve hook (World::setPreSolve): it is asked about each awake contact with points, once per step, and a
// contact it disables gives no row, does not touch and is not listed; the rows' layout follows it. A one-way platform
// built with it lets a box thrown up pass through and land on top, and lets a box that stops partly through fall back.
// Tolerances: a box resting on a face sits within the linear slop (5 mm) of it under the soft contacts (that is the
// bar: "within the linear slop of the platform top"); 0.02 m (4 slops) where a box comes to rest after falling.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;

BodyId addGround(World& world) {
    BodyDef g;
    g.type = BodyType::Static;
    g.shape = makeBox(10.0, 0.5);
    g.position = {0.0, -0.5};  // top face at y = 0
    return world.createBody(g);
}

BodyId addBox(World& world, double halfSize, const Vec2& at, const Vec2& velocity = Vec2::Zero()) {
    BodyDef b;
    b.shape = makeBox(halfSize, halfSize);
    b.position = at;
    b.velocity = velocity;
    return world.createBody(b);
}

bool touching(const World& world, BodyId a, BodyId b) {
    for (const Manifold& m : world.contacts())
        if ((m.bodyA == a && m.bodyB == b) || (m.bodyA == b && m.bodyB == a)) return true;
    return false;
}

bool hasEvent(const std::vector<ContactEvent>& events, BodyId a, BodyId b) {
    return std::any_of(events.begin(), events.end(), [&](const ContactEvent& e) {
        return (e.bodyA == a && e.bodyB == b) || (e.bodyA == b && e.bodyB == a);
    });
}

// A one-way platform's rule: a contact with `platform` acts only while the other shape lies above it (the normal from
// the platform to it points up) and has not sunk into it by more than `through` (m): a body partly through passes on.
struct OneWay {
    ShapeId platform;
    double through;
    bool operator()(const Manifold& m) const {
        double sign = 0.0;
        if (m.shapeA == platform) sign = 1.0;       // the normal points from A to B: from the platform
        else if (m.shapeB == platform) sign = -1.0;
        else return true;
        if (sign * m.normal.y() < 0.7) return false;  // below or beside the platform
        double deepest = std::numeric_limits<double>::infinity();
        for (int p = 0; p < m.pointCount; ++p) deepest = std::min(deepest, m.points[p].separation);
        return deepest > -through;
    }
};

struct Platform {
    World world;
    BodyId ground, platform, box;
    static constexpr double kTop = 2.1;   // m, the platform's top face
    static constexpr double kHalf = 0.25; // m, the box's half size
    explicit Platform(double launchSpeed) {
        ground = addGround(world);
        BodyDef p;
        p.type = BodyType::Static;
        p.shape = makeBox(2.0, 0.1);
        p.position = {0.0, kTop - 0.1};
        platform = world.createBody(p);
        box = addBox(world, kHalf, {0.0, kHalf}, {0.0, launchSpeed});
        world.setPreSolve(OneWay{world.shapes(platform)[0], 4.0 * world.settings().linearSlop});
    }
};

TEST(OneWay, BoxThrownUpThroughPlatformLandsAndRestsOnIt) {
    const double launch = 7.0;  // apex of the centre 0.25 + 49 / 19.62 = 2.75 m: the bottom clears the top by 0.4 m
    Platform s(launch);
    double highest = 0.0;
    const double g = -s.world.settings().gravity.y();
    for (int i = 0; i < 240; ++i) {
        s.world.step(kDt);
        highest = std::max(highest, s.world.position(s.box).y());
        // Up to the apex the box flies free, through the platform: its speed falls by g dt a step and nothing else
        // (to rounding; the platform's contact, disabled, gives no impulse, and once clear it only separates).
        if (i < 40) EXPECT_NEAR(s.world.velocity(s.box).y(), launch - g * kDt * (i + 1), 1e-9) << "step " << i;
    }
    EXPECT_GT(highest - Platform::kHalf, Platform::kTop) << "the box passed up through the platform";
    const double bottom = s.world.position(s.box).y() - Platform::kHalf;
    EXPECT_NEAR(bottom, Platform::kTop, s.world.settings().linearSlop) << "rests on the platform's top";
    EXPECT_TRUE(touching(s.world, s.platform, s.box) || !s.world.isAwake(s.box));
}

TEST(OneWay, BoxStoppingPartlyThroughFallsBack) {
    // Thrown so that its centre stops at the platform's middle (y = 2.0): it straddles the platform at its apex, and
    // must fall back through to the ground, never touching the platform.
    Platform s(std::sqrt(2.0 * 9.81 * (2.0 - Platform::kHalf)));
    double highest = 0.0;
    for (int i = 0; i < 240; ++i) {
        s.world.step(kDt);
        highest = std::max(highest, s.world.position(s.box).y());
        ASSERT_FALSE(hasEvent(s.world.contactEvents().begin, s.platform, s.box)) << "step " << i;
    }
    // At its apex the box was partly through: its top above the platform's bottom (1.9 m), its bottom under the top.
    EXPECT_GT(highest + Platform::kHalf, Platform::kTop - 0.2);
    EXPECT_LT(highest - Platform::kHalf, Platform::kTop);
    EXPECT_NEAR(s.world.position(s.box).y(), Platform::kHalf, 0.02) << "back on the ground";
}

TEST(OneWay, FastBoxesPassUpAndLandThroughTheContinuousStage) {
    // At 12 m/s a box moves 0.2 m a step, more than half its core radius (0.125 m): the Continuous stage sweeps it
    // against the platform, and must ask the hook too, or it would stop the box under the platform every step.
    // Apex of the centre about 0.25 + 144 / 19.62 = 7.6 m; it comes down at about 10 m/s onto the top.
    // The apex of free flight, without the platform, is what the box must reach: the stage stopping it under the
    // platform for a single step leaves it 0.025 m short, so the match is to rounding (1e-9 m).
    auto apex = [](World& world, BodyId box) {
        double highest = 0.0;
        for (int i = 0; i < 240; ++i) {
            world.step(kDt);
            highest = std::max(highest, world.position(box).y());
        }
        return highest;
    };
    for (const CollisionDetection mode :
         {CollisionDetection::Discrete, CollisionDetection::ContinuousExact, CollisionDetection::ContinuousSampled}) {
        World free;
        const BodyId alone = addBox(free, Platform::kHalf, {0.0, Platform::kHalf}, {0.0, 12.0});
        free.setCollisionDetection(alone, mode);
        Platform s(12.0);
        s.world.setCollisionDetection(s.box, mode);
        EXPECT_NEAR(apex(s.world, s.box), apex(free, alone), 1e-9) << "flew free to its apex";
        const double bottom = s.world.position(s.box).y() - Platform::kHalf;
        EXPECT_NEAR(bottom, Platform::kTop, s.world.settings().linearSlop) << "mode " << static_cast<int>(mode);
    }
}

TEST(PreSolve, DisablesExactlyTheContactsItRefuses) {
    WorldSettings settings;
    settings.enableSleep = false;
    World world(settings);
    const BodyId ground = addGround(world);
    const BodyId refused = addBox(world, 0.5, {-2.0, 0.5});
    const BodyId kept = addBox(world, 0.5, {2.0, 0.5});
    std::vector<std::pair<BodyId, BodyId>> asked;
    world.setPreSolve([&](const Manifold& m) {
        EXPECT_GT(m.pointCount, 0);
        asked.emplace_back(m.bodyA, m.bodyB);
        return m.bodyA != refused && m.bodyB != refused;
    });
    world.step(kDt);
    // Both contacts were asked, once each; the refused one is neither listed nor begun, and gave no row.
    ASSERT_EQ(asked.size(), 2u);
    EXPECT_FALSE(touching(world, ground, refused));
    EXPECT_TRUE(touching(world, ground, kept));
    EXPECT_FALSE(hasEvent(world.contactEvents().begin, ground, refused));
    EXPECT_TRUE(hasEvent(world.contactEvents().begin, ground, kept));
    EXPECT_EQ(world.profile().manifolds, 1u);
    for (int i = 0; i < 90; ++i) world.step(kDt);
    EXPECT_LT(world.position(refused).y(), -5.0);  // 1.5 s of free fall: 11 m
    EXPECT_NEAR(world.position(kept).y(), 0.5, world.settings().linearSlop);
    // Disabling a touching contact ends it: an end event at the next step, and the box falls.
    world.setPreSolve([](const Manifold&) { return false; });
    world.step(kDt);
    EXPECT_TRUE(hasEvent(world.contactEvents().end, ground, kept));
    EXPECT_FALSE(touching(world, ground, kept));
    EXPECT_EQ(world.profile().manifolds, 0u);
}

TEST(PreSolve, RowLayoutFollowsTheHookStepByStep) {
    // A box resting on the ground whose contact the hook allows only on even steps: the solver's rows (the layout,
    // kept from step to step while nothing it depends on changes) must follow: one row, none, one, ...
    WorldSettings settings;
    settings.enableSleep = false;
    World world(settings);
    addGround(world);
    const BodyId box = addBox(world, 0.5, {0.0, 0.5});
    world.step(kDt);
    ASSERT_EQ(world.profile().manifolds, 1u);
    int step = 0;
    world.setPreSolve([&](const Manifold&) { return step % 2 == 0; });
    for (step = 0; step < 40; ++step) {
        world.step(kDt);
        EXPECT_EQ(world.profile().manifolds, step % 2 == 0 ? 1u : 0u) << "step " << step;
    }
    // Unset: the contact acts every step again, and the box comes back to rest on the ground.
    world.setPreSolve(nullptr);
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        ASSERT_EQ(world.profile().manifolds, 1u);
    }
    EXPECT_NEAR(world.position(box).y(), 0.5, world.settings().linearSlop);
}

TEST(PreSolve, CalledInAFixedOrderSoRunsRepeat) {
    // Two runs of a pile over a one-way platform: the same calls in the same order, and the same final poses.
    auto runPile = [](std::vector<std::pair<std::uint32_t, std::uint32_t>>& calls) {
        WorldSettings settings;
        settings.threads = 2;
        World world(settings);
        addGround(world);
        BodyDef p;
        p.type = BodyType::Static;
        p.shape = makeBox(3.0, 0.1);
        p.position = {0.0, 1.5};
        const ShapeId platform = world.shapes(world.createBody(p))[0];
        std::vector<BodyId> boxes;
        for (int i = 0; i < 20; ++i)
            boxes.push_back(addBox(world, 0.2, {-2.0 + 0.21 * i, 0.3 + 0.5 * (i % 3)}, {0.0, 4.0 + 0.2 * (i % 5)}));
        const OneWay rule{platform, 0.02};
        world.setPreSolve([&](const Manifold& m) {
            calls.emplace_back(m.shapeA.index, m.shapeB.index);
            return rule(m);
        });
        for (int i = 0; i < 180; ++i) world.step(kDt);
        std::vector<double> poses;
        for (const BodyId b : boxes) {
            poses.push_back(world.position(b).x());
            poses.push_back(world.position(b).y());
        }
        return poses;
    };
    std::vector<std::pair<std::uint32_t, std::uint32_t>> first, second;
    const std::vector<double> a = runPile(first), b = runPile(second);
    EXPECT_FALSE(first.empty());
    EXPECT_EQ(first, second);
    EXPECT_EQ(a, b);  // bit for bit
}

}  // namespace
}  // namespace physim
