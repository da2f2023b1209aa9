// Drag against its analytic answers: terminal velocities and the approach to them under linear and quadratic
// drag, rotational drag's decay, the default width; bad input.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace physim {
namespace {

constexpr double kG = 9.81;
constexpr double kDt = 1.0 / 60.0;
constexpr double kH = kDt / 8;  // the default substep

struct Falling {
    World world;
    BodyId ball;
};

// A ball of radius 0.1 m and density 50 kg/m^2 (1.571 kg) released at rest, alone (no contacts).
void drop(Falling& f, const DragDef& drag) {
    BodyDef d;
    d.shape = makeCircle(0.1);
    d.density = 50.0;
    d.drag = drag;
    f.ball = f.world.createBody(d);
}

double fallSpeedAfter(Falling& f, double seconds) {
    const int steps = static_cast<int>(std::lround(seconds / kDt));
    for (int i = 0; i < steps; ++i) f.world.step(kDt);
    return -f.world.velocity(f.ball).y();
}

// F = -b v: v(t) = v_t (1 - exp(-t / tau)), v_t = m g / b, tau = m / b.
TEST(Drag, LinearDragReachesItsTerminalVelocityAlongTheExponential) {
    Falling f;
    DragDef drag;
    drag.linear = 2.0 * 1.571;  // tau about 0.5 s
    drop(f, drag);
    const double m = f.world.mass(f.ball), b = drag.linear;
    const double tau = m / b, terminal = m * kG / b;
    // Backward Euler's decay rate per substep is ln(1 + h/tau) / h = (1 - h / (2 tau)) / tau to first order: at
    // t = tau the speed is off by at most e^-1 (h / 2 tau) v_t, below h / (2 tau) of v(tau).
    const double atTau = fallSpeedAfter(f, 30 * kDt);  // 0.5 s
    const double t = 30 * kDt;
    EXPECT_NEAR(atTau / (terminal * (1.0 - std::exp(-t / tau))), 1.0, kH / (2 * tau));
    // The discrete fixed point is the exact terminal velocity; after 20 tau what is left is exp(-20).
    EXPECT_NEAR(fallSpeedAfter(f, 10.0) / terminal, 1.0, 1e-8);
    EXPECT_TRUE(f.world.profile().didRun(Effect::Drag));
}

// F = -q |v| v, q = rho C_d w / 2: v(t) = v_t tanh(g t / v_t), v_t = sqrt(m g / q).
TEST(Drag, QuadraticDragReachesItsTerminalVelocityAlongTheTanh) {
    Falling f;
    DragDef drag;
    drag.dragCoefficient = 1.0;
    drag.fluidDensity = 1.2;  // width: the default, the ball's diameter 0.2 m
    drop(f, drag);
    const double m = f.world.mass(f.ball), q = 0.5 * 1.2 * 1.0 * 0.2;
    const double terminal = std::sqrt(m * kG / q), tau = terminal / kG;  // about 11.3 m/s, 1.15 s
    // First-order in h: the relative error stays below h times the drag's linearised rate 2 g / v_t per unit of
    // t / tau, so below 2 h / tau at t = tau (measured well inside).
    const double t = std::round(tau / kDt) * kDt;
    EXPECT_NEAR(fallSpeedAfter(f, t) / (terminal * std::tanh(t / tau)), 1.0, 2 * kH / tau);
    EXPECT_NEAR(fallSpeedAfter(f, 20.0) / terminal, 1.0, 1e-8) << "terminal velocity, exactly";
}

TEST(Drag, BothLawsTogetherBalanceGravityAtTheRootOfTheQuadratic) {
    Falling f;
    DragDef drag;
    drag.linear = 0.5;
    drag.dragCoefficient = 0.8;
    drag.width = 0.3;
    drop(f, drag);
    const double m = f.world.mass(f.ball), b = 0.5, q = 0.5 * 1.2 * 0.8 * 0.3;
    // m g = b v + q v^2.
    const double terminal = (-b + std::sqrt(b * b + 4 * q * m * kG)) / (2 * q);
    EXPECT_NEAR(fallSpeedAfter(f, 30.0) / terminal, 1.0, 1e-8);
}

TEST(Drag, SidewaysThrowSlowsAlongItsVelocity) {
    // Without gravity a thrown ball keeps its direction and slows as dv/dt = -(q / m) v^2: v = v0 / (1 + q v0 t / m).
    WorldSettings s;
    s.gravity = Vec2::Zero();
    Falling f{World(s), {}};
    DragDef drag;
    drag.dragCoefficient = 1.0;
    drop(f, drag);
    f.world.setVelocity(f.ball, {6.0, 8.0});
    const double m = f.world.mass(f.ball), q = 0.5 * 1.2 * 1.0 * 0.2;
    for (int i = 0; i < 120; ++i) f.world.step(kDt);
    const Vec2 v = f.world.velocity(f.ball);
    EXPECT_NEAR(v.y() / v.x(), 8.0 / 6.0, 1e-12) << "drag acts along the velocity";
    const double exact = 10.0 / (1.0 + q * 10.0 * 2.0 / m);
    EXPECT_NEAR(v.norm() / exact, 1.0, 2 * kH * q * 10.0 / m) << "first order in h at the initial rate";
}

TEST(Drag, AngularDragDecaysTheSpinExponentially) {
    WorldSettings s;
    s.gravity = Vec2::Zero();
    Falling f{World(s), {}};
    DragDef drag;
    drag.angular = 0.01;
    drop(f, drag);
    f.world.setAngularVelocity(f.ball, 10.0);
    const double tau = f.world.inertia(f.ball) / drag.angular;  // 0.785 s
    const int steps = static_cast<int>(std::lround(tau / kDt));
    for (int i = 0; i < steps; ++i) f.world.step(kDt);
    EXPECT_NEAR(f.world.angularVelocity(f.ball) / (10.0 * std::exp(-steps * kDt / tau)), 1.0, kH / (2 * tau));
    EXPECT_EQ(f.world.velocity(f.ball), Vec2::Zero()) << "no linear drag asked for, and none moving";
}

TEST(Drag, DefaultWidthIsTheMeanWidthPerimeterOverPi) {
    // A square of side 1 shows the flow perimeter / pi = 4 / pi on average: its terminal speed under the
    // quadratic law is sqrt(m g / (rho C_d (4 / pi) / 2)).
    Falling f;
    BodyDef d;
    d.shape = makeBox(0.5, 0.5);
    d.fixedRotation = true;
    d.drag.dragCoefficient = 1.0;
    f.ball = f.world.createBody(d);
    const double m = f.world.mass(f.ball);
    EXPECT_NEAR(fallSpeedAfter(f, 30.0), std::sqrt(m * kG / (0.5 * 1.2 * 4.0 / M_PI)), 1e-6);
}

TEST(Drag, ACompoundBodyShowsTheFlowItsConvexHull) {
    // Two unit squares side by side on one body (Shape.hpp): air sees their convex hull, a 2 x 1 rectangle, whose mean
    // width is its perimeter over pi, 6 / pi. Adding the second square after the drag was set recomputes it.
    Falling f;
    BodyDef d;
    d.shape = makeBox(0.5, 0.5, {-0.5, 0.0}, 0.0);
    d.fixedRotation = true;
    d.drag.dragCoefficient = 1.0;
    f.ball = f.world.createBody(d);
    ShapeDef second;
    second.geometry = makeBox(0.5, 0.5, {0.5, 0.0}, 0.0);
    f.world.createShape(f.ball, second);
    const double m = f.world.mass(f.ball);
    EXPECT_NEAR(m, 2.0, 1e-12);
    EXPECT_NEAR(fallSpeedAfter(f, 30.0), std::sqrt(m * kG / (0.5 * 1.2 * 6.0 / M_PI)), 1e-6);
}

TEST(Drag, SetGetRemoveAndBadInput) {
    Falling f;
    drop(f, DragDef{});
    EXPECT_TRUE(isNone(f.world.drag(f.ball)));
    f.world.step(kDt);
    EXPECT_FALSE(f.world.profile().didRun(Effect::Drag)) << "no body has drag";
    DragDef drag;
    drag.linear = 1.0;
    f.world.setDrag(f.ball, drag);
    EXPECT_EQ(f.world.drag(f.ball).linear, 1.0);
    f.world.step(kDt);
    EXPECT_TRUE(f.world.profile().didRun(Effect::Drag));
    f.world.setDrag(f.ball, DragDef{});
    f.world.step(kDt);
    EXPECT_FALSE(f.world.profile().didRun(Effect::Drag)) << "all zero removes it";

    for (double DragDef::*field : {&DragDef::linear, &DragDef::dragCoefficient, &DragDef::fluidDensity,
                                   &DragDef::width, &DragDef::angular}) {
        DragDef bad;
        bad.*field = -1.0;
        EXPECT_THROW(f.world.setDrag(f.ball, bad), std::invalid_argument);
        bad.*field = NAN;
        EXPECT_THROW(f.world.setDrag(f.ball, bad), std::invalid_argument);
        BodyDef d;
        d.drag = bad;
        EXPECT_THROW(f.world.createBody(d), std::invalid_argument);
    }
    try {
        DragDef bad;
        bad.dragCoefficient = -2.0;
        f.world.setDrag(f.ball, bad);
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("drag coefficient"), std::string::npos) << e.what();
    }
    f.world.setDrag(f.ball, drag);
    f.world.destroyBody(f.ball);
    f.world.step(kDt);
    EXPECT_FALSE(f.world.profile().didRun(Effect::Drag)) << "a destroyed body leaves the effect";
}

}  // namespace
}  // namespace physim
