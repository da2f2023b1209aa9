#pragma once

#include <array>
#include <cstddef>
#include <string_view>

namespace physim {

/// The stages of one fixed step, in order. A stage the scene's content does not call for is skipped before
/// it does any work (StepProfile::ran tells which ran).
enum class Stage : std::size_t {
    Forces,       ///< gravity and accumulated forces into velocities
    BroadPhase,   ///< candidate pairs whose bounding boxes overlap
    NarrowPhase,  ///< contact manifolds of the candidate pairs
    Continuous,   ///< time of impact for fast bodies
    Solve,        ///< contact impulses
    Integrate,    ///< velocities into positions, position correction
    Sleep,        ///< bodies at rest stop being simulated
    Count
};

std::string_view stageName(Stage s);

/// Wall-clock cost of the last step, per stage.
struct StepProfile {
    static constexpr std::size_t stageCount = static_cast<std::size_t>(Stage::Count);
    std::array<double, stageCount> seconds{};
    std::array<bool, stageCount> ran{};
    std::size_t candidatePairs = 0;
    std::size_t manifolds = 0;

    double& secondsOf(Stage s) { return seconds[static_cast<std::size_t>(s)]; }
    double secondsOf(Stage s) const { return seconds[static_cast<std::size_t>(s)]; }
    bool didRun(Stage s) const { return ran[static_cast<std::size_t>(s)]; }
    double total() const;
};

}  // namespace physim
