// The window's trails (L): a ring buffer per body holding its last positions, checked against positions the test
// collects itself after every step; bounded memory, and cleared by L, a scrub and a restart.

#include "RunnerAccess.hpp"
#include "Trails.hpp"
#include "support/SfmlEvents.hpp"

#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace physim {
namespace {

TEST(Trail, KeepsTheLastPointsOldestFirst) {
    Trail trail(3);
    EXPECT_EQ(trail.size(), 0u);
    for (int i = 0; i < 2; ++i) trail.push({double(i), 0.0});
    ASSERT_EQ(trail.size(), 2u);
    EXPECT_EQ(trail[0].x(), 0.0);
    EXPECT_EQ(trail[1].x(), 1.0);
    for (int i = 2; i < 8; ++i) trail.push({double(i), 0.0});
    ASSERT_EQ(trail.size(), 3u) << "never more than its capacity";
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(trail[i].x(), 5.0 + double(i));
    trail.clear();
    EXPECT_EQ(trail.size(), 0u);
    trail.push({9.0, 0.0});
    EXPECT_EQ(trail[0].x(), 9.0);
    EXPECT_THROW(Trail(0), std::invalid_argument);
    EXPECT_THROW(Trails(0, 4), std::invalid_argument);
    EXPECT_THROW(Trails(4, 0), std::invalid_argument);
}

TEST(Trail, TrailsFollowTheBodiesThatComeAndGo) {
    const BodyId a{0, 0}, b{1, 0}, c{2, 0}, d{3, 0};
    Trails trails(10, 2);
    trails.record({{a, {1.0, 0.0}}, {b, {2.0, 0.0}}, {c, {3.0, 0.0}}});
    ASSERT_EQ(trails.entries().size(), 2u) << "at most 2 bodies";
    trails.record({{a, {1.5, 0.0}}, {b, {2.5, 0.0}}});
    EXPECT_EQ(trails.entries()[1].trail.size(), 2u);
    trails.record({{b, {2.75, 0.0}}, {d, {4.0, 0.0}}});  // a went, d came
    ASSERT_EQ(trails.entries().size(), 2u);
    EXPECT_EQ(trails.entries()[0].body, b);
    EXPECT_EQ(trails.entries()[0].trail.size(), 3u) << "b's trail kept";
    EXPECT_EQ(trails.entries()[0].trail[2].x(), 2.75);
    EXPECT_EQ(trails.entries()[1].body, d);
    EXPECT_EQ(trails.entries()[1].trail.size(), 1u) << "d's starts anew";
}

// Two balls thrown in gravity, no floor.
class Thrown : public Simulation {
public:
    void onCreate() override {
        for (int i = 0; i < 2; ++i) {
            auto& ball = spawn<Object>(Vec2(1.0, 1.0));
            ball.setPosition({3.0 * i, 0.0});
            ball.rb.setVelocity({2.0, 5.0 + i});
        }
    }
};

// One step a frame (a frame of exactly the step): after each, the test notes each body's centre of mass. The
// trails must hold the last 200 of those, exactly (the same doubles, copied).
TEST(Trail, RunnerRecordsTheLastPositionsOfEachBody) {
    RunOptions options;
    options.headless = true;
    options.hz = 40.0;
    Runner runner([] { return std::make_unique<Thrown>(); }, options);
    runner.restart();
    Simulation& sim = runner.simulation();
    const double dt = sim.fixedTimeStep();
    runner.frame(dt, nullptr);
    EXPECT_TRUE(RunnerAccess::trails(runner).entries().empty()) << "off: nothing recorded";
    runner.handleEvent(test::keyPress(sf::Keyboard::L), nullptr);
    const std::vector<BodyId> bodies = sim.world().bodies();
    std::vector<std::vector<Vec2>> seen(bodies.size());
    for (int i = 0; i < 250; ++i) {
        ASSERT_EQ(runner.frame(dt, nullptr), 1);
        for (std::size_t b = 0; b < bodies.size(); ++b) seen[b].push_back(sim.world().centerOfMass(bodies[b]));
    }
    const Trails& trails = RunnerAccess::trails(runner);
    ASSERT_EQ(trails.entries().size(), bodies.size());
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const Trails::Entry& e = trails.entries()[b];
        EXPECT_EQ(e.body, bodies[b]);
        ASSERT_EQ(e.trail.size(), 200u);
        for (std::size_t i = 0; i < 200; ++i) EXPECT_EQ(e.trail[i], seen[b][50 + i]) << "body " << b << " point " << i;
    }
    // A scrub back clears them; L off clears them (and records nothing); a restart clears them.
    runner.handleEvent(test::keyPress(sf::Keyboard::Left), nullptr);
    EXPECT_TRUE(RunnerAccess::trails(runner).entries().empty());
    runner.handleEvent(test::keyPress(sf::Keyboard::P), nullptr);  // the scrub paused
    runner.frame(dt, nullptr);
    EXPECT_EQ(RunnerAccess::trails(runner).entries().size(), 2u);
    runner.handleEvent(test::keyPress(sf::Keyboard::L), nullptr);
    runner.frame(dt, nullptr);
    EXPECT_TRUE(RunnerAccess::trails(runner).entries().empty());
    runner.handleEvent(test::keyPress(sf::Keyboard::L), nullptr);
    runner.frame(dt, nullptr);
    runner.handleEvent(test::keyPress(sf::Keyboard::Space), nullptr);
    EXPECT_TRUE(RunnerAccess::trails(runner).entries().empty());
}

// In zero gravity, a ball at rest and one moving at 0.2 m/s (above the 0.1 m/s a trail starts at): only the moving
// one is traced, so resting bodies take no place under the cap.
class OneMoving : public Simulation {
public:
    void onCreate() override {
        WorldSettings settings = world().settings();
        settings.gravity = Vec2::Zero();
        world().setSettings(settings);
        spawn<Object>(Vec2(1.0, 1.0)).setPosition({-3.0, 0.0});
        auto& moving = spawn<Object>(Vec2(1.0, 1.0));
        moving.setPosition({3.0, 0.0});
        moving.rb.setVelocity({0.2, 0.0});
    }
};

TEST(Trail, OnlyMovingBodiesAreTraced) {
    RunOptions options;
    options.headless = true;
    Runner runner([] { return std::make_unique<OneMoving>(); }, options);
    runner.restart();
    runner.handleEvent(test::keyPress(sf::Keyboard::L), nullptr);
    for (int i = 0; i < 5; ++i) runner.frame(runner.simulation().fixedTimeStep(), nullptr);
    const Trails& trails = RunnerAccess::trails(runner);
    ASSERT_EQ(trails.entries().size(), 1u);
    EXPECT_EQ(trails.entries()[0].body, runner.simulation().world().bodies()[1]);
    EXPECT_EQ(trails.entries()[0].trail.size(), 5u);
}

// The body last pressed on (Controls::picked) is traced first, even beyond the cap of bodies.
TEST(Trail, PickedBodyComesFirst) {
    RunOptions options;
    options.headless = true;
    options.width = 800;
    options.height = 600;
    Runner runner([] { return std::make_unique<Thrown>(); }, options);
    runner.restart();
    Simulation& sim = runner.simulation();
    const BodyId second = sim.world().bodies()[1];
    const sf::Vector2f px = sim.view.worldToPixels({800, 600}).transformPoint(
        float(sim.world().centerOfMass(second).x()), float(sim.world().centerOfMass(second).y()));
    const sf::Vector2i pixel(int(px.x), int(px.y));
    runner.handleEvent(test::mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left, pixel), nullptr);
    runner.handleEvent(test::mouseButton(sf::Event::MouseButtonReleased, sf::Mouse::Left, pixel), nullptr);
    ASSERT_EQ(RunnerAccess::controls(runner).picked(), second);
    runner.handleEvent(test::keyPress(sf::Keyboard::L), nullptr);
    runner.frame(sim.fixedTimeStep(), nullptr);
    ASSERT_EQ(RunnerAccess::trails(runner).entries().size(), 2u);
    EXPECT_EQ(RunnerAccess::trails(runner).entries()[0].body, second);
}

}  // namespace
}  // namespace physim
