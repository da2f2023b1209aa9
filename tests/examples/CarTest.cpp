// car run headless: a chassis on two Wheel joints climbing a 10 degree incline of a chain terrain, its
// acceleration against (T / r - M g sin(theta)) / M_eff and the driven wheel's slip against 0.

#include "Results.hpp"
#include "RunProgram.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

constexpr double kG = 9.81;

std::map<std::string, physim::test::LessonResult> runCar(const std::string& name, const std::string& more = "") {
    const auto dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_CAR, "--headless --seconds 5 " + more + " --out " + dir.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "graphs.png"));
    auto results = physim::test::readResults((dir / "summary.json").string());
    std::filesystem::remove_all(dir);
    return results;
}

// The defaults: 90 N m on a wheel of 0.3 m, a 120 kg chassis and two 10 kg discs, 10 degrees. The bar for
// the Wheel joint at 40 Hz: the driven wheel's omega r within 1% of its travel speed (measured 0.05%); the
// acceleration within 1% of the energy balance's (measured +0.13%; at 240 Hz -0.03%).
TEST(CarWheel, RollsWithoutSlippingAndAcceleratesAsPredictedAtFortyHz) {
    const auto results = runCar("physim_car_test_bar");
    const double theta = 10.0 * M_PI / 180.0, mass = 140.0, massEff = mass + 2.0 * 0.5 * 10.0;  // I = m r^2 / 2
    const double a = (90.0 / 0.3 - mass * kG * std::sin(theta)) / massEff;
    const auto it = results.find("acceleration on the incline");
    ASSERT_NE(it, results.end());
    ASSERT_TRUE(it->second.predicted);
    EXPECT_NEAR(*it->second.predicted, a, 1e-9);  // computed, not measured
    physim::test::expectResult(results, "acceleration on the incline", "m/s^2", 0.01 * a);
    physim::test::expectResult(results, "driven wheel's worst slip |omega r / v - 1| on the incline", "", 0.01);
}

// A weaker motor on a gentler slope (80 N m, 5 degrees): still rolling, and as predicted while torque-limited.
TEST(CarWheel, OtherTorqueAndSlope) {
    const auto results = runCar("physim_car_test_other", "--param torque=80 --param slope=5");
    const double theta = 5.0 * M_PI / 180.0;
    const double a = (80.0 / 0.3 - 140.0 * kG * std::sin(theta)) / 150.0;
    physim::test::expectResult(results, "acceleration on the incline", "m/s^2", 0.01 * a);
    physim::test::expectResult(results, "driven wheel's worst slip |omega r / v - 1| on the incline", "", 0.01);
}

}  // namespace
