// projectile run headless: the simulated flight against the analytic one, with the integrator's known error.

#include "Results.hpp"
#include "RunProgram.hpp"

#include <physim/core/WorldSettings.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace {

TEST(Projectile, FlightMatchesTheAnalyticAnswer) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_projectile_test";
    std::filesystem::remove_all(dir);
    const double hz = 60.0, dt = 1.0 / hz, g = 9.81;
    const double h = dt / physim::WorldSettings{}.substeps;  // the integrator's step: the frame's substeps
    const auto r = physim::test::runProgram(PHYSIM_PROJECTILE, "--headless --seconds 4 --hz 60 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;

    const double v0 = 20.0, angle = 60.0 * M_PI / 180.0, vx = v0 * std::cos(angle), vy = v0 * std::sin(angle);
    const auto trajectory = physim::test::readGraphCsv((dir / "graph_0.csv").string());
    const auto analytic = physim::test::readGraphCsv((dir / "graph_1.csv").string());
    const auto speed = physim::test::readGraphCsv((dir / "graph_2.csv").string());
    // Semi-implicit Euler with step h gives y(t) = vy t - g t (t + h) / 2 at the step times, so frame n (t = n dt)
    // is above launch height while t <= 2 vy / g - h (the exact flight, 2 vy / g = 3.53 s, is 211.9 frames).
    ASSERT_EQ(static_cast<double>(trajectory.size()), std::floor((2 * vy / g - h) / dt));
    ASSERT_EQ(analytic.size(), trajectory.size());
    ASSERT_EQ(speed.size(), trajectory.size());
    for (std::size_t i = 0; i < trajectory.size(); ++i) {
        const auto [x, y] = trajectory[i];
        const double t = x / vx;  // no horizontal force: x = vx t exactly
        // Semi-implicit Euler lags the parabola by exactly g h t / 2 (see the free-fall test); 1e-9 m covers
        // the rounding of about a thousand additions.
        EXPECT_NEAR(y, analytic[i].second - 0.5 * g * h * t, 1e-9) << "t = " << t;
        // Its velocities are exact at the step times: the speed curve matches the analytic one.
        EXPECT_NEAR(speed[i].second, std::hypot(vx, vy - g * speed[i].first), 1e-9) << "t = " << t;
    }

    // summary.json's results: range, time of flight and highest point beside the no-air formulas. Semi-implicit
    // Euler lags the parabola by g h t / 2 (above): 2e-3 of the height at the apex and 5e-4 of the range (the
    // lag over the landing's vertical speed, times vx); the frames sample the apex within g dt^2 / 8 = 3.4e-4 m
    // and the interpolated crossing is off by less. Bound: 0.5% of each.
    const auto results = physim::test::readResults((dir / "summary.json").string());
    EXPECT_EQ(results.size(), 3u);
    const double range = v0 * v0 * std::sin(2 * angle) / g, flight = 2 * vy / g, height = vy * vy / (2 * g);
    physim::test::expectResult(results, "range at launch height", "m", 5e-3 * range);
    physim::test::expectResult(results, "time of flight", "s", 5e-3 * flight);
    physim::test::expectResult(results, "highest point", "m", 5e-3 * height);
    EXPECT_NEAR(*results.at("range at launch height").predicted, range, 1e-12 * range);
    std::filesystem::remove_all(dir);
}

}  // namespace
