// double_pendulum run headless: two branches 1e-9 rad apart drift apart exponentially, and the fitted exponent is
// written to summary.json's results as "lyapunov exponent" (1/s, no closed form: predicted null). The bar is
// a positive exponent; a chaotic double pendulum released from 150 degrees has one of order 1/s (measured 2.8), so
// the check asks for 0.5 to 10 1/s: a fit of noise, or of a branch that never left the first run, falls outside.

#include "Results.hpp"
#include "RunProgram.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

TEST(DoublePendulum, BranchesDivergeWithAPositiveLyapunovExponent) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_double_pendulum";
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_DOUBLE_PENDULUM, "--headless --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(dir / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(in);
    bool found = false;
    for (const nlohmann::json& e : summary["results"]) {
        if (e["name"] != "lyapunov exponent") continue;
        found = true;
        EXPECT_EQ(e["unit"], "1/s");
        EXPECT_TRUE(e["predicted"].is_null());
        EXPECT_GT(e["measured"].get<double>(), 0.5);
        EXPECT_LT(e["measured"].get<double>(), 10.0);
    }
    EXPECT_TRUE(found) << summary.dump(2);
    std::filesystem::remove_all(dir);
}

}  // namespace
