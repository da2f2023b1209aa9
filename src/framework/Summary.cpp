#include "Summary.hpp"

#include "physim/framework/RigidBody.hpp"
#include "physim/framework/Simulation.hpp"

#include <nlohmann/json.hpp>

namespace physim {

std::string summaryJson(const Simulation& sim) {
    nlohmann::ordered_json entities = nlohmann::ordered_json::array();
    for (const auto& e : sim.entities()) {
        nlohmann::ordered_json j{{"id", e->id()}};
        if (const auto* rb = e->TryGetBehavior<RigidBody>(); rb && rb->attached()) {
            const Vec2 p = rb->position(), v = rb->velocity();
            j["position"] = {p.x(), p.y()};
            j["angle"] = rb->angle();
            j["velocity"] = {v.x(), v.y()};
            j["angularVelocity"] = rb->angularVelocity();
            j["mass"] = rb->mass();
        }
        entities.push_back(std::move(j));
    }
    nlohmann::ordered_json results = nlohmann::ordered_json::array();
    for (const Simulation::Result& r : sim.results()) {
        nlohmann::ordered_json j{{"name", r.name}, {"measured", r.measured}, {"predicted", nullptr}, {"unit", r.unit}};
        if (r.predicted) j["predicted"] = *r.predicted;
        results.push_back(std::move(j));
    }
    const nlohmann::ordered_json summary{{"time", sim.time},
                                         {"physicsRate", sim.physicsRate()},
                                         {"steps", sim.world().stepCount()},
                                         {"entities", std::move(entities)},
                                         {"results", std::move(results)}};
    return summary.dump(2) + "\n";
}

}  // namespace physim
