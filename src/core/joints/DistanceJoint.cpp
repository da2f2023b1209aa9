#include "DistanceJoint.hpp"

#include "../JointData.hpp"

#include "physim/core/Validate.hpp"
#include "physim/core/World.hpp"

#include <stdexcept>
#include <string>

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

JointId World::createDistanceJoint(const DistanceJointDef& def) {
    return createJoint({KindDefinition<DistanceJoint>{&def, "createDistanceJoint"}});
}

DistanceJoint DistanceJoint::make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB) {
    requireWithin("joint anchor A", def.localAnchorA, kMaxCoordinate);
    requireWithin("joint anchor B", def.localAnchorB, kMaxCoordinate);
    requireWithin("joint length", def.length, kMaxCoordinate);
    double length = def.length;
    if (length <= 0.0) length = (B.xf.apply(def.localAnchorB) - A.xf.apply(def.localAnchorA)).norm();
    if (!(length > 1e-9))
        throw std::invalid_argument("physim: distance joint length must be > 0 m, got " + std::to_string(length));
    requireNonNegative("distance joint hertz", def.hertz);
    requireNonNegative("distance joint dampingRatio", def.dampingRatio);
    localA = def.localAnchorA;
    localB = def.localAnchorB;
    DistanceJoint j;
    j.length = length;
    j.hertz = def.hertz;
    j.dampingRatio = def.dampingRatio;
    return j;
}

void DistanceJoint::prepare(JointConstraint& row, const BodyData&, const BodyData&, double h,
                            const Softness& rodSoftness) const {
    row.softness = hertz > 0.0 ? makeSoftness(hertz, dampingRatio, h) : rodSoftness;
}

void DistanceJoint::warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const {
    const RodState s = rod(row, A, B);
    applyImpulse(row, A, B, s.rA, s.rB, impulse * s.u);
}

void DistanceJoint::solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias) {
    const RodState s = rod(row, A, B);
    const double ra = cross(s.rA, s.u), rb = cross(s.rB, s.u);
    const double k = row.invMassA + row.invMassB + row.invIA * ra * ra + row.invIB * rb * rb;
    if (!(k > 0.0)) return;
    double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    if (useBias || hertz > 0.0) {  // a soft link is a spring in the relax pass too
        bias = row.softness.biasRate * (s.length - length);
        massScale = row.softness.massScale;
        impulseScale = row.softness.impulseScale;
    }
    const double Cdot = s.u.dot(relativeVelocity(A, B, s.rA, s.rB));
    const double lambda = -massScale * (Cdot + bias) / k - impulseScale * impulse;
    impulse += lambda;
    applyImpulse(row, A, B, s.rA, s.rB, lambda * s.u);
}

JointReaction DistanceJoint::reaction(const JointEndsNow& now, double invH) const {
    const Vec2 d = now.pointB - now.pointA;
    const double l = d.norm();
    const Vec2 u = l > 1e-12 ? Vec2(d / l) : Vec2(0.0, 1.0);
    return {impulse * invH * u, 0.0};
}

}  // namespace physim
