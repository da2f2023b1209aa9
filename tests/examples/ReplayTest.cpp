// Runs anyone can reproduce: --out writes run.json (program, arguments, rate, build, final state hash) and
// `--replay run.json` runs it again headless and says whether it ends in the same state: exit 0 when the hash
// matches, 1 when it does not (a tampered hash, another step count), 2 for a file that cannot be replayed (corrupt,
// truncated, another program's, another version), each with a message naming the problem.

#include "RunProgram.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using physim::test::Result;

struct Recorded {
    fs::path dir;
    nlohmann::json record;
};

Recorded recordFallingBox(const std::string& name, const std::string& args) {
    Recorded r;
    r.dir = fs::temp_directory_path() / ("physim_replay_" + name);
    fs::remove_all(r.dir);
    const Result run = physim::test::runProgram(PHYSIM_FALLING_BOX, args + " --out " + r.dir.string());
    EXPECT_EQ(run.exitCode, 0) << run.output;
    std::ifstream in(r.dir / "run.json");
    r.record = nlohmann::json::parse(in);
    return r;
}

fs::path write(const fs::path& dir, const std::string& name, const std::string& text) {
    const fs::path p = dir / name;
    std::ofstream(p) << text;
    return p;
}

TEST(Replay, RunJsonRecordsTheRunAndItsReplayMatches) {
    const Recorded r = recordFallingBox("match", "--headless --seconds 3 --param restitution=0.5 --substeps 4");
    EXPECT_EQ(r.record["program"], "falling_box");
    EXPECT_EQ(r.record["steps"], 120);
    EXPECT_EQ(r.record["time_step_s"], 0.025);
    EXPECT_EQ(r.record["substeps"], 4);
    EXPECT_EQ(r.record["parameters"]["restitution"], 0.5);
    EXPECT_EQ(r.record["final_state_hash"].get<std::string>().size(), 16u);
    EXPECT_TRUE(r.record["build"].contains("commit"));
    const Result replay = physim::test::runProgram(PHYSIM_FALLING_BOX, "--replay " + (r.dir / "run.json").string());
    EXPECT_EQ(replay.exitCode, 0) << replay.output;
    EXPECT_NE(replay.output.find("matches"), std::string::npos) << replay.output;
    fs::remove_all(r.dir);
}

TEST(Replay, AnotherEndingExitsOneAndSaysHow) {
    Recorded r = recordFallingBox("differs", "--headless --seconds 1");
    r.record["final_state_hash"] = "0123456789abcdef";
    const fs::path tampered = write(r.dir, "tampered.json", r.record.dump());
    const Result replay = physim::test::runProgram(PHYSIM_FALLING_BOX, "--replay " + tampered.string());
    EXPECT_EQ(replay.exitCode, 1) << replay.output;
    EXPECT_NE(replay.output.find("0123456789abcdef"), std::string::npos) << replay.output;
    fs::remove_all(r.dir);
}

TEST(Replay, AFileThatCannotBeReplayedExitsTwoNamingTheProblem) {
    const Recorded r = recordFallingBox("bad", "--headless --seconds 1");
    std::ifstream in(r.dir / "run.json");
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    struct Case {
        std::string name, text, mentions;
    };
    nlohmann::json otherProgram = r.record, otherVersion = r.record, noSteps = r.record, badHash = r.record;
    otherProgram["program"] = "pendulum";
    otherVersion["version"] = 99;
    noSteps.erase("steps");
    badHash["final_state_hash"] = "xyz";
    for (const Case& c : {Case{"truncated.json", text.substr(0, text.size() / 2), "not valid JSON"},
                          Case{"garbage.json", "\x01\x02 not json", "not valid JSON"},
                          Case{"list.json", "[1, 2]", "not a JSON object"},
                          Case{"other_program.json", otherProgram.dump(), "a run of pendulum, not of falling_box"},
                          Case{"other_version.json", otherVersion.dump(), "version 99"},
                          Case{"no_steps.json", noSteps.dump(), "no \"steps\" field"},
                          Case{"bad_hash.json", badHash.dump(), "final_state_hash"}}) {
        const fs::path p = write(r.dir, c.name, c.text);
        const Result replay = physim::test::runProgram(PHYSIM_FALLING_BOX, "--replay " + p.string());
        EXPECT_EQ(replay.exitCode, 2) << c.name << "\n" << replay.output;
        EXPECT_NE(replay.output.find(c.mentions), std::string::npos) << c.name << "\n" << replay.output;
    }
    const Result missing = physim::test::runProgram(PHYSIM_FALLING_BOX, "--replay " + (r.dir / "none.json").string());
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.output.find("cannot read"), std::string::npos) << missing.output;
    const Result joined =
        physim::test::runProgram(PHYSIM_FALLING_BOX, "--replay " + (r.dir / "run.json").string() + " --hz 60");
    EXPECT_EQ(joined.exitCode, 2);
    fs::remove_all(r.dir);
}

}  // namespace
