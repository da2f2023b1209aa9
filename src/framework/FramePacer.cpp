#include "FramePacer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace physim {
namespace {

constexpr double kEase = 0.25;     // share of a lower measurement taken per frame

double valid(double seconds) { return std::isfinite(seconds) && seconds > 0.0 ? seconds : 0.0; }

// Rises at once, falls by kEase of the gap each frame.
double follow(double estimate, double measured) {
    return measured >= estimate ? measured : estimate + kEase * (measured - estimate);
}

}  // namespace

void FramePacer::record(int steps, double stepSeconds, double otherSeconds) {
    otherCost_ = follow(otherCost_, valid(otherSeconds));
    if (steps > 0) stepCost_ = follow(stepCost_, valid(stepSeconds) / steps);
}

int FramePacer::maxSteps() const {
    if (!(stepCost_ > 0.0)) return mostSteps;
    // The tolerance: a budget of exactly n steps gives n, though the times' rounding puts the quotient a hair below.
    const double fit = std::floor((frameBudget - otherCost_) / stepCost_ + 1e-9);
    return static_cast<int>(std::clamp(fit, 1.0, static_cast<double>(mostSteps)));
}

}  // namespace physim
