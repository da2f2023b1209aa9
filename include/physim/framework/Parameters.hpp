#pragma once
// A simulation's adjustable numbers (launch speed, friction, number of bodies...), declared by the simulation
// with their ranges and read in onCreate. The gallery shows them as sliders and `--param name=value` sets them
// from the command line; a change takes effect when the simulation is made again (the runner restarts it
// and carries the values over).

#include <string>
#include <string_view>
#include <vector>

namespace physim {

struct Parameter {
    std::string name;   ///< identifier used on the command line: letters, digits, '_'
    std::string label;  ///< what the slider says, with the unit: "launch speed (m/s)"
    double value = 0.0;
    double min = 0.0;
    double max = 0.0;
    bool integer = false;  ///< a count: whole values only
};

class Parameters {
public:
    /// Declares a parameter at its default value. Throws std::invalid_argument for a repeated or malformed
    /// name, non-finite bounds, min > max, or a default outside [min, max] (or not whole for a count).
    void add(const std::string& name, const std::string& label, double value, double min, double max,
             bool integer = false);
    /// The current value. Throws std::invalid_argument for an unknown name.
    double get(std::string_view name) const;
    int getInt(std::string_view name) const;
    /// Throws std::invalid_argument naming the parameter and the value when it is unknown, outside its range,
    /// or not whole for a count.
    void set(std::string_view name, double value);
    bool contains(std::string_view name) const;
    /// Every value of `from` whose name this set also has (restarts keep what the user chose).
    void copyValuesFrom(const Parameters& from);
    const std::vector<Parameter>& all() const { return parameters_; }
    bool empty() const { return parameters_.empty(); }
    /// "name (label) in [min, max], now value", one line each, for --help.
    std::string describe() const;

private:
    const Parameter& find(std::string_view name) const;
    std::vector<Parameter> parameters_;
};

}  // namespace physim
