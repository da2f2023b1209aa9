#pragma once
// The accuracy knobs every physim program takes (--substeps, --iterations, --ccd, --precision): the settings the
// accuracy study sweeps (docs/accuracy.md), so a user can try one of its settings on their own scene.

#include "physim/framework/RunOptions.hpp"

#include <functional>
#include <string>

namespace physim {

class Simulation;

/// Parses `flag` when it is one of the accuracy options (taking its value from `value`); false otherwise.
/// Throws UsageError naming a bad value.
bool parseAccuracyOption(const std::string& flag, const std::function<const std::string&()>& value, RunOptions& o);
/// Checks the accuracy options together once all are parsed (--precision only with sampled detection).
void checkAccuracyOptions(RunOptions& o);
/// The options' lines for --help.
std::string accuracyUsage();
/// Applies the options to the simulation's world settings and to every dynamic body it has now. Called after
/// onCreate, so the command line wins over the simulation's own choice, and again when bodies are added.
void applyAccuracyOptions(const RunOptions& o, Simulation& sim);

}  // namespace physim
