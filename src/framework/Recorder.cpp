#include "Recorder.hpp"

#include "Arrows.hpp"

#include "physim/framework/RigidBody.hpp"
#include "physim/graphs/TreeFile.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace physim {
namespace {

const RigidBody* bodyOf(const Simulation& sim, int id) {
    for (const auto& e : sim.entities())
        if (e->id() == id) {
            const auto* rb = e->TryGetBehavior<RigidBody>();
            return rb && rb->attached() ? rb : nullptr;
        }
    return nullptr;
}

double valueOf(const World& world, const RigidBody& rb, const std::string& q, double dt) {
    if (q == "contact_force") return contactForceOn(world, rb.bodyId(), dt).norm();
    if (q == "joint_force") return jointForceOn(world, rb.bodyId()).norm();
    if (q == "x") return rb.position().x();
    if (q == "y") return rb.position().y();
    if (q == "angle") return rb.angle();
    if (q == "vx") return rb.velocity().x();
    if (q == "vy") return rb.velocity().y();
    if (q == "speed") return rb.velocity().norm();
    if (q == "angular_velocity") return rb.angularVelocity();
    return world.kineticEnergy(rb.bodyId());  // kinetic_energy
}

std::string specText(const RecordSpec& s) { return std::to_string(s.entity) + ":" + s.quantity; }

}  // namespace

double recordValue(const Simulation& sim, const RecordSpec& spec) {
    const RigidBody* rb = bodyOf(sim, spec.entity);
    return rb ? valueOf(sim.world(), *rb, spec.quantity, sim.fixedTimeStep()) : std::numeric_limits<double>::quiet_NaN();
}

Recorder::Recorder(std::vector<RecordSpec> specs, const Simulation& sim) : specs_(std::move(specs)) {
    columns_ = {"t"};
    units_ = {"s"};
    for (const RecordSpec& s : specs_) {
        bool exists = false;
        for (const auto& e : sim.entities()) exists = exists || e->id() == s.entity;
        if (!exists)
            throw std::invalid_argument("--record " + specText(s) + ": no entity has id " + std::to_string(s.entity) +
                                        " (summary.json lists the ids)");
        if (!bodyOf(sim, s.entity))
            throw std::invalid_argument("--record " + specText(s) + ": entity " + std::to_string(s.entity) +
                                        " has no body");
        columns_.push_back(s.quantity + "_" + std::to_string(s.entity));
        units_.push_back(RecordSpec::unit(s.quantity));
    }
}

void Recorder::sample(const Simulation& sim) {
    const double halfStep = 0.5 * sim.fixedTimeStep();
    while (!rows_.empty() && rows_.back()[0] > sim.time - halfStep) rows_.pop_back();
    std::vector<double> row{sim.time};
    for (const RecordSpec& s : specs_) row.push_back(recordValue(sim, s));
    rows_.push_back(std::move(row));
}

std::vector<std::string> Recorder::write(const std::string& directory) const {
    namespace fs = std::filesystem;
    const fs::path csv = fs::path(directory) / "records.csv";
    std::ofstream out(csv);
    for (std::size_t c = 0; c < columns_.size(); ++c) out << (c ? "," : "") << columns_[c] << " (" << units_[c] << ")";
    out << "\n";
    char number[32];
    for (const auto& row : rows_) {
        for (std::size_t c = 0; c < row.size(); ++c) {
            std::snprintf(number, sizeof number, "%.17g", row[c]);
            out << (c ? "," : "") << number;
        }
        out << "\n";
    }
    if (!out) throw std::runtime_error("physim: cannot write " + csv.string());
    const fs::path root = fs::path(directory) / "graphs.root";
    writeTree(root.string(), "records", columns_, rows_);
    return {csv.string(), root.string()};
}

}  // namespace physim
