#pragma once
// The --out folder: checked before the run starts, and the one line that says what the run wrote there.

#include <string>
#include <vector>

namespace physim {

/// Makes `directory` (and its parents) if missing and checks that it is a folder this process can write in,
/// before any simulation time is spent. Throws UsageError naming the folder and the reason.
void prepareOutputFolder(const std::string& directory);

/// "wrote summary.json, graphs.png, graphs.root, graph_0.csv ... graph_6.csv (10 files) to DIR": `written` are
/// the paths of the files, in the order written.
std::string writtenLine(const std::string& directory, const std::vector<std::string>& written);

}  // namespace physim
