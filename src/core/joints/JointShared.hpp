#pragma once
// What the joint kinds share (Joints.hpp lists the kinds and what each provides): the ends a definition names,
// the row a joint is prepared into for a step, what it reports, and the point and angle pieces of the pin, weld
// and mouse joints. Internal.

#include "../BodyData.hpp"
#include "../Impulse.hpp"
#include "../Softness.hpp"

#include "physim/core/Body.hpp"
#include "physim/core/Math.hpp"

#include <algorithm>
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
    double h = 0.0;           // the substep, s (pin, weld: their points' bend; 0 without WorldSettings::jointArcs)
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
    const double invDet = 1.0 / det;
    out = {(k22 * rhs.x() - k12 * rhs.y()) * invDet, (k11 * rhs.y() - k12 * rhs.x()) * invDet};
    return true;
}

/// A row's lever arm before its body turns: an anchor in the body's frame (from its origin), from its centre of
/// mass, m.
inline Vec2 armFromCenter(const Vec2& local, const BodyData& body) { return local - body.localCenter; }

/// The most a body's turn over a substep counts for in an arm's bend (rad): past it the series below is no longer
/// the arc's, and a turn that large makes the prediction a guess anyway.
constexpr double kMaxBendTurn = 0.5;

/// The bend of a lever arm r over a substep, as a velocity. A body turning at w carries the tip of r round an arc,
/// not along the straight path h (w x r) that a row's velocity sees: (cos t - 1) r + (sin t - t) perp(r) further
/// for the turn t = h w. Divided by h and to third order in t: (-t^2 / 2) r / h + (-t^3 / 6) perp(r) / h. `turn`:
/// t capped at kMaxBendTurn. On doubles or, lane by lane, on Wide (PinLanes.cpp), with the same operations.
template <class T>
[[gnu::always_inline]] inline void bendRate(const T& turn, const T& invH, const T& rx, const T& ry, T& bx, T& by) {
    const T c = -0.5 * turn * turn * invH;  // (cos t - 1) / h
    const T s = c * turn * (1.0 / 3.0);    // (sin t - t) / h
    bx = c * rx - s * ry;
    by = c * ry + s * rx;
}

// Where B's anchor bends away from A's over the substep (bendRate on each side's arm) for bodies turning at wA and
// wB, m/s.
inline Vec2 pointBend(const JointConstraint& row, double wA, double wB, const Vec2& rA, const Vec2& rB) {
    Vec2 bA, bB;
    bendRate(std::clamp(row.h * wA, -kMaxBendTurn, kMaxBendTurn), row.invH, rA.x(), rA.y(), bA.x(), bA.y());
    bendRate(std::clamp(row.h * wB, -kMaxBendTurn, kMaxBendTurn), row.invH, rB.x(), rB.y(), bB.x(), bB.y());
    return bB - bA;
}

// The shared point of a revolute or weld joint. Solve pass: the separation pulled back softly (a spring of
// jointHertz), and the anchors' bend over the substep taken rigidly, so that the row aims where the anchors will be:
// straight steps would part a turning arm's anchors by about h^2 w^2 r / 2 a substep, and the soft pull-back's
// damping would drain a swing (docs/dynamics.md, "Joints keep a swing's energy"). The bend is taken once more at the
// turns the impulse itself gives: the swing's energy depends on that too. Relax pass: rigid. `accumulated`: the
// point's impulse, N s.
inline void solvePoint(const JointConstraint& row, Vec2& accumulated, MotionSide& A, MotionSide& B, bool useBias) {
    const Vec2 rA = A.dq.apply(row.anchorA), rB = B.dq.apply(row.anchorB);
    const Vec2 Cdot = relativeVelocity(A, B, rA, rB);
    Vec2 rhs = Cdot, bend = Vec2::Zero();
    double impulseScale = 0.0;
    const bool arcs = useBias && row.h > 0.0;
    if (useBias) {
        const Vec2 separation = row.deltaCenter + (B.dp - A.dp) + rB - rA;
        if (arcs) bend = pointBend(row, A.w, B.w, rA, rB);
        rhs = row.softness.massScale * (Cdot + row.softness.biasRate * separation) + bend;
        impulseScale = row.softness.impulseScale;
    }
    Vec2 solved;
    if (!solvePointMass(row, rA, rB, rhs, solved)) return;
    Vec2 impulse = -solved - impulseScale * accumulated;
    if (arcs) {
        const double wA = A.w - row.invIA * cross(rA, impulse), wB = B.w + row.invIB * cross(rB, impulse);
        solvePointMass(row, rA, rB, pointBend(row, wA, wB, rA, rB) - bend, solved);
        impulse -= solved;
    }
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
    row.h = h;
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
