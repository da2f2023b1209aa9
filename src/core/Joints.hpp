#pragma once
// Joint rows of the soft step (see ContactSolver.hpp for the step's passes). Internal.
//   distance: a rigid rod; solved stiff (WorldSettings::jointHertz) with the bias, and exactly without it in the
//             relax pass, so its length error is pushed out without adding energy;
//   mouse:    a spring-damper from an anchor on the body to a target point, its force capped at maxForce, so a
//             dragged body still collides and cannot be pulled through walls.

#include "JointData.hpp"

#include <vector>

namespace physim {

void prepareJoint(JointConstraint& row, const JointData& joint, const std::vector<BodyData>& bodies, double h,
                  const Softness& rodSoftness);
void warmStartJoint(const JointConstraint& row, const JointData& joint, SolverBody* states);
void solveJoint(const JointConstraint& row, JointData& joint, SolverBody* states, bool useBias);

}  // namespace physim
