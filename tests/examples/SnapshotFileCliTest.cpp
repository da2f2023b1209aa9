// Snapshot files on the command line, run as a user would: a headless run with --snapshot-every N writes
// DIR/snapshots/step-<N>.psnap, and a run started --from it for M more steps ends in the state (run.json's final state
// hash and step count) of one run straight through N + M steps. Exact: the step is deterministic, so anything else
// is state the file missed. Checked on gas (hundreds of colliding discs, sleep) and double_pendulum (a branch and the
// subclass's writeState: its Lyapunov fit must come out the same too). A file that cannot be resumed exits 2 with a
// line naming the problem.

#include "RunProgram.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

namespace fs = std::filesystem;
using physim::test::Result;
using physim::test::runProgram;

nlohmann::json readJson(const fs::path& p) {
    std::ifstream in(p);
    return nlohmann::json::parse(in);
}

fs::path fresh(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("physim_snapshot_cli_" + name);
    fs::remove_all(dir);
    return dir;
}

// Both runs at 40 Hz: `first` steps, a snapshot at its end; then `more` steps from it; against first + more at once.
void expectResumesExactly(const std::string& program, const std::string& name, int first, int more) {
    const fs::path dir = fresh(name);
    const auto seconds = [](int steps) { return " --hz 40 --seconds " + std::to_string(steps / 40.0); };
    const Result a = runProgram(program, "--headless --quiet --snapshot-every " + std::to_string(first) + seconds(first) +
                                             " --out " + (dir / "a").string());
    ASSERT_EQ(a.exitCode, 0) << a.output;
    char file[64];
    std::snprintf(file, sizeof file, "step-%09d.psnap", first);
    const fs::path snapshot = dir / "a" / "snapshots" / file;
    ASSERT_TRUE(fs::exists(snapshot)) << a.output;
    const Result b = runProgram(program, "--headless --quiet --from " + snapshot.string() + seconds(more) + " --out " +
                                             (dir / "b").string());
    ASSERT_EQ(b.exitCode, 0) << b.output;
    const Result c = runProgram(program, "--headless --quiet" + seconds(first + more) + " --out " + (dir / "c").string());
    ASSERT_EQ(c.exitCode, 0) << c.output;
    const nlohmann::json resumed = readJson(dir / "b" / "run.json"), straight = readJson(dir / "c" / "run.json");
    EXPECT_EQ(resumed["steps"], first + more);
    EXPECT_EQ(resumed["steps"], straight["steps"]);
    EXPECT_EQ(resumed["final_state_hash"], straight["final_state_hash"]);
    const nlohmann::json straightFirst = readJson(dir / "a" / "run.json");
    EXPECT_NE(straightFirst["final_state_hash"], straight["final_state_hash"]) << "the scene stood still";
    const nlohmann::json results = readJson(dir / "c" / "summary.json")["results"];
    EXPECT_FALSE(results.empty()) << "no results to compare";
    EXPECT_EQ(readJson(dir / "b" / "summary.json")["results"], results);
    fs::remove_all(dir);
}

TEST(SnapshotFileCli, GasResumedFromItsSnapshotEndsAsOneRun) { expectResumesExactly(PHYSIM_GAS, "gas", 60, 60); }

// The branch and the members double_pendulum writes (writeState) carry the Lyapunov fit across: it is made after
// the resume (the distance reaches 1 mm at about 11 s) and must equal the straight run's.
TEST(SnapshotFileCli, DoublePendulumResumedFromItsSnapshotEndsAsOneRun) {
    expectResumesExactly(PHYSIM_DOUBLE_PENDULUM, "double_pendulum", 160, 480);
}

TEST(SnapshotFileCli, SnapshotsAreNumberedByStep) {
    const fs::path dir = fresh("numbered");
    const Result r = runProgram(PHYSIM_FALLING_BOX, "--headless --quiet --seconds 1 --snapshot-every 15 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    for (const char* name : {"step-000000015.psnap", "step-000000030.psnap"})
        EXPECT_TRUE(fs::exists(dir / "snapshots" / name)) << name;
    EXPECT_FALSE(fs::exists(dir / "snapshots" / "step-000000040.psnap"));  // 40 steps: the last at 30
    fs::remove_all(dir);
}

// Exit 2 with one line naming the problem: no such file, a truncated one, another scene's, another rate; and the
// flags' own misuse.
TEST(SnapshotFileCli, AFileThatCannotBeResumedExitsTwoNamingTheProblem) {
    const fs::path dir = fresh("bad");
    ASSERT_EQ(runProgram(PHYSIM_FALLING_BOX, "--headless --quiet --seconds 0.5 --snapshot-every 20 --out " + dir.string())
                  .exitCode,
              0);
    const fs::path good = dir / "snapshots" / "step-000000020.psnap";
    std::ifstream in(good, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const fs::path cut = dir / "cut.psnap";
    std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    struct Case {
        std::string program, args, mentions;
    };
    for (const Case& c : {Case{PHYSIM_FALLING_BOX, "--from " + (dir / "none.psnap").string(), "cannot open"},
                          Case{PHYSIM_FALLING_BOX, "--from " + cut.string(), "truncated"},
                          Case{PHYSIM_DOUBLE_PENDULUM, "--from " + good.string(), "entities"},
                          Case{PHYSIM_FALLING_BOX, "--hz 60 --from " + good.string(), "physics rate of 40 Hz"},
                          Case{PHYSIM_FALLING_BOX, "--snapshot-every 10", "--out"},
                          Case{PHYSIM_FALLING_BOX, "--snapshot-every 0 --out " + dir.string(), "--snapshot-every"}}) {
        const Result r = runProgram(c.program, "--headless --quiet --seconds 0.1 " + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << ": " << r.output;
        EXPECT_NE(r.output.find(c.mentions), std::string::npos) << c.args << ": " << r.output;
        EXPECT_EQ(r.output.find('\n'), r.output.size() - 1) << "one line: " << r.output;
    }
    fs::remove_all(dir);
}

TEST(SnapshotFileCli, HelpListsTheFlags) {
    const Result r = runProgram(PHYSIM_FALLING_BOX, "--help");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.output.find("--snapshot-every N"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("--from FILE"), std::string::npos) << r.output;
}

}  // namespace
