#include "Stopwatch.hpp"

#include "physim/core/Validate.hpp"

#include <algorithm>

namespace physim {

void Stopwatch::press(double simTime) {
    requireFinite("stopwatch time", simTime);
    if (state_ == State::Running) {
        stopped_ = reading(simTime);
        state_ = State::Stopped;
    } else {
        start_ = simTime;
        state_ = State::Running;
    }
}

double Stopwatch::reading(double simTime) const {
    switch (state_) {
        case State::Idle: return 0.0;
        case State::Stopped: return stopped_;
        case State::Running: return std::max(0.0, simTime - start_);
    }
    return 0.0;
}

}  // namespace physim
