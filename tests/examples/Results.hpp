#pragma once
// The "results" list of an example's summary.json (Simulation::setResult), read back by name.

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <string>

namespace physim::test {

struct LessonResult {
    double measured = 0.0;
    std::optional<double> predicted;  // null in the file: no closed form
    std::string unit;
};

inline std::map<std::string, LessonResult> readResults(const std::string& summaryPath) {
    std::ifstream in(summaryPath);
    const nlohmann::json s = nlohmann::json::parse(in);
    std::map<std::string, LessonResult> results;
    for (const auto& r : s.at("results")) {
        LessonResult x;
        x.measured = r.at("measured").get<double>();
        if (!r.at("predicted").is_null()) x.predicted = r.at("predicted").get<double>();
        x.unit = r.at("unit").get<std::string>();
        results[r.at("name").get<std::string>()] = x;
    }
    return results;
}

/// Expects the result `name` with a prediction, in `unit`, measured within `tolerance` (absolute) of it.
inline void expectResult(const std::map<std::string, LessonResult>& results, const std::string& name,
                         const std::string& unit, double tolerance) {
    const auto it = results.find(name);
    if (it == results.end()) {
        ADD_FAILURE() << "no result named '" << name << "' in summary.json";
        return;
    }
    EXPECT_EQ(it->second.unit, unit) << name;
    ASSERT_TRUE(it->second.predicted.has_value()) << name;
    EXPECT_NEAR(it->second.measured, *it->second.predicted, tolerance) << name;
}

}  // namespace physim::test
