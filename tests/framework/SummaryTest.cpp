// summary.json's "results" list: the figures a simulation reports with setResult, in the order first reported,
// with a missing prediction as JSON null and every number read back as the same double.

#include "Summary.hpp"

#include <physim/framework/Simulation.hpp>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace physim {
namespace {

nlohmann::json summaryOf(const Simulation& sim) { return nlohmann::json::parse(summaryJson(sim)); }

TEST(SummaryResults, EmptyListWhenNothingWasReported) {
    Simulation sim;
    const nlohmann::json s = summaryOf(sim);
    ASSERT_TRUE(s.contains("results"));
    EXPECT_TRUE(s["results"].is_array());
    EXPECT_TRUE(s["results"].empty());
}

TEST(SummaryResults, NameMeasuredPredictedUnitWithNullWhereNoPrediction) {
    Simulation sim;
    sim.setResult("period at 90 degrees", 2.3680218, 2.3680217, "s");
    sim.setResult("Kolmogorov-Smirnov distance", 0.05, std::nullopt, "");
    const std::string text = summaryJson(sim);
    // Keys in the documented order, so the file reads as the docs show it.
    EXPECT_NE(text.find("\"name\": \"period at 90 degrees\",\n      \"measured\""), std::string::npos) << text;
    const nlohmann::json r = summaryOf(sim)["results"];
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(r[0]["name"], "period at 90 degrees");
    EXPECT_EQ(r[0]["unit"], "s");
    EXPECT_EQ(r[0]["predicted"].get<double>(), 2.3680217);
    EXPECT_EQ(r[1]["name"], "Kolmogorov-Smirnov distance");
    ASSERT_TRUE(r[1].contains("predicted"));
    EXPECT_TRUE(r[1]["predicted"].is_null());
    EXPECT_EQ(r[1]["unit"], "");
}

TEST(SummaryResults, NumbersReadBackBitForBit) {
    Simulation sim;
    const double values[] = {0.1 + 0.2, 1.0 / 3.0, -2.25, 6.02214076e23, 1e-300,
                             std::numeric_limits<double>::denorm_min(), std::nextafter(1.0, 2.0)};
    for (std::size_t i = 0; i < std::size(values); ++i)
        sim.setResult("value " + std::to_string(i), values[i], -values[i], "m");
    const nlohmann::json r = summaryOf(sim)["results"];
    ASSERT_EQ(r.size(), std::size(values));
    for (std::size_t i = 0; i < r.size(); ++i) {
        EXPECT_EQ(r[i]["measured"].get<double>(), values[i]);
        EXPECT_EQ(r[i]["predicted"].get<double>(), -values[i]);
    }
}

TEST(SummaryResults, ReportingAgainReplacesInPlace) {
    Simulation sim;
    sim.setResult("a", 1.0, 1.0, "m");
    sim.setResult("b", 2.0, std::nullopt, "s");
    sim.setResult("a", 3.0, std::nullopt, "J");  // a relaunch measures again
    ASSERT_EQ(sim.results().size(), 2u);
    const nlohmann::json r = summaryOf(sim)["results"];
    EXPECT_EQ(r[0]["name"], "a");
    EXPECT_EQ(r[0]["measured"].get<double>(), 3.0);
    EXPECT_TRUE(r[0]["predicted"].is_null());
    EXPECT_EQ(r[0]["unit"], "J");
    EXPECT_EQ(r[1]["name"], "b");
}

TEST(SummaryResults, NonFiniteIsWrittenAsNullAndEmptyNameRefused) {
    Simulation sim;
    sim.setResult("diverged", std::numeric_limits<double>::quiet_NaN(), 1.0, "m");
    EXPECT_TRUE(summaryOf(sim)["results"][0]["measured"].is_null());  // still valid JSON
    EXPECT_THROW(sim.setResult("", 1.0, 1.0, "m"), std::invalid_argument);
}

}  // namespace
}  // namespace physim
