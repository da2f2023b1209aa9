#pragma once
// Joints: constraints between a body and another body (distance, revolute, weld) or a world point (mouse),
// solved as soft rows beside the contacts (Joints.cpp); and springs, forces between the same kinds of ends
// (effects/Springs.cpp), kept here so they link islands and go with their bodies like the others. Internal.

#include "BodyData.hpp"
#include "ContactSolver.hpp"

#include "physim/core/Math.hpp"

#include <cstdint>

namespace physim {

enum class JointKind { Distance, Mouse, Spring, Revolute, Weld };

struct JointData {
    JointKind kind = JointKind::Distance;
    // Body slots. A mouse joint, and a spring to a point, hold only b; a is unused (= b).
    std::uint32_t a = 0, b = 0;
    bool toPoint = false;     // spring: its first end is the world point `target`
    Vec2 localA = Vec2::Zero(), localB = Vec2::Zero();  // anchors in the bodies' frames (origin-relative), m
    double length = 0.0;      // distance joint: the rod's length; spring: its rest length, m
    Vec2 target = Vec2::Zero();  // mouse joint, spring to a point: world point, m
    double maxForce = 0.0;    // mouse joint: N
    double hertz = 0.0, dampingRatio = 0.0;  // mouse joint spring; soft distance joint (hertz 0: rigid)
    double stiffness = 0.0, damping = 0.0;   // spring: N/m, N s/m
    double referenceAngle = 0.0;  // revolute, weld: angle(B) - angle(A) at creation, rad
    bool enableLimit = false, enableMotor = false;  // revolute
    double lowerAngle = 0.0, upperAngle = 0.0;      // revolute limits relative to the reference, rad
    double motorSpeed = 0.0, maxMotorTorque = 0.0;  // revolute motor: rad/s, N m
    // Accumulated impulses (warm start), N s (angular: N m s).
    double impulse = 0.0;
    Vec2 linearImpulse = Vec2::Zero();
    double angularImpulse = 0.0;  // weld
    double motorImpulse = 0.0, lowerImpulse = 0.0, upperImpulse = 0.0;  // revolute
    // Intrusive lists through each body's joints (side 0: a's list, side 1: b's list).
    std::int32_t prev[2] = {kNullIndex, kNullIndex};
    std::int32_t next[2] = {kNullIndex, kNullIndex};
    std::uint32_t generation = 0;
    bool alive = false;

    bool twoBodies() const { return kind != JointKind::Mouse && !toPoint; }
    /// Solved as a row of the soft step (all but springs, which are forces).
    bool isRow() const { return kind != JointKind::Spring; }
};

/// A joint's row for one step.
struct JointConstraint {
    std::uint32_t joint = 0;
    std::int32_t indexA = kNullIndex, indexB = kNullIndex;  // awake body indices; kNullIndex: fixed
    Vec2 anchorA = Vec2::Zero(), anchorB = Vec2::Zero();    // lever arms from the centres of mass at the start, m
    Vec2 deltaCenter = Vec2::Zero();  // centre of B minus centre of A at the start (mouse: B's centre - target)
    double deltaAngle = 0.0;  // revolute, weld: joint angle at the start, rad
    double invMassA = 0.0, invMassB = 0.0, invIA = 0.0, invIB = 0.0;
    double axialMass = 0.0;   // revolute, weld: 1 / (invIA + invIB), kg m^2; 0 when neither turns
    Softness softness;
    double maxImpulse = 0.0;  // mouse: per substep, N s; revolute motor: N m s per substep
    double invH = 0.0;        // 1 / substep, 1/s
};

}  // namespace physim
