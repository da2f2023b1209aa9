// double_pendulum run headless: two branches 1e-9 rad apart drift apart exponentially, and the fitted exponent is
// written to summary.json's results as "lyapunov exponent" (1/s, no closed form: predicted null). The bar is
// a positive exponent; a chaotic double pendulum released from 150 degrees has one of order 1/s (measured 0.92 at 40
// Hz; 0.6 to 2.3 at 160 to 2560 Hz, a fit over one stretch of one orbit), so the check asks for 0.5 to 10 1/s: a fit
// of noise, or of a branch that never left the first run, falls outside. At about 1/s the distance reaches the fit's
// 1 mm after about 11 s (later on other orbits), so the run lasts 30 s.

#include "Results.hpp"
#include "RunProgram.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

TEST(DoublePendulum, BranchesDivergeWithAPositiveLyapunovExponent) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_double_pendulum";
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_DOUBLE_PENDULUM, "--headless --seconds 30 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    const auto results = physim::test::readResults((dir / "summary.json").string());
    const auto it = results.find("lyapunov exponent");
    ASSERT_NE(it, results.end()) << r.output;
    EXPECT_EQ(it->second.unit, "1/s");
    EXPECT_FALSE(it->second.predicted.has_value());
    EXPECT_GT(it->second.measured, 0.5);
    EXPECT_LT(it->second.measured, 10.0);
    std::filesystem::remove_all(dir);
}

}  // namespace
