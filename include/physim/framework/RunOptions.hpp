#pragma once
// Command-line options shared by every physim program (examples included).

#include "physim/core/TimeOfImpact.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace physim {

struct RunOptions {
    bool help = false;
    bool headless = false;             ///< no window, no display needed
    std::optional<double> seconds;     ///< simulated seconds to run; headless default 10, window: until closed
    std::optional<std::string> outDir; ///< where summary.json and the graphs' files go
    std::optional<double> hz;          ///< physics rate; the simulation's own default otherwise (40 Hz)
    std::optional<std::string> screenshot;  ///< window mode: the last frame is saved to this PNG at the end
    bool quiet = false;                ///< no progress on stderr and no closing line
    int maxStepsPerFrame = 8;          ///< cap on catch-up steps per window frame
    int width = 1280;                  ///< window size, pixels
    int height = 720;
    // Accuracy knobs (docs/accuracy.md); applied after onCreate, so they win over the simulation's own choice.
    std::optional<int> substeps;            ///< substeps per physics step
    std::optional<int> iterations;          ///< solver velocity iterations per substep
    std::optional<CollisionDetection> ccd;  ///< every dynamic body's collision detection
    std::optional<double> precision;        ///< sampled detection's spacing, fraction of the step, (0, 1]

    static constexpr double defaultHeadlessSeconds = 10.0;
};

/// A command line that cannot be run; what() names the offending argument and value. Exit code 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Parses the arguments after the program name. Throws UsageError.
RunOptions parseRunOptions(const std::vector<std::string>& args);
std::string usage(std::string_view program, std::string_view title);

}  // namespace physim
