#pragma once
// The runner's frame-loop state, and the way physim's own tests reach it. Internal: Runner.hpp names
// RunnerAccess (its friend) and Runner::Loop only, so the installed header needs none of these types.

#include "Arrows.hpp"
#include "Controls.hpp"
#include "FixedStepAccumulator.hpp"
#include "FramePacer.hpp"
#include "PaceMeter.hpp"
#include "Stats.hpp"
#include "Trails.hpp"

#include "physim/framework/Runner.hpp"

#include <chrono>
#include <functional>

namespace physim {

struct Runner::Loop {
    /// `maxStepsPerFrame`: --max-steps-per-frame's N, or FramePacer::mostSteps while the pacer sets each frame's.
    explicit Loop(int maxStepsPerFrame) : accumulator(1.0 / 40.0, maxStepsPerFrame) {}  // restart() sets the rate

    FixedStepAccumulator accumulator;
    FramePacer pacer;  // each frame's step limit unless --max-steps-per-frame was given
    /// Wall clock (s) the pacer's times are read from; tests put a fake one in (RunnerAccess::setClock).
    std::function<double()> clock = [] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    };
    Controls controls;
    PaceMeter pace;
    StepTimes stepTimes;
    /// L's trails: 200 positions a body (5 s at 40 Hz), at most 64 bodies (the picked one first, then those that
    /// moved: Runner.cpp's recordTrails), recorded after each step while shown.
    Trails trails{200, 64};
    std::vector<std::pair<BodyId, Vec2>> trailPositions;  // reused each step
    /// V's arrows: their scales, and the bar's legend saying them (empty while they are off).
    ArrowScale velocityScale, forceScale;
    std::string arrowsLegend;
};

/// A runner's internals, for tests that drive it frame by frame and look at what the window would show.
struct RunnerAccess {
    static const FixedStepAccumulator& accumulator(const Runner& runner) { return runner.loop_->accumulator; }
    static Controls& controls(Runner& runner) { return runner.loop_->controls; }
    static const PaceMeter& pace(const Runner& runner) { return runner.loop_->pace; }
    static const FramePacer& pacer(const Runner& runner) { return runner.loop_->pacer; }
    /// The wall clock (s) the frame loop times its steps and drawing with.
    static void setClock(Runner& runner, std::function<double()> clock) { runner.loop_->clock = std::move(clock); }
    static const Trails& trails(const Runner& runner) { return runner.loop_->trails; }
    /// Records the timeline as a window run does (headless runs keep none).
    static void recordTimeline(Runner& runner) { runner.recording_ = true; }
    /// The same with a timeline of these settings (its spacing of snapshots made independent of timing).
    static void recordTimeline(Runner& runner, const Timeline::Settings& settings) {
        runner.timeline_ = Timeline(settings);
        runner.recording_ = true;
    }
};

}  // namespace physim
