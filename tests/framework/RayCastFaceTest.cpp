// Rays and point queries from the paper's face: Simulation::castRay answers as World::castRayClosest and names the
// Object it hit; objectsAt finds the Objects containing a point; with debugDraw.rays on, the rays are kept to draw.

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>

#include <gtest/gtest.h>

namespace physim {
namespace {

const sf::Color kColor(40, 160, 90);

TEST(RayCastFace, SimulationRayNamesTheObjectItHits) {
    Simulation sim;
    Object& ball = sim.spawn<Object>(CircleShape(0.5), kColor);
    ball.setPosition({3.0, 0.0});
    Object& box = sim.spawn<Object>(Vec2(1.0, 1.0));
    box.setPosition({6.0, 0.0});
    // From the origin along +x by 10 m: the ball's left point at x = 2.5, fraction 0.25 (exact).
    const auto hit = sim.castRay(Vec2::Zero(), Vec2(10.0, 0.0));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->object, &ball);
    EXPECT_EQ(hit->hit.fraction, 0.25);
    EXPECT_EQ(hit->hit.body, ball.rb.bodyId());
    EXPECT_EQ(sim.objectOf(box.rb.bodyId()), &box);
    // Past the ball (from inside it, which the ray does not hit): the box's face at x = 5.5.
    const auto next = sim.castRay(Vec2(3.0, 0.0), Vec2(10.0, 0.0));
    ASSERT_TRUE(next);
    EXPECT_EQ(next->object, &box);
    EXPECT_DOUBLE_EQ(next->hit.fraction, 0.25);
    EXPECT_FALSE(sim.castRay(Vec2(0.0, 2.0), Vec2(10.0, 0.0)));
    EXPECT_EQ(sim.objectsAt(Vec2(6.2, 0.3)), std::vector<Object*>{&box});
    EXPECT_TRUE(sim.objectsAt(Vec2(4.4, 0.0)).empty());
}

TEST(RayCastFace, RaysAreKeptForDrawingWhenAsked) {
    Simulation sim;
    sim.spawn<Object>(CircleShape(0.5), kColor);
    sim.castRay(Vec2(-5.0, 0.0), Vec2(10.0, 0.0));
    EXPECT_TRUE(sim.debugRays().empty());  // drawing rays is off
    sim.debugDraw.rays = true;
    sim.castRay(Vec2(-5.0, 0.0), Vec2(10.0, 0.0));
    sim.castRay(Vec2(-5.0, 3.0), Vec2(10.0, 0.0));
    ASSERT_EQ(sim.debugRays().size(), 2u);
    ASSERT_TRUE(sim.debugRays()[0].hit);
    EXPECT_DOUBLE_EQ(sim.debugRays()[0].hit->fraction, 0.45);
    EXPECT_FALSE(sim.debugRays()[1].hit);
    sim.fixedStep();  // a new step: the last step's rays are dropped
    EXPECT_TRUE(sim.debugRays().empty());
}

}  // namespace
}  // namespace physim
