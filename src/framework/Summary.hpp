#pragma once
// summary.json, which the runner writes with --out (Runner::writeOutputs).

#include <string>

namespace physim {

class Simulation;

/// The final state as JSON, SI units: {"time": t, "physicsRate": hz, "steps": n, "entities": [{"id": 1,
/// "position": [x, y], "angle": a, "velocity": [vx, vy], "angularVelocity": w, "mass": m}, ...]}.
/// "position" is the body origin (Object::getPosition), "velocity" the centre of mass's. Entities without a
/// rigid body carry only their id.
std::string summaryJson(const Simulation& simulation);

}  // namespace physim
