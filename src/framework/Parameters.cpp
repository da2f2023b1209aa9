#include "physim/framework/Parameters.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace physim {
namespace {

std::string show(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
}

void check(const Parameter& p, double value) {
    if (!std::isfinite(value) || value < p.min || value > p.max)
        throw std::invalid_argument("physim: parameter " + p.name + " must be in [" + show(p.min) + ", " +
                                    show(p.max) + "], got " + show(value));
    if (p.integer && value != std::floor(value))
        throw std::invalid_argument("physim: parameter " + p.name + " is a count, got " + show(value));
}

}  // namespace

void Parameters::add(const std::string& name, const std::string& label, double value, double min, double max,
                     bool integer) {
    const bool wellFormed = !name.empty() && std::all_of(name.begin(), name.end(), [](unsigned char c) {
        return std::isalnum(c) || c == '_';
    });
    if (!wellFormed)
        throw std::invalid_argument("physim: parameter name '" + name + "' must be letters, digits and '_'");
    if (contains(name)) throw std::invalid_argument("physim: parameter " + name + " is declared twice");
    if (!(std::isfinite(min) && std::isfinite(max) && min <= max))
        throw std::invalid_argument("physim: parameter " + name + " needs finite bounds min <= max, got [" +
                                    show(min) + ", " + show(max) + "]");
    Parameter p{name, label.empty() ? name : label, value, min, max, integer};
    check(p, value);
    parameters_.push_back(std::move(p));
}

const Parameter& Parameters::find(std::string_view name) const {
    for (const Parameter& p : parameters_)
        if (p.name == name) return p;
    std::string known;
    for (const Parameter& p : parameters_) known += (known.empty() ? "" : ", ") + p.name;
    throw std::invalid_argument("physim: no parameter named '" + std::string(name) + "' (" +
                                (known.empty() ? "this simulation has none" : "it has: " + known) + ")");
}

double Parameters::get(std::string_view name) const { return find(name).value; }
int Parameters::getInt(std::string_view name) const { return static_cast<int>(std::lround(find(name).value)); }

void Parameters::set(std::string_view name, double value) {
    Parameter& p = const_cast<Parameter&>(find(name));
    check(p, value);
    p.value = value;
}

bool Parameters::contains(std::string_view name) const {
    return std::any_of(parameters_.begin(), parameters_.end(), [&](const Parameter& p) { return p.name == name; });
}

void Parameters::copyValuesFrom(const Parameters& from) {
    for (const Parameter& p : from.parameters_)
        if (contains(p.name)) set(p.name, p.value);
}

std::string Parameters::describe() const {
    std::ostringstream os;
    for (const Parameter& p : parameters_)
        os << "  " << p.name << ": " << p.label << ", " << (p.integer ? "a count " : "") << "in [" << p.min << ", "
           << p.max << "], default " << p.value << "\n";
    return os.str();
}

}  // namespace physim
