#pragma once
// The pulley joint (PulleyJointDef): one rope over two fixed points, a one-sided row C = length - lengthA -
// ratio * lengthB >= 0 that only pulls; speculative while slack, stiff (jointHertz) with the bias once stretched and
// exact in the relax pass, as the revolute joint's limits. Internal.

#include "JointShared.hpp"

#include "physim/core/Joint.hpp"

namespace physim {

struct PulleyJoint {
    using Def = PulleyJointDef;
    static constexpr JointType kType = JointType::Pulley;
    static constexpr const char* kName = "pulley";
    static constexpr bool kRow = true;

    Vec2 groundA = Vec2::Zero(), groundB = Vec2::Zero();  // world points, m
    double ratio = 1.0;
    double length = 0.0;   // lengthA + ratio * lengthB at most, m
    double impulse = 0.0;  // the rope's tension on A's side, N s per substep (>= 0); B's side pulls ratio times it

    static JointEnds ends(const Def& def) { return {def.bodyA, def.bodyB, false}; }
    static PulleyJoint make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB);
    void prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                 const Softness& rodSoftness) const;
    void warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const;
    void solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias);
    JointReaction reaction(const JointEndsNow& now, double invH) const;
    /// World::jointLength: the rope's length, lengthA + ratio * lengthB when taut, m.
    double jointLength() const { return length; }
};

}  // namespace physim
