#pragma once
// Checks for values that cross the API boundary. Each throws std::invalid_argument whose message names the
// value and what was wrong with it, before any state is touched.

#include "physim/core/Math.hpp"

#include <string_view>

namespace physim {

void requireFinite(std::string_view name, double value);
void requireFinite(std::string_view name, const Vec2& value);
void requirePositive(std::string_view name, double value);     ///< finite and > 0
void requireNonNegative(std::string_view name, double value);  ///< finite and >= 0
void requireInRange(std::string_view name, double value, double lo, double hi);  ///< finite, lo <= v <= hi

}  // namespace physim
