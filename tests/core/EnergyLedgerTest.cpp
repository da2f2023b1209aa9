// The energy ledger (EnergyLedger.hpp) against physics: friction's loss on a rough incline is mu m g cos(theta)
// times the distance slid, a bounce loses (1 - e^2) of the energy it met with, drag's loss at terminal speed is
// m g v per second, and the residue (the method's share) stays at rounding where nothing else acts (an elastic gas)
// and does not drift where the method's energy only swings (a frictionless pendulum, a stack at rest). Switching
// the ledger on changes no result.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 40.0;  // the examples' rate

WorldSettings noSleep() {
    WorldSettings s;
    s.enableSleep = false;
    return s;
}

// A block of 1 m sent down a rough incline at 5 m/s slides to rest: friction took mu m g cos(theta) per metre slid
// (mu = 0.35 against tan(theta) = 0.31, so it decelerates at 0.38 m/s^2 and stops after about 33 m). Tolerance 1e-6
// relative: the ledger counts each substep's friction impulse times the distance slid in it, and the normal impulse
// carries the block's weight to rounding while it slides (the start, where the box tips a little, and the stop
// leave 2e-8).
TEST(EnergyLedger, FrictionOnARoughInclineIsMuMgCosThetaPerMetreSlid) {
    const double theta = 0.3, mu = 0.35;
    World w(noSleep());
    const Vec2 down(std::cos(theta), -std::sin(theta)), up(std::sin(theta), std::cos(theta));
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.shape = makeBox(50.0, 1.0);
    ground.angle = -theta;
    ground.position = -1.0 * up;  // its top face passes through the origin
    ground.staticFriction = ground.dynamicFriction = mu;
    w.createBody(ground);
    BodyDef block;
    block.shape = makeBox(0.5, 0.5);
    block.angle = -theta;
    block.position = -20.0 * down + 0.5 * up;
    block.staticFriction = block.dynamicFriction = mu;
    const BodyId id = w.createBody(block);
    for (int s = 0; s < 20; ++s) w.step(kDt);  // the contact settles, at rest (static friction holds it)
    w.setVelocity(id, 5.0 * down);
    w.setEnergyLedger(true);
    const Vec2 start = w.position(id);
    for (int s = 0; s < 800; ++s) w.step(kDt);
    ASSERT_LT(w.velocity(id).norm(), 1e-6);  // at rest again
    const double slid = (w.position(id) - start).dot(down);
    ASSERT_NEAR(slid, 25.0 / (2.0 * 9.81 * (mu * std::cos(theta) - std::sin(theta))), 0.5);  // v^2 / 2a
    const double expected = -mu * w.mass(id) * 9.81 * std::cos(theta) * slid;
    EXPECT_NEAR(w.energyLedger().total.friction / expected, 1.0, 1e-6);
}

// A ball thrown at 8 m/s against an elastic wall, without gravity, with restitution e: the bounce loses
// (1 - e^2) m v^2 / 2 to impacts (e = 0: all of it), and nothing is left to the residue. Tolerance 1e-9 of the
// energy: the ledger counts the contact's impulses exactly.
TEST(EnergyLedger, AnImpactLosesOneMinusESquaredOfTheEnergyItMetWith) {
    for (const double e : {0.0, 0.3, 0.5, 0.9, 1.0}) {
        WorldSettings s = noSleep();
        s.gravity = Vec2::Zero();
        World w(s);
        BodyDef wall;
        wall.type = BodyType::Static;
        wall.shape = makeBox(0.5, 5.0);
        wall.position = {3.5, 0.0};
        wall.restitution = 1.0;  // the pair takes the smaller
        w.createBody(wall);
        BodyDef ball;
        ball.shape = makeCircle(0.1);
        ball.velocity = {8.0, 0.0};
        ball.restitution = e;
        ball.staticFriction = ball.dynamicFriction = 0.0;
        const BodyId id = w.createBody(ball);
        w.setEnergyLedger(true);
        for (int k = 0; k < 40; ++k) w.step(kDt);
        const double met = 0.5 * w.mass(id) * 64.0;
        EXPECT_NEAR(w.energyLedger().total.impacts, -(1.0 - e * e) * met, 1e-9 * met) << "e = " << e;
        EXPECT_NEAR(w.energyLedger().total.residue, 0.0, 1e-9 * met) << "e = " << e;
        EXPECT_NEAR(w.velocity(id).x(), -e * 8.0, 1e-9) << "e = " << e;
    }
}

// The same dropped from 5 m on a floor: the bounce (ImpactEvent::approachSpeed v) loses (1 - e^2) m v^2 / 2.
// Tolerance 1%: a bounce under gravity leaves at e v plus what gravity took in its substep (so that e = 1 retraces
// the fall), up to 2 g h = 0.06 m/s at 9 m/s.
TEST(EnergyLedger, ADroppedBallLosesOneMinusESquaredOfItsImpactEnergyToImpacts) {
    for (const double e : {0.0, 0.3, 0.5}) {
        World w(noSleep());
        BodyDef floor;
        floor.type = BodyType::Static;
        floor.shape = makeBox(10.0, 0.5);
        floor.position = {0.0, -0.5};
        floor.restitution = 1.0;
        w.createBody(floor);
        BodyDef ball;
        ball.shape = makeCircle(0.1);
        ball.position = {0.0, 5.1};
        ball.restitution = e;
        ball.staticFriction = ball.dynamicFriction = 0.0;
        const BodyId id = w.createBody(ball);
        w.setEnergyLedger(true);
        double met = 0.0;
        for (int s = 0; s < 60 && met == 0.0; ++s) {
            w.step(kDt);
            for (const ImpactEvent& impact : w.contactEvents().impacts) met = impact.approachSpeed;
        }
        ASSERT_GT(met, 9.0) << e;  // sqrt(2 g 5) = 9.9 at the floor, less where the contact met it early
        const double expected = -(1.0 - e * e) * 0.5 * w.mass(id) * met * met;
        EXPECT_NEAR(w.energyLedger().total.impacts / expected, 1.0, 1e-2) << "e = " << e;
    }
}

// A body falling through air at its terminal speed v: drag takes m g v every second (it balances gravity).
// Linear drag b: v = m g / b. Tolerance 1e-6 relative: after 60 s the speed is terminal to 1e-12.
TEST(EnergyLedger, DragTakesWhatForceTimesVelocitySaysAtTerminalSpeed) {
    World w(noSleep());
    BodyDef d;
    d.shape = makeCircle(0.5);
    d.collides = false;
    const BodyId id = w.createBody(d);
    DragDef drag;
    drag.linear = 2.0;
    w.setDrag(id, drag);
    for (int s = 0; s < 2400; ++s) w.step(kDt);
    w.setEnergyLedger(true);
    for (int s = 0; s < 40; ++s) w.step(kDt);
    const double m = w.mass(id), v = m * 9.81 / drag.linear;
    ASSERT_NEAR(-w.velocity(id).y() / v, 1.0, 1e-9);
    EXPECT_NEAR(w.energyLedger().total.drag / (-m * 9.81 * v * 1.0), 1.0, 1e-6);
}

// A motor spins a disc pinned at its centre up to 10 rad/s, without gravity: the motor's work is the kinetic
// energy it gave, (1/2) I w^2, and nothing is left to the residue. Tolerance 1e-9 of the energy: the motor's
// impulse is the only torque, counted exactly.
TEST(EnergyLedger, AMotorsWorkIsTheEnergyItGives) {
    WorldSettings s = noSleep();
    s.gravity = Vec2::Zero();
    World w(s);
    BodyDef axle;
    axle.type = BodyType::Static;
    axle.shape = makeCircle(0.05);
    axle.collides = false;
    const BodyId a = w.createBody(axle);
    BodyDef disc;
    disc.shape = makeCircle(0.5);
    disc.collides = false;
    const BodyId d = w.createBody(disc);
    RevoluteJointDef pin;
    pin.bodyA = a;
    pin.bodyB = d;
    pin.enableMotor = true;
    pin.motorSpeed = 10.0;
    pin.maxMotorTorque = 0.5;
    w.createRevoluteJoint(pin);
    w.setEnergyLedger(true);
    for (int k = 0; k < 80; ++k) w.step(kDt);
    const double spin = 0.5 * w.inertia(d) * w.angularVelocity(d) * w.angularVelocity(d);
    ASSERT_GT(w.angularVelocity(d), 1.0);  // spun up (to 10 rad/s at 0.5 N m in about 1.2 s)
    EXPECT_NEAR(w.energyLedger().total.work, spin, 1e-9 * spin);
    EXPECT_NEAR(w.energyLedger().total.residue, 0.0, 1e-9 * spin);
}

// Two attracting bodies on a circular orbit about their centre of mass, without gravity: the ledger's potential is
// -G m1 m2 / r (to rounding), kinetic plus potential stays put, and nothing but the residue moves: it swings with
// semi-implicit Euler's error, under 1e-4 of the binding energy over two orbits at 240 substeps a second.
TEST(EnergyLedger, GravitationsPotentialIsMinusGMmOverR) {
    WorldSettings s = noSleep();
    s.gravity = Vec2::Zero();
    World w(s);
    GravitationSettings g;
    g.G = 1.0;
    w.setGravitation(g);
    BodyDef d;
    d.shape = makeCircle(0.1);
    d.collides = false;
    d.attracting = true;
    d.position = {-1.0, 0.0};
    const BodyId a = w.createBody(d);
    d.position = {1.0, 0.0};
    const BodyId b = w.createBody(d);
    const double m = w.mass(a), r = 2.0, v = std::sqrt(g.G * m / (2.0 * r));  // each circles at 1 m: v^2 = G m / 4
    w.setVelocity(a, {0.0, -v});
    w.setVelocity(b, {0.0, v});
    w.setEnergyLedger(true);
    EXPECT_NEAR(w.potentialEnergy(), -g.G * m * m / r, 1e-15 * g.G * m * m / r);
    const double binding = 0.5 * g.G * m * m / r, period = 2.0 * 3.141592653589793 * 1.0 / v;
    for (int k = 0; k < static_cast<int>(2.0 * period / kDt); ++k) w.step(kDt);
    const EnergyLedger& ledger = w.energyLedger();
    EXPECT_NEAR((w.position(b) - w.position(a)).norm(), r, 1e-2);  // still on its orbit
    EXPECT_LT(std::abs(ledger.total.residue), 1e-4 * binding);
    EXPECT_EQ(ledger.total.work + ledger.total.drag + ledger.total.friction + ledger.total.impacts + ledger.total.soft, 0.0);
}

// 200 elastic, frictionless discs in a closed box without gravity: every change of energy is a contact's, each
// counted exactly, so the residue is rounding: under 1e-9 of the energy per simulated second.
TEST(EnergyLedger, ResidueOfAnElasticGasIsRounding) {
    WorldSettings s = noSleep();
    s.gravity = Vec2::Zero();
    World w(s);
    for (int side = 0; side < 4; ++side) {
        BodyDef wall;
        wall.type = BodyType::Static;
        wall.shape = side < 2 ? makeBox(0.5, 11.0) : makeBox(11.0, 0.5);
        wall.position = side < 2 ? Vec2(side == 0 ? -10.5 : 10.5, 0.0) : Vec2(0.0, side == 2 ? -10.5 : 10.5);
        wall.restitution = 1.0;
        wall.staticFriction = wall.dynamicFriction = 0.0;
        w.createBody(wall);
    }
    std::mt19937 random(7);
    std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
    for (int i = 0; i < 200; ++i) {
        BodyDef disc;
        disc.shape = makeCircle(0.3);
        disc.position = {-9.0 + (i % 14) * 1.3, -9.0 + (i / 14) * 1.3};
        const double a = angle(random);
        disc.velocity = 5.0 * Vec2(std::cos(a), std::sin(a));
        disc.restitution = 1.0;
        disc.staticFriction = disc.dynamicFriction = 0.0;
        w.createBody(disc);
    }
    w.setEnergyLedger(true);
    const double seconds = 10.0;
    for (int k = 0; k < static_cast<int>(seconds / kDt); ++k) w.step(kDt);
    const EnergyLedger& ledger = w.energyLedger();
    EXPECT_LT(std::abs(ledger.total.residue), 1e-9 * ledger.start * seconds);
    EXPECT_EQ(ledger.total.friction, 0.0);
}

// A frictionless pendulum released at 57 degrees: its joint does no work, so what the method does to its energy is
// all residue. Semi-implicit Euler swings kinetic against potential energy (about 5e-3 of the energy at 40 Hz), so
// the residue is averaged over each whole swing (from one upward pass of the lowest point to the next) and its
// drift is the least-squares slope of those averages over 400 s. The residue stays within `band` of the energy.
struct PendulumDrift {
    double perSecond = 0.0;  // the slope, of the energy per second
    double soft = 0.0, friction = 0.0;
};

PendulumDrift frictionlessPendulum(const WorldSettings& settings, double band, bool limits = false) {
    World w(settings);
    BodyDef pivot;
    pivot.type = BodyType::Static;
    pivot.shape = makeCircle(0.05);
    pivot.collides = false;
    const BodyId p = w.createBody(pivot);
    BodyDef bob;
    bob.shape = makeCircle(0.1);
    bob.position = {std::sin(1.0), -std::cos(1.0)};
    bob.collides = false;
    const BodyId b = w.createBody(bob);
    RevoluteJointDef pin;
    pin.bodyA = p;
    pin.bodyB = b;
    pin.enableLimit = limits;  // far beyond the swing: they never act, but the pin is then a scalar row, not a lane
    pin.lowerAngle = -3.0;
    pin.upperAngle = 3.0;
    w.createRevoluteJoint(pin);
    w.setEnergyLedger(true);
    const double energy = w.mass(b) * 9.81 * (1.0 - std::cos(1.0));  // above its lowest point
    std::vector<double> times, means;  // each whole swing's mean residue, at the swing's end
    double sum = 0.0, x = w.position(b).x();
    int count = -1;  // no swing started yet
    for (int k = 1; k <= 40 * 400; ++k) {
        w.step(kDt);
        const double residue = w.energyLedger().total.residue, now = w.position(b).x();
        if (!(std::abs(residue) < band * energy)) {
            ADD_FAILURE() << "step " << k << ": residue " << residue / energy << " of the energy";
            return {};
        }
        if (x < 0.0 && now >= 0.0) {  // an upward pass of the lowest point: a swing ends, the next starts
            if (count > 0) {
                times.push_back(k * kDt);
                means.push_back(sum / count);
            }
            sum = 0.0;
            count = 0;
        }
        x = now;
        if (count >= 0) {
            sum += residue;
            ++count;
        }
    }
    EXPECT_GT(times.size(), 150u);  // a period of about 2.2 s
    double tMean = 0.0, rMean = 0.0;
    for (std::size_t i = 0; i < times.size(); ++i) tMean += times[i], rMean += means[i];
    tMean /= static_cast<double>(times.size()), rMean /= static_cast<double>(times.size());
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < times.size(); ++i) {
        num += (times[i] - tMean) * (means[i] - rMean);
        den += (times[i] - tMean) * (times[i] - tMean);
    }
    return {num / den / energy, w.energyLedger().total.soft, w.energyLedger().total.friction};
}

// The bar: under 1e-9 of the energy per second at default settings (measured 5e-11; the arc taken only at
// the turns before the pin's impulse drifts 1e-6, to first order in their change 2e-8). Its joint does no work and
// stores nothing. The same with limits that never act, which make the pin a scalar row instead of a lane.
TEST(EnergyLedger, ResidueOfAFrictionlessPendulumDoesNotDrift) {
    for (const bool limits : {false, true}) {
        const PendulumDrift drift = frictionlessPendulum(noSleep(), 0.01, limits);
        EXPECT_LT(std::abs(drift.perSecond), 1e-9) << drift.perSecond << " of the energy per second; limits " << limits;
        EXPECT_EQ(drift.soft, 0.0);
        EXPECT_EQ(drift.friction, 0.0);
    }
}

// Without jointArcs the pin aims along straight lines: its anchors part by about h^2 w^2 r / 2 a substep and the
// soft pull-back damps what it pulls, a drain of about 2e-5 of the energy a second (measured -2.0e-5). The ledger
// shows it as residue; the bound (a drain between 5e-6 and 5e-5 a second) says the setting is what keeps it.
TEST(EnergyLedger, APendulumOnStraightLinePinsDrains) {
    WorldSettings settings = noSleep();
    settings.jointArcs = false;
    const PendulumDrift drift = frictionlessPendulum(settings, 0.02);
    EXPECT_LT(drift.perSecond, -5e-6);
    EXPECT_GT(drift.perSecond, -5e-5);
}

// A pyramid of 10 rows settled on the ground (sleep off): nothing moves, and the residue does not grow: over 20 s
// it changes by less than 1e-9 of the pyramid's potential energy per second.
TEST(EnergyLedger, ResidueOfAStackAtRestDoesNotGrow) {
    World w(noSleep());
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.shape = makeBox(20.0, 0.5);
    ground.position = {0.0, -0.5};
    w.createBody(ground);
    for (int row = 0; row < 10; ++row)
        for (int k = 0; k < 10 - row; ++k) {
            BodyDef box;
            box.shape = makeBox(0.5, 0.5);
            box.position = {-4.5 + row * 0.5 + k, 0.5 + row};
            w.createBody(box);
        }
    for (int s = 0; s < 400; ++s) w.step(kDt);
    const double scale = std::abs(w.potentialEnergy());
    w.setEnergyLedger(true);
    const double seconds = 20.0;
    for (int s = 0; s < static_cast<int>(seconds / kDt); ++s) w.step(kDt);
    EXPECT_LT(std::abs(w.energyLedger().total.residue), 1e-9 * scale * seconds);
}

// The parts sum to each step's change, and the ledger changes nothing: a scene with every part at work (a pile
// with friction, bounces, a spring, drag, a user's force) gives the same bits with the ledger on and off.
TEST(EnergyLedger, PartsSumToEachStepsChangeAndChangeNothing) {
    auto build = [](World& w) {
        BodyDef ground;
        ground.type = BodyType::Static;
        ground.shape = makeBox(20.0, 0.5);
        ground.position = {0.0, -0.5};
        w.createBody(ground);
        std::vector<BodyId> ids;
        for (int i = 0; i < 12; ++i) {
            BodyDef d;
            d.shape = i % 2 ? Geometry(makeCircle(0.3)) : Geometry(makeBox(0.3, 0.3));
            d.position = {-3.0 + (i % 6), 1.0 + (i / 6) * 1.5};
            d.restitution = 0.4;
            ids.push_back(w.createBody(d));
        }
        DragDef drag;
        drag.linear = 0.5;
        w.setDrag(ids[3], drag);
        SpringJointDef spring;
        spring.bodyA = ids[0];
        spring.bodyB = ids[1];
        spring.stiffness = 50.0;
        spring.damping = 0.5;
        w.createSpringJoint(spring);
        return ids;
    };
    World on(noSleep()), off(noSleep());
    const std::vector<BodyId> idsOn = build(on), idsOff = build(off);
    on.setEnergyLedger(true);
    for (int s = 0; s < 200; ++s) {
        on.applyForce(idsOn[5], {3.0, 0.0});
        off.applyForce(idsOff[5], {3.0, 0.0});
        const double before = on.kineticEnergy() + on.potentialEnergy();
        on.step(kDt);
        off.step(kDt);
        const EnergyLedger& ledger = on.energyLedger();
        EXPECT_NEAR(ledger.step.sum(), ledger.energy() - before, 1e-12 * (1.0 + std::abs(before))) << s;
    }
    EXPECT_EQ(on.stateHash(), off.stateHash());
    const EnergyLedger& ledger = on.energyLedger();
    EXPECT_LT(ledger.total.friction, 0.0);
    EXPECT_LT(ledger.total.impacts, 0.0);
    EXPECT_LT(ledger.total.drag, 0.0);
    EXPECT_GT(ledger.total.work, 0.0);
    EXPECT_EQ(ledger.steps, 200);
}

}  // namespace
}  // namespace physim
