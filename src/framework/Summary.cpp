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
    const nlohmann::ordered_json summary{{"time", sim.time},
                                 {"physicsRate", sim.physicsRate()},
                                 {"steps", sim.world().stepCount()},
                                 {"entities", std::move(entities)}};
    return summary.dump(2) + "\n";
}

}  // namespace physim
