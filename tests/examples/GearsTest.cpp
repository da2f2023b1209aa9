// gears run headless: a Gear train's measured ratios against the set ones, and a crank-slider piston (Prismatic and
// revolute joints) against x = r cos(theta) + sqrt(l^2 - r^2 sin^2(theta)).

#include "Results.hpp"
#include "RunProgram.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace {

std::map<std::string, physim::test::LessonResult> runGears(const std::string& name, const std::string& more = "") {
    const auto dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_GEARS, "--headless --seconds 5 " + more + " --out " + dir.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "graphs.png"));
    auto results = physim::test::readResults((dir / "summary.json").string());
    std::filesystem::remove_all(dir);
    return results;
}

// The bar: a gear train keeps its ratio to 1e-6 (relative) at the default 40 Hz; the piston stays within
// 1 mm of the formula (measured 9.4e-5 m: the pins and the slider are soft in the solve pass).
TEST(GearsGear, RatiosKeptAndPistonOnTheFormulaAtFortyHz) {
    const auto results = runGears("physim_gears_test_bar");
    physim::test::expectResult(results, "gear ratio 1:2", "", 2.0e-6);
    physim::test::expectResult(results, "gear ratio 2:3", "", 0.5e-6);
    physim::test::expectResult(results, "piston's worst deviation from the crank-slider formula", "m", 1e-3);
}

// Other ratios (3 and 0.25): the same.
TEST(GearsGear, OtherRatiosKept) {
    const auto results = runGears("physim_gears_test_ratios", "--param ratio12=3 --param ratio23=0.25");
    physim::test::expectResult(results, "gear ratio 1:2", "", 3.0e-6);
    physim::test::expectResult(results, "gear ratio 2:3", "", 0.25e-6);
}

}  // namespace
