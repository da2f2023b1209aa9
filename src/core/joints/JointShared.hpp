#pragma once
// What the joint kinds share (Joints.hpp lists the kinds and what each provides): the ends a definition names,
// the row a joint is prepared into for a step, what it reports, and the point and angle pieces of the pin, weld
// and mouse joints. Internal.

#include "../BodyData.hpp"
#include "../Impulse.hpp"
#include "../Softness.hpp"

#include "physim/core/Body.hpp"
#include "physim/core/Math.hpp"

#include <cstdint>

namespace physim {

/// The bodies a definition names: two, or one and a world point (toWorld: `a` is unused).
struct JointEnds {
    BodyId a, b;
    bool toWorld = false;
};

/// How a joint's row is solved this step: alone (its kind's warmStart and solve), or with others of its colour in
/// lanes, as a pin (PinLanes.hpp) or a wheel (WheelLanes.hpp).
enum class RowLanes : std::uint8_t { None, Pin, Wheel };

/// A joint's row for one step: where its ends are and how they move, the same fields for every kind (a kind uses
/// those it needs). The solver keeps these rows group by group, each naming its joint.
struct JointConstraint {
    std::uint32_t joint = 0;
    std::int32_t indexA = kNullIndex, indexB = kNullIndex;  // awake body indices; kNullIndex: fixed
    RowLanes lanes = RowLanes::None;  // Joints.hpp's jointLanes
    bool chained = false;  // a pin of a chain solved as one block (PinChains.hpp); kept with the layout
    Vec2 anchorA = Vec2::Zero(), anchorB = Vec2::Zero();    // lever arms from the centres of mass at the start, m
    Vec2 deltaCenter = Vec2::Zero();  // centre of B minus centre of A at the start (a world end: minus its point)
    Vec2 groundB = Vec2::Zero();      // pulley: its ground anchor B minus B's centre at the start, m
    double deltaAngle = 0.0;  // revolute, weld, prismatic: joint angle at the start, rad; gear: its error, rad or m
    Vec2 axis = Vec2::Zero();  // prismatic, wheel: the slider's unit axis in the world at the start (turns with A)
    double invMassA = 0.0, invMassB = 0.0, invIA = 0.0, invIB = 0.0;
    double axialMass = 0.0;   // revolute, weld, wheel: 1 / (invIA + invIB), kg m^2; 0 when neither turns
    Softness softness;
    Softness spring;  // revolute, prismatic, wheel: the joint's own spring over a substep (rigid: off)
    double maxImpulse = 0.0;  // mouse, prismatic motor: per substep, N s; revolute, wheel motor: N m s per substep
    double invH = 0.0;        // 1 / substep, 1/s
};

/// What a joint does to body B (and, reversed, to A), N and N m: its accumulated impulses over the substep.
struct JointReaction {
    Vec2 force = Vec2::Zero();  // at B's anchor
    double torque = 0.0;        // besides the force's moment
};

/// A joint's ends after the step, in world coordinates: where they are and how fast they move (m, m/s).
struct JointEndsNow {
    Vec2 pointA = Vec2::Zero(), pointB = Vec2::Zero();
    Vec2 velocityA = Vec2::Zero(), velocityB = Vec2::Zero();
};

// K^-1 rhs for a point constraint, K = (mA + mB) I + IA [rA]x^T [rA]x + IB [rB]x^T [rB]x, the 2x2 effective inverse
// mass of the relative motion of two body points. false when K is singular (nothing can move the point).
inline bool solvePointMass(const JointConstraint& r, const Vec2& rA, const Vec2& rB, const Vec2& rhs, Vec2& out) {
    const double m = r.invMassA + r.invMassB;
    const double k11 = m + r.invIA * rA.y() * rA.y() + r.invIB * rB.y() * rB.y();
    const double k12 = -r.invIA * rA.x() * rA.y() - r.invIB * rB.x() * rB.y();
    const double k22 = m + r.invIA * rA.x() * rA.x() + r.invIB * rB.x() * rB.x();
    const double det = k11 * k22 - k12 * k12;
    if (!(det > 0.0)) return false;
    out = {(k22 * rhs.x() - k12 * rhs.y()) / det, (k11 * rhs.y() - k12 * rhs.x()) / det};
    return true;
}

// The shared point of a revolute or weld joint: soft with the bias (the separation pushed out as a spring of
// jointHertz), rigid in the relax pass. `accumulated`: the point's impulse, N s.
inline void solvePoint(const JointConstraint& row, Vec2& accumulated, MotionSide& A, MotionSide& B, bool useBias) {
    const Vec2 rA = A.dq.apply(row.anchorA), rB = B.dq.apply(row.anchorB);
    const Vec2 Cdot = relativeVelocity(A, B, rA, rB);
    Vec2 bias = Vec2::Zero();
    double massScale = 1.0, impulseScale = 0.0;
    if (useBias) {
        const Vec2 separation = row.deltaCenter + (B.dp - A.dp) + rB - rA;
        bias = row.softness.biasRate * separation;
        massScale = row.softness.massScale;
        impulseScale = row.softness.impulseScale;
    }
    Vec2 solved;
    if (!solvePointMass(row, rA, rB, Cdot + bias, solved)) return;
    const Vec2 impulse = -massScale * solved - impulseScale * accumulated;
    accumulated += impulse;
    applyImpulse(row, A, B, rA, rB, impulse);
}

// Turns A and B apart by an angular impulse (N m s) on B, its reaction on A.
inline void turn(const JointConstraint& row, MotionSide& A, MotionSide& B, double impulse) {
    A.w -= row.invIA * impulse;
    B.w += row.invIB * impulse;
}

// The pin and weld's rows for a step (the point stiff as jointHertz, the angle rows' mass), and the joint angle at
// the start.
inline void preparePinned(JointConstraint& row, double referenceAngle, const BodyData& A, const BodyData& B,
                          double h, const Softness& rodSoftness) {
    row.softness = rodSoftness;
    row.invH = 1.0 / h;
    row.deltaAngle = B.angle - A.angle - referenceAngle;
    const double turning = row.invIA + row.invIB;
    row.axialMass = turning > 0.0 ? 1.0 / turning : 0.0;
}

// A pin or weld at a world point: each body keeps the point where it is now (anchors in the bodies' frames), and
// the joint angle counts from the bodies' relative angle now.
inline double pinAt(const Vec2& anchor, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB) {
    localA = A.xf.applyInverse(anchor);
    localB = B.xf.applyInverse(anchor);
    return B.angle - A.angle;
}

}  // namespace physim
