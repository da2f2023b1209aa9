#pragma once
// Adds the time from its construction to its destruction to a stage of the step's profile. Internal.

#include "physim/core/StepProfile.hpp"

#include <chrono>
#include <cstddef>

namespace physim {

class StageTimer {
public:
    StageTimer(StepProfile& profile, Stage stage) : profile_(profile), stage_(stage) {}
    ~StageTimer() {
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
        profile_.secondsOf(stage_) += elapsed.count();
        profile_.ran[static_cast<std::size_t>(stage_)] = true;
    }

private:
    StepProfile& profile_;
    Stage stage_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace physim
