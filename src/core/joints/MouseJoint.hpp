#pragma once
// The mouse joint (MouseJointDef): a spring-damper from an anchor on a body to a world point (the joint's world end,
// JointData::localA), its force capped at maxForce, so a dragged body still collides and cannot be pulled through
// walls. Always soft: the spring is the point of this joint, in the relax pass too. Internal.

#include "JointShared.hpp"

#include "physim/core/Joint.hpp"

namespace physim {

struct MouseJoint {
    using Def = MouseJointDef;
    static constexpr JointType kType = JointType::Mouse;
    static constexpr const char* kName = "mouse";
    static constexpr bool kRow = true;

    double maxForce = 0.0;                   // N
    double hertz = 0.0, dampingRatio = 0.0;  // the spring
    Vec2 linearImpulse = Vec2::Zero();       // on B, N s per substep

    static JointEnds ends(const Def& def) { return {BodyId{}, def.body, true}; }
    static MouseJoint make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB);
    void prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                 const Softness& rodSoftness) const;
    void warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const;
    void solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias);
    JointReaction reaction(const JointEndsNow& now, double invH) const;
};

}  // namespace physim
