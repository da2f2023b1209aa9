// Branches started from the window (key B, the gallery's Branch box): the branch's world is this run's at that
// moment with exactly the one change asked for, and the trace of Simulation::branchDistance the gallery plots
// follows the two runs, checked against motion worked out by hand: in free flight, a body 1 mm/s faster is
// 1 mm/s x t ahead.

#include "RunnerAccess.hpp"
#include "support/SfmlEvents.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace physim {
namespace {

constexpr double kFrame = 1.0 / 40.0;  // one fixed step per frame at 40 Hz

// A box on a floor, and a ball flying free (no gravity), added last: the velocity change nudges the ball.
class Scene : public Simulation {
public:
    void onCreate() override {
        WorldSettings settings = world().settings();
        settings.gravity = Vec2::Zero();
        world().setSettings(settings);
        auto& floor = spawn<Object>(Vec2(8.0, 1.0));
        floor.rb.setMass(0.0);
        floor.setPosition({0.0, -3.5});
        box = &spawn<Object>(Vec2(1.0, 1.0));
        box->setPosition({0.0, -2.5});
        ball = &spawn<Object>(CircleShape(0.2), sf::Color::Blue);
        ball->setPosition({-3.0, 2.0});
        ball->rb.setVelocity({0.5, 0.0});
    }
    Object* box = nullptr;  // owned by the simulation
    Object* ball = nullptr;
};

Runner makeRunner() {
    RunOptions options;
    options.headless = true;
    options.hz = 40.0;
    return Runner([] { return std::make_unique<Scene>(); }, options);
}

Scene& scene(Runner& runner) { return static_cast<Scene&>(runner.simulation()); }

TEST(RunnerBranch, KeyBStartsAVelocityBranchWhoseDistanceGrowsAsTheNudgeTimesTime) {
    Runner runner = makeRunner();
    runner.restart();
    for (int i = 0; i < 10; ++i) runner.frame(kFrame, nullptr);
    ASSERT_EQ(runner.simulation().branch(), nullptr);
    runner.handleEvent(test::keyPress(sf::Keyboard::B), nullptr);
    Simulation& sim = runner.simulation();
    ASSERT_NE(sim.branch(), nullptr);
    const BodyId ball = scene(runner).ball->rb.bodyId(), box = scene(runner).box->rb.bodyId();
    // Exactly the change: the ball 1e-3 m/s faster along x, everything else as in this run.
    EXPECT_EQ(sim.branch()->velocity(ball), sim.world().velocity(ball) + Vec2(1e-3, 0.0));
    EXPECT_EQ(sim.branch()->velocity(box), sim.world().velocity(box));
    ASSERT_EQ(runner.branchTrace().size(), 1u);
    EXPECT_EQ(runner.branchTrace()[0].second, 0.0);
    const double start = sim.time;
    for (int i = 0; i < 80; ++i) runner.frame(kFrame, nullptr);
    ASSERT_EQ(runner.branchTrace().size(), 81u);  // a point a step
    // Free flight: the distance is the nudge times the time since (1e-12 m: the rounding of 80 steps' sums).
    for (const auto& [t, d] : runner.branchTrace()) EXPECT_NEAR(d, 1e-3 * (t - start), 1e-12) << t;
    EXPECT_NEAR(runner.branchTrace().back().first, sim.time, 1e-12);
    runner.handleEvent(test::keyPress(sf::Keyboard::B), nullptr);  // B again ends it
    EXPECT_EQ(sim.branch(), nullptr);
    EXPECT_TRUE(runner.branchTrace().empty());
}

TEST(RunnerBranch, EachChangeChangesOnlyWhatItSays) {
    Runner runner = makeRunner();
    runner.restart();
    runner.frame(kFrame, nullptr);
    const World& w = runner.simulation().world();
    const ShapeId boxShape = w.shapes(scene(runner).box->rb.bodyId()).front();
    runner.startBranch(BranchChange::Restitution);
    EXPECT_EQ(runner.simulation().branch()->restitution(boxShape), std::min(1.0, w.restitution(boxShape) + 0.1));
    EXPECT_EQ(runner.simulation().branch()->dynamicFriction(boxShape), w.dynamicFriction(boxShape));
    runner.startBranch(BranchChange::Friction);  // replaces the branch: from this run again
    EXPECT_EQ(runner.simulation().branch()->restitution(boxShape), w.restitution(boxShape));
    EXPECT_EQ(runner.simulation().branch()->staticFriction(boxShape), 0.5 * w.staticFriction(boxShape));
    EXPECT_EQ(runner.simulation().branch()->dynamicFriction(boxShape), 0.5 * w.dynamicFriction(boxShape));
    runner.startBranch(BranchChange::Substeps);
    EXPECT_EQ(runner.simulation().branch()->settings().substeps, 2 * w.settings().substeps);
    EXPECT_EQ(runner.simulation().branch()->stateHash(), w.stateHash());  // the same bodies, only the settings
    runner.endBranch();
    EXPECT_EQ(runner.simulation().branch(), nullptr);
    for (BranchChange c : {BranchChange::Velocity, BranchChange::Restitution, BranchChange::Friction,
                           BranchChange::Substeps})
        EXPECT_GT(std::string(describe(c)).size(), 5u);
}

// The timeline's snapshots as far apart as they may grow where snapshots are dear against steps (a slow host): none
// between the restart's and the branch's own, which the scrub back must start from.
TEST(RunnerBranch, ScrubbingBackTrimsTheTraceAndRunningOnRepeatsIt) {
    Runner runner = makeRunner();
    Timeline::Settings sparse;
    sparse.minInterval = 1000;
    RunnerAccess::recordTimeline(runner, sparse);
    runner.restart();
    for (int i = 0; i < 20; ++i) runner.frame(kFrame, nullptr);
    runner.startBranch(BranchChange::Velocity);
    for (int i = 0; i < 120; ++i) runner.frame(kFrame, nullptr);
    const std::vector<std::pair<double, double>> first = runner.branchTrace();
    Simulation& sim = runner.simulation();
    const double back = runner.scrubTo(sim.time - 2.0);
    ASSERT_NE(sim.branch(), nullptr);
    ASSERT_FALSE(runner.branchTrace().empty());
    EXPECT_NEAR(runner.branchTrace().back().first, back, 1e-9);  // no point after the moment scrubbed to
    EXPECT_EQ(runner.branchTrace().size(), first.size() - 80);   // 2 s at 40 Hz went
    sim.paused = false;
    for (int i = 0; i < 80; ++i) runner.frame(kFrame, nullptr);
    ASSERT_EQ(runner.branchTrace().size(), first.size());
    for (std::size_t i = 0; i < first.size(); ++i) EXPECT_EQ(runner.branchTrace()[i], first[i]) << i;  // bit for bit
    runner.scrubTo(0.1);  // before the branch began: the restored run has none
    EXPECT_EQ(sim.branch(), nullptr);
    EXPECT_TRUE(runner.branchTrace().empty());
}

}  // namespace
}  // namespace physim
