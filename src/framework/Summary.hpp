#pragma once
// summary.json, which the runner writes with --out (Runner::writeOutputs).

#include <string>

namespace physim {

class Simulation;

/// The final state as JSON, SI units: {"time": t, "physicsRate": hz, "steps": n, "entities": [{"id": 1,
/// "position": [x, y], "angle": a, "velocity": [vx, vy], "angularVelocity": w, "mass": m}, ...]}.
/// "position" is the body origin (Object::getPosition), "velocity" the centre of mass's. Entities without a
/// rigid body carry only their id. Then "results": [{"name": ..., "measured": x, "predicted": y or null,
/// "unit": ...}, ...], the figures the simulation reported with setResult, in the order first reported (an
/// empty list if none). Numbers are written with enough digits to read back the same double; a non-finite
/// value is written as null.
std::string summaryJson(const Simulation& simulation);

}  // namespace physim
