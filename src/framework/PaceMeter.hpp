#pragma once
// How fast the simulation really runs in a window: simulated seconds per real second over the last second,
// and whether the frame's step limit (FramePacer's, or --max-steps-per-frame) is what holds it below the time scale
// asked for.

#include <cstddef>
#include <cstdint>
#include <deque>

namespace physim {

class PaceMeter {
public:
    /// One frame: `realSeconds` of wall clock in which the simulation advanced `simulatedSeconds`, with
    /// `droppedSteps` steps the step limit dropped. A paused frame does not count.
    void record(double realSeconds, double simulatedSeconds, std::uint64_t droppedSteps, bool paused);
    void clear();
    /// Simulated seconds per real second over the last second of running frames; 0 before any.
    double pace() const;
    /// True when the pace fell below `timeScale` (by more than 3%, frame timing jitter) and the limit dropped
    /// steps in at least two and an eighth of the last second's frames: a sustained limit, not one slow frame
    /// (the first after a start, a window being moved). Paced slow motion may drop in only some frames (steps
    /// of 30 ms at 40 Hz: one frame in five), hence not a larger share.
    bool cappedBelow(double timeScale) const;

private:
    struct Frame {
        double real, simulated;
        bool capped;
    };
    std::deque<Frame> frames_;  // the last second of running frames
    double real_ = 0.0, simulated_ = 0.0;
    std::size_t capped_ = 0;    // frames in frames_ that the limit cut short
};

}  // namespace physim
