#include "Joints.hpp"

#include "Impulse.hpp"

#include <algorithm>
#include <cmath>

namespace physim {
namespace {

// The rod's direction and length now, from the start and the displacements since.
struct RodState {
    Vec2 rA, rB, u;
    double length;
};

RodState rod(const JointConstraint& r, const MotionSide& A, const MotionSide& B) {
    RodState s;
    s.rA = A.dq.apply(r.anchorA);
    s.rB = B.dq.apply(r.anchorB);
    const Vec2 d = r.deltaCenter + (B.dp - A.dp) + s.rB - s.rA;
    s.length = d.norm();
    s.u = s.length > 1e-12 ? Vec2(d / s.length) : Vec2(0.0, 1.0);  // coincident anchors: any direction, no NaN
    return s;
}

// K^-1 rhs for a point constraint, K = (mA + mB) I + IA [rA]x^T [rA]x + IB [rB]x^T [rB]x, the 2x2 effective inverse
// mass of the relative motion of two body points. false when K is singular (nothing can move the point).
template <class Row>
bool solvePointMass(const Row& r, const Vec2& rA, const Vec2& rB, const Vec2& rhs, Vec2& out) {
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
// jointHertz), rigid in the relax pass.
void solvePoint(const JointConstraint& row, JointData& joint, MotionSide& A, MotionSide& B, bool useBias) {
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
    const Vec2 impulse = -massScale * solved - impulseScale * joint.linearImpulse;
    joint.linearImpulse += impulse;
    applyImpulse(row, A, B, rA, rB, impulse);
}

// Turns A and B apart by an angular impulse (N m s) on B, its reaction on A.
void turn(const JointConstraint& row, MotionSide& A, MotionSide& B, double impulse) {
    A.w -= row.invIA * impulse;
    B.w += row.invIB * impulse;
}

// A one-sided angle row: C = sign (jointAngle - limit) must stay >= 0. Apart, it is speculative (stops the bodies at
// the limit within the substep); past it, pushed back softly with the bias, rigidly in the relax pass.
void solveLimit(const JointConstraint& row, double C, double sign, double& accumulated, MotionSide& A,
                MotionSide& B, bool useBias) {
    double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    if (C > 0.0) {
        bias = C * row.invH;
    } else if (useBias) {
        bias = row.softness.biasRate * C;
        massScale = row.softness.massScale;
        impulseScale = row.softness.impulseScale;
    }
    const double Cdot = sign * (B.w - A.w);
    const double lambda = -row.axialMass * massScale * (Cdot + bias) - impulseScale * accumulated;
    const double total = std::max(accumulated + lambda, 0.0);
    turn(row, A, B, sign * (total - accumulated));
    accumulated = total;
}

void solveRevolute(const JointConstraint& row, JointData& joint, MotionSide& A, MotionSide& B, bool useBias) {
    if (joint.enableMotor && row.axialMass > 0.0) {
        const double Cdot = B.w - A.w - joint.motorSpeed;
        const double old = joint.motorImpulse;
        joint.motorImpulse = std::clamp(old - row.axialMass * Cdot, -row.maxImpulse, row.maxImpulse);
        turn(row, A, B, joint.motorImpulse - old);
    }
    if (joint.enableLimit && row.axialMass > 0.0) {
        const double angle = row.deltaAngle + B.dAngle - A.dAngle;
        solveLimit(row, angle - joint.lowerAngle, 1.0, joint.lowerImpulse, A, B, useBias);
        solveLimit(row, joint.upperAngle - angle, -1.0, joint.upperImpulse, A, B, useBias);
    }
    solvePoint(row, joint, A, B, useBias);
}

void solveWeld(const JointConstraint& row, JointData& joint, MotionSide& A, MotionSide& B, bool useBias) {
    if (row.axialMass > 0.0) {
        double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
        if (useBias) {
            bias = row.softness.biasRate * (row.deltaAngle + B.dAngle - A.dAngle);
            massScale = row.softness.massScale;
            impulseScale = row.softness.impulseScale;
        }
        const double lambda = -row.axialMass * massScale * (B.w - A.w + bias) - impulseScale * joint.angularImpulse;
        joint.angularImpulse += lambda;
        turn(row, A, B, lambda);
    }
    solvePoint(row, joint, A, B, useBias);
}

}  // namespace

void prepareJoint(JointConstraint& row, const JointData& joint, const std::vector<BodyData>& bodies, double h,
                  const Softness& rodSoftness) {
    const BodyData& B = bodies[joint.b];
    const RowSide sideB = rowSide(B);
    row.indexB = sideB.index;
    row.invMassB = sideB.invMass;
    row.invIB = sideB.invI;
    row.anchorB = B.xf.q.apply(joint.localB - B.localCenter);
    if (joint.kind == JointKind::Mouse) {
        row.indexA = kNullIndex;
        row.invMassA = row.invIA = 0.0;
        row.anchorA = Vec2::Zero();
        row.deltaCenter = B.center - joint.target;
        row.softness = makeSoftness(joint.hertz, joint.dampingRatio, h);
        row.maxImpulse = joint.maxForce * h;
        return;
    }
    const BodyData& A = bodies[joint.a];
    const RowSide sideA = rowSide(A);
    row.indexA = sideA.index;
    row.invMassA = sideA.invMass;
    row.invIA = sideA.invI;
    row.anchorA = A.xf.q.apply(joint.localA - A.localCenter);
    row.deltaCenter = B.center - A.center;
    row.softness = joint.kind == JointKind::Distance && joint.hertz > 0.0
                       ? makeSoftness(joint.hertz, joint.dampingRatio, h)
                       : rodSoftness;
    row.invH = 1.0 / h;
    row.deltaAngle = B.angle - A.angle - joint.referenceAngle;
    const double turning = row.invIA + row.invIB;
    row.axialMass = turning > 0.0 ? 1.0 / turning : 0.0;
    row.maxImpulse = joint.maxMotorTorque * h;
}

void warmStartJoint(const JointConstraint& row, const JointData& joint, SolverBody* states) {
    MotionSide A = loadSide(states, row.indexA), B = loadSide(states, row.indexB);
    if (joint.kind == JointKind::Mouse) {
        applyImpulse(row, A, B, Vec2::Zero(), B.dq.apply(row.anchorB), joint.linearImpulse);
    } else if (joint.kind == JointKind::Revolute || joint.kind == JointKind::Weld) {
        applyImpulse(row, A, B, A.dq.apply(row.anchorA), B.dq.apply(row.anchorB), joint.linearImpulse);
        turn(row, A, B,
             joint.angularImpulse + joint.motorImpulse + joint.lowerImpulse - joint.upperImpulse);
    } else {
        const RodState s = rod(row, A, B);
        applyImpulse(row, A, B, s.rA, s.rB, joint.impulse * s.u);
    }
    storeSide(states, row.indexA, row.invMassA, A);
    storeSide(states, row.indexB, row.invMassB, B);
}

void solveJoint(const JointConstraint& row, JointData& joint, SolverBody* states, bool useBias) {
    MotionSide A = loadSide(states, row.indexA), B = loadSide(states, row.indexB);
    if (joint.kind == JointKind::Mouse) {
        // Always soft: the spring is the point of this joint, in the relax pass too.
        const Vec2 rB = B.dq.apply(row.anchorB);
        const Vec2 C = row.deltaCenter + B.dp + rB;  // anchor minus target, m
        const Vec2 Cdot = B.v + cross(B.w, rB);
        Vec2 solved;
        if (solvePointMass(row, Vec2::Zero(), rB, Cdot + row.softness.biasRate * C, solved)) {
            const Vec2 old = joint.linearImpulse;
            Vec2 total = old - row.softness.massScale * solved - row.softness.impulseScale * old;
            const double magnitude = total.norm();
            if (magnitude > row.maxImpulse) total *= row.maxImpulse / magnitude;
            joint.linearImpulse = total;
            applyImpulse(row, A, B, Vec2::Zero(), rB, total - old);
        }
    } else if (joint.kind == JointKind::Revolute) {
        solveRevolute(row, joint, A, B, useBias);
    } else if (joint.kind == JointKind::Weld) {
        solveWeld(row, joint, A, B, useBias);
    } else {
        const RodState s = rod(row, A, B);
        const double ra = cross(s.rA, s.u), rb = cross(s.rB, s.u);
        const double k = row.invMassA + row.invMassB + row.invIA * ra * ra + row.invIB * rb * rb;
        if (k > 0.0) {
            double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
            if (useBias || joint.hertz > 0.0) {  // a soft link is a spring in the relax pass too
                bias = row.softness.biasRate * (s.length - joint.length);
                massScale = row.softness.massScale;
                impulseScale = row.softness.impulseScale;
            }
            const double Cdot = s.u.dot(relativeVelocity(A, B, s.rA, s.rB));
            const double lambda = -massScale * (Cdot + bias) / k - impulseScale * joint.impulse;
            joint.impulse += lambda;
            applyImpulse(row, A, B, s.rA, s.rB, lambda * s.u);
        }
    }
    storeSide(states, row.indexA, row.invMassA, A);
    storeSide(states, row.indexB, row.invMassB, B);
}

}  // namespace physim
