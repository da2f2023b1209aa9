// photogate run headless: a ball falling through six sensor gates, its speed at each against the exact free-fall
// speed over the gate's chord, and g fitted from the gate times with a start offset.

#include "Results.hpp"
#include "RunProgram.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace {

constexpr double kG = 9.81;

std::map<std::string, physim::test::LessonResult> runPhotogate(const std::string& name, const std::string& more = "") {
    const auto dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir);
    const auto r =
        physim::test::runProgram(PHYSIM_PHOTOGATE, "--headless --seconds 1 " + more + " --out " + dir.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "graphs.png"));
    auto results = physim::test::readResults((dir / "summary.json").string());
    std::filesystem::remove_all(dir);
    return results;
}

// The bar: at the default 40 Hz every result within 0.5% of its prediction. The gates time the crossing on
// the ball's path through the substeps (measured: every speed within 1e-5 of the exact chord speed, g within 2e-5),
// so the bar holds with room; a gate read once per step would miss it by tens of percent.
TEST(PhotogateSensor, ResultsWithinHalfAPercentAtFortyHz) {
    const auto results = runPhotogate("physim_photogate_test_bar");
    ASSERT_EQ(results.size(), 7u);  // six gates and g
    for (const auto& [name, result] : results) {
        ASSERT_TRUE(result.predicted) << name;
        physim::test::expectResult(results, name, name == "g fitted" ? "m/s^2" : "m/s", 0.005 * *result.predicted);
    }
    ASSERT_EQ(results.count("g fitted"), 1u);
    EXPECT_EQ(*results.at("g fitted").predicted, kG);
    // The prediction at 0.5 m is the exact chord speed, within L^2 / (16 h^2) (0.03%) of sqrt(2 g h).
    ASSERT_EQ(results.count("v at 0.5 m"), 1u);
    EXPECT_NEAR(*results.at("v at 0.5 m").predicted, std::sqrt(2.0 * kG * 0.5), 0.001 * std::sqrt(2.0 * kG * 0.5));
}

// A larger ball and a coarser rate (20 Hz): still within the bar (the times do not depend on the step).
TEST(PhotogateSensor, ResultsWithinHalfAPercentAtTwentyHzWithALargerBall) {
    const auto results = runPhotogate("physim_photogate_test_20", "--hz 20 --param r=0.05");
    ASSERT_EQ(results.size(), 7u);
    for (const auto& [name, result] : results)
        physim::test::expectResult(results, name, name == "g fitted" ? "m/s^2" : "m/s", 0.005 * *result.predicted);
}

}  // namespace
