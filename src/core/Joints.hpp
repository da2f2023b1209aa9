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
// A kind that is not a row (a spring: a force, effects/Springs.cpp) provides, instead of the row's functions,
//   addTo, removeFrom(effects, joint)  hand the joint to the effect that applies its force, and take it back
// A row's kind may also say `static constexpr bool kSerial = true`: its rows are then solved one after another in the
// joints' order, after the joint colours (a row that reaches bodies besides its two ends must). The others are
// coloured like contacts (ConstraintGraph.cpp) and solved a colour at a time, on the team's threads.
// A kind may also provide (World::jointLength, jointAngle, jointMotorTorque and jointMotorForce refuse the others):
//   jointLength()             its length, m
//   jointAngle(A, B)          its angle between the bodies, rad
//   motorTorque(invH)         what its rotary motor applied over the last step, N m (on B; the reaction on A)
//   motorForce(invH)          what its linear motor applied over the last step, N (on B along the axis)
//   jointTranslation(A, B, localA, localB), jointSpeed(...)   a slider's translation along its axis, m, m/s
// The functions below visit the kind once per call (a switch) for the step and the World's generic queries. Beside
// them, creation visits the definition (WorldJoints.cpp), and a kind's own setters and effect reach its data by
// its type.

#include "JointData.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace physim {

struct Effects;

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

// Whether a kind provides jointLength() or jointAngle(A, B).
template <class Kind, class = void>
struct HasLength : std::false_type {};
template <class Kind>
struct HasLength<Kind, std::void_t<decltype(std::declval<const Kind&>().jointLength())>> : std::true_type {};
template <class Kind, class = void>
struct HasAngle : std::false_type {};
template <class Kind>
struct HasAngle<Kind, std::void_t<decltype(std::declval<const Kind&>().jointAngle(std::declval<const BodyData&>(),
                                                                                   std::declval<const BodyData&>()))>>
    : std::true_type {};

template <class Kind, class = void>
struct IsSerial : std::false_type {};
template <class Kind>
struct IsSerial<Kind, std::enable_if_t<Kind::kSerial>> : std::true_type {};

template <class Kind, class = void>
struct HasMotorTorque : std::false_type {};
template <class Kind>
struct HasMotorTorque<Kind, std::void_t<decltype(std::declval<const Kind&>().motorTorque(0.0))>> : std::true_type {};
template <class Kind, class = void>
struct HasMotorForce : std::false_type {};
template <class Kind>
struct HasMotorForce<Kind, std::void_t<decltype(std::declval<const Kind&>().motorForce(0.0))>> : std::true_type {};

template <class Kind, class = void>
struct HasTranslation : std::false_type {};
template <class Kind>
struct HasTranslation<Kind, std::void_t<decltype(std::declval<const Kind&>().jointTranslation(
                                std::declval<const BodyData&>(), std::declval<const BodyData&>(),
                                std::declval<const Vec2&>(), std::declval<const Vec2&>()))>> : std::true_type {};

// "a distance or spring joint": the kinds that have what `call` reads, for refusing the one at hand.
template <template <class, class> class Has, class... Kinds>
[[noreturn]] void refuseKind(const char* call, const char* kind, JointKindList<Kinds...>) {
    std::string names;
    ((Has<Kinds, void>::value ? (names += (names.empty() ? "" : " or ") + std::string(Kinds::kName), 0) : 0), ...);
    throw std::invalid_argument(std::string("physim: ") + call + " needs a " + names + " joint, not a " + kind +
                                " joint");
}
}  // namespace detail

/// Whether the joint's row may share a colour with others (it reads and writes only its two ends' records).
inline bool jointColoured(const JointData& joint) {
    return std::visit([](const auto& kind) { return !detail::IsSerial<std::decay_t<decltype(kind)>>::value; },
                      joint.params);
}

/// Whether the joint's row is solved in lanes: a pin (PinLanes.hpp) or a wheel (WheelLanes.hpp).
inline RowLanes jointLanes(const JointData& joint) {
    if (const RevoluteJoint* pin = std::get_if<RevoluteJoint>(&joint.params); pin && pin->pointOnly())
        return RowLanes::Pin;
    if (const WheelJoint* wheel = std::get_if<WheelJoint>(&joint.params); wheel && wheel->solvesInLanes())
        return RowLanes::Wheel;
    return RowLanes::None;
}

inline void prepareJoint(JointConstraint& row, const JointData& joint, const std::vector<BodyData>& bodies,
                         double h, const Softness& rodSoftness) {
    const BodyData& B = bodies[joint.b];
    const RowSide sideB = rowSide(B);
    row.indexB = sideB.index;
    row.invMassB = sideB.invMass;
    row.invIB = sideB.invI;
    row.anchorB = B.xf.q.apply(armFromCenter(joint.localB, B));
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
        row.anchorA = A.xf.q.apply(armFromCenter(joint.localA, A));
        row.deltaCenter = B.center - A.center;
    }
    detail::visitRow(joint.params, [&](const auto& kind) { kind.prepare(row, A, B, h, rodSoftness); });
    row.lanes = jointLanes(joint);
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

/// World::jointLength: the joint's length, m; std::invalid_argument for a kind without one.
inline double jointLength(const JointData& joint) {
    return std::visit(
        [](const auto& kind) -> double {
            using Kind = std::decay_t<decltype(kind)>;
            if constexpr (detail::HasLength<Kind>::value) return kind.jointLength();
            else detail::refuseKind<detail::HasLength>("jointLength", Kind::kName, JointKinds{});
        },
        joint.params);
}

/// World::jointAngle: the joint's angle between its bodies, rad; std::invalid_argument for a kind without one.
inline double jointAngle(const JointData& joint, const std::vector<BodyData>& bodies) {
    return std::visit(
        [&](const auto& kind) -> double {
            using Kind = std::decay_t<decltype(kind)>;
            if constexpr (detail::HasAngle<Kind>::value) return kind.jointAngle(bodies[joint.a], bodies[joint.b]);
            else detail::refuseKind<detail::HasAngle>("jointAngle", Kind::kName, JointKinds{});
        },
        joint.params);
}

/// World::jointMotorTorque and jointMotorForce: what the joint's motor applied over the last step of substep 1 / invH
/// (N m, N); std::invalid_argument for a kind without such a motor.
inline double jointMotorTorque(const JointData& joint, double invH) {
    return std::visit(
        [&](const auto& kind) -> double {
            using Kind = std::decay_t<decltype(kind)>;
            if constexpr (detail::HasMotorTorque<Kind>::value) return kind.motorTorque(invH);
            else detail::refuseKind<detail::HasMotorTorque>("jointMotorTorque", Kind::kName, JointKinds{});
        },
        joint.params);
}
inline double jointMotorForce(const JointData& joint, double invH) {
    return std::visit(
        [&](const auto& kind) -> double {
            using Kind = std::decay_t<decltype(kind)>;
            if constexpr (detail::HasMotorForce<Kind>::value) return kind.motorForce(invH);
            else detail::refuseKind<detail::HasMotorForce>("jointMotorForce", Kind::kName, JointKinds{});
        },
        joint.params);
}

/// World::jointTranslation and jointSpeed: a slider's translation along its axis and its rate (m, m/s);
/// std::invalid_argument for a kind without one.
inline double jointTranslation(const JointData& joint, const std::vector<BodyData>& bodies, bool rate) {
    return std::visit(
        [&](const auto& kind) -> double {
            using Kind = std::decay_t<decltype(kind)>;
            if constexpr (detail::HasTranslation<Kind>::value) {
                const BodyData &A = bodies[joint.a], &B = bodies[joint.b];
                return rate ? kind.jointSpeed(A, B, joint.localA, joint.localB)
                            : kind.jointTranslation(A, B, joint.localA, joint.localB);
            } else {
                detail::refuseKind<detail::HasTranslation>(rate ? "jointSpeed" : "jointTranslation", Kind::kName,
                                                           JointKinds{});
            }
        },
        joint.params);
}

/// A joint that is not a row is a force: its kind hands it to the effect that applies it (a row: nothing to do).
inline void addForceJoint(const JointData& joint, std::uint32_t index, Effects& effects) {
    std::visit(
        [&](const auto& kind) {
            using Kind = std::decay_t<decltype(kind)>;
            if constexpr (!Kind::kRow) Kind::addTo(effects, index);
        },
        joint.params);
}

/// The joint is going: a force's kind takes it back from its effect.
inline void removeForceJoint(const JointData& joint, std::uint32_t index, Effects& effects) {
    std::visit(
        [&](const auto& kind) {
            using Kind = std::decay_t<decltype(kind)>;
            if constexpr (!Kind::kRow) Kind::removeFrom(effects, index);
        },
        joint.params);
}

}  // namespace physim
