// Bad input at the World's boundary: each case is refused with std::invalid_argument naming the value, and the
// world is left bit-identical and still stepping. The first cases are what fuzzing found (support/Fuzz.hpp).

#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;

// A small scene to refuse things in: ground, a box resting on it, a disc hanging from the box by a rod.
struct Scene {
    World world{test::awakeSettings()};
    std::vector<BodyId> ids;
    JointId rod;
    Scene() {
        ids.push_back(test::addGround(world, 10.0));
        ids.push_back(test::addBox(world, {0.0, 0.5}, 0.5, 0.5));
        BodyDef d;
        d.shape = makeCircle(0.2);
        d.position = {2.0, 0.5};
        ids.push_back(world.createBody(d));
        DistanceJointDef j;
        j.bodyA = ids[1];
        j.bodyB = ids[2];
        rod = world.createDistanceJoint(j);
        world.step(kDt);
    }
    // `call` must throw std::invalid_argument whose message holds `named`, and change nothing.
    void expectRefused(const std::function<void()>& call, const std::string& named) {
        const std::uint64_t before = test::stateHash(world, ids);
        const std::size_t bodies = world.bodyCount(), joints = world.jointCount();
        try {
            call();
            ADD_FAILURE() << "accepted; expected a refusal naming " << named;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(named), std::string::npos) << e.what();
        }
        EXPECT_EQ(test::stateHash(world, ids), before);
        EXPECT_EQ(world.bodyCount(), bodies);
        EXPECT_EQ(world.jointCount(), joints);
        world.step(kDt);
        for (const BodyId id : ids) EXPECT_TRUE(std::isfinite(world.position(id).y()));
    }
};

// Fuzzing found a static body placed at y = 1e300 accepted; a joint to it then made its partner NaN.
TEST(StabilityBadInput, HugeCoordinatesAndSpeedsAreRefused) {
    Scene s;
    BodyDef far;
    far.position = {0.0, 1e300};
    s.expectRefused([&] { s.world.createBody(far); }, "e+300");
    s.expectRefused([&] { s.world.setTransform(s.ids[1], {2e10, 0.0}, 0.0); }, "20000000000");
    s.expectRefused([&] { s.world.setVelocity(s.ids[1], {0.0, -1e9}); }, "-1000000000");
    s.expectRefused([&] { s.world.setAngularVelocity(s.ids[1], 1e300); }, "e+300");
    s.expectRefused([&] { s.world.applyForceAtPoint(s.ids[1], {1.0, 0.0}, {1e11, 0.0}); }, "100000000000");
    DistanceJointDef j;
    j.bodyA = s.ids[1];
    j.bodyB = s.ids[2];
    j.length = 1e300;
    s.expectRefused([&] { s.world.createDistanceJoint(j); }, "e+300");
}

// Fuzzing found a density of 1e-300 accepted: the body's inverse inertia was infinite. A refused body takes no
// slot: the next body gets the index it would have had.
TEST(StabilityBadInput, VanishingOrHugeMassIsRefusedWithoutTakingASlot) {
    Scene s;
    BodyDef light;
    light.density = 1e-300;
    s.expectRefused([&] { s.world.createBody(light); }, "mass");
    BodyDef heavy;
    heavy.density = 1e300;
    s.expectRefused([&] { s.world.createBody(heavy); }, "mass");
    s.expectRefused([&] { s.world.setMass(s.ids[1], 1e-20); }, "body mass");
    EXPECT_EQ(s.world.createBody(BodyDef{}).index, 3u);
}

// Fuzzing found a mouse joint of 1e300 Hz accepted and turned into NaN. Every soft spring is now capped at a
// quarter of the substep rate, so such a joint is simply as stiff as the solver allows: the body reaches the
// target (1 cm) and stays finite.
TEST(StabilityBadInput, AnAbsurdlyStiffMouseJointIsCappedNotNaN) {
    Scene s;
    MouseJointDef m;
    m.body = s.ids[2];
    m.target = {2.0, 3.0};
    m.hertz = 1e300;
    m.maxForce = 1e4;
    s.world.createMouseJoint(m);
    for (int i = 0; i < 120; ++i) s.world.step(kDt);
    EXPECT_LT((s.world.position(s.ids[2]) - m.target).norm(), 0.01);
}

// Destroying twice: the second call names the stale handle and changes nothing.
TEST(StabilityBadInput, DestroyingTwiceIsRefused) {
    Scene s;
    s.world.destroyJoint(s.rod);
    s.expectRefused([&] { s.world.destroyJoint(s.rod); }, "joint id");
    const BodyId disc = s.ids.back();
    s.world.destroyBody(disc);
    s.ids.pop_back();
    s.expectRefused([&] { s.world.destroyBody(disc); }, "body id");
    s.expectRefused([&] { s.world.destroyBody(BodyId{}); }, "body id");
}

// Enums outside their range, through every entry point that takes one.
TEST(StabilityBadInput, EnumsOutsideTheirRangeAreRefused) {
    Scene s;
    BodyDef d;
    d.type = static_cast<BodyType>(-1);
    s.expectRefused([&] { s.world.createBody(d); }, "-1");
    d.type = BodyType::Dynamic;
    d.collisionDetection = static_cast<CollisionDetection>(3);
    s.expectRefused([&] { s.world.createBody(d); }, "3");
    s.expectRefused([&] { s.world.setType(s.ids[1], static_cast<BodyType>(3)); }, "3");
    s.expectRefused([&] { s.world.setCollisionDetection(s.ids[1], static_cast<CollisionDetection>(9)); }, "9");
}

}  // namespace
}  // namespace physim
