#pragma once
// Semi-implicit (symplectic) Euler: velocities first from this step's forces, positions from the new
// velocities. For constant acceleration g the position error after time t is exactly g dt t / 2.

#include "BodyData.hpp"

#include <vector>

namespace physim {

void integrateVelocities(std::vector<BodyData>& bodies, const Vec2& gravity, double dt);
void integratePositions(std::vector<BodyData>& bodies, double dt);
void clearForces(std::vector<BodyData>& bodies);

}  // namespace physim
