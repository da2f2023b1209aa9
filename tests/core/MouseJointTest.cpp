// Mouse joints: a soft spring-damper (implicit Euler) from a body's point to a target, its force clamped.
// Checked against the implicit spring-damper recurrence step by step, its static sag g / w^2, the clamp's
// reduced free fall, contacts winning over the pull, and bad input.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kG = 9.81;

WorldSettings noSleep(const Vec2& gravity = {0.0, -kG}) {
    WorldSettings s;
    s.gravity = gravity;
    s.enableSleep = false;
    return s;
}

// A 1 kg disc (radius 0.2 m) at `position`, its rotation locked so the joint sees the point mass m.
BodyId disc(World& world, const Vec2& position) {
    BodyDef def;
    def.shape = makeCircle(0.2);
    def.position = position;
    def.fixedRotation = true;
    const BodyId id = world.createBody(def);
    world.setMass(id, 1.0);
    return id;
}

MouseJointDef grab(BodyId body, const Vec2& target, double hertz = 5.0, double dampingRatio = 0.7) {
    MouseJointDef def;
    def.body = body;
    def.target = target;
    def.maxForce = 1000.0 * kG;  // 1 kg: a thousand times its weight
    def.hertz = hertz;
    def.dampingRatio = dampingRatio;
    return def;
}

// Implicit Euler of m x'' = -k x - d x' over one substep h: m (v' - v) = -h (k x' + d v'), x' = x + h v'.
// The joint must follow this recurrence; rounding over a few hundred substeps stays below 1e-12 m.
TEST(MouseJoint, FollowsTheImplicitSpringDamperStepByStep) {
    for (const double zeta : {0.0, 0.3, 1.0}) {
        World world(noSleep(Vec2::Zero()));
        const BodyId body = disc(world, {0.5, -0.2});
        world.createMouseJoint(grab(body, Vec2::Zero(), 3.0, zeta));
        const double m = 1.0, w = 2 * M_PI * 3.0, k = m * w * w, d = 2 * m * zeta * w;
        const double h = kDt / world.settings().substeps;
        Vec2 x(0.5, -0.2), v = Vec2::Zero();
        for (int step = 0; step < 120; ++step) {
            world.step(kDt);
            for (int s = 0; s < world.settings().substeps; ++s) {
                v = (m * v - h * k * x) / (m + h * d + h * h * k);
                x += h * v;
            }
            ASSERT_NEAR((world.position(body) - x).norm(), 0.0, 1e-12) << "zeta " << zeta << ", step " << step;
            ASSERT_NEAR((world.velocity(body) - v).norm(), 0.0, 1e-10) << "zeta " << zeta << ", step " << step;
        }
    }
}

// Undamped, the anchor oscillates about the target at `hertz`: implicit Euler turns by atan(w h) per substep
// instead of w h, lengthening the period by w h / atan(w h) = 0.6% at 5 Hz and h = 1/240 s. 1% allows that.
TEST(MouseJoint, UndampedPullOscillatesAtItsFrequency) {
    World world(noSleep(Vec2::Zero()));
    const BodyId body = disc(world, {0.3, 0.0});
    world.createMouseJoint(grab(body, Vec2::Zero(), 5.0, 0.0));
    std::vector<double> upCrossings;
    double t = 0.0, x = 0.3;
    while (upCrossings.size() < 4) {
        world.step(kDt);
        t += kDt;
        const double nx = world.position(body).x();
        if (x < 0.0 && nx >= 0.0) upCrossings.push_back(t - kDt * nx / (nx - x));
        x = nx;
        ASSERT_LT(t, 5.0);
    }
    const double period = (upCrossings.back() - upCrossings.front()) / 3.0;
    EXPECT_NEAR(period, 0.2, 0.01 * 0.2);
}

// Held still against gravity, the spring stretches until k C = m g: the anchor hangs g / w^2 below the target
// (9.9 mm at 5 Hz). After 4 s of damping ratio 0.7 (exp(-zeta w t) = 1e-38) the sag is exact to rounding.
TEST(MouseJoint, HoldsAWeightSagging_g_OverOmegaSquared) {
    World world(noSleep());
    const BodyId body = disc(world, {1.0, 2.0});
    world.createMouseJoint(grab(body, {1.0, 2.0}));
    for (int i = 0; i < 240; ++i) world.step(kDt);
    const double w = 2 * M_PI * 5.0;
    EXPECT_NEAR(world.position(body).y(), 2.0 - kG / (w * w), 1e-9);
    EXPECT_NEAR(world.position(body).x(), 1.0, 1e-12);
    EXPECT_LT(world.velocity(body).norm(), 1e-9);
}

// A pull capped at half the weight, towards a target 1 m above (the spring asks for 100 times the weight):
// the disc falls with g / 2. Semi-implicit Euler at substep h puts it at -(g / 2) h^2 n (n + 1) / 2 after n
// substeps (the free-fall test's formula with half of g).
TEST(MouseJoint, MaxForceCapsThePull) {
    World world(noSleep());
    const BodyId body = disc(world, Vec2::Zero());
    MouseJointDef def = grab(body, {0.0, 1.0});
    def.maxForce = 0.5 * kG;
    world.createMouseJoint(def);
    for (int i = 0; i < 30; ++i) world.step(kDt);
    const double h = kDt / world.settings().substeps;
    const double n = 30.0 * world.settings().substeps;
    EXPECT_NEAR(world.position(body).y(), -0.5 * kG * h * h * n * (n + 1) / 2, 1e-9);
}

// The pull is a force; contacts are constraints. Dragged 2 m into a static wall with up to 1000 times its
// weight, a disc stops at the wall's face. It arrives at 31 m/s, so the step that finds the contact overlaps by
// up to one substep of travel (13 mm measured, 128 mm possible); the position passes then bring the overlap
// back to the linearSlop (5 mm) that every resting contact keeps, and it stays there against the pull.
TEST(MouseJoint, DraggedBodyStopsAtAWall) {
    World world(noSleep(Vec2::Zero()));
    BodyDef wall;
    wall.type = BodyType::Static;
    wall.shape = makeBox(0.5, 2.0);
    wall.position = {1.5, 0.0};  // face at x = 1
    world.createBody(wall);
    const BodyId body = disc(world, Vec2::Zero());
    const JointId joint = world.createMouseJoint(grab(body, {3.0, 0.0}));
    double deepest = 0.0;
    for (int i = 0; i < 180; ++i) {
        world.step(kDt);
        deepest = std::max(deepest, world.position(body).x() + 0.2 - 1.0);
    }
    const double slop = world.settings().linearSlop;
    EXPECT_LT(deepest, 31.0 * kDt / world.settings().substeps) << "never deeper than one substep of travel";
    EXPECT_NEAR(world.position(body).x() + 0.2 - 1.0, slop, 1e-4) << "resting against the face";
    world.setMouseJointTarget(joint, {-1.0, 0.5});  // and follows the cursor back out
    for (int i = 0; i < 120; ++i) world.step(kDt);
    EXPECT_LT((world.position(body) - Vec2(-1.0, 0.5)).norm(), 1e-3);
}

// A dragged body pushes a free one ahead of it; momentum goes to the other through the contact.
TEST(MouseJoint, DraggedBodyPushesOthers) {
    World world(noSleep(Vec2::Zero()));
    const BodyId pushed = disc(world, {0.5, 0.0});
    const BodyId body = disc(world, Vec2::Zero());
    world.createMouseJoint(grab(body, {3.0, 0.0}, 2.0, 1.0));
    for (int i = 0; i < 120; ++i) world.step(kDt);
    EXPECT_GT(world.position(pushed).x(), 3.0) << "the free disc was pushed ahead of the dragged one";
    EXPECT_GT((world.position(pushed) - world.position(body)).norm(), 0.4 - world.settings().linearSlop - 1e-3);
}

// A box grabbed by a corner swings about it. The implicit spring only removes energy; what remains is
// symplectic Euler's bounded O(h) wobble of kinetic + potential + the spring's k C^2 / 2 (2.4e-4 J measured
// on a swing whose potential energy spans 2.8 J). 1e-3 J bounds the wobble; over 10 s the energy must fall.
TEST(MouseJoint, OffCentreGrabAddsNoEnergy) {
    World world(noSleep());
    BodyDef def;
    def.shape = makeBox(0.4, 0.2);
    const BodyId box = world.createBody(def);
    MouseJointDef grabDef = grab(box, {0.4, 0.2}, 5.0, 0.0);
    grabDef.localAnchor = {0.4, 0.2};
    world.createMouseJoint(grabDef);
    const double m = world.mass(box), I = world.inertia(box), k = m * std::pow(2 * M_PI * 5.0, 2);
    const auto energy = [&] {
        const Vec2 anchor = world.transform(box).apply({0.4, 0.2});
        const double w = world.angularVelocity(box);
        return 0.5 * m * world.velocity(box).squaredNorm() + 0.5 * I * w * w + m * kG * world.position(box).y() +
               0.5 * k * (anchor - Vec2(0.4, 0.2)).squaredNorm();
    };
    const double start = energy();
    double swing = 0.0;
    for (int i = 0; i < 600; ++i) {
        world.step(kDt);
        ASSERT_LE(energy(), start + 1e-3) << "step " << i;
        swing = std::max(swing, std::abs(world.angle(box)));
    }
    EXPECT_LT(energy(), start);
    EXPECT_GT(swing, 1.0) << "it did swing about the corner";
}

void expectThrowsNaming(const std::function<void()>& call, const std::string& name) {
    try {
        call();
        ADD_FAILURE() << "no exception; expected one naming " << name;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
}

TEST(MouseJoint, BadInputIsRefusedByName) {
    World world;
    const BodyId body = disc(world, Vec2::Zero());
    BodyDef ground;
    ground.type = BodyType::Static;
    const BodyId fixed = world.createBody(ground);
    const auto with = [&](auto change) {
        MouseJointDef def = grab(body, Vec2::Zero());
        change(def);
        return [&world, def] { world.createMouseJoint(def); };
    };
    expectThrowsNaming(with([&](MouseJointDef& d) { d.body = fixed; }), "dynamic");
    expectThrowsNaming(with([&](MouseJointDef& d) { d.body = BodyId{}; }), "not a live body");
    expectThrowsNaming(with([](MouseJointDef& d) { d.target = {NAN, 0.0}; }), "target");
    expectThrowsNaming(with([](MouseJointDef& d) { d.localAnchor = {0.0, INFINITY}; }), "anchor");
    expectThrowsNaming(with([](MouseJointDef& d) { d.maxForce = 0.0; }), "maxForce");
    expectThrowsNaming(with([](MouseJointDef& d) { d.maxForce = NAN; }), "maxForce");
    expectThrowsNaming(with([](MouseJointDef& d) { d.hertz = -1.0; }), "hertz");
    expectThrowsNaming(with([](MouseJointDef& d) { d.dampingRatio = -0.1; }), "dampingRatio");
    EXPECT_EQ(world.jointCount(), 0u) << "nothing was created";

    const JointId joint = world.createMouseJoint(grab(body, Vec2::Zero()));
    expectThrowsNaming([&] { world.setMouseJointTarget(joint, {0.0, NAN}); }, "target");
    EXPECT_THROW(world.jointLength(joint), std::invalid_argument);
    DistanceJointDef rod;
    rod.bodyA = fixed;
    rod.bodyB = body;
    rod.localAnchorA = {0.0, 1.0};
    const JointId distance = world.createDistanceJoint(rod);
    expectThrowsNaming([&] { world.setMouseJointTarget(distance, Vec2::Zero()); }, "mouse joint");
}

TEST(MouseJoint, LifetimeGettersAndWaking) {
    World world;  // sleep on
    const BodyId body = disc(world, {0.0, 1.0});
    const JointId joint = world.createMouseJoint(grab(body, {0.0, 1.0}));
    EXPECT_EQ(world.jointType(joint), JointType::Mouse);
    EXPECT_EQ(world.joints().size(), 1u);
    for (int i = 0; i < 120; ++i) world.step(kDt);
    EXPECT_FALSE(world.isAwake(body)) << "held still, it sleeps like any resting body";
    world.setMouseJointTarget(joint, {1.0, 1.0});
    EXPECT_TRUE(world.isAwake(body)) << "moving the target wakes it";
    for (int i = 0; i < 120; ++i) world.step(kDt);
    const auto [target, anchor] = world.jointAnchors(joint);
    EXPECT_EQ(target, Vec2(1.0, 1.0));
    EXPECT_LT((anchor - target).norm(), 0.011) << "within the sag g / w^2 of the target";

    world.destroyJoint(joint);
    EXPECT_FALSE(world.contains(joint));
    EXPECT_EQ(world.jointCount(), 0u);
    const double y = world.position(body).y();
    world.step(kDt);
    EXPECT_LT(world.velocity(body).y(), 0.0) << "released, it falls";
    EXPECT_LT(world.position(body).y(), y);

    const JointId again = world.createMouseJoint(grab(body, Vec2::Zero()));
    world.destroyBody(body);
    EXPECT_FALSE(world.contains(again)) << "the joint goes with its body";
    EXPECT_TRUE(world.joints().empty());
    EXPECT_TRUE(world.bodies().empty());
}

}  // namespace
}  // namespace physim
