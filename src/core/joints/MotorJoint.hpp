#pragma once
// The motor joint (MotorJointDef): B's origin driven towards A's point at the linear offset and the relative angle
// towards the angular offset, each a velocity row whose target removes correctionFactor of the error per substep,
// its accumulated impulse capped by maxForce (a disc) or maxTorque. The target velocity is the point of the joint,
// so both passes solve it alike, as the revolute joint's motor. Internal.
//
// The linear offset is A's anchor (JointData::localA, in A's origin frame) and B's anchor is its origin, so the
// shared ends of Joints.hpp carry the target point.

#include "JointShared.hpp"

#include "physim/core/Joint.hpp"

namespace physim {

struct MotorJoint {
    using Def = MotorJointDef;
    static constexpr JointType kType = JointType::Motor;
    static constexpr const char* kName = "motor";
    static constexpr bool kRow = true;

    double angularOffset = 0.0;            // target angle(B) - angle(A), rad
    double maxForce = 0.0, maxTorque = 0.0;  // N, N m
    double correctionFactor = 0.0;         // per substep, in [0, 1]
    Vec2 linearImpulse = Vec2::Zero();     // N s per substep
    double angularImpulse = 0.0;           // N m s per substep

    static JointEnds ends(const Def& def) { return {def.bodyA, def.bodyB, false}; }
    static MotorJoint make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB);
    void prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                 const Softness& rodSoftness) const;
    void warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const;
    void solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias);
    JointReaction reaction(const JointEndsNow& now, double invH) const;
    /// World::jointMotorTorque: its torque on B over the last step, N m.
    double motorTorque(double invH) const { return angularImpulse * invH; }
    /// World::jointMotorForce: the size of its force on B over the last step, N (jointReactionForce: the vector).
    double motorForce(double invH) const { return linearImpulse.norm() * invH; }
    /// World::jointAngle: angle(B) - angle(A) minus the angular offset, rad (0 on target).
    double jointAngle(const BodyData& A, const BodyData& B) const { return B.angle - A.angle - angularOffset; }
};

}  // namespace physim
