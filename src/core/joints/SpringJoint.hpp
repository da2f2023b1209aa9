#pragma once
// The spring joint (SpringJointDef): Hooke's law with damping between an anchor on each body, or from a body's
// anchor to a world point (the joint's world end, JointData::localA). A force, not a row: the springs effect
// (effects/Springs.cpp) applies it every substep; it is stored as a joint so that it links islands and goes with
// its bodies. Internal.

#include "JointShared.hpp"

#include "physim/core/Joint.hpp"

#include <cstdint>

namespace physim {

struct Effects;

struct SpringJoint {
    using Def = SpringJointDef;
    static constexpr JointType kType = JointType::Spring;
    static constexpr const char* kName = "spring";
    static constexpr bool kRow = false;

    double restLength = 0.0;  // m
    double stiffness = 0.0;   // N/m
    double damping = 0.0;     // N s/m

    static JointEnds ends(const Def& def) { return {def.bodyA, def.bodyB, def.bodyA.isNull()}; }
    static SpringJoint make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB);
    /// Hooke's law with damping: the pull along the spring at `length` m stretching at `rate` m/s, N.
    double tension(double length, double rate) const { return stiffness * (length - restLength) + damping * rate; }
    /// Its force on B now (the reaction: a force has no impulses to report).
    JointReaction reaction(const JointEndsNow& now, double invH) const;
    /// World::jointLength: the rest length, m.
    double jointLength() const { return restLength; }
    /// Not a row: the springs effect applies its force from the step after it is added until it is removed.
    static void addTo(Effects& effects, std::uint32_t joint);
    static void removeFrom(Effects& effects, std::uint32_t joint);
};

}  // namespace physim
