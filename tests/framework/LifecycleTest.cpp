// The paper's frame loop (section 2) and fixed-step phases (section 4.3), recorded call by call.

#include "RunnerAccess.hpp"
#include "support/Recorder.hpp"

#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

#include <algorithm>

namespace physim {
namespace {

using test::CallLog;
using test::RecordingSimulation;

Runner makeRunner(CallLog& log, double hz = 40.0) {
    RunOptions options;
    options.headless = true;
    options.hz = hz;
    options.maxStepsPerFrame = 4;
    return Runner([&log] { return std::make_unique<RecordingSimulation>(log); }, options);
}

CallLog fixedStep() {
    return {"beforeFixedUpdate 1", "beforeFixedUpdate 2", "checkCollisions 1", "checkCollisions 2",
            "fixedUpdate 1",       "fixedUpdate 2"};
}

CallLog frameWith(int steps) {
    CallLog expected{"onUpdate", "update 1", "update 2"};
    for (int i = 0; i < steps; ++i) {
        const CallLog s = fixedStep();
        expected.insert(expected.end(), s.begin(), s.end());
    }
    expected.push_back("onDrawGraphs");
    return expected;
}

TEST(Lifecycle, OnCreateOnceThenFramesInThePapersOrder) {
    CallLog log;
    Runner runner = makeRunner(log);
    runner.restart();
    EXPECT_EQ(log, (CallLog{"onCreate"}));
    EXPECT_TRUE(runner.simulation().start);

    log.clear();
    EXPECT_EQ(runner.frame(1.0 / 40.0, nullptr), 1);
    EXPECT_EQ(log, frameWith(1));
}

// Frame times against a 40 Hz step (25 ms): steps = whole steps in the accumulated time, carried over.
TEST(Lifecycle, FixedStepsPerFrameFollowTheAccumulatedTime) {
    CallLog log;
    Runner runner = makeRunner(log);
    runner.restart();
    struct Case {
        double frameSeconds;
        int steps;
    };
    const Case cases[] = {{0.010, 0}, {0.010, 0}, {0.010, 1},  // 30 ms: one step, 5 ms carried
                          {0.050, 2},                          // 55 ms: two steps, 5 ms carried
                          {0.020, 1},                          // 25 ms: one step
                          {0.0, 0}};
    for (const Case& c : cases) {
        log.clear();
        EXPECT_EQ(runner.frame(c.frameSeconds, nullptr), c.steps) << c.frameSeconds;
        EXPECT_EQ(log, frameWith(c.steps)) << c.frameSeconds;
    }
    EXPECT_NEAR(runner.simulation().time, 4 * 0.025, 1e-12);
}

TEST(Lifecycle, SlowFrameIsCappedNoSpiralOfDeath) {
    CallLog log;
    Runner runner = makeRunner(log);
    runner.restart();
    EXPECT_EQ(runner.frame(1.0, nullptr), 4);  // 40 steps due, cap 4
    EXPECT_EQ(RunnerAccess::accumulator(runner).droppedSteps(), 36u);
    EXPECT_EQ(runner.frame(0.025, nullptr), 1);  // the backlog is gone, not carried
}

TEST(Lifecycle, PausedRunsNoFixedStepsButStillUpdates) {
    CallLog log;
    Runner runner = makeRunner(log);
    runner.restart();
    runner.simulation().paused = true;
    log.clear();
    EXPECT_EQ(runner.frame(0.1, nullptr), 0);
    EXPECT_EQ(log, frameWith(0));
    EXPECT_EQ(runner.simulation().time, 0.0);
}

TEST(Lifecycle, RestartMakesAFreshSimulation) {
    CallLog log;
    Runner runner = makeRunner(log);
    runner.restart();
    runner.frame(0.1, nullptr);
    const Simulation* before = &runner.simulation();
    EXPECT_GT(before->time, 0.0);
    runner.restart();
    EXPECT_EQ(runner.simulation().time, 0.0);
    EXPECT_EQ(runner.simulation().entities().size(), 2u);
    EXPECT_EQ(std::count(log.begin(), log.end(), "onCreate"), 2);
}

TEST(Lifecycle, PhysicsRateFromOptions) {
    CallLog log;
    Runner runner = makeRunner(log, 60.0);
    runner.restart();
    EXPECT_DOUBLE_EQ(runner.simulation().fixedTimeStep(), 1.0 / 60.0);
    EXPECT_EQ(runner.frame(0.05, nullptr), 3);
}

}  // namespace
}  // namespace physim
