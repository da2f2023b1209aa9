#pragma once
// Runs a program as a user would from a shell and collects its exit code and output.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace physim::test {

struct Result {
    int exitCode = -1;
    std::string output;  // stdout and stderr
};

inline Result runProgram(const std::string& program, const std::string& args) {
    const std::string command = program + " " + args + " 2>&1";
    Result r;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buffer{};
    while (fgets(buffer.data(), static_cast<int>(buffer.size()), pipe)) r.output += buffer.data();
    const int status = pclose(pipe);
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

/// The (x, y) rows of a graph CSV written by GraphsManager (comment and header lines skipped).
inline std::vector<std::pair<double, double>> readGraphCsv(const std::string& path) {
    std::ifstream in(path);
    std::vector<std::pair<double, double>> points;
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#' || line == "x,y") continue;
        const auto comma = line.find(',');
        points.emplace_back(std::stod(line.substr(0, comma)), std::stod(line.substr(comma + 1)));
    }
    return points;
}

}  // namespace physim::test
