#pragma once
// The weld joint (WeldJointDef): the shared point as the pin's, and the relative angle held like the rod's length
// (stiff with the bias, exact in the relax pass). Internal.

#include "JointShared.hpp"

#include "physim/core/Joint.hpp"

namespace physim {

struct WeldJoint {
    using Def = WeldJointDef;
    static constexpr JointType kType = JointType::Weld;
    static constexpr const char* kName = "weld";
    static constexpr bool kRow = true;

    double referenceAngle = 0.0;        // angle(B) - angle(A) at creation, rad
    Vec2 linearImpulse = Vec2::Zero();  // the point's, N s per substep
    double angularImpulse = 0.0;        // the angle's, N m s per substep

    static JointEnds ends(const Def& def) { return {def.bodyA, def.bodyB, false}; }
    static WeldJoint make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB);
    void prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                 const Softness& rodSoftness) const;
    void warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const;
    void solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias);
    JointReaction reaction(const JointEndsNow& now, double invH) const;
    /// World::jointAngle: angle(B) - angle(A) minus its value at creation, rad.
    double jointAngle(const BodyData& A, const BodyData& B) const { return B.angle - A.angle - referenceAngle; }
};

}  // namespace physim
