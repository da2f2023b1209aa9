#pragma once
// The mouse joint's soft point constraint, solved as sequential impulses beside the other joints.
//
// A spring of stiffness k = m w^2 and a damper d = 2 m zeta w (w = 2 pi hertz, m the body's mass) pull the
// anchor towards the target. Integrated implicitly over the substep h, m (v' - v) = -h (k C' + d v') with
// C' = C + h v' (C: anchor minus target, m), which is the velocity constraint  v' + beta C + gamma P = 0  on the
// substep's impulse P = m (v' - v), with gamma = 1 / (h (d + h k)) and beta = h k gamma (1/s). Implicit, it is
// stable at any stiffness and step. P is clamped to maxForce * h, so the pull never exceeds maxForce. No
// position pass: the spring itself brings the anchor back.

#include "BodyData.hpp"

#include "physim/core/Math.hpp"

namespace physim {

struct MouseJointData {
    Vec2 localAnchor = Vec2::Zero();  // m, body frame
    Vec2 target = Vec2::Zero();       // m, world
    double maxForce = 0.0;            // N
    double hertz = 5.0;               // Hz
    double dampingRatio = 0.7;
    Vec2 impulse = Vec2::Zero();      // accumulated over the substep, N s (warm start for the next)
    // Per substep:
    Vec2 r = Vec2::Zero();            // anchor's lever arm from the centre of mass, m
    Eigen::Matrix2d softMass = Eigen::Matrix2d::Zero();  // (K + gamma I)^-1
    Vec2 bias = Vec2::Zero();         // m/s
    double gamma = 0.0;               // (N s)^-1 m/s: softness
    double maxImpulse = 0.0;          // N s per substep
};

/// Computes the substep's soft-constraint terms from the body's pose and warm-starts with the last impulse.
void prepareMouseJoint(BodyData& body, MouseJointData& joint, double h);
/// One velocity iteration.
void solveMouseJoint(BodyData& body, MouseJointData& joint);

}  // namespace physim
