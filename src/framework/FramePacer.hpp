#pragma once
// How many fixed steps a window frame may run so the window keeps at least 20 frames per second: a scene whose
// steps cannot keep up then runs in slow motion instead of as a slideshow. Window-free: fed measured times.

namespace physim {

class FramePacer {
public:
    /// Wall clock a frame may take, steps and drawing together: 1/20 s, 20 frames per second.
    static constexpr double frameBudget = 1.0 / 20.0;
    /// Most steps a paced frame runs however cheap they are (a frame after a stall catches up at most this many).
    static constexpr int mostSteps = 1000;

    /// After a frame: `steps` fixed steps took `stepSeconds` of wall clock, and the rest of the frame (hooks,
    /// drawing, display) `otherSeconds`. Negative or non-finite times (a clock reset by a restart) count as 0.
    void record(int steps, double stepSeconds, double otherSeconds);
    /// Steps the next frame may run: as many as fit in frameBudget less the drawing, at least 1, at most mostSteps
    /// (that many before any step was measured).
    int maxSteps() const;
    /// The estimates maxSteps uses, in seconds: a step's cost and the rest of a frame's. A rise is taken at once
    /// (the frame rate holds when a scene gets heavier), a fall eased in over a few frames (one fast frame does
    /// not let the next run long).
    double stepCost() const { return stepCost_; }
    double otherCost() const { return otherCost_; }

private:
    double stepCost_ = 0.0;   // s per step; 0 until measured
    double otherCost_ = 0.0;  // s per frame
};

}  // namespace physim
