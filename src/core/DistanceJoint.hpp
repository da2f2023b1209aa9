#pragma once
// Distance joints solved as sequential impulses beside the contacts: the velocity along the rod is driven to
// zero (push or pull, so the accumulated impulse is unclamped and warm-started), then a position pass moves the
// anchors back to the rod's length without touching velocities (adds no energy), like the contacts' pass.

#include "BodyData.hpp"
#include "MouseJoint.hpp"

#include "physim/core/Joint.hpp"

#include <vector>

namespace physim {

struct JointData {
    JointType type = JointType::Distance;
    std::uint32_t a = 0, b = 0;  // body slots (a mouse joint's one body is both)
    Vec2 localA = Vec2::Zero(), localB = Vec2::Zero();
    double length = 0.0;         // m
    double impulse = 0.0;        // accumulated along the rod, N s (warm start)
    std::uint32_t generation = 0;
    bool alive = false;
    bool active = true;          // this substep: false when neither body is awake and movable (skipped)
    // Per substep:
    Vec2 rA = Vec2::Zero(), rB = Vec2::Zero(), u = Vec2::Zero();
    double mass = 0.0;
    double bias = 0.0;  // target rod-wise speed, m/s (see prepareJoints)
    MouseJointData mouse;  // type Mouse only
};

// These solve the distance joints (and skip the others).
/// h: the substep (s) the positions will move over after the solve.
void prepareJoints(std::vector<BodyData>& bodies, std::vector<JointData>& joints, double h);
void solveJointVelocities(std::vector<BodyData>& bodies, std::vector<JointData>& joints);
void correctJointPositions(std::vector<BodyData>& bodies, std::vector<JointData>& joints);

}  // namespace physim
