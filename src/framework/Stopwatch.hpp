#pragma once
// The window's stopwatch (key W): it times simulated seconds, so a reading does not depend on the time scale, the
// frame rate or pauses. Internal to the runner; window-free so it can be tested headless.

namespace physim {

class Stopwatch {
public:
    enum class State { Idle, Running, Stopped };

    /// The key: Idle or Stopped -> Running from `simTime` (a new reading), Running -> Stopped holding the reading.
    /// Throws std::invalid_argument for a non-finite `simTime` (s).
    void press(double simTime);
    /// Seconds of simulated time timed: 0 when idle, the held reading when stopped, simTime minus the start when
    /// running (0 when simTime lies before the start, after a scrub back past it).
    double reading(double simTime) const;
    State state() const { return state_; }

    /// Shift+W: from now on sensors press it (it is reset to idle): the next body entering any sensor starts it, the
    /// next entry after that stops it, and it disarms.
    void arm() { *this = Stopwatch(); armed_ = true; }
    bool armed() const { return armed_; }
    /// A body entered a sensor at `simTime` (s): a press while armed.
    void sensorEntered(double simTime) {
        if (!armed_) return;
        press(simTime);
        if (state_ == State::Stopped) armed_ = false;
    }

private:
    State state_ = State::Idle;
    double start_ = 0.0;    // s, simulated time at the start
    double stopped_ = 0.0;  // s, the held reading
    bool armed_ = false;    // sensors press it
};

}  // namespace physim
