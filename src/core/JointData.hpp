#pragma once
// A joint's record in the World: its ends (the bodies and anchors every kind has) and its kind's own data, one of
// the joint kinds (joints/, Joints.hpp). Internal.

#include "BodyData.hpp"
#include "joints/DistanceJoint.hpp"
#include "joints/GearJoint.hpp"
#include "joints/MotorJoint.hpp"
#include "joints/MouseJoint.hpp"
#include "joints/PrismaticJoint.hpp"
#include "joints/PulleyJoint.hpp"
#include "joints/RevoluteJoint.hpp"
#include "joints/SpringJoint.hpp"
#include "joints/WeldJoint.hpp"
#include "joints/WheelJoint.hpp"

#include "physim/core/Joint.hpp"
#include "physim/core/Math.hpp"

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <variant>

namespace physim {

/// A createXJoint's definition on its way through World::createJoint (the one creation path), with its kind.
template <class Kind>
struct KindDefinition {
    using Type = Kind;
    const typename Kind::Def* def;
    const char* call;  // the public call, for its errors
};

/// The joint kinds, in JointType's order: adding a kind adds it here.
template <class... Kinds>
struct JointKindList {
    using Params = std::variant<Kinds...>;
    using Definition = std::variant<KindDefinition<Kinds>...>;
    static constexpr bool inTypeOrder() {
        std::size_t i = 0;
        return ((static_cast<std::size_t>(Kinds::kType) == i++) && ...);
    }
};
using JointKinds = JointKindList<DistanceJoint, MouseJoint, SpringJoint, RevoluteJoint, WeldJoint, PulleyJoint,
                                 MotorJoint, PrismaticJoint, WheelJoint, GearJoint>;
static_assert(JointKinds::inTypeOrder(), "a joint kind's place in JointKinds is its JointType");

struct JointDefinition {
    JointKinds::Definition kind;
};

struct JointData {
    // The kind's data: its parameters and accumulated impulses (the warm start). One variant rather than one flat
    // struct of every kind's fields: a pass over the joint rows reads a record of a few lines, whatever the kind.
    JointKinds::Params params;
    // Body slots. A joint to a world point (toWorld: mouse joints, springs to a point) holds only b; a = b.
    std::uint32_t a = 0, b = 0;
    bool toWorld = false;
    // Anchors in the bodies' frames (origin-relative), m; a world end's anchor A is its world point.
    Vec2 localA = Vec2::Zero(), localB = Vec2::Zero();
    // Intrusive lists through each body's joints (side 0: a's list, side 1: b's list).
    std::int32_t prev[2] = {kNullIndex, kNullIndex};
    std::int32_t next[2] = {kNullIndex, kNullIndex};
    std::uint32_t generation = 0;
    bool alive = false;
    bool collideConnected = false;  // JointDefBase's
    double breakForce = 0.0, breakTorque = 0.0;  // N, N m; infinite: never breaks

    JointType type() const { return static_cast<JointType>(params.index()); }
    bool twoBodies() const { return !toWorld; }
    /// Solved as a row of the soft step (all but forces such as springs, which their effect applies).
    bool isRow() const {
        return std::visit([](const auto& kind) { return std::decay_t<decltype(kind)>::kRow; }, params);
    }
};

}  // namespace physim
