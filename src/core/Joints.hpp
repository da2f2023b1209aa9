#pragma once
// Joint rows of the soft step (see ContactSolver.hpp for the step's passes). Internal.
//   distance: a rigid rod; solved stiff (WorldSettings::jointHertz) with the bias, and exactly without it in the
//             relax pass, so its length error is pushed out without adding energy. A soft one (hertz > 0) is
//             its own spring in both passes;
//   mouse:    a spring-damper from an anchor on the body to a target point, its force capped at maxForce, so a
//             dragged body still collides and cannot be pulled through walls;
//   revolute: the shared point as the rod (stiff with the bias, exact in the relax pass); the motor, an angular
//             velocity row capped at maxMotorTorque; each limit a one-sided angle row, speculative while apart;
//   weld:     the shared point, and the relative angle held like the rod's length.
// Spring joints are forces, not rows (effects/Springs.cpp).

#include "JointData.hpp"

#include <vector>

namespace physim {

void prepareJoint(JointConstraint& row, const JointData& joint, const std::vector<BodyData>& bodies, double h,
                  const Softness& rodSoftness);
void warmStartJoint(const JointConstraint& row, const JointData& joint, SolverBody* states);
void solveJoint(const JointConstraint& row, JointData& joint, SolverBody* states, bool useBias);

}  // namespace physim
