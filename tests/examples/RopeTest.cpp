// rope run headless: the free end never gets farther from the pivot than the rope is long.

#include "RunProgram.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace {

TEST(Rope, EndStaysWithinTheRopesLength) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_rope_test";
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_ROPE, "--headless --seconds 6 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto distance = physim::test::readGraphCsv((dir / "graph_0.csv").string());
    ASSERT_EQ(distance.size(), 360u);  // 6 s at 60 Hz
    const double length = 20 * 0.12;
    EXPECT_NEAR(distance.front().second, length, 1e-3) << "released horizontal, straight";
    // Rigid links: each may stretch by at most 1 mm (the rod tolerance, tests/core/JointTest.cpp), so 20 links
    // at most 2 cm in all (measured 4.4 mm in the whip).
    double longest = 0.0, shortest = length;
    for (const auto& [t, d] : distance) longest = std::max(longest, d), shortest = std::min(shortest, d);
    EXPECT_LT(longest, length + 20 * 1e-3);
    EXPECT_LT(shortest, 0.9 * length) << "the rope folds as it swings";
    std::filesystem::remove_all(dir);
}

}  // namespace
