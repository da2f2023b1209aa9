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

/// m: largest |coordinate| the World accepts for a position, point, anchor or length. Sums, products and squared
/// distances of such values stay far from overflow, and a double still resolves about 2 micrometres there.
constexpr double kMaxCoordinate = 1e10;
/// m/s (and rad/s): largest speed the World accepts, so a 1 s step moves a body at most 1e8 m.
constexpr double kMaxSpeed = 1e8;
/// kg: a dynamic body's mass lies in [kMinMass, kMaxMass] (a nanogram to a billion tonnes), and its inertia is at
/// least kMinInertia (a nanogram a micrometre from its axis), so inverse masses and the impulses they scale stay
/// far from overflow (a density of 1e-300 made a body whose inverse inertia was infinite).
constexpr double kMinMass = 1e-12;
constexpr double kMaxMass = 1e12;
constexpr double kMinInertia = 1e-24;  ///< kg m^2
void requireWithin(std::string_view name, double value, double limit);       ///< finite, |v| <= limit
void requireWithin(std::string_view name, const Vec2& value, double limit);  ///< each component

}  // namespace physim
