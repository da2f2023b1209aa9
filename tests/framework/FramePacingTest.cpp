// The window's frame pacing: a scene whose steps cannot keep up runs in slow motion at 20 frames per second or more
// instead of as a slideshow of catch-up steps, --max-steps-per-frame N still catches up as far as N allows, and a
// scene that keeps up runs the steps real time asks for. Times come from a fake clock that each step and each
// frame's drawing advance by a set cost, so the checks are exact and untimed.

#include "FixedStepAccumulator.hpp"
#include "FramePacer.hpp"
#include "RunnerAccess.hpp"

#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace physim {
namespace {

constexpr double kDisplayFrame = 1.0 / 60.0;  // s: a 60 Hz display shows a frame no sooner than this

struct Costs {
    double step = 0.0;  // s of wall clock per fixed step
    double draw = 0.0;  // s of wall clock per frame besides the steps
};

// One falling box; each frame's drawing (onDrawGraphs runs once a frame, after the steps) advances `drawn`.
class Scene : public Simulation {
public:
    explicit Scene(double drawCost) : drawCost_(drawCost) {}
    void onCreate() override { spawn<Object>(Vec2(1.0, 1.0)); }
    void onDrawGraphs() override { drawn += drawCost_; }
    double drawn = 0.0;  // s

private:
    double drawCost_;
};

// A runner at `hz` whose clock reads the costs of the steps run and the frames drawn so far.
Runner makeRunner(Costs costs, double hz, std::optional<int> maxStepsPerFrame = std::nullopt) {
    RunOptions options;
    options.headless = true;  // no window: the tests drive frame() as runWindow does
    options.hz = hz;
    options.maxStepsPerFrame = maxStepsPerFrame;
    return Runner([costs] { return std::make_unique<Scene>(costs.draw); }, options);
}

double clockOf(Runner& runner, Costs costs) {
    return costs.step * static_cast<double>(runner.simulation().world().stepCount()) +
           static_cast<Scene&>(runner.simulation()).drawn;
}

struct Frames {
    std::vector<int> steps;       // per frame
    std::vector<double> seconds;  // per frame, wall clock
};

// A start, then `count` frames as runWindow runs them: each is handed the wall time the one before took (the
// display's 1/60 s at least, and that for the first).
Frames runFrames(Runner& runner, Costs costs, int count) {
    runner.restart();
    RunnerAccess::setClock(runner, [&runner, costs] { return clockOf(runner, costs); });
    Frames frames;
    double last = kDisplayFrame;
    for (int i = 0; i < count; ++i) {
        const double before = clockOf(runner, costs);
        frames.steps.push_back(runner.frame(last, nullptr));
        last = std::max(kDisplayFrame, clockOf(runner, costs) - before);
        frames.seconds.push_back(last);
    }
    return frames;
}

// Steps of 30 ms at 100 Hz: real time would need 3 steps per 30 ms. Paced, each frame runs one step, so the window
// shows 33 frames per second at 1/3 of real time, and the bar says so.
TEST(FramePacing, SlowSceneRunsOneStepPerFrameInSlowMotion) {
    const Costs costs{0.030, 0.0};
    Runner runner = makeRunner(costs, 100.0);
    const Frames frames = runFrames(runner, costs, 90);
    for (std::size_t i = 0; i < frames.steps.size(); ++i) {
        ASSERT_EQ(frames.steps[i], 1) << "frame " << i;
        ASSERT_LE(frames.seconds[i], FramePacer::frameBudget) << "frame " << i;
    }
    // Exact up to rounding: the last second's frames each took 30 ms of wall clock for 10 ms of simulated time.
    EXPECT_NEAR(RunnerAccess::pace(runner).pace(), 1.0 / 3.0, 1e-9);
    EXPECT_TRUE(RunnerAccess::pace(runner).cappedBelow(1.0)) << "the slow motion is announced";
    EXPECT_NEAR(RunnerAccess::pacer(runner).stepCost(), 0.030, 1e-12);
    runner.restart();
    EXPECT_EQ(RunnerAccess::pacer(runner).maxSteps(), 1) << "a restart keeps the costs measured (no catch-up burst)";
}

// The same scene with --max-steps-per-frame 8, as before pacing: it catches up 8 steps a frame, frames of 240 ms
// (4 per second), the same 1/3 of real time.
TEST(FramePacing, ExplicitMaxStepsPerFrameKeepsCatchingUp) {
    const Costs costs{0.030, 0.0};
    Runner runner = makeRunner(costs, 100.0, 8);
    const Frames frames = runFrames(runner, costs, 30);
    // Frames 0 and 1 ramp up (1 step, then 3: each asks for the time the one before took).
    for (std::size_t i = 2; i < frames.steps.size(); ++i) {
        ASSERT_EQ(frames.steps[i], 8) << "frame " << i;
        ASSERT_NEAR(frames.seconds[i], 0.240, 1e-12) << "frame " << i;
    }
    EXPECT_NEAR(RunnerAccess::pace(runner).pace(), 1.0 / 3.0, 1e-9);
    EXPECT_TRUE(RunnerAccess::pace(runner).cappedBelow(1.0));
}

// Steps of 0.2 ms at 1000 Hz with 5 ms of drawing: about 17 steps (3.4 ms) a 60 Hz frame, well inside the budget,
// so every step real time asks for runs: 2000 in 2 s, none dropped. The old fixed cap of 8 steps, given
// explicitly, still holds the same scene at 8 x 60 / 1000 = 0.48 of real time.
TEST(FramePacing, SceneThatKeepsUpRunsInRealTime) {
    const Costs costs{0.0002, 0.005};
    Runner runner = makeRunner(costs, 1000.0);
    const Frames frames = runFrames(runner, costs, 120);
    long steps = 0;
    for (int s : frames.steps) steps += s;
    // +-1: the accumulator carries up to one step's time over, and rounds a frame of 16.67 steps either way.
    EXPECT_NEAR(static_cast<double>(steps), 2000.0, 1.0);
    EXPECT_EQ(RunnerAccess::accumulator(runner).droppedSteps(), 0u);
    EXPECT_NEAR(RunnerAccess::pace(runner).pace(), 1.0, 0.02);  // 0.02: the one step carried over, of 60
    EXPECT_FALSE(RunnerAccess::pace(runner).cappedBelow(1.0));

    Runner capped = makeRunner(costs, 1000.0, 8);
    runFrames(capped, costs, 120);
    EXPECT_NEAR(RunnerAccess::pace(capped).pace(), 0.48, 1e-9);
    EXPECT_TRUE(RunnerAccess::pace(capped).cappedBelow(1.0));
}

// Drawing takes its share of the budget: with 20 ms of drawing, 30 ms are left, three 10 ms steps. Frames of
// 50 ms (20 per second) run 30 ms of the 50 ms asked for at 100 Hz: 0.6 of real time.
TEST(FramePacing, DrawingTimeShrinksTheStepBudget) {
    const Costs costs{0.010, 0.020};
    Runner runner = makeRunner(costs, 100.0);
    const Frames frames = runFrames(runner, costs, 60);
    for (std::size_t i = 2; i < frames.steps.size(); ++i) {
        ASSERT_EQ(frames.steps[i], 3) << "frame " << i;
        ASSERT_NEAR(frames.seconds[i], FramePacer::frameBudget, 1e-12) << "frame " << i;
    }
    EXPECT_NEAR(RunnerAccess::pace(runner).pace(), 0.6, 1e-9);
    EXPECT_TRUE(RunnerAccess::pace(runner).cappedBelow(1.0));
}

// A headless run is one step a frame however long the steps take: pacing never drops one (results stay those of
// a run without it).
TEST(FramePacing, HeadlessRunsEveryStep) {
    const Costs costs{0.200, 0.0};  // four times the whole frame budget
    RunOptions options;
    options.headless = true;
    options.quiet = true;
    options.hz = 40.0;
    options.seconds = 2.0;
    Runner runner([costs] { return std::make_unique<Scene>(costs.draw); }, options);
    RunnerAccess::setClock(runner, [&runner, costs] { return clockOf(runner, costs); });
    EXPECT_EQ(runner.run(), 0);
    EXPECT_EQ(runner.simulation().world().stepCount(), 80u);
    EXPECT_EQ(RunnerAccess::accumulator(runner).droppedSteps(), 0u);
}

// The pacer alone: steps that fit the budget less the drawing, at least one; a rise in cost taken at once, a fall
// eased in.
TEST(FramePacing, PacerFitsStepsInTheBudget) {
    FramePacer pacer;
    EXPECT_EQ(pacer.maxSteps(), FramePacer::mostSteps) << "nothing measured yet";
    pacer.record(2, 0.060, 0.010);  // 30 ms a step, 10 ms of drawing: 40 ms leave room for one
    EXPECT_EQ(pacer.maxSteps(), 1);
    pacer.record(1, 0.080, 0.010);  // a step longer than the whole budget: still one a frame
    EXPECT_EQ(pacer.maxSteps(), 1);
    pacer.record(4, 0.004, 0.010);  // 1 ms a step: eased, 80 + (1 - 80) / 4 = 60.25 ms
    EXPECT_NEAR(pacer.stepCost(), 0.06025, 1e-12);
    EXPECT_EQ(pacer.maxSteps(), 1);
    for (int i = 0; i < 200; ++i) pacer.record(4, 0.004, 0.010);
    EXPECT_NEAR(pacer.stepCost(), 0.001, 1e-9);
    EXPECT_EQ(pacer.maxSteps(), 40);  // (50 - 10) / 1
    pacer.record(1, 0.004, 0.030);    // dearer steps and drawing count at once: (50 - 30) / 4
    EXPECT_EQ(pacer.maxSteps(), 5);
    pacer.record(0, 0.0, 0.030);      // a frame without steps leaves the step cost
    EXPECT_NEAR(pacer.stepCost(), 0.004, 1e-12);
    pacer.record(1, -1.0, NAN);       // a clock set back (a restart): no time
    EXPECT_TRUE(std::isfinite(pacer.stepCost()) && std::isfinite(pacer.otherCost()));
}

// The accumulator's per-frame limit: the steps beyond it are dropped (counted), and it never lifts the cap the
// accumulator was made with.
TEST(FramePacing, AccumulatorDropsStepsBeyondTheFramesLimit) {
    FixedStepAccumulator acc(0.01, 8);
    EXPECT_EQ(acc.advance(0.1, 3), 3);
    EXPECT_EQ(acc.droppedSteps(), 7u);
    EXPECT_EQ(acc.advance(0.1, 100), 8) << "the accumulator's own cap still holds";
    EXPECT_EQ(acc.droppedSteps(), 9u);
    EXPECT_EQ(acc.advance(0.02, 3), 2) << "a frame under its limit runs what it asks";
    EXPECT_THROW(acc.advance(0.01, 0), std::invalid_argument);
}

}  // namespace
}  // namespace physim
