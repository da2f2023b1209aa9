#include "OutputFolder.hpp"

#include "physim/framework/RunOptions.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>

namespace physim {

void prepareOutputFolder(const std::string& directory) {
    namespace fs = std::filesystem;
    const std::string where = "--out " + directory + ": ";
    std::error_code ec;
    if (fs::exists(directory, ec) && !fs::is_directory(directory, ec))
        throw UsageError(where + "exists and is not a folder");
    fs::create_directories(directory, ec);
    if (ec) throw UsageError(where + "cannot create it (" + ec.message() + ")");
    // Writing a file is the only sure test (permissions, read-only mounts, /proc and the like).
    const fs::path probe = fs::path(directory) / (".physim-write-check-" + std::to_string(::getpid()));
    {
        std::ofstream out(probe);
        out << "physim\n";
        out.flush();
        if (!out) {
            const std::string reason = std::strerror(errno);
            fs::remove(probe, ec);
            throw UsageError(where + "cannot write in it (" + reason + ")");
        }
    }
    fs::remove(probe, ec);
}

std::string writtenLine(const std::string& directory, const std::vector<std::string>& written) {
    namespace fs = std::filesystem;
    // Runs of graph_<i>.csv with consecutive i are named by their ends.
    static const std::regex csv(R"(graph_([0-9]+)\.csv)");
    std::string names;
    auto add = [&names](const std::string& s) { names += (names.empty() ? "" : ", ") + s; };
    for (std::size_t i = 0; i < written.size();) {
        const std::string name = fs::path(written[i]).filename().string();
        std::smatch m;
        std::size_t j = i + 1;
        if (std::regex_match(name, m, csv)) {
            long next = std::stol(m[1]) + 1;
            std::string last = name;
            for (; j < written.size(); ++j, ++next) {
                const std::string n = fs::path(written[j]).filename().string();
                if (n != "graph_" + std::to_string(next) + ".csv") break;
                last = n;
            }
            add(last == name ? name : j - i == 2 ? name + ", " + last : name + " ... " + last);
        } else {
            add(name);
        }
        i = j;
    }
    return "wrote " + names + " (" + std::to_string(written.size()) + (written.size() == 1 ? " file" : " files") +
           ") to " + directory;
}

}  // namespace physim
