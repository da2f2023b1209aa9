// pyramid run headless at 60 Hz for 3 s (the core stacking test's set-up and rate, sleeping off): the stack
// holds at its analytic rest height and energy, within what the solver's slop allows, and gains no energy.

#include "RunProgram.hpp"

#include <physim/core/WorldSettings.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

namespace {

std::string scientific(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", x);
    return text;
}

TEST(Pyramid, StandsAtItsRestHeightAndEnergy) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_pyramid_test";
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_PYRAMID, "--headless --seconds 3 --hz 60 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto energy = physim::test::readGraphCsv((dir / "graph_0.csv").string());
    const auto energyRest = physim::test::readGraphCsv((dir / "graph_1.csv").string());
    const auto top = physim::test::readGraphCsv((dir / "graph_2.csv").string());
    const auto topRest = physim::test::readGraphCsv((dir / "graph_3.csv").string());
    ASSERT_EQ(energy.size(), 180u);
    ASSERT_EQ(energyRest.size(), energy.size());
    ASSERT_EQ(top.size(), energy.size());
    ASSERT_EQ(topRest.size(), energy.size());

    const int base = 20;
    const double g = 9.81, mass = 1.0, slop = physim::WorldSettings{}.linearSlop;
    ASSERT_NEAR(topRest[0].second, base - 0.5, 1e-12);
    // Each contact may keep up to the slop of overlap, so a box in row r (r + 1 contacts down to the ground)
    // may sit up to (r + 1) slops low: the stack's energy may fall short of the rest value by at most
    // sum over rows of (boxes in the row) m g (r + 1) slop (75.5 J of 14077 J), and the top box by 20 slops.
    double energyBound = 0.0;
    for (int row = 0; row < base; ++row) energyBound += (base - row) * mass * g * (row + 1) * slop;
    // The boxes start at rest at their rest heights, so their start energy is the rest value; nothing feeds
    // energy in, so it may not rise above that (1e-9 relative: rounding of the 210-term sum).
    double lowest = energy[0].second, highest = energy[0].second;
    for (std::size_t i = 0; i < energy.size(); ++i) {
        const double rest = energyRest[i].second;
        lowest = std::min(lowest, energy[i].second);
        highest = std::max(highest, energy[i].second);
        EXPECT_LE(energy[i].second, rest * (1 + 1e-9)) << "t = " << energy[i].first;
        EXPECT_GE(energy[i].second, rest - energyBound) << "t = " << energy[i].first;
        EXPECT_LE(top[i].second, topRest[i].second + 1e-9) << "t = " << top[i].first;
        EXPECT_GE(top[i].second, topRest[i].second - base * slop) << "t = " << top[i].first;
    }
    // Issue #4's stacking criterion (tests/core/StackingTest): after the first second the top box stays within
    // 1 cm of where it was then.
    double drift = 0.0;
    const std::size_t oneSecond = 59;  // frame n ends at t = (n + 1) / 60 s
    for (std::size_t i = oneSecond; i < top.size(); ++i)
        drift = std::max(drift, std::abs(top[i].second - top[oneSecond].second));
    EXPECT_LT(drift, 0.01);
    RecordProperty("energy_lowest_J", scientific(lowest));
    RecordProperty("energy_highest_J", scientific(highest));
    RecordProperty("energy_rest_J", scientific(energyRest[0].second));
    RecordProperty("top_final_m", scientific(top.back().second));
    RecordProperty("top_drift_m", scientific(drift));
    std::filesystem::remove_all(dir);
}

}  // namespace
