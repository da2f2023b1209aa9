// drag run headless: the air ball's speed follows v_t tanh(g t / v_t) to its terminal velocity.

#include "Results.hpp"
#include "RunProgram.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

TEST(DragExample, SpeedFollowsTheTerminalVelocityCurve) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_drag_test";
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_DRAG, "--headless --seconds 8 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto speed = physim::test::readGraphCsv((dir / "graph_0.csv").string());
    ASSERT_GT(speed.size(), 300u) << "about 6 s of falling at 60 frames per second";
    const double g = 9.81, m = 50.0 * M_PI * 0.01, terminal = std::sqrt(m * g / (0.5 * 1.2 * 1.2 * 0.2));
    for (const auto& [t, v] : speed) {
        // Backward Euler in the drag at the 1/480 s substep: within 2 h / tau of the curve at t = tau
        // (tests/core/DragTest.cpp), less before and after; 0.5% holds every point (tau = v_t / g = 1.05 s).
        EXPECT_NEAR(v, terminal * std::tanh(g * t / terminal), 5e-3 * terminal) << "t = " << t;
    }
    EXPECT_NEAR(speed.back().second / terminal, 1.0, 1e-3) << "terminal velocity before it lands";

    // summary.json's results, within the same bounds: 0.5% of v_t on the curve, 0.1% at the end.
    const auto results = physim::test::readResults((dir / "summary.json").string());
    EXPECT_EQ(results.size(), 2u);
    physim::test::expectResult(results, "speed at one time constant", "m/s", 5e-3 * terminal);
    physim::test::expectResult(results, "speed before landing (terminal velocity)", "m/s", 1e-3 * terminal);
    EXPECT_NEAR(*results.at("speed before landing (terminal velocity)").predicted, terminal, 1e-9 * terminal);
    std::filesystem::remove_all(dir);
}

}  // namespace
