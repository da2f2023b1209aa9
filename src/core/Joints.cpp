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

}  // namespace

void prepareJoint(JointConstraint& row, const JointData& joint, const std::vector<BodyData>& bodies, double h,
                  const Softness& rodSoftness) {
    const BodyData& B = bodies[joint.b];
    const bool movesB = B.awake() && B.type == BodyType::Dynamic;
    row.indexB = B.awakeIndex;
    row.invMassB = movesB ? B.invMass : 0.0;
    row.invIB = movesB ? B.invInertia : 0.0;
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
    const bool movesA = A.awake() && A.type == BodyType::Dynamic;
    row.indexA = A.awakeIndex;
    row.invMassA = movesA ? A.invMass : 0.0;
    row.invIA = movesA ? A.invInertia : 0.0;
    row.anchorA = A.xf.q.apply(joint.localA - A.localCenter);
    row.deltaCenter = B.center - A.center;
    row.softness = rodSoftness;
}

void warmStartJoint(const JointConstraint& row, const JointData& joint, SolverBody* states) {
    MotionSide A = loadSide(states, row.indexA), B = loadSide(states, row.indexB);
    if (joint.kind == JointKind::Mouse) {
        applyImpulse(row, A, B, Vec2::Zero(), B.dq.apply(row.anchorB), joint.linearImpulse);
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
        // K = m^-1 I + I^-1 [rB]x^T [rB]x for a point on B: the 2x2 effective inverse mass.
        const double k11 = row.invMassB + row.invIB * rB.y() * rB.y();
        const double k12 = -row.invIB * rB.x() * rB.y();
        const double k22 = row.invMassB + row.invIB * rB.x() * rB.x();
        const double det = k11 * k22 - k12 * k12;
        if (det > 0.0) {
            const Vec2 b = Cdot + row.softness.biasRate * C;
            const Vec2 solved((k22 * b.x() - k12 * b.y()) / det, (k11 * b.y() - k12 * b.x()) / det);
            const Vec2 old = joint.linearImpulse;
            Vec2 total = old - row.softness.massScale * solved - row.softness.impulseScale * old;
            const double magnitude = total.norm();
            if (magnitude > row.maxImpulse) total *= row.maxImpulse / magnitude;
            joint.linearImpulse = total;
            applyImpulse(row, A, B, Vec2::Zero(), rB, total - old);
        }
    } else {
        const RodState s = rod(row, A, B);
        const double ra = cross(s.rA, s.u), rb = cross(s.rB, s.u);
        const double k = row.invMassA + row.invMassB + row.invIA * ra * ra + row.invIB * rb * rb;
        if (k > 0.0) {
            double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
            if (useBias) {
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
