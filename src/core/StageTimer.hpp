#pragma once
// Time spent in the step's stages, into its profile (StepProfile): one span at a time (StageTimer), or the spans of
// one thread that switches between stages (StageClock). Internal.

#include "physim/core/StepProfile.hpp"

#include <chrono>
#include <cstddef>

namespace physim {

/// Charges one thread's consecutive spans to stages, reading the clock once at each switch where a StageTimer per
/// span reads it twice (a step's substeps switch stages tens of times). Null profile: times nothing.
class StageClock {
public:
    explicit StageClock(StepProfile* profile) : profile_(profile) {}
    StageClock(const StageClock&) = delete;
    StageClock& operator=(const StageClock&) = delete;
    ~StageClock() { stop(); }
    /// From now on the time counts in `stage`.
    void enter(Stage stage) {
        if (!profile_ || (running_ && stage == stage_)) return;  // the span goes on: no reading
        const auto now = std::chrono::steady_clock::now();
        charge(now);
        stage_ = stage;
        start_ = now;
        running_ = true;
    }
    /// From now on the time counts nowhere.
    void stop() {
        if (!profile_ || !running_) return;
        charge(std::chrono::steady_clock::now());
        running_ = false;
    }

private:
    void charge(std::chrono::steady_clock::time_point now) {
        if (!running_) return;
        const std::chrono::duration<double> elapsed = now - start_;
        profile_->secondsOf(stage_) += elapsed.count();
        profile_->ran[static_cast<std::size_t>(stage_)] = true;
    }

    StepProfile* profile_;
    Stage stage_ = Stage::Solve;
    bool running_ = false;
    std::chrono::steady_clock::time_point start_;
};

/// Adds the time from its construction to its destruction to a stage of the step's profile.
class StageTimer {
public:
    StageTimer(StepProfile& profile, Stage stage) : clock_(&profile) { clock_.enter(stage); }

private:
    StageClock clock_;
};

}  // namespace physim
