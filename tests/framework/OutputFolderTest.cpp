// The --out folder is checked before a run: made if missing, refused with the reason when it cannot be used.

#include "OutputFolder.hpp"

#include <physim/framework/RunOptions.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace physim {
namespace {

namespace fs = std::filesystem;

std::string refusal(const std::string& dir) {
    try {
        prepareOutputFolder(dir);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

TEST(OutputFolder, MadeWhenMissingAndLeftClean) {
    const fs::path dir = fs::temp_directory_path() / "physim_out_folder_test" / "a" / "b";
    fs::remove_all(dir.parent_path().parent_path());
    EXPECT_EQ(refusal(dir.string()), "");
    EXPECT_TRUE(fs::is_directory(dir));
    EXPECT_TRUE(fs::is_empty(dir)) << "the write check leaves nothing behind";
    fs::remove_all(dir.parent_path().parent_path());
}

TEST(OutputFolder, RefusedWithTheReason) {
    const fs::path file = fs::temp_directory_path() / "physim_out_folder_file";
    std::ofstream(file) << "x";
    EXPECT_NE(refusal(file.string()).find("is not a folder"), std::string::npos) << refusal(file.string());
    EXPECT_NE(refusal((file / "sub").string()).find("cannot create"), std::string::npos);
    fs::remove(file);
    const std::string proc = refusal("/proc/physim_out");
    EXPECT_NE(proc.find("--out /proc/physim_out"), std::string::npos) << proc;
    EXPECT_NE(proc.find("cannot"), std::string::npos) << proc;
}

TEST(OutputFolder, OneLineNamesWhatWasWritten) {
    EXPECT_EQ(writtenLine("out", {"out/summary.json", "out/graph_0.csv", "out/graph_1.csv", "out/graph_2.csv",
                                  "out/graph_3.csv", "out/graphs.png", "out/graphs.root"}),
              "wrote summary.json, graph_0.csv ... graph_3.csv, graphs.png, graphs.root (7 files) to out");
    EXPECT_EQ(writtenLine("d", {"d/summary.json", "d/graph_0.csv", "d/graph_1.csv"}),
              "wrote summary.json, graph_0.csv, graph_1.csv (3 files) to d");
    EXPECT_EQ(writtenLine("d", {"d/summary.json"}), "wrote summary.json (1 file) to d");
}

}  // namespace
}  // namespace physim
