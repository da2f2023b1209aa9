#pragma once
// Joints: constraints between a body and another body (distance) or a world point (mouse), solved as soft rows
// beside the contacts (Joints.cpp). Internal.

#include "BodyData.hpp"
#include "ContactSolver.hpp"

#include "physim/core/Math.hpp"

#include <cstdint>

namespace physim {

enum class JointKind { Distance, Mouse };

struct JointData {
    JointKind kind = JointKind::Distance;
    // Body slots. A mouse joint holds only b; a is unused.
    std::uint32_t a = 0, b = 0;
    Vec2 localA = Vec2::Zero(), localB = Vec2::Zero();  // anchors in the bodies' frames (origin-relative), m
    double length = 0.0;      // distance joint: the rod's length, m
    Vec2 target = Vec2::Zero();  // mouse joint: world point, m
    double maxForce = 0.0;    // mouse joint: N
    double hertz = 0.0, dampingRatio = 0.0;  // mouse joint spring
    // Accumulated impulses (warm start), N s.
    double impulse = 0.0;
    Vec2 linearImpulse = Vec2::Zero();
    // Intrusive lists through each body's joints (side 0: a's list, side 1: b's list).
    std::int32_t prev[2] = {kNullIndex, kNullIndex};
    std::int32_t next[2] = {kNullIndex, kNullIndex};
    std::uint32_t generation = 0;
    bool alive = false;

    bool twoBodies() const { return kind == JointKind::Distance; }
};

/// A joint's row for one step.
struct JointConstraint {
    std::uint32_t joint = 0;
    std::int32_t indexA = kNullIndex, indexB = kNullIndex;  // awake body indices; kNullIndex: fixed
    Vec2 anchorA = Vec2::Zero(), anchorB = Vec2::Zero();    // lever arms from the centres of mass at the start, m
    Vec2 deltaCenter = Vec2::Zero();  // centre of B minus centre of A at the start (mouse: B's centre - target)
    double invMassA = 0.0, invMassB = 0.0, invIA = 0.0, invIB = 0.0;
    Softness softness;
    double maxImpulse = 0.0;  // mouse: per substep, N s
};

}  // namespace physim
