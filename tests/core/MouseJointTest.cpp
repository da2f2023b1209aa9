// Mouse joints: a soft spring-damper from a body's point to a target, its force clamped, solved in the soft step.
// Checked against the exact damped oscillator (first-order convergence in the substep), its frequency, its
// static sag g / w^2, the clamp's reduced free fall, contacts winning over the pull, and bad input.

#include "physim/core/World.hpp"

#include "support/ThrowsNaming.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

// x(t) of x'' + 2 zeta w x' + w^2 x = 0 from rest at x0.
double dampedOscillator(double x0, double zeta, double w, double t) {
    if (zeta >= 1.0) return x0 * std::exp(-w * t) * (1.0 + w * t);  // critical (the only zeta >= 1 used)
    const double wd = w * std::sqrt(1.0 - zeta * zeta);
    return x0 * std::exp(-zeta * w * t) * (std::cos(wd * t) + zeta * w / wd * std::sin(wd * t));
}

// A point mass (rotation locked) on the joint is the damped oscillator m x'' = -k x - d x' with k = m w^2 and
// d = 2 m zeta w. The soft step is first order in its substep h: over one period of a 3 Hz spring the largest
// distance from the exact path must halve as h halves (8 -> 16 -> 32 substeps; measured ratios 0.51 to 0.53,
// e.g. 0.118, 0.063, 0.032 m undamped). A wrong stiffness or damping would not converge: the ratio would go to 1.
TEST(MouseJoint, ConvergesToTheExactSpringDamperAtFirstOrder) {
    const double w = 2 * M_PI * 3.0;
    const int steps = 20;  // 1/3 s at 60 Hz: one period
    for (const double zeta : {0.0, 0.3, 1.0}) {
        std::vector<double> errors;
        for (const int substeps : {8, 16, 32}) {
            WorldSettings settings = noSleep(Vec2::Zero());
            settings.substeps = substeps;
            World world(settings);
            const Vec2 start(0.5, -0.2);
            const BodyId body = disc(world, start);
            world.createMouseJoint(grab(body, Vec2::Zero(), 3.0, zeta));
            double error = 0.0;
            for (int step = 1; step <= steps; ++step) {
                world.step(kDt);
                const double t = step * kDt;
                const Vec2 exact(dampedOscillator(start.x(), zeta, w, t), dampedOscillator(start.y(), zeta, w, t));
                error = std::max(error, (world.position(body) - exact).norm());
            }
            errors.push_back(error);
        }
        for (std::size_t i = 1; i < errors.size(); ++i) {
            EXPECT_GT(errors[i] / errors[i - 1], 0.45) << "zeta " << zeta << ": errors " << errors[i - 1] << ", "
                                                        << errors[i];
            EXPECT_LT(errors[i] / errors[i - 1], 0.56) << "zeta " << zeta << ": errors " << errors[i - 1] << ", "
                                                        << errors[i];
        }
    }
}

// Undamped, the anchor oscillates about the target at `hertz`: the soft step's first-order error lengthens the
// period slightly (0.2% measured at 5 Hz and h = 1/480 s). 1% allows that.
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

// The pull is a force; contacts are constraints. Dragged towards a target 2 m inside a static wall, a disc stops
// at the wall's face: it arrives at 31 m/s, and never gets deeper than one substep of travel. Resting there, the
// wall's soft contact (a spring of w_c = 2 pi contactHertz, capped at a quarter of the substep rate) holds the
// joint's pull k_j (2.2 m - overlap): the overlap is 2.2 k_j / (k_c + k_j) with k = m w^2 (3.81 mm here;
// measured to 1e-7 m). 1e-5 m allows for the rest of the settling.
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
    const WorldSettings& s = world.settings();
    EXPECT_LT(deepest, 31.0 * kDt / s.substeps) << "never deeper than one substep of travel";
    const double contactW = 2 * M_PI * std::min(s.contactHertz, s.substeps / kDt / 4.0);
    const double jointW = 2 * M_PI * 5.0;
    const double overlap = 2.2 * jointW * jointW / (contactW * contactW + jointW * jointW);
    EXPECT_NEAR(world.position(body).x() + 0.2 - 1.0, overlap, 1e-5) << "resting against the face";
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

// A box grabbed by a corner swings about it, and the pull must not pump energy into the swing. The joint's
// stiffness is w^2 times the grabbed point's effective mass K^-1 (K = 1/m + r x I^-1 x r, as Box2D's), not
// m w^2: off the centre of mass it is softer across the lever arm and turns with the box, so kinetic +
// potential + k C^2 / 2 with k = m w^2 is not exactly kept even as h -> 0. Measured: above the start by at most
// 26 mJ, a tenth of a second in (36 mJ as h -> 0), on a swing whose potential energy spans 0.83 J; then the
// step's damping wins: at least 21 mJ below the start over the last 5 s, 49 mJ below after 10 s. 50 mJ bounds
// the early excess; over the last 5 s the energy must stay below the start, and it must end lower.
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
        ASSERT_LE(energy(), start + (i < 300 ? 0.05 : 0.0)) << "step " << i;
        swing = std::max(swing, std::abs(world.angle(box)));
    }
    EXPECT_LT(energy(), start);
    EXPECT_GT(swing, 1.0) << "it did swing about the corner";
}

using testing::expectThrowsNaming;

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
