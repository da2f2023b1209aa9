#pragma once
// Joint rows of the soft step (see ContactSolver.hpp for the step's passes). Internal.
//
// Each joint kind is a room of its own, joints/<Kind>Joint.hpp and .cpp, listed once in JointKinds (JointData.hpp),
// whose place there is its JointType. A kind provides:
//   Def, kType, kName, kRow   its public definition, its JointType, its name in errors, whether it is a row
//   ends(def)                 the bodies its definition names (or one body and a world point)
//   make(def, A, B, ...)      checks the definition's values (std::invalid_argument naming the bad one) and fills its
//                             anchors and data; World::createJoint (WorldJoints.cpp) does the rest for every kind
//   prepare                   its row's fields for a step (the ends' common fields are filled here)
//   warmStart, solve          on the row's two bodies; solve with the bias (soft push-out) or without (relax)
//   reaction(now, 1/h)        its force on B and torque, N and N m: the accumulated impulses over the substep
// and its World::createXJoint, with any setters of its own. A kind keeps its accumulated impulses in its own record:
// solve adds to them in place, and they are the next step's warm start, so nothing is stored after the last pass.
// A kind that is not a row (a spring: a force, effects/Springs.cpp) provides only the creation and the reaction.
// The functions below visit the kind once per call (a switch): the only place that dispatches on it.

#include "JointData.hpp"

#include <type_traits>
#include <variant>
#include <vector>

namespace physim {

namespace detail {
// Calls f(kind) for a joint solved as a row.
template <class Params, class F>
void visitRow(Params& params, F&& f) {
    std::visit(
        [&](auto& kind) {
            if constexpr (std::decay_t<decltype(kind)>::kRow) f(kind);
        },
        params);
}
}  // namespace detail

inline void prepareJoint(JointConstraint& row, const JointData& joint, const std::vector<BodyData>& bodies,
                         double h, const Softness& rodSoftness) {
    const BodyData& B = bodies[joint.b];
    const RowSide sideB = rowSide(B);
    row.indexB = sideB.index;
    row.invMassB = sideB.invMass;
    row.invIB = sideB.invI;
    row.anchorB = B.xf.q.apply(joint.localB - B.localCenter);
    const BodyData& A = bodies[joint.a];
    if (joint.toWorld) {
        row.indexA = kNullIndex;
        row.invMassA = row.invIA = 0.0;
        row.anchorA = Vec2::Zero();
        row.deltaCenter = B.center - joint.localA;
    } else {
        const RowSide sideA = rowSide(A);
        row.indexA = sideA.index;
        row.invMassA = sideA.invMass;
        row.invIA = sideA.invI;
        row.anchorA = A.xf.q.apply(joint.localA - A.localCenter);
        row.deltaCenter = B.center - A.center;
    }
    detail::visitRow(joint.params, [&](const auto& kind) { kind.prepare(row, A, B, h, rodSoftness); });
}

inline void warmStartJoint(const JointConstraint& row, const JointData& joint, SolverBody* states) {
    MotionSide A = loadSide(states, row.indexA), B = loadSide(states, row.indexB);
    detail::visitRow(joint.params, [&](const auto& kind) { kind.warmStart(row, A, B); });
    storeSide(states, row.indexA, row.invMassA, A);
    storeSide(states, row.indexB, row.invMassB, B);
}

inline void solveJoint(const JointConstraint& row, JointData& joint, SolverBody* states, bool useBias) {
    MotionSide A = loadSide(states, row.indexA), B = loadSide(states, row.indexB);
    detail::visitRow(joint.params, [&](auto& kind) { kind.solve(row, A, B, useBias); });
    storeSide(states, row.indexA, row.invMassA, A);
    storeSide(states, row.indexB, row.invMassB, B);
}

/// The joint's force on B and torque (N, N m) after a step of substep 1 / invH, from the bodies' state now.
inline JointReaction jointReaction(const JointData& joint, const std::vector<BodyData>& bodies, double invH) {
    JointEndsNow now;
    const BodyData& B = bodies[joint.b];
    const Vec2 rB = B.xf.q.apply(joint.localB - B.localCenter);
    now.pointB = B.center + rB;
    now.velocityB = B.v + cross(B.w, rB);
    if (joint.toWorld) {
        now.pointA = joint.localA;
    } else {
        const BodyData& A = bodies[joint.a];
        const Vec2 rA = A.xf.q.apply(joint.localA - A.localCenter);
        now.pointA = A.center + rA;
        now.velocityA = A.v + cross(A.w, rA);
    }
    return std::visit([&](const auto& kind) { return kind.reaction(now, invH); }, joint.params);
}

}  // namespace physim
