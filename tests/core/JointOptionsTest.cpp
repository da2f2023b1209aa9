// What every joint kind shares (JointDefBase): bodies joined by a joint meet only through it unless
// collideConnected, and a joint breaks when what it applies crosses breakForce or breakTorque.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kG = 9.81;

BodyId box(World& world, const Vec2& at, double half = 0.5) {
    BodyDef d;
    d.shape = makeBox(half, half);
    d.position = at;
    return world.createBody(d);
}

// Whether the last step left a touching contact between the two bodies.
bool touching(const World& world, BodyId a, BodyId b) {
    for (const Manifold& m : world.contacts())
        if ((m.bodyA == a && m.bodyB == b) || (m.bodyA == b && m.bodyB == a)) return true;
    return false;
}

// Two 1 m boxes overlapping by half their width, pinned where they overlap, no gravity. With nothing but the pin
// between them nothing acts, so they stay exactly at rest; colliding, their overlap pushes them apart against it.
struct OverlappingPair {
    World world{test::awakeSettings(Vec2::Zero())};
    BodyId left = box(world, {0.0, 0.0});
    BodyId right = box(world, {0.5, 0.0});

    JointId pin(bool collideConnected) {
        RevoluteJointDef def;
        def.bodyA = left;
        def.bodyB = right;
        def.anchor = {0.25, 0.0};
        def.collideConnected = collideConnected;
        return world.createRevoluteJoint(def);
    }
    double speed() const { return world.velocity(left).norm() + world.velocity(right).norm(); }
};

TEST(JointedBodiesDoNotCollide, ByDefault) {
    OverlappingPair p;
    p.pin(false);
    for (int i = 0; i < 60; ++i) p.world.step(kDt);
    EXPECT_FALSE(touching(p.world, p.left, p.right));
    EXPECT_EQ(p.speed(), 0.0) << "no contact: nothing acts on them";
    EXPECT_EQ(p.world.position(p.right), Vec2(0.5, 0.0));
}

TEST(JointedBodiesDoNotCollide, UnlessCollideConnected) {
    OverlappingPair p;
    p.pin(true);
    p.world.step(kDt);
    EXPECT_TRUE(touching(p.world, p.left, p.right));
    // The soft push-out moves them (some cm/s, capped by maxPushVelocity) where nothing moves them without contact.
    EXPECT_GT(p.speed(), 1e-3) << "their overlap pushes them apart against the pin";
}

TEST(JointedBodiesDoNotCollide, AJointEndsTheirContactAndGivesItBackWhenDestroyed) {
    OverlappingPair p;
    p.world.step(kDt);
    ASSERT_TRUE(touching(p.world, p.left, p.right)) << "unjoined, the overlap is a contact";
    p.world.setVelocity(p.left, Vec2::Zero());
    p.world.setVelocity(p.right, Vec2::Zero());
    const JointId pin = p.pin(false);
    p.world.step(kDt);
    EXPECT_FALSE(touching(p.world, p.left, p.right)) << "the new joint removed their contact";
    p.world.destroyJoint(pin);
    p.world.step(kDt);
    EXPECT_TRUE(touching(p.world, p.left, p.right)) << "without the joint they collide again";
}

// A 1 kg box hanging from a pivot on a 1 m rod: at rest the rod pulls m g = 9.81 N.
struct Hanging {
    World world{test::awakeSettings()};
    BodyId pivot = test::addStaticPivot(world);
    BodyId weight;
    JointId rod;

    explicit Hanging(double breakForce) {
        BodyDef d;
        d.shape = makeBox(0.1, 0.1);
        d.position = {0.0, -1.0};
        d.collides = false;
        weight = world.createBody(d);
        world.setMass(weight, 1.0);
        DistanceJointDef def;
        def.bodyA = pivot;
        def.bodyB = weight;
        def.breakForce = breakForce;
        rod = world.createDistanceJoint(def);
    }
};

TEST(JointBreak, HoldsBelowItsThresholdAndBreaksAboveIt) {
    Hanging h(2.0 * kG);  // twice the weight
    for (int i = 0; i < 60; ++i) h.world.step(kDt);
    ASSERT_TRUE(h.world.contains(h.rod));
    EXPECT_TRUE(h.world.jointEvents().broken.empty());
    // Pulled down with two more weights, the rod must hold 3 m g: more than its 2 m g.
    int brokeAt = -1;
    for (int i = 0; i < 10 && brokeAt < 0; ++i) {
        h.world.applyForce(h.weight, {0.0, -2.0 * kG});
        h.world.step(kDt);
        if (!h.world.jointEvents().broken.empty()) brokeAt = i;
    }
    ASSERT_EQ(brokeAt, 0) << "the first step that loads it past the threshold breaks it";
    const JointBreakEvent& e = h.world.jointEvents().broken.front();
    EXPECT_EQ(e.joint, h.rod);
    EXPECT_EQ(e.bodyB, h.weight);
    EXPECT_GT(e.force.norm(), 2.0 * kG);
    EXPECT_FALSE(h.world.contains(h.rod));
    EXPECT_EQ(h.world.jointCount(), 0u);
    // Free now: it falls at g (a part in 1e-9: only rounding, no drag, nothing holds it).
    const double v0 = h.world.velocity(h.weight).y();
    h.world.step(kDt);
    EXPECT_NEAR((h.world.velocity(h.weight).y() - v0) / kDt, -kG, 1e-9 * kG);
    EXPECT_TRUE(h.world.jointEvents().broken.empty()) << "events are the last step's";
}

// A 2 m beam welded to a wall at its end must hold the moment m g L / 2 of its weight.
TEST(JointBreak, AWeldBreaksOnTorque) {
    for (const double share : {0.9, 1.1}) {
        World world(test::awakeSettings());
        const BodyId wall = test::addStaticPivot(world);
        BodyDef d;
        d.shape = makeBox(1.0, 0.05);
        d.position = {1.0, 0.0};
        d.collides = false;
        const BodyId beam = world.createBody(d);
        WeldJointDef weld;
        weld.bodyA = wall;
        weld.bodyB = beam;
        weld.breakTorque = share * world.mass(beam) * kG * 1.0;
        const JointId j = world.createWeldJoint(weld);
        for (int i = 0; i < 30; ++i) world.step(kDt);
        EXPECT_EQ(world.contains(j), share > 1.0) << "breakTorque " << share << " of the moment";
    }
}

TEST(JointBreak, BadThresholdsAreRefusedAndTheWorldUnchanged) {
    for (const double bad : {0.0, -1.0, std::nan("")}) {
        World world(test::awakeSettings());
        const BodyId pivot = test::addStaticPivot(world);
        const BodyId b = box(world, {0.0, -1.0});
        DistanceJointDef def;
        def.bodyA = pivot;
        def.bodyB = b;
        def.breakForce = bad;
        EXPECT_THROW(world.createDistanceJoint(def), std::invalid_argument) << bad;
        def.breakForce = std::numeric_limits<double>::infinity();
        def.breakTorque = bad;
        EXPECT_THROW(world.createDistanceJoint(def), std::invalid_argument) << bad;
        EXPECT_EQ(world.jointCount(), 0u);
    }
}

}  // namespace
}  // namespace physim
