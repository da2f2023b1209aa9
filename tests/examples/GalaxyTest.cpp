// galaxy run headless: the tree's gravitation runs every step, and the softened energy stays near its start.

#include "RunProgram.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

TEST(GalaxyExample, TreeGravitationRunsAndKeepsTheEnergy) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_galaxy_test";
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_GALAXY, "--headless --seconds 1 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto cost = physim::test::readGraphCsv((dir / "graph_0.csv").string());    // gravitation, ms per step
    const auto step = physim::test::readGraphCsv((dir / "graph_1.csv").string());    // whole step
    const auto energy = physim::test::readGraphCsv((dir / "graph_2.csv").string());  // E / E(0)
    ASSERT_EQ(cost.size(), 60u);
    for (std::size_t i = 0; i < cost.size(); ++i) {
        EXPECT_GT(cost[i].second, 0.0) << "the gravitation effect ran at " << cost[i].first << " s";
        EXPECT_LE(cost[i].second, step[i].second) << "and is part of the step";
    }
    ASSERT_GE(energy.size(), 4u);
    // The tree's force error (about 1% of a typical star's pull at theta 0.5, tests/core/GravitationTest.cpp)
    // is not conservative; over a second (about a quarter turn of the outer disc) the energy stays within 1%.
    for (const auto& [t, e] : energy) EXPECT_NEAR(e, 1.0, 1e-2) << "t = " << t;
    std::filesystem::remove_all(dir);
}

}  // namespace
