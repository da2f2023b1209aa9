#include "physim/core/StepProfile.hpp"

#include <numeric>

namespace physim {

std::string_view stageName(Stage s) {
    switch (s) {
        case Stage::BroadPhase: return "broad phase";
        case Stage::NarrowPhase: return "narrow phase";
        case Stage::Forces: return "forces";
        case Stage::Solve: return "solve";
        case Stage::Integrate: return "integrate";
        case Stage::Continuous: return "continuous";
        case Stage::Sensors: return "sensors";
        case Stage::Sleep: return "sleep";
        case Stage::Count: break;
    }
    return "?";
}

std::string_view effectName(Effect e) {
    switch (e) {
        case Effect::Drag: return "drag";
        case Effect::Springs: return "springs";
        case Effect::Gravitation: return "gravitation";
        case Effect::Callbacks: return "force callbacks";
        case Effect::Count: break;
    }
    return "?";
}

double StepProfile::total() const { return std::accumulate(seconds.begin(), seconds.end(), 0.0); }

}  // namespace physim
