#pragma once

#include <string>

namespace physim {

class Simulation;

/// The final state as JSON, SI units: {"time": t, "physicsRate": hz, "steps": n, "entities": [{"id": 1,
/// "position": [x, y], "angle": a, "velocity": [vx, vy], "angularVelocity": w, "mass": m}, ...]}.
/// Entities without a rigid body carry only their id.
std::string summaryJson(const Simulation& simulation);

}  // namespace physim
