// The window's "plot anything": a click picks the body under the cursor, and a live plot of one of its quantities
// follows the run step by step, and a scrub back; the values are the body's own, read back from the world.

#include "RunnerAccess.hpp"
#include "support/SfmlEvents.hpp"

#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace physim {
namespace {

constexpr double kFrame = 1.0 / 40.0;  // one fixed step per frame at 40 Hz
const sf::Vector2u kWindow(800, 600);

// A box falling onto a floor.
class Scene : public Simulation {
public:
    void onCreate() override {
        auto& floor = spawn<Object>(Vec2(8.0, 1.0));
        floor.rb.setMass(0.0);
        floor.setPosition({0.0, -3.5});
        box = &spawn<Object>(Vec2(1.0, 1.0));
        box->setPosition({0.0, 2.0});
    }
    Object* box = nullptr;  // owned by the simulation
};

Runner makeRunner() {
    RunOptions options;
    options.headless = true;
    options.hz = 40.0;
    options.width = static_cast<int>(kWindow.x);
    options.height = static_cast<int>(kWindow.y);
    return Runner([] { return std::make_unique<Scene>(); }, options);
}

sf::Vector2i pixelOf(const Simulation& sim, const Vec2& p) { return test::pixelOf(sim.view, p, kWindow); }

TEST(LivePlot, AClickPicksTheBodyAndItsPlotFollowsTheRunAndAScrub) {
    Runner runner = makeRunner();
    RunnerAccess::recordTimeline(runner);
    runner.restart();
    Scene& sim = static_cast<Scene&>(runner.simulation());
    EXPECT_FALSE(runner.pickedEntity());
    runner.handleEvent(test::mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left, pixelOf(sim, {0.0, 2.0})),
                       nullptr);
    runner.handleEvent(test::mouseButton(sf::Event::MouseButtonReleased, sf::Mouse::Left, pixelOf(sim, {0.0, 2.0})),
                       nullptr);
    ASSERT_EQ(runner.pickedEntity(), sim.box->id());
    runner.addLivePlot({sim.box->id(), "y"});
    for (int i = 0; i < 40; ++i) {
        runner.frame(kFrame, nullptr);
        const auto& points = runner.livePlots().at(0).points;
        EXPECT_EQ(points.back().first, sim.time);
        EXPECT_EQ(points.back().second, sim.box->getPosition().y());  // the body's own value, exactly
    }
    EXPECT_EQ(runner.livePlots()[0].points.size(), 41u);  // the moment it was added, then a point a step
    runner.scrubTo(sim.time - 0.5);
    EXPECT_EQ(runner.livePlots()[0].points.size(), 21u);
    EXPECT_NEAR(runner.livePlots()[0].points.back().first, runner.simulation().time, 1e-12);
    runner.handleEvent(test::mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left, pixelOf(sim, {3.0, 5.0})),
                       nullptr);
    EXPECT_EQ(runner.pickedEntity(), sim.box->id()) << "a click elsewhere (a panel's button) keeps the pick";
    runner.removeLivePlot(0);
    EXPECT_TRUE(runner.livePlots().empty());
}

TEST(LivePlot, BadSpecsAreRefusedNamingTheProblem) {
    Runner runner = makeRunner();
    runner.restart();
    const int box = static_cast<Scene&>(runner.simulation()).box->id();
    EXPECT_THROW(runner.addLivePlot({box, "mass"}), std::invalid_argument);
    EXPECT_THROW(runner.addLivePlot({999, "y"}), std::invalid_argument);
    EXPECT_THROW(runner.removeLivePlot(0), std::out_of_range);
    runner.addLivePlot({box, "kinetic_energy"});
    runner.restart();
    EXPECT_TRUE(runner.livePlots().empty()) << "a restart starts a new scene: its plots go";
}

}  // namespace
}  // namespace physim
