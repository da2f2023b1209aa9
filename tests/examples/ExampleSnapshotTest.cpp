// Every example, snapshot and restore (Simulation::snapshot, World::stateHash): run 2 s through the runner's own
// frame loop (headless: one fixed step per frame, every hook as in a window), take a snapshot, run 2 s, restore, run
// the same 2 s again: the world's state hash (and its branch's, where it has one) must be the same both times.
// Exact: the step is deterministic, so a difference is state the snapshot (or an example's saveState) missed. The hash must also have changed over the
// 2 s, or the example stood still and the check proved nothing about it. The same through a snapshot file
// (Simulation::writeSnapshot, readSnapshot) into a fresh runner, whose simulation's own members start afresh: what
// steers the physics must be in the world or in the example's writeState.

#include "Scenes.hpp"

#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

namespace {

class ExampleSnapshot : public testing::TestWithParam<physim::examples::Scene> {};

void runFor(physim::Runner& runner, double seconds) {
    const double dt = runner.simulation().fixedTimeStep();
    const long frames = std::lround(seconds / dt);
    for (long i = 0; i < frames; ++i) runner.frame(dt, nullptr);
}

TEST_P(ExampleSnapshot, RestoreReplaysTheSameTwoSeconds) {
    physim::RunOptions options;
    options.headless = true;
    options.quiet = true;
    physim::Runner runner(GetParam().make, options);
    runner.restart();
    runFor(runner, 2.0);
    const physim::Simulation::Snapshot snapshot = runner.simulation().snapshot();
    const std::uint64_t then = runner.simulation().world().stateHash();
    runFor(runner, 2.0);
    const std::uint64_t first = runner.simulation().world().stateHash();
    const physim::World* branch = runner.simulation().branch();  // double_pendulum's second future
    const std::uint64_t firstBranch = branch ? branch->stateHash() : 0;
    const double firstTime = runner.simulation().time;
    runner.simulation().restore(snapshot);
    EXPECT_EQ(runner.simulation().world().stateHash(), then);
    runFor(runner, 2.0);
    EXPECT_EQ(runner.simulation().world().stateHash(), first) << GetParam().name << " did not replay bit for bit";
    EXPECT_EQ(runner.simulation().time, firstTime);
    if (branch) {
        EXPECT_EQ(runner.simulation().branch()->stateHash(), firstBranch) << "its branch";
    }
    EXPECT_NE(first, then) << GetParam().name << " stood still: nothing was checked";
}

TEST_P(ExampleSnapshot, AFileResumesInAFreshRunner) {
    physim::RunOptions options;
    options.headless = true;
    options.quiet = true;
    physim::Runner first(GetParam().make, options);
    first.restart();
    runFor(first, 2.0);
    std::ostringstream out(std::ios::binary);
    first.simulation().writeSnapshot(out);
    runFor(first, 2.0);

    physim::Runner second(GetParam().make, options);
    second.restart();
    std::istringstream in(out.str(), std::ios::binary);
    second.simulation().readSnapshot(in);
    runFor(second, 2.0);
    EXPECT_EQ(second.simulation().world().stateHash(), first.simulation().world().stateHash())
        << GetParam().name << " did not resume bit for bit";
    EXPECT_EQ(second.simulation().time, first.simulation().time);
    ASSERT_EQ(second.simulation().branch() != nullptr, first.simulation().branch() != nullptr);
    if (const physim::World* branch = first.simulation().branch()) {
        EXPECT_EQ(second.simulation().branch()->stateHash(), branch->stateHash()) << "its branch";
    }
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleSnapshot, testing::ValuesIn(physim::examples::scenes()),
                         [](const testing::TestParamInfo<physim::examples::Scene>& info) { return info.param.name; });

}  // namespace
