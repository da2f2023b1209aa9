#pragma once
// run.json: what a run was (the program, its arguments, its physics rate and settings, the build) and where it
// ended (the step count and World::stateHash), so that `--replay run.json` runs it again and says whether it ended in
// the same state. Internal.

#include "physim/framework/Simulation.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace physim {

/// The run as recorded: what a replay needs.
struct RecordedRun {
    std::string program;
    std::vector<std::string> arguments;  ///< as given, after the program's name
    std::uint64_t steps = 0;
    double timeStep = 0.0;               ///< s
    std::uint64_t stateHash = 0;
    std::string build;                   ///< "commit, compiler, build type", for the message when hashes differ
};

/// run.json's text for a run of `program` with `arguments` that ended in `sim`'s state.
std::string runRecordJson(const std::string& program, const std::vector<std::string>& arguments,
                          const Simulation& sim);
/// This build: its commit (when it was configured), compiler and build type.
std::string buildDescription();
/// Reads and checks run.json at `path` for `program`; throws UsageError naming the problem (a missing or unreadable
/// file, bad JSON, another format or version, another program, a missing or mistyped field).
RecordedRun readRunRecord(const std::string& path, const std::string& program);
/// The hash as run.json writes it: 16 lowercase hex digits.
std::string hashText(std::uint64_t hash);

}  // namespace physim
