// The World with the SAT narrow phase: a box resting flat on a static box keeps two contact points with
// stable feature ids (so warm starting holds it still), and a tilted box settles onto its face.
// Tolerances: a resting box may sink by about the linear slop (5 mm) and drift by rounding; 1e-3 m and
// 1e-3 rad are a few times the slop, far below any visible motion over the 5 s simulated.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace physim {
namespace {

// Sleep off: these tests look at the resting contact itself, which a sleeping body no longer reports.
WorldSettings awake() {
    WorldSettings s;
    s.enableSleep = false;
    return s;
}

struct Scene {
    World world{awake()};
    BodyId ground, box;
};

void build(Scene& s, double boxAngle, double boxY) {
    BodyDef g;
    g.type = BodyType::Static;
    g.shape = makeBox(5.0, 0.5);
    g.position = {0.0, -0.5};  // top face at y = 0
    s.ground = s.world.createBody(g);
    BodyDef b;
    b.shape = makeBox(0.5, 0.5);
    b.position = {0.3, boxY};
    b.angle = boxAngle;
    s.box = s.world.createBody(b);
}

TEST(WorldContact, BoxRestsFlatOnStaticBoxWithTwoStablePoints) {
    Scene s;
    build(s, 0.0, 0.5);
    const double dt = 1.0 / 60.0;
    s.world.step(dt);
    ASSERT_EQ(s.world.contacts().size(), 1u);
    const Manifold first = s.world.contacts()[0];
    ASSERT_EQ(first.pointCount, 2);
    EXPECT_NEAR(first.normal.y(), 1.0, 1e-12);
    for (int i = 0; i < 300; ++i) {
        s.world.step(dt);
        ASSERT_EQ(s.world.contacts().size(), 1u) << "step " << i;
        const Manifold& m = s.world.contacts()[0];
        ASSERT_EQ(m.pointCount, 2) << "step " << i;
        EXPECT_EQ(m.points[0].id, first.points[0].id) << "step " << i;
        EXPECT_EQ(m.points[1].id, first.points[1].id) << "step " << i;
    }
    EXPECT_NEAR(s.world.position(s.box).y(), 0.5, 1e-2);
    EXPECT_NEAR(s.world.position(s.box).x(), 0.3, 1e-3);
    EXPECT_NEAR(s.world.angle(s.box), 0.0, 1e-3);
    EXPECT_LT(s.world.velocity(s.box).norm(), 1e-2);
    // Both points together carry the weight: m g dt over the step (contacts() holds the step's impulses).
    const Manifold& m = s.world.contacts()[0];
    const double weight = s.world.mass(s.box) * 9.81 * dt;
    EXPECT_NEAR(m.points[0].normalImpulse + m.points[1].normalImpulse, weight, 0.05 * weight);
}

TEST(WorldContact, TiltedBoxFallsOntoItsFace) {
    Scene s;
    build(s, 0.3, 1.0);
    for (int i = 0; i < 600; ++i) s.world.step(1.0 / 60.0);
    // A cube dropped on a corner at 0.3 rad tips back onto a face (angle a multiple of pi/2).
    const double a = s.world.angle(s.box);
    const double toFace = std::remainder(a, M_PI / 2);
    EXPECT_NEAR(toFace, 0.0, 1e-2) << "angle " << a;
    EXPECT_NEAR(s.world.position(s.box).y(), 0.5, 1e-2);
    ASSERT_EQ(s.world.contacts().size(), 1u);
    EXPECT_EQ(s.world.contacts()[0].pointCount, 2);
}

}  // namespace
}  // namespace physim
