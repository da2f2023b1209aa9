// The paper's collision-detection API on RigidBody: modes reach the world before and after attachment, bad
// precision is rejected, and checkDiscreteCollision / checkContinuousCollision answer as the paper's
// pseudo-code (section 5.1.2, 5.1.4) would, within the exact method's 1e-4 m tolerance.

#include "physim/core/World.hpp"
#include "physim/framework/RigidBody.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace physim {
namespace {

TEST(RigidBodyCcd, ModeReachesTheWorldBeforeAndAfterAttach) {
    World world;
    RigidBody rb;
    rb.setGeometry(makeCircle(0.01));
    EXPECT_EQ(rb.collisionDetectionMode(), CollisionDetectionMode::DISCRETE);
    rb.setCollisionDetectionMode(CollisionDetectionMode::CONTINUOUS, ContinuousMethod::SAMPLED, 0.05);
    rb.attach(world);
    EXPECT_EQ(world.collisionDetection(rb.bodyId()), CollisionDetection::ContinuousSampled);
    EXPECT_EQ(world.collisionPrecision(rb.bodyId()), 0.05);
    rb.setCollisionDetectionMode(CollisionDetectionMode::CONTINUOUS);
    EXPECT_EQ(world.collisionDetection(rb.bodyId()), CollisionDetection::ContinuousExact);
    EXPECT_EQ(rb.continuousMethod(), ContinuousMethod::EXACT);
    rb.setCollisionDetectionMode(CollisionDetectionMode::DISCRETE);
    EXPECT_EQ(world.collisionDetection(rb.bodyId()), CollisionDetection::Discrete);
    EXPECT_EQ(rb.collisionDetectionMode(), CollisionDetectionMode::DISCRETE);
    rb.detach();
}

TEST(RigidBodyCcd, BadPrecisionNamesTheValue) {
    RigidBody rb;
    for (const double bad : {0.0, 2.0, -0.5, std::nan("")}) {
        try {
            rb.setCollisionDetectionMode(CollisionDetectionMode::CONTINUOUS, ContinuousMethod::SAMPLED, bad);
            ADD_FAILURE() << bad;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("precision"), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(rb.precision(), kDefaultPrecision) << "nothing changed";
}

TEST(RigidBodyCcd, PaperChecksFindTheWallOrTunnel) {
    RigidBody ball, wall;
    ball.setGeometry(makeCircle(0.01));
    wall.setGeometry(makeBox(0.005, 1.0));
    wall.setPose({1.0, 0.0}, 0.0);
    ball.setPose({0.035, 0.0}, 0.0);
    // Discrete: only the final position counts, so a target beyond the wall is "no collision" (tunnelling).
    EXPECT_FALSE(ball.checkDiscreteCollision({2.0, 0.0}, wall));
    EXPECT_TRUE(ball.checkDiscreteCollision({0.99, 0.0}, wall));
    // Sampled at 0.1 from 0.035 to 2.035: positions 0.035 + 0.2 k miss the window [0.985, 1.015]...
    ball.setCollisionDetectionMode(CollisionDetectionMode::CONTINUOUS, ContinuousMethod::SAMPLED, 0.1);
    EXPECT_FALSE(ball.checkContinuousCollision({2.035, 0.0}, wall).has_value());
    // ...at 0.01 (positions 0.035 + 0.02 k) the first inside is 0.995.
    ball.setCollisionDetectionMode(CollisionDetectionMode::CONTINUOUS, ContinuousMethod::SAMPLED, 0.01);
    const auto sampled = ball.checkContinuousCollision({2.035, 0.0}, wall);
    ASSERT_TRUE(sampled.has_value());
    EXPECT_NEAR(sampled->x(), 0.995, 1e-12);
    // Exact: the contact position 0.985, from the near side, within the tolerance.
    ball.setCollisionDetectionMode(CollisionDetectionMode::CONTINUOUS, ContinuousMethod::EXACT);
    const auto exact = ball.checkContinuousCollision({2.035, 0.0}, wall);
    ASSERT_TRUE(exact.has_value());
    EXPECT_LE(exact->x(), 0.985);
    EXPECT_GE(exact->x(), 0.985 - kToiTolerance);
}

}  // namespace
}  // namespace physim
