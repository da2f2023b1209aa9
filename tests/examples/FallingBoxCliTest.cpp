// falling_box run as a user runs it: bad arguments exit with 2 and name the value; a headless run writes
// summary.json and the graph's CSV describing the box at rest on the ground.

#include "RunProgram.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using physim::test::Result;

Result run(const std::string& args) { return physim::test::runProgram(PHYSIM_FALLING_BOX, args); }

TEST(FallingBoxCli, BadArgumentsExitWithTwoAndNameTheValue) {
    struct Case {
        const char* args;
        const char* mentions;
    };
    for (const Case& c : {Case{"--bogus", "--bogus"}, Case{"--headless --seconds -1", "-1"},
                          Case{"--headless --seconds nan", "nan"}, Case{"--headless --hz 0", "--hz"},
                          Case{"--headless --seconds", "needs a value"}}) {
        const Result r = run(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.mentions), std::string::npos) << c.args << "\n" << r.output;
    }
}

TEST(FallingBoxCli, HelpExplainsTheOptions) {
    const Result r = run("--help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* flag : {"--headless", "--seconds", "--out", "--hz", "summary.json"})
        EXPECT_NE(r.output.find(flag), std::string::npos) << flag;
}

TEST(FallingBoxCli, HeadlessRunWritesTheFinalStateAndGraph) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_falling_box_cli";
    std::filesystem::remove_all(dir);
    const Result r = run("--headless --seconds 4 --hz 40 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;

    std::ifstream in(dir / "summary.json");
    ASSERT_TRUE(in) << "summary.json missing";
    const nlohmann::json s = nlohmann::json::parse(in);
    EXPECT_NEAR(s["time"].get<double>(), 4.0, 1e-9);
    EXPECT_EQ(s["steps"].get<int>(), 160);  // 4 s at 40 Hz
    ASSERT_EQ(s["entities"].size(), 2u);
    const auto& ground = s["entities"][0];
    const auto& box = s["entities"][1];
    EXPECT_EQ(ground["id"], 1);
    EXPECT_EQ(box["id"], 2);
    EXPECT_EQ(ground["position"][1].get<double>(), -0.5) << "static ground does not move";
    // At rest on the ground's top (y = 0): centre at half its 1 m size, less at most twice the solver's
    // 5 mm allowed overlap (linearSlop), and still.
    const double y = box["position"][1];
    EXPECT_GT(y, 0.5 - 0.01);
    EXPECT_LT(y, 0.5 + 1e-3);
    EXPECT_LT(std::hypot(box["velocity"][0].get<double>(), box["velocity"][1].get<double>()), 1e-3);
    // A straight drop stays centred and upright: the solver takes a face's two points one at a time, the first
    // alternating every substep, so neither corner leads (measured: x 2.3 micrometres, angle 6e-8 rad, then the box
    // sleeps). 10 micrometres and 1 microradian: with the same point always first it ends 0.7 mm off centre.
    EXPECT_NEAR(box["position"][0].get<double>(), 0.0, 1e-5);
    EXPECT_NEAR(box["angle"].get<double>(), 0.0, 1e-6);

    // One graph point per frame: 160 frames, plus the title and series comments and the header.
    std::ifstream csv(dir / "graph_0.csv");
    int lines = 0;
    for (std::string l; std::getline(csv, l);) ++lines;
    EXPECT_EQ(lines, 163);
    EXPECT_TRUE(std::filesystem::exists(dir / "graphs.png"));
    std::filesystem::remove_all(dir);
}

TEST(FallingBoxCli, OutIsCheckedBeforeTheRun) {
    // Exit code 2 can only come from the check before the run (errors while running exit with 1); a run of
    // 1e6 simulated seconds would take minutes.
    for (const char* bad : {"/proc/physim_out", "/dev/null/out"}) {
        const Result r = run(std::string("--headless --seconds 1000000 --out ") + bad);
        EXPECT_EQ(r.exitCode, 2) << r.output;
        EXPECT_NE(r.output.find(std::string("--out ") + bad + ": cannot"), std::string::npos) << r.output;
    }
}

TEST(FallingBoxCli, TheFolderHoldsThisRunsFilesAndOneLineSaysWhich) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_falling_box_out";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "graph_3.csv") << "from an earlier run\n";
    const Result r = run("--headless --seconds 2 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"graph_0.csv", "graphs.png", "graphs.root", "run.json", "summary.json"}));
    // A CUDA build on a machine without a usable GPU says so first; the run's own output is its closing line.
    std::string output = r.output;
    if (output.rfind("physim: no usable CUDA device", 0) == 0) output.erase(0, output.find('\n') + 1);
    EXPECT_EQ(output, "wrote summary.json, run.json, graph_0.csv, graphs.png, graphs.root (5 files) to " + dir.string() + "\n");
    const Result quiet = run("--headless --seconds 2 --quiet --out " + dir.string());
    EXPECT_EQ(quiet.exitCode, 0);
    EXPECT_EQ(quiet.output, "") << "--quiet";
    std::filesystem::remove_all(dir);
}

TEST(FallingBoxCli, LongHeadlessRunsReportProgress) {
    // Progress shows after Progress::kQuietFor (2 s) of the program's wall time (ProgressTest checks the rule with
    // a test clock); the box sleeps, so a simulated second costs little and a machine's speed decides how many make
    // 2 s. Four times longer runs until one reports (20 000 s took 0.6 to 1.6 s here). Not the test's own timing:
    // on a loaded machine the program's start alone can take a second, which its progress clock does not count.
    // stderr is a pipe: plain lines.
    double seconds = 20000.0;
    Result r;
    for (; seconds <= 1e7; seconds *= 4.0) {
        r = run("--headless --seconds " + std::to_string(seconds));
        ASSERT_EQ(r.exitCode, 0) << r.output;
        if (r.output.find("%  t = ") != std::string::npos) break;  // a progress line (a CUDA build says more)
    }
    ASSERT_LE(seconds, 1e7) << "even --seconds 1e7 reported no progress\n" << r.output;
    char total[32];
    std::snprintf(total, sizeof total, " of %.1f s  ", seconds);
    EXPECT_EQ(r.output.rfind("physim: ", 0), 0u) << r.output;
    for (const char* part : {"%  t = ", static_cast<const char*>(total), " steps/s  about ", " left\n"})
        EXPECT_NE(r.output.find(part), std::string::npos) << part << "\n" << r.output;
    EXPECT_EQ(r.output.find('\r'), std::string::npos) << "no bar when stderr is not a terminal";
}

// No display, or one that does not answer: exit 2 with the reason and the way out, never SFML's abort (134).
TEST(FallingBoxCli, WindowWithoutDisplayExitsTwoWithTheReason) {
    Result r = physim::test::runProgram("env -u DISPLAY " PHYSIM_FALLING_BOX, "--seconds 1");
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--headless"), std::string::npos) << r.output;
    r = physim::test::runProgram("DISPLAY=:9876 " PHYSIM_FALLING_BOX, "--seconds 1");  // no X server there
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("':9876'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--headless"), std::string::npos) << r.output;
}

TEST(FallingBoxCli, CommandLineFormsAndRefusals) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_falling_box_forms";
    std::filesystem::remove_all(dir);
    // --name=value, and a parameter: dropped from 3 m, 0 s run, the box is where it was put.
    Result r = run("--headless --seconds=0 --param=height=3 --out=" + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(dir / "summary.json");
    const nlohmann::json s = nlohmann::json::parse(in);
    EXPECT_EQ(s["entities"][1]["position"][1].get<double>(), 3.0);
    std::filesystem::remove_all(dir);

    struct Case {
        const char* args;
        const char* mentions;
    };
    for (const Case& c : {Case{"--headless --seconds 1e18", "1e18"},  // no step would run: refused, not exit 0
                          Case{"--headless --screenshot x.png", "--screenshot"},
                          Case{"--headless --param nope=1", "height"},    // names the parameters it has
                          Case{"--headless --param height=100", "height"},
                          Case{"--headless --param height=abc", "abc"}}) {
        r = run(c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.mentions), std::string::npos) << c.args << "\n" << r.output;
    }
    r = run("--help");
    EXPECT_NE(r.output.find("height"), std::string::npos) << "--help lists the parameters\n" << r.output;
}

}  // namespace
