// tipping run headless: compound cups (a dense base and two light walls, one body) released on the edge of their
// base at tilts 22.5 to 70 degrees; those beyond atan(d / h) tip over, the others fall back.

#include "Results.hpp"
#include "RunProgram.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

// The tipping angle from the cup's parts, computed here from the scene's sizes: base 0.6 x 0.1 m at `baseDensity`,
// walls 0.08 x 0.8 m at 1 kg/m^2 standing on it; d = 0.3 m, h the compound centre's height above the base's
// underside.
double tippingDegrees(double baseDensity) {
    const double base = baseDensity * 0.6 * 0.1, walls = 2.0 * 0.08 * 0.8;
    const double h = 0.05 + walls * 0.45 / (base + walls);
    return std::atan(0.3 / h) * 180.0 / M_PI;
}

TEST(TippingCompound, CupsBeyondTheClosedFormTipTheOthersFallBack) {
    for (double density : {2.0, 4.0}) {
        const auto dir = std::filesystem::temp_directory_path() / "physim_tipping_test";
        std::filesystem::remove_all(dir);
        const auto r = physim::test::runProgram(
            PHYSIM_TIPPING, "--headless --seconds 10 --param base_density=" + std::to_string(density) + " --out " +
                                dir.string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
        const double critical = tippingDegrees(density);
        // Each cup's outcome (graph 0: tilt, then 90 tipped or 0 fell back) is the side of atan(d / h) it started
        // on; the cups are at least 0.4 degrees from it at these densities, where they decide within the run.
        const auto outcomes = physim::test::readGraphCsv((dir / "graph_0.csv").string());
        EXPECT_EQ(outcomes.size(), 20u);
        for (const auto& [tilt, turn] : outcomes) EXPECT_EQ(turn > 45.0, tilt > critical) << tilt << " degrees";
        // The result: midway between the largest tilt that fell back and the smallest that tipped, so within half
        // the 2.5 degree spacing of the closed form.
        const auto results = physim::test::readResults((dir / "summary.json").string());
        physim::test::expectResult(results, "tipping angle", "degrees", 1.25);
        std::filesystem::remove_all(dir);
    }
}

}  // namespace
