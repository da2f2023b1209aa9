// circles run headless: contacts only take energy away, and the discs end at rest inside the box.

#include "RunProgram.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

TEST(Circles, EnergyNeverRisesAndTheHeapComesToRest) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_circles_test";
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_CIRCLES, "--headless --seconds 10 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(dir / "summary.json");
    const nlohmann::json s = nlohmann::json::parse(in);
    double totalMass = 0.0;
    int discs = 0;
    for (const auto& e : s["entities"]) {
        if (e["mass"].get<double>() == 0.0) continue;  // the box
        ++discs;
        totalMass += e["mass"].get<double>();
        // Inside the 4 m box (walls' inner faces at x = +-2, floor at y = 0; radii are 0.1 to 0.3 m).
        EXPECT_LT(std::abs(e["position"][0].get<double>()), 2.0);
        EXPECT_GT(e["position"][1].get<double>(), 0.1 - 0.01);
        EXPECT_LT(std::hypot(e["velocity"][0].get<double>(), e["velocity"][1].get<double>()), 0.05) << "at rest";
    }
    ASSERT_EQ(discs, 40);

    const auto energy = physim::test::readGraphCsv((dir / "graph_0.csv").string());
    const auto initial = physim::test::readGraphCsv((dir / "graph_1.csv").string());
    ASSERT_FALSE(energy.empty());
    const double e0 = initial.front().second;
    // Restitution 0.4 and friction only dissipate. The position pass may lift a disc by up to the 5 mm slop it
    // leaves in each contact: at most M g (2 x 5 mm) in all.
    for (const auto& [t, e] : energy) EXPECT_LE(e, e0 + totalMass * 9.81 * 0.01) << "t = " << t;
    EXPECT_LT(energy.back().second, 0.5 * e0) << "the fall's energy is gone into the heap's collisions";
    std::filesystem::remove_all(dir);
}

}  // namespace
