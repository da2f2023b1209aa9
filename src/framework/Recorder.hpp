#pragma once
// The runner's --record: chosen quantities of entities' bodies after every fixed step, as a table with a time
// column, written to records.csv and as the TTree "records" in graphs.root. Internal.

#include "physim/framework/RunOptions.hpp"
#include "physim/framework/Simulation.hpp"

#include <string>
#include <vector>

namespace physim {

/// The spec's quantity now (SI units), or NaN when its entity is gone or has no body.
double recordValue(const Simulation& sim, const RecordSpec& spec);

class Recorder {
public:
    /// Checks every spec against the simulation's entities: std::invalid_argument naming the spec for an id no
    /// entity has, or an entity without a body.
    Recorder(std::vector<RecordSpec> specs, const Simulation& sim);
    /// A row at the simulation's time. After a scrub back, the rows from that time on go first. An entity
    /// removed since reads NaN.
    void sample(const Simulation& sim);
    /// "t" then one column per spec: "<quantity>_<id>" (a C identifier, for the TTree's branches).
    const std::vector<std::string>& columns() const { return columns_; }
    const std::vector<std::vector<double>>& rows() const { return rows_; }
    /// records.csv (a header of the columns with their units, then the rows) and the tree in graphs.root, in
    /// `directory`. Returns the paths written.
    std::vector<std::string> write(const std::string& directory) const;

private:
    std::vector<RecordSpec> specs_;
    std::vector<std::string> columns_, units_;
    std::vector<std::vector<double>> rows_;
};

}  // namespace physim
