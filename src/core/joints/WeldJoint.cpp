#include "WeldJoint.hpp"

#include "../JointData.hpp"

#include "physim/core/Validate.hpp"
#include "physim/core/World.hpp"

namespace physim {

JointId World::createWeldJoint(const WeldJointDef& def) {
    return createJoint({KindDefinition<WeldJoint>{&def, "createWeldJoint"}});
}

WeldJoint WeldJoint::make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB) {
    requireWithin("weld joint anchor", def.anchor, kMaxCoordinate);
    WeldJoint j;
    j.referenceAngle = pinAt(def.anchor, A, B, localA, localB);
    return j;
}

void WeldJoint::prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                        const Softness& rodSoftness) const {
    preparePinned(row, referenceAngle, A, B, h, rodSoftness);
}

void WeldJoint::warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const {
    applyImpulse(row, A, B, A.dq.apply(row.anchorA), B.dq.apply(row.anchorB), linearImpulse);
    turn(row, A, B, angularImpulse);
}

void WeldJoint::solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias) {
    if (row.axialMass > 0.0) {
        double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
        if (useBias) {
            bias = row.softness.biasRate * (row.deltaAngle + B.dAngle - A.dAngle);
            massScale = row.softness.massScale;
            impulseScale = row.softness.impulseScale;
        }
        const double lambda = -row.axialMass * massScale * (B.w - A.w + bias) - impulseScale * angularImpulse;
        angularImpulse += lambda;
        turn(row, A, B, lambda);
    }
    solvePoint(row, linearImpulse, A, B, useBias);
}

JointReaction WeldJoint::reaction(const JointEndsNow&, double invH) const {
    return {linearImpulse * invH, angularImpulse * invH};
}

}  // namespace physim
