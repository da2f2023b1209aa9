#include "PaceMeter.hpp"

namespace physim {
namespace {
constexpr double kWindowSeconds = 1.0;
}

void PaceMeter::record(double realSeconds, double simulatedSeconds, std::uint64_t droppedSteps, bool paused) {
    if (paused || !(realSeconds > 0.0)) return;
    frames_.push_back({realSeconds, simulatedSeconds, droppedSteps > 0});
    real_ += realSeconds;
    simulated_ += simulatedSeconds;
    capped_ += droppedSteps > 0;
    while (frames_.size() > 1 && real_ - frames_.front().real >= kWindowSeconds) {
        real_ -= frames_.front().real;
        simulated_ -= frames_.front().simulated;
        capped_ -= frames_.front().capped;
        frames_.pop_front();
    }
}

void PaceMeter::clear() {
    frames_.clear();
    real_ = simulated_ = 0.0;
    capped_ = 0;
}

double PaceMeter::pace() const { return real_ > 0.0 ? simulated_ / real_ : 0.0; }

bool PaceMeter::cappedBelow(double timeScale) const {
    return capped_ >= 2 && 8 * capped_ >= frames_.size() && pace() < 0.97 * timeScale;
}

}  // namespace physim
