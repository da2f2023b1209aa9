#pragma once
// The distance joint (DistanceJointDef): a rigid rod between an anchor on each body, solved stiff (jointHertz) with
// the bias and exactly without it in the relax pass, so its length error is pushed out without adding energy; or,
// with hertz > 0, a soft link that is its own spring in both passes. Internal.

#include "JointShared.hpp"

#include "physim/core/Joint.hpp"

namespace physim {

struct DistanceJoint {
    using Def = DistanceJointDef;
    static constexpr JointType kType = JointType::Distance;
    static constexpr const char* kName = "distance";
    static constexpr bool kRow = true;

    double length = 0.0;                     // m
    double hertz = 0.0, dampingRatio = 0.0;  // a soft link's spring; hertz 0: rigid
    double impulse = 0.0;                    // along the rod (A to B), N s per substep

    static JointEnds ends(const Def& def) { return {def.bodyA, def.bodyB, false}; }
    static DistanceJoint make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB);
    void prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                 const Softness& rodSoftness) const;
    void warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const;
    void solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias);
    JointReaction reaction(const JointEndsNow& now, double invH) const;
    /// World::jointLength: the rod's length, m.
    double jointLength() const { return length; }
};

}  // namespace physim
