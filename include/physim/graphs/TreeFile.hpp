#pragma once
// A table of numbers as a ROOT TTree: what the runner's --record writes beside the graphs, for analysis in ROOT
// (tree->Draw("kinetic_energy_3:t")).

#include <string>
#include <vector>

namespace physim {

/// Adds a TTree called `name` to the ROOT file at `path` (created if absent, else updated; a tree of that name
/// already there is replaced), one double branch per column, one entry per row. Branch names must be C
/// identifiers; every row has one value per branch. Throws std::invalid_argument for a bad name or row and
/// std::runtime_error when the file cannot be written.
void writeTree(const std::string& path, const std::string& name, const std::vector<std::string>& branches,
               const std::vector<std::vector<double>>& rows);

}  // namespace physim
