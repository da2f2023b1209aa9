// conveyor run headless: a box carried by a belt (tangent speed) and a ball rolling to rest under rolling
// resistance, each figure against its formula.

#include "Results.hpp"
#include "RunProgram.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace {

constexpr double kG = 9.81;

// Default parameters at the default 40 Hz: u = 2 m/s, mu = 0.4, v0 = 2 m/s, C_rr = 0.1.
TEST(ConveyorTangentSpeedRollingResistance, ResultsAgainstTheirFormulas) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_conveyor_test";
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_CONVEYOR, "--headless --seconds 4 --out " + dir.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "graphs.png"));
    const auto results = physim::test::readResults((dir / "summary.json").string());
    std::filesystem::remove_all(dir);
    const double u = 2.0, reach = u / (0.4 * kG), distance = 3.0 * 2.0 * 2.0 / (4.0 * 0.1 * kG);
    ASSERT_EQ(results.count("box_final_speed"), 1u);
    ASSERT_EQ(results.count("box_time_to_belt_speed"), 1u);
    ASSERT_EQ(results.count("ball_stopping_distance"), 1u);
    EXPECT_NEAR(*results.at("box_time_to_belt_speed").predicted, reach, 1e-9);  // computed, not measured
    EXPECT_NEAR(*results.at("ball_stopping_distance").predicted, distance, 1e-9);
    // Riding with the belt: its speed to rounding (1e-6 m/s).
    physim::test::expectResult(results, "box_final_speed", "m/s", 1e-6);
    // The catch-up time from the last sliding frame's acceleration: the first substep holds the face at the static
    // bound, and the box rocks as it locks; 1% (5 ms, a fifth of a 40 Hz frame).
    physim::test::expectResult(results, "box_time_to_belt_speed", "s", 0.01 * reach);
    // The deceleration acts substep by substep, so the distance is off by about v0 times a step (2 m/s / 40 Hz =
    // 5 cm at most, 1.6%); 2% bounds it.
    physim::test::expectResult(results, "ball_stopping_distance", "m", 0.02 * distance);
}

}  // namespace
