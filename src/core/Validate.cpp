#include "physim/core/Validate.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace physim {
namespace {

[[noreturn]] void fail(std::string_view name, const std::string& value, std::string_view expectation) {
    std::ostringstream os;
    os << "physim: " << name << " must be " << expectation << ", got " << value;
    throw std::invalid_argument(os.str());
}

std::string show(double v) {
    std::ostringstream os;
    os.precision(17);
    os << v;
    return os.str();
}

}  // namespace

void requireFinite(std::string_view name, double value) {
    if (!std::isfinite(value)) fail(name, show(value), "finite");
}

void requireFinite(std::string_view name, const Vec2& value) {
    if (!std::isfinite(value.x()) || !std::isfinite(value.y()))
        fail(name, "(" + show(value.x()) + ", " + show(value.y()) + ")", "finite");
}

void requirePositive(std::string_view name, double value) {
    if (!(std::isfinite(value) && value > 0.0)) fail(name, show(value), "finite and > 0");
}

void requireNonNegative(std::string_view name, double value) {
    if (!(std::isfinite(value) && value >= 0.0)) fail(name, show(value), "finite and >= 0");
}

void requireInRange(std::string_view name, double value, double lo, double hi) {
    if (!(std::isfinite(value) && value >= lo && value <= hi))
        fail(name, show(value), "in [" + show(lo) + ", " + show(hi) + "]");
}

void requireWithin(std::string_view name, double value, double limit) {
    if (!(std::isfinite(value) && std::abs(value) <= limit))
        fail(name, show(value), "finite, |value| <= " + show(limit));
}

void requireWithin(std::string_view name, const Vec2& value, double limit) {
    if (!(std::isfinite(value.x()) && std::isfinite(value.y()) && std::abs(value.x()) <= limit &&
          std::abs(value.y()) <= limit))
        fail(name, "(" + show(value.x()) + ", " + show(value.y()) + ")", "finite, each |component| <= " + show(limit));
}

}  // namespace physim
