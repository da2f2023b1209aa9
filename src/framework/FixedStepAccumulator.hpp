#pragma once
// Turns variable frame times into a whole number of fixed physics steps (the paper's fixed update).

#include <cstdint>

namespace physim {

class FixedStepAccumulator {
public:
    /// `step` in seconds (> 0), at most `maxStepsPerFrame` (>= 1) steps per frame.
    explicit FixedStepAccumulator(double step, int maxStepsPerFrame = 8);

    /// Adds one frame's duration (s, >= 0) and returns how many fixed steps to run now. When a frame would
    /// need more than maxStepsPerFrame steps the excess time is dropped: the simulation then runs slower than
    /// real time rather than falling ever further behind (no spiral of death).
    int advance(double frameSeconds) { return advance(frameSeconds, maxSteps_); }
    /// As advance(frameSeconds), with this frame's cap lowered to `limit` (>= 1) when it is below
    /// maxStepsPerFrame: the window's pacing (FramePacer) sets it frame by frame.
    int advance(double frameSeconds, int limit);

    double step() const { return step_; }
    int maxStepsPerFrame() const { return maxSteps_; }
    /// Time carried to the next frame, in [0, step).
    double remainder() const { return accumulated_; }
    /// Steps dropped by the cap since construction.
    std::uint64_t droppedSteps() const { return dropped_; }

private:
    double step_;
    int maxSteps_;
    double accumulated_ = 0.0;
    std::uint64_t dropped_ = 0;
};

}  // namespace physim
