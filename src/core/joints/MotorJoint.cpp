#include "MotorJoint.hpp"

#include "../WorldImpl.hpp"

#include "physim/core/Validate.hpp"
#include "physim/core/World.hpp"

#include <algorithm>
#include <stdexcept>
#include <variant>

namespace physim {

JointId World::createMotorJoint(const MotorJointDef& def) {
    return createJoint({KindDefinition<MotorJoint>{&def, "createMotorJoint"}});
}

void World::setMotorJointOffsets(JointId id, const Vec2& linearOffset, double angularOffset) {
    requireWithin("motor joint linearOffset", linearOffset, kMaxCoordinate);
    requireFinite("motor joint angularOffset", angularOffset);
    const JointData& j = joint(id);
    impl_->requireNotStepping("setMotorJointOffsets");
    if (j.type() != JointType::Motor)
        throw std::invalid_argument("physim: setMotorJointOffsets needs a motor joint");
    JointData& data = impl_->joints[id.index];
    data.localA = linearOffset;
    std::get<MotorJoint>(data.params).angularOffset = angularOffset;
    impl_->wakeBody(j.a);
    impl_->wakeBody(j.b);
}

MotorJoint MotorJoint::make(const Def& def, const BodyData&, const BodyData&, Vec2& localA, Vec2& localB) {
    requireWithin("motor joint linearOffset", def.linearOffset, kMaxCoordinate);
    requireFinite("motor joint angularOffset", def.angularOffset);
    requireNonNegative("motor joint maxForce", def.maxForce);
    requireNonNegative("motor joint maxTorque", def.maxTorque);
    requireInRange("motor joint correctionFactor", def.correctionFactor, 0.0, 1.0);
    localA = def.linearOffset;
    localB = Vec2::Zero();
    MotorJoint j;
    j.angularOffset = def.angularOffset;
    j.maxForce = def.maxForce;
    j.maxTorque = def.maxTorque;
    j.correctionFactor = def.correctionFactor;
    return j;
}

void MotorJoint::prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                         const Softness& rodSoftness) const {
    preparePinned(row, angularOffset, A, B, h, rodSoftness);
    row.maxImpulse = maxForce * h;
}

void MotorJoint::warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const {
    applyImpulse(row, A, B, A.dq.apply(row.anchorA), B.dq.apply(row.anchorB), linearImpulse);
    turn(row, A, B, angularImpulse);
}

void MotorJoint::solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool) {
    const double rate = correctionFactor * row.invH;  // 1/s: the error's share removed per second
    if (row.axialMass > 0.0) {
        const double error = row.deltaAngle + B.dAngle - A.dAngle;
        const double cap = maxTorque / row.invH;
        const double old = angularImpulse;
        angularImpulse = std::clamp(old - row.axialMass * (B.w - A.w + rate * error), -cap, cap);
        turn(row, A, B, angularImpulse - old);
    }
    const Vec2 rA = A.dq.apply(row.anchorA), rB = B.dq.apply(row.anchorB);
    const Vec2 error = row.deltaCenter + (B.dp - A.dp) + rB - rA;
    Vec2 solved;
    if (!solvePointMass(row, rA, rB, relativeVelocity(A, B, rA, rB) + rate * error, solved)) return;
    const Vec2 old = linearImpulse;
    Vec2 total = old - solved;
    const double magnitude = total.norm();
    if (magnitude > row.maxImpulse) total *= row.maxImpulse / magnitude;
    linearImpulse = total;
    applyImpulse(row, A, B, rA, rB, total - old);
}

JointReaction MotorJoint::reaction(const JointEndsNow&, double invH) const {
    return {linearImpulse * invH, angularImpulse * invH};
}

}  // namespace physim
