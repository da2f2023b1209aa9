#pragma once
// The gear joint (GearJointDef): one velocity row holding coordinate1 + ratio coordinate2 where it was at creation
// (stiff with the bias, exact in the relax pass). Each coordinate is a revolute joint's angle or a prismatic joint's
// translation; the row acts on the two bodies the geared joints move, reading each coordinate from their poses
// (the static bodies' part is a constant). Internal.

#include "JointShared.hpp"

#include "physim/core/Joint.hpp"

#include <cstdint>
#include <vector>

namespace physim {

struct WorldImpl;

/// createGearJoint's definition once the geared joints are resolved: the gear's two bodies and the row's
/// coefficients (World::createGearJoint, GearJoint.cpp).
struct GearDefinition : GearJointDef {
    BodyId bodyA, bodyB;
    double angularA = 0.0, angularB = 0.0;  // d coordinate / d angle of A and of B (rad/rad, m/rad)
    Vec2 linearA = Vec2::Zero(), linearB = Vec2::Zero();  // d coordinate / d anchor (world) of A and B
    Vec2 anchorA = Vec2::Zero(), anchorB = Vec2::Zero();  // the prismatic anchors in A's and B's frames, m
};

struct GearJoint {
    using Def = GearDefinition;
    static constexpr JointType kType = JointType::Gear;
    static constexpr const char* kName = "gear";
    static constexpr bool kRow = true;

    JointId joint1, joint2;
    double ratio = 1.0;
    // The coordinate sum c = angularA angle(A) + angularB angle(B) + linearA . anchorA + linearB . anchorB (world
    // anchors) up to a constant; the row holds it at its value at creation, `initial`.
    double angularA = 0.0, angularB = 0.0;
    Vec2 linearA = Vec2::Zero(), linearB = Vec2::Zero();
    double initial = 0.0;
    double impulse = 0.0;  // accumulated per substep, N s per unit of the coordinates' Jacobian

    static JointEnds ends(const Def& def) { return {def.bodyA, def.bodyB, false}; }
    static GearJoint make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB);
    void prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                 const Softness& rodSoftness) const;
    void warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const;
    void solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias);
    JointReaction reaction(const JointEndsNow& now, double invH) const;
};

/// The live gears on the joint `index` (a revolute or prismatic joint), which go with it: World::destroyJoint.
std::vector<JointId> gearsOn(const WorldImpl& w, std::uint32_t index);

}  // namespace physim
