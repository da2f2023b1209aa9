// orbits run headless: the energy stays in its band about the start value and the angular momentum is kept.

#include "Results.hpp"
#include "RunProgram.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

TEST(OrbitsExample, EnergyAndAngularMomentumStayAtTheirStartValues) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_orbits_test";
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_ORBITS, "--headless --seconds 30 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto energy = physim::test::readGraphCsv((dir / "graph_0.csv").string());      // E / E(0)
    const auto momentum = physim::test::readGraphCsv((dir / "graph_2.csv").string());    // L / L(0)
    ASSERT_EQ(energy.size(), 1800u);  // 30 s at 60 Hz
    ASSERT_EQ(momentum.size(), 1800u);
    double worstEnergy = 0.0, worstMomentum = 0.0, firstHalf = 0.0, secondHalf = 0.0;
    for (std::size_t i = 0; i < energy.size(); ++i) {
        const double dE = std::abs(energy[i].second - 1.0);
        worstEnergy = std::max(worstEnergy, dE);
        double& half = i < energy.size() / 2 ? firstHalf : secondHalf;
        half = std::max(half, dE);
        worstMomentum = std::max(worstMomentum, std::abs(momentum[i].second - 1.0));
    }
    // Symplectic Euler at h = 1/480 s: a bounded energy error of first order in omega h for the inner planet
    // (omega = 3.95 rad/s: 8e-3; on near-circular orbits far less); direct sums of central pairwise forces keep the
    // angular momentum to rounding (tests/core/GravitationTest.cpp).
    EXPECT_LT(worstEnergy, 3.95 / 480.0);
    EXPECT_LT(secondHalf, 2.0 * firstHalf + 1e-12) << "bounded, not drifting";
    EXPECT_LT(worstMomentum, 1e-11);

    // summary.json's results: energy and angular momentum beside their start values, to the same bounds.
    const auto results = physim::test::readResults((dir / "summary.json").string());
    EXPECT_EQ(results.size(), 2u);
    ASSERT_TRUE(results.count("total energy") && results.at("total energy").predicted);
    ASSERT_TRUE(results.count("angular momentum") && results.at("angular momentum").predicted);
    physim::test::expectResult(results, "total energy", "J",
                               3.95 / 480.0 * std::abs(*results.at("total energy").predicted));
    physim::test::expectResult(results, "angular momentum", "kg m^2/s",
                               1e-11 * std::abs(*results.at("angular momentum").predicted));
    std::filesystem::remove_all(dir);
}

}  // namespace
