// Persistent contacts (src/core/Contacts.cpp): a pair that has hardly moved relative to itself keeps its last
// collision and rebuilds the manifold from it at the present poses. Checked against a fresh collision of the same
// shapes at the same poses, step after step, in scenes where pairs rest, creep, slide, tip and roll.

#include "Manifolds.hpp"
#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;

BodyId add(World& world, BodyType type, Geometry shape, Vec2 at, double angle = 0.0, Vec2 velocity = Vec2::Zero(),
           double spin = 0.0) {
    BodyDef d;
    d.type = type;
    d.shape = shape;
    d.position = at;
    d.angle = angle;
    d.velocity = velocity;
    d.angularVelocity = spin;
    return world.createBody(d);
}

// A settling base-6 pyramid, a box sliding to a stop, a box tipping over a ledge, a ball rolling to the side and a
// box tumbling onto the ground: pairs that rest (kept manifolds), creep (kept, then collided again) and move
// fast (collided every step).
std::vector<BodyId> buildScene(World& world) {
    std::vector<BodyId> ids;
    ids.push_back(add(world, BodyType::Static, makeBox(30.0, 0.5), {0.0, -0.5}));
    for (int row = 0; row < 6; ++row)
        for (int col = 0; col < 6 - row; ++col)
            ids.push_back(add(world, BodyType::Dynamic, makeBox(0.5, 0.5), {(col - 0.5 * (5 - row)) * 1.0, 0.5 + row}));
    ids.push_back(add(world, BodyType::Dynamic, makeBox(0.4, 0.2), {8.0, 0.2}, 0.0, {1.5, 0.0}));
    ids.push_back(add(world, BodyType::Static, makeBox(1.0, 1.0), {-12.0, 1.0}));
    ids.push_back(add(world, BodyType::Dynamic, makeBox(0.5, 0.5), {-11.2, 2.5}));
    ids.push_back(add(world, BodyType::Dynamic, makeCircle(0.3), {14.0, 0.3}, 0.0, {-0.5, 0.0}, 0.5 / 0.3));
    ids.push_back(add(world, BodyType::Dynamic, makeBox(0.6, 0.3), {20.0, 2.0}, 0.7, Vec2::Zero(), 3.0));
    return ids;
}

// Every point the world reports (touching, or speculative up to the speculative distance apart) is where a fresh
// collision of the two shapes, at the poses the step started from and with the point's separation as its margin,
// puts the point with the same feature id: within the reuse tolerance (a tenth of the linear slop) along the
// surfaces, and within 1e-5 m in separation. A kept manifold's separation is
// measured at the present poses from points that lag by at most the tolerance along faces that have turned
// by at most the tolerance over the body's size, so its error is of order tolerance^2 / size (~1e-6 m here).
TEST(Contacts, AKeptManifoldMatchesAFreshCollisionAtThePresentPoses) {
    WorldSettings settings;
    settings.enableSleep = false;
    World world(settings);
    const std::vector<BodyId> ids = buildScene(world);
    const double tolerance = 0.1 * settings.linearSlop;
    auto slot = [&](BodyId id) { return std::find(ids.begin(), ids.end(), id) - ids.begin(); };

    double worstPoint = 0.0, worstSeparation = 0.0;
    int checked = 0;
    for (int step = 0; step < 240; ++step) {
        std::vector<Transform> before;
        for (const BodyId id : ids) before.push_back(world.transform(id));
        world.step(kDt);
        for (const Manifold& m : world.contacts()) {
            for (int p = 0; p < m.pointCount; ++p) {
                const ContactPoint& kept = m.points[p];
                const Manifold fresh =
                    collideGeometries(world.shape(m.bodyA), before[static_cast<std::size_t>(slot(m.bodyA))],
                                      world.shape(m.bodyB), before[static_cast<std::size_t>(slot(m.bodyB))],
                                      std::max(kept.separation, 0.0) + tolerance)
                        .manifold;
                const ContactPoint* match = nullptr;
                for (int q = 0; q < fresh.pointCount; ++q)
                    if (fresh.points[q].id == kept.id) match = &fresh.points[q];
                ASSERT_NE(match, nullptr) << "step " << step << ": point " << kept.id << " of bodies "
                                          << m.bodyA.index << ", " << m.bodyB.index << " has no fresh twin";
                worstPoint = std::max(worstPoint, (kept.point - match->point).norm());
                worstSeparation = std::max(worstSeparation, std::abs(kept.separation - match->separation));
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 10000);
    EXPECT_LE(worstPoint, tolerance + 1e-9);
    EXPECT_LE(worstSeparation, 1e-5);
}

// A contact lives while its bodies' proxies overlap. After a step in which nothing moved, the narrow phase takes
// the overlap as known; a ball that then leaves slowly (its proxy moved by the step, not by a call) must still lose
// its contact once its proxy no longer overlaps the ground's.
TEST(Contacts, AContactEndsWhenItsProxiesPartAfterRestingSteps) {
    WorldSettings settings;
    settings.gravity = {0.0, 0.0};  // the ball stays where it is put, at rest, then drifts off at a set speed
    settings.enableSleep = false;
    World world(settings);
    add(world, BodyType::Static, makeBox(5.0, 0.5), {0.0, -0.5});
    const BodyId ball = add(world, BodyType::Dynamic, makeCircle(0.25), {0.0, 0.25});
    for (int i = 0; i < 30; ++i) world.step(kDt);
    ASSERT_EQ(world.profile().candidatePairs, 1u) << "the resting ball's contact";
    world.setVelocity(ball, {0.0, 1.0});  // 1 m/s up: the proxy (a 0.1 m margin) is outgrown within a few steps
    int parted = -1;
    for (int i = 0; i < 120 && parted < 0; ++i) {
        world.step(kDt);
        if (world.profile().candidatePairs == 0) parted = i;
    }
    EXPECT_GE(parted, 0) << "the contact ended";
    EXPECT_LT(world.position(ball).y(), 2.5) << "within two metres of leaving";
}

}  // namespace
}  // namespace physim
