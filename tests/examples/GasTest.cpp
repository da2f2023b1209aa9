// gas run headless: the speeds relax from one value to the 2D Maxwell-Boltzmann distribution, and the elastic
// collisions keep the kinetic energy.

#include "Results.hpp"
#include "RunProgram.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

namespace {

TEST(Gas, SpeedsFollowMaxwellBoltzmannAndEnergyIsKept) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_gas_test";
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_GAS, "--headless --seconds 10 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(dir / "summary.json");
    const nlohmann::json s = nlohmann::json::parse(in);
    std::vector<double> speeds;
    double energy = 0.0;
    for (const auto& e : s["entities"]) {
        if (e["mass"].get<double>() == 0.0) continue;  // the walls
        const double vx = e["velocity"][0], vy = e["velocity"][1];
        speeds.push_back(std::hypot(vx, vy));
        energy += 0.5 * e["mass"].get<double>() * (vx * vx + vy * vy);
    }
    ASSERT_EQ(speeds.size(), 300u);

    // Kolmogorov-Smirnov distance between the speeds and F(v) = 1 - exp(-v^2 / (2 s^2)), s^2 = <v^2> / 2.
    // At the start every disc has the same speed, sqrt(2) s, so D = 1 - exp(-1) = 0.63. The critical value for
    // 300 samples at the 0.1% level is 1.95 / sqrt(300) = 0.113.
    std::sort(speeds.begin(), speeds.end());
    double sumV2 = 0.0;
    for (double v : speeds) sumV2 += v * v;
    const double s2 = sumV2 / speeds.size() / 2.0;
    double d = 0.0;
    const double n = static_cast<double>(speeds.size());
    for (std::size_t i = 0; i < speeds.size(); ++i) {
        const double cdf = 1.0 - std::exp(-speeds[i] * speeds[i] / (2 * s2));
        d = std::max({d, std::abs(cdf - i / n), std::abs(cdf - (i + 1) / n)});
    }
    EXPECT_LT(d, 1.95 / std::sqrt(n)) << "KS distance to Maxwell-Boltzmann";

    // Kinetic energy: 300 discs of pi 0.2^2 kg at 5 m/s. Elastic, frictionless bounces keep it, also with several
    // discs at once (1e-14 relative over 10 s, rounding). Bound: 1e-6, and never a gain beyond rounding.
    const double initial = 300 * 0.5 * (M_PI * 0.04) * 25.0;
    EXPECT_NEAR(energy / initial, 1.0, 1e-6);
    EXPECT_LT(energy, initial * (1 + 1e-9));

    // summary.json's results: the energy (1e-6, as above); the mean speed against s sqrt(pi / 2), within four
    // standard errors of a mean of 300 Rayleigh speeds (sd s sqrt(2 - pi / 2): 3.0% of the mean each, 12%); the
    // KS distance, which has no prediction, below the same critical value.
    const auto results = physim::test::readResults((dir / "summary.json").string());
    EXPECT_EQ(results.size(), 3u);
    physim::test::expectResult(results, "kinetic energy", "J", 1e-6 * initial);
    physim::test::expectResult(results, "mean speed", "m/s", 0.12 * std::sqrt(M_PI / 2 * s2));
    const auto ks = results.find("Kolmogorov-Smirnov distance to Maxwell-Boltzmann");
    ASSERT_NE(ks, results.end());
    EXPECT_FALSE(ks->second.predicted.has_value()) << "written as null";
    EXPECT_NEAR(ks->second.measured, d, 1e-12) << "the same distance as computed here";
    std::filesystem::remove_all(dir);
}

}  // namespace
