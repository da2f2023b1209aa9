#pragma once
// Command-line options shared by every physim program (examples included).

#include "physim/core/TimeOfImpact.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace physim {

/// One --record ENTITY:QUANTITY: a quantity of an entity's body (by the entity's id, as summary.json lists it)
/// sampled after every fixed step. The quantities, in SI units: x, y (m), angle (rad), vx, vy, speed (m/s),
/// angular_velocity (rad/s), kinetic_energy (J: translation and rotation).
struct RecordSpec {
    int entity = 0;
    std::string quantity;
    static const std::vector<std::string>& quantities();
    /// The quantity's SI unit ("m", "rad", "m/s", "rad/s", "J"); "" for an unknown one.
    static const char* unit(const std::string& quantity);
};

struct RunOptions {
    bool help = false;
    bool headless = false;             ///< no window, no display needed
    std::optional<double> seconds;     ///< simulated seconds to run; headless default 10, window: until closed
    std::optional<std::string> outDir; ///< where summary.json and the graphs' files go
    std::optional<double> hz;          ///< physics rate; the simulation's own default otherwise (40 Hz)
    std::optional<std::string> screenshot;  ///< window mode: the last frame is saved to this PNG at the end
    bool quiet = false;                ///< no progress on stderr and no closing line
    /// --param name=value, in order: the simulation's Parameters set before onCreate.
    std::vector<std::pair<std::string, double>> parameters;
    /// --max-steps-per-frame N: at most N steps per window frame, catching up behind real time as far as N allows.
    /// Unset: each frame runs as many steps as fit in 1/20 s with its drawing (at least one), so a heavy scene
    /// runs in slow motion at 20 frames per second or more. Set, it wins over that pacing.
    std::optional<int> maxStepsPerFrame;
    int width = 1280;                  ///< window size, pixels
    int height = 720;
    // Accuracy knobs (docs/accuracy.md); applied after onCreate, so they win over the simulation's own choice.
    std::optional<int> substeps;            ///< substeps per physics step
    std::optional<int> iterations;          ///< solver velocity iterations per substep
    std::optional<CollisionDetection> ccd;  ///< every dynamic body's collision detection
    std::optional<double> precision;        ///< sampled detection's spacing, fraction of the step, (0, 1]
    /// --replay FILE: run the run that FILE (a run.json) records, and say whether it ends in the same state.
    std::optional<std::string> replay;
    /// --record ENTITY:QUANTITY, repeatable, in order: series written to --out (records.csv, and a TTree in
    /// graphs.root).
    std::vector<RecordSpec> records;
    /// --snapshot-every N (headless, with --out): a snapshot file every N physics steps, into DIR/snapshots.
    std::optional<int> snapshotEvery;
    /// --from FILE: the run starts from a snapshot file (Simulation::readSnapshot), after onCreate built the scene.
    std::optional<std::string> from;
    /// The arguments as given (after the program's name), which --out's run.json records; and the program's name,
    /// which runMain sets.
    std::vector<std::string> arguments;
    std::string program;

    static constexpr double defaultHeadlessSeconds = 10.0;
    /// Longest --seconds: 10^7 s (116 days) is 10^11 steps at the highest rate, still counted exactly.
    static constexpr double maxSeconds = 1e7;
    static constexpr double minHz = 1.0;  ///< a step is at most 1 s (World::step's limit)
    static constexpr double maxHz = 10000.0;
};

/// A command line that cannot be run; what() names the offending argument and value. Exit code 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Parses the arguments after the program name; `--name value` and `--name=value` both work. Throws UsageError.
RunOptions parseRunOptions(const std::vector<std::string>& args);
std::string usage(std::string_view program, std::string_view title);

}  // namespace physim
