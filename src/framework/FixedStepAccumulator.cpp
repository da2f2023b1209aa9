#include "FixedStepAccumulator.hpp"

#include "physim/core/Validate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace physim {

FixedStepAccumulator::FixedStepAccumulator(double step, int maxStepsPerFrame)
    : step_(step), maxSteps_(maxStepsPerFrame) {
    requirePositive("fixed step (s)", step);
    if (maxStepsPerFrame < 1)
        throw std::invalid_argument("physim: maxStepsPerFrame must be >= 1, got " + std::to_string(maxStepsPerFrame));
}

int FixedStepAccumulator::advance(double frameSeconds, int limit) {
    requireNonNegative("frame time (s)", frameSeconds);
    if (limit < 1)
        throw std::invalid_argument("physim: a frame's step limit must be >= 1, got " + std::to_string(limit));
    const int cap = std::min(limit, maxSteps_);
    accumulated_ += frameSeconds;
    // A frame of exactly one step must give one step even when the sum rounds a hair below it.
    const double tolerance = 1e-9 * step_;
    const double whole = std::floor((accumulated_ + tolerance) / step_);
    accumulated_ -= whole * step_;
    if (!(accumulated_ >= 0.0 && accumulated_ < step_)) accumulated_ = 0.0;  // rounding, or an absurd frame
    if (whole > cap) {
        dropped_ += static_cast<std::uint64_t>(std::min(whole - cap, 1e18));
        return cap;
    }
    return static_cast<int>(whole);
}

}  // namespace physim
