// Coulomb friction on an incline (issue #4), default settings at 60 Hz. Both bodies have mu_s = 0.6 and
// mu_d = 0.4, so the pair's averaged coefficients are the same. Below the angle of repose (tan 25 deg = 0.47)
// the box stays put; above it (tan 35 deg = 0.70) it slides with a = g (sin - mu_d cos), within 2%.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kG = 9.81;

WorldSettings awake() {
    WorldSettings s;
    s.enableSleep = false;  // sleep would hide creep
    return s;
}

struct Incline {
    World world{awake()};
    BodyId box;
    Vec2 down;  // unit vector down the slope
};

void build(Incline& s, double theta, double staticFriction = 0.6, double dynamicFriction = 0.4) {
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.shape = makeBox(30.0, 0.5);
    ground.angle = theta;
    ground.staticFriction = staticFriction;
    ground.dynamicFriction = dynamicFriction;
    const Vec2 normal{-std::sin(theta), std::cos(theta)};
    s.down = {-std::cos(theta), -std::sin(theta)};
    s.world.createBody(ground);
    BodyDef box;
    box.shape = makeBox(0.25, 0.25);
    box.angle = theta;
    box.position = (0.5 + 0.25) * normal + 10.0 * (-s.down);  // resting on the top face, 10 m up the slope
    box.staticFriction = staticFriction;
    box.dynamicFriction = dynamicFriction;
    s.box = s.world.createBody(box);
}

TEST(Friction, BoxStaysOnInclineBelowAngleOfRepose) {
    Incline s;
    const double theta = 25.0 * M_PI / 180.0;
    build(s, theta);
    for (int i = 0; i < 30; ++i) s.world.step(kDt);  // contact established
    const Vec2 start = s.world.position(s.box);
    for (int i = 0; i < 5 * 60; ++i) s.world.step(kDt);
    const double slid = (s.world.position(s.box) - start).dot(s.down);
    RecordProperty("slid_m", std::to_string(slid));
    // Sticking: the solver may let it creep by rounding only; 1 mm over 5 s is far below sliding (which
    // would cover metres).
    EXPECT_LT(std::abs(slid), 1e-3);
    EXPECT_LT(s.world.velocity(s.box).norm(), 1e-3);
}

TEST(Friction, BoxSlidesDownInclineWithCoulombAcceleration) {
    Incline s;
    const double theta = 35.0 * M_PI / 180.0;
    build(s, theta);
    const double expected = kG * (std::sin(theta) - 0.4 * std::cos(theta));
    for (int i = 0; i < 15; ++i) s.world.step(kDt);
    const double v0 = s.world.velocity(s.box).dot(s.down);
    for (int i = 0; i < 60; ++i) s.world.step(kDt);
    const double v1 = s.world.velocity(s.box).dot(s.down);
    const double a = (v1 - v0) / (60 * kDt);
    RecordProperty("acceleration_m_s2", std::to_string(a));
    EXPECT_NEAR(a, expected, 0.02 * expected);
    EXPECT_NEAR(s.world.angle(s.box), theta, 1e-2) << "slides flat, does not tumble";
}

// Static against dynamic friction is decided per manifold, on the whole normal load of the face, so a block released
// at rest holds whenever tan(angle) <= mu_s (tested up to 0.98 mu_s: the margin a user would notice), for mu_s from
// 0.2 to 1.0, with mu_d < mu_s and sleep off (so nothing hides creep): it moves less than 1 mm in 5 s. Deciding per
// point let the uphill corner, which carries little load, slip first, and the block slid at tan = 0.96 mu_s.
// Above the angle of repose it slides with a = g (sin - mu_d cos), within 2%.
TEST(Friction, HoldsUpToTheAngleOfReposeAndSlidesAboveIt) {
    for (const double mu : {0.2, 0.4, 0.6, 0.8, 1.0}) {
        const double muD = 0.7 * mu;
        for (const double fraction : {0.5, 0.9, 0.98}) {
            Incline s;
            build(s, std::atan(fraction * mu), mu, muD);
            const Vec2 start = s.world.position(s.box);
            for (int i = 0; i < 5 * 60; ++i) s.world.step(kDt);
            EXPECT_LT(std::abs((s.world.position(s.box) - start).dot(s.down)), 1e-3)
                << "mu_s " << mu << ", tan = " << fraction << " mu_s";
        }
        const double theta = std::atan(1.3 * mu);
        Incline s;
        build(s, theta, mu, muD);
        for (int i = 0; i < 15; ++i) s.world.step(kDt);
        const double v0 = s.world.velocity(s.box).dot(s.down);
        for (int i = 0; i < 60; ++i) s.world.step(kDt);
        const double a = (s.world.velocity(s.box).dot(s.down) - v0) / (60 * kDt);
        const double expected = kG * (std::sin(theta) - muD * std::cos(theta));
        EXPECT_NEAR(a, expected, 0.02 * expected) << "mu_s " << mu;
    }
}

// A ball spinning towards a wall (clockwise, its bottom sliding away from the wall) lands beside the wall, the wall's
// face touching it. Every impulse there drives the spin towards zero and the ball into the wall: ground friction
// pushes it in, the wall's normal holds it, the wall's friction and the ground's slow the spin. It must end pressed
// against the wall, at rest. The landing's friction, warm-started into the next substep and taken back only when the
// relax pass reached the ground's row, used to drive the ball into the wall after the wall's row had run; the
// push-out that followed threw it off at up to 24 cm/s. 1 cm/s: one relax pass leaves a few mm/s of the rows' order
// (Gauss-Seidel; two relax passes leave none; 4 substeps leave about 1 cm/s, so the default 8 and finer are
// checked); 1 cm of gap: a ball rolling off at the old speeds would be 15 cm away or more by the end.
TEST(Friction, ASpinningBallLandingAgainstAWallStaysAgainstIt) {
    for (const int substeps : {8, 16, 32}) {
        WorldSettings settings = awake();
        settings.substeps = substeps;
        World world(settings);
        test::addStaticBox(world, {0.0, -1.0}, 25.0, 0.5);   // ground, top at y = -0.5
        test::addStaticBox(world, {24.45, 0.25}, 0.25, 0.75);  // wall, face at x = 24.2
        BodyDef ball;
        ball.shape = makeCircle(0.2);
        ball.position = {24.0, -0.03};  // touching the wall, 0.27 m above the ground, at the top of its hop
        ball.velocity = {0.0, 0.44};
        ball.angularVelocity = -10.0;
        const BodyId id = world.createBody(ball);
        for (int i = 0; i < 80; ++i) world.step(1.0 / 40.0);  // 2 s
        const std::string where = std::to_string(substeps) + " substeps";
        EXPECT_LT(std::abs(world.velocity(id).x()), 0.01) << where;
        EXPECT_GT(world.position(id).x(), 24.0 - 0.01) << where;
    }
}

// A disc dropped spinning (omega0 = -10 rad/s, r = 0.2 m) lands, slips, and rolls away at omega0 r / 3: every
// impulse acts at the contact point and gravity acts through it, so the angular momentum about that point,
// I omega + m r v, stays I omega0, and rolling (v = -omega r) takes a third of it into the motion (I = m r^2 / 2).
// From any height: rubbing at the midway point of the gap it closed in the landing step, the disc used to roll away
// 6% slower from 0.27 m and 12% from 1 m. 0.5%: what is left is rounding and the landing's push-out, which acts
// along the normal through the point (measured within 1e-4 here).
TEST(Friction, ASpinningBallRollsAwayAtAThirdOfItsSurfaceSpeed) {
    for (const double height : {0.0, 0.27, 1.0}) {
        World world(awake());
        test::addGround(world, 25.0);
        BodyDef ball;
        ball.shape = makeCircle(0.2);
        ball.position = {0.0, 0.2 + height};
        ball.angularVelocity = -10.0;
        const BodyId id = world.createBody(ball);
        for (int i = 0; i < 180; ++i) world.step(kDt);
        const double expected = 10.0 * 0.2 / 3.0;
        EXPECT_NEAR(world.velocity(id).x(), expected, 0.005 * expected) << "dropped from " << height << " m";
        EXPECT_NEAR(world.angularVelocity(id), -expected / 0.2, 0.005 * expected / 0.2) << "dropped from " << height;
    }
}

}  // namespace
}  // namespace physim
