// The window's arrows (V): each body's velocity, weight and contact force, and the 1-2-5 scales the legend states.
// The contact force is checked against statics: a body at rest is held up by its contacts with exactly its weight.

#include "Arrows.hpp"
#include "RunnerAccess.hpp"
#include "support/SfmlEvents.hpp"

#include <physim/core/World.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace physim {
namespace {

TEST(Arrows, ScalesRoundUpToOneTwoOrFive) {
    EXPECT_DOUBLE_EQ(roundScaleUp(0.3), 0.5);
    EXPECT_DOUBLE_EQ(roundScaleUp(1.0), 1.0);
    EXPECT_DOUBLE_EQ(roundScaleUp(1.01), 2.0);
    EXPECT_DOUBLE_EQ(roundScaleUp(2.5), 5.0);
    EXPECT_DOUBLE_EQ(roundScaleUp(7.0), 10.0);
    EXPECT_DOUBLE_EQ(roundScaleUp(1e-3), 1e-3);
    EXPECT_DOUBLE_EQ(roundScaleUp(0.00101), 0.002);
    EXPECT_DOUBLE_EQ(roundScaleUp(4321.0), 5000.0);
    EXPECT_THROW(roundScaleUp(0.0), std::invalid_argument);
    EXPECT_THROW(roundScaleUp(-1.0), std::invalid_argument);
    EXPECT_THROW(roundScaleUp(NAN), std::invalid_argument);
}

TEST(Arrows, ScaleHoldsUntilArrowsGrowTooLongOrShort) {
    ArrowScale scale;
    EXPECT_EQ(scale.update(0.0, 2.0), 1.0) << "nothing to show: any scale";
    EXPECT_DOUBLE_EQ(scale.update(6.0, 2.0), 5.0) << "6 / 2 = 3 per metre, rounded up";
    EXPECT_DOUBLE_EQ(scale.update(8.0, 2.0), 5.0) << "the longest arrow 1.6 m: kept";
    EXPECT_DOUBLE_EQ(scale.update(1.2, 2.0), 5.0) << "0.24 m, above a tenth of 2 m: kept";
    EXPECT_DOUBLE_EQ(scale.update(0.6, 2.0), 0.5) << "0.12 m, below a tenth: rescaled";
    EXPECT_DOUBLE_EQ(scale.update(12.0, 2.0), 10.0) << "too long: rescaled";
    EXPECT_DOUBLE_EQ(scale.update(0.0, 2.0), 10.0) << "nothing moving: kept";
    EXPECT_THROW(scale.update(-1.0, 2.0), std::invalid_argument);
    EXPECT_THROW(scale.update(1.0, 0.0), std::invalid_argument);
}

// Two 1 m boxes stacked on a static floor, and a ball 5 m to the side falling freely.
class Stack : public Simulation {
public:
    void onCreate() override {
        auto& floor = spawn<Object>(Vec2(20.0, 1.0));
        floor.rb.setMass(0.0);
        floor.setPosition({0.0, -0.5});
        spawn<Object>(Vec2(1.0, 1.0)).setPosition({0.0, 0.5});
        spawn<Object>(Vec2(1.0, 1.0)).setPosition({0.0, 1.5});
        falling = &spawn<Object>(Vec2(0.5, 0.5));
        falling->setPosition({5.0, 100.0});
    }
    Object* falling = nullptr;  // owned by the simulation
};

Stack& scene(Runner& runner) { return static_cast<Stack&>(runner.simulation()); }

// At rest, each body's contacts hold its weight: the floor pushes the bottom box up with both boxes' weights, the
// top box pushes it down with one. Tolerance 1e-5 of the weight: the stack still settles by a few micrometres a
// step (its contact + weight, m dv/dt, measured at 2e-6 of the weight), asleep as awake (the sleeping pile's contacts
// are read from the last step that solved them). Falling, the ball feels no contact; landed, its weight.
TEST(Arrows, ContactForceHoldsARestingBodysWeight) {
    RunOptions options;
    options.headless = true;
    options.hz = 40.0;
    Runner runner([] { return std::make_unique<Stack>(); }, options);
    runner.restart();
    Simulation& sim = runner.simulation();
    const double dt = sim.fixedTimeStep();
    ASSERT_NEAR(sim.world().settings().gravity.y(), -9.81, 1e-15);
    const auto check = [&](const char* when, int resting) {
        const std::vector<BodyArrows> arrows = bodyArrows(sim.world(), dt);
        ASSERT_EQ(arrows.size(), 3u) << "the dynamic bodies only";
        for (int i = 0; i < 3; ++i) {
            const BodyArrows& a = arrows[i];
            const double weight = sim.world().mass(a.body) * 9.81;
            EXPECT_NEAR(a.weight.y(), -weight, 1e-12 * weight) << when;
            EXPECT_EQ(a.velocity, sim.world().velocity(a.body)) << when;
            EXPECT_EQ(a.at, sim.world().centerOfMass(a.body)) << when;
            if (i < resting) EXPECT_NEAR((a.contact + a.weight).norm(), 0.0, 1e-5 * weight) << when << ", body " << i;
            else EXPECT_EQ(a.contact, Vec2::Zero()) << when << ", body " << i;
        }
    };
    for (int i = 0; i < 80; ++i) runner.frame(dt, nullptr);
    check("after 2 s, the ball falling", 2);
    for (int i = 0; i < 400; ++i) runner.frame(dt, nullptr);
    ASSERT_FALSE(sim.world().isAwake(sim.world().bodies()[1])) << "the pile sleeps";
    check("after 12 s, the ball landed", 3);
    EXPECT_THROW(bodyArrows(sim.world(), 0.0), std::invalid_argument);
}

// A bob hanging at rest from a pin: the joint's arrow on the bob is its weight upwards, at the pin, and the pivot's
// the opposite. Tolerance 1e-6 of the weight: the soft joint settles to rounding within 4 s.
TEST(Arrows, AJointsArrowHoldsAHangingBobsWeight) {
    WorldSettings settings;
    settings.enableSleep = false;
    World world(settings);
    BodyDef pivot;
    pivot.type = BodyType::Static;
    pivot.shape = makeCircle(0.05);
    pivot.collides = false;
    const BodyId p = world.createBody(pivot);
    BodyDef bob;
    bob.shape = makeCircle(0.2);
    bob.position = {0.0, -1.0};
    bob.collides = false;
    const BodyId b = world.createBody(bob);
    RevoluteJointDef pin;
    pin.bodyA = p;
    pin.bodyB = b;
    world.createRevoluteJoint(pin);
    for (int i = 0; i < 160; ++i) world.step(1.0 / 40.0);
    const std::vector<JointArrows> arrows = jointArrows(world);
    ASSERT_EQ(arrows.size(), 1u);
    const double weight = world.mass(b) * 9.81;
    EXPECT_NEAR(arrows[0].onB.x(), 0.0, 1e-6 * weight);
    EXPECT_NEAR(arrows[0].onB.y(), weight, 1e-6 * weight);
    // At the pin, give or take the soft joint's stretch under the weight: g / (2 pi 80 Hz)^2 = 4e-5 m.
    EXPECT_NEAR((arrows[0].atB - Vec2(0.0, 0.0)).norm(), 0.0, 1e-4);
    EXPECT_FALSE(arrows[0].toWorld);
}

// Newton's second law over each step of the ball's landing (an impact, then rest): the contact and the weight
// together change each body's momentum by (contact + weight) dt. Tolerance: 1e-9 of the ball's momentum at impact.
TEST(Arrows, ContactForceIsTheMomentumChange) {
    RunOptions options;
    options.headless = true;
    options.hz = 40.0;
    Runner runner([] { return std::make_unique<Stack>(); }, options);
    runner.restart();
    Simulation& sim = runner.simulation();
    const double dt = sim.fixedTimeStep();
    const BodyId ball = scene(runner).falling->rb.bodyId();
    const double m = sim.world().mass(ball);
    while (sim.world().centerOfMass(ball).y() > 3.0) runner.frame(dt, nullptr);
    const double scale = m * sim.world().velocity(ball).norm();
    int touching = 0;
    for (int i = 0; i < 40; ++i) {
        const Vec2 before = sim.world().velocity(ball);
        runner.frame(dt, nullptr);
        const BodyArrows a = bodyArrows(sim.world(), dt)[2];
        ASSERT_EQ(a.body, ball);
        if (a.contact != Vec2::Zero()) ++touching;
        EXPECT_NEAR((m * (sim.world().velocity(ball) - before) - (a.contact + a.weight) * dt).norm(), 0.0, 1e-9 * scale)
            << "step " << i;
    }
    EXPECT_GT(touching, 10) << "it landed";
}

TEST(Arrows, KeyTogglesThem) {
    RunOptions options;
    options.headless = true;
    Runner runner([] { return std::make_unique<Stack>(); }, options);
    runner.restart();
    EXPECT_FALSE(RunnerAccess::controls(runner).arrowsShown());
    runner.handleEvent(test::keyPress(sf::Keyboard::V), nullptr);
    EXPECT_TRUE(RunnerAccess::controls(runner).arrowsShown());
    runner.handleEvent(test::keyPress(sf::Keyboard::V), nullptr);
    EXPECT_FALSE(RunnerAccess::controls(runner).arrowsShown());
}

}  // namespace
}  // namespace physim
