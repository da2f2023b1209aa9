#include "WheelJoint.hpp"

#include "../WorldImpl.hpp"

#include "physim/core/Validate.hpp"
#include "physim/core/World.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <variant>

namespace physim {
namespace {

void requireSpring(double hertz, double dampingRatio) {
    requireNonNegative("wheel joint hertz", hertz);
    requireNonNegative("wheel joint dampingRatio", dampingRatio);
}

void requireMotor(double speed, double maxTorque) {
    requireFinite("wheel joint motorSpeed", speed);
    requireNonNegative("wheel joint maxMotorTorque", maxTorque);
}

}  // namespace

JointId World::createWheelJoint(const WheelJointDef& def) {
    return createJoint({KindDefinition<WheelJoint>{&def, "createWheelJoint"}});
}

void World::setWheelSpring(JointId id, bool enable, double hertz, double dampingRatio) {
    requireSpring(hertz, dampingRatio);
    impl_->changeJoint<WheelJoint>(joint(id), id, "setWheelSpring",
                                   [&](WheelJoint& j) { j.setSpring(enable, hertz, dampingRatio); });
}

void World::setWheelLimits(JointId id, bool enable, double lower, double upper) {
    requireTranslationLimits("wheel", lower, upper);
    impl_->changeJoint<WheelJoint>(joint(id), id, "setWheelLimits",
                                   [&](WheelJoint& j) { j.setLimits(enable, lower, upper); });
}

void World::setWheelMotor(JointId id, bool enable, double speed, double maxTorque) {
    requireMotor(speed, maxTorque);
    impl_->changeJoint<WheelJoint>(joint(id), id, "setWheelMotor",
                                   [&](WheelJoint& j) { j.setMotor(enable, speed, maxTorque); });
}

void WheelJoint::setSpring(bool enable, double springHertz, double ratio) {
    enableSpring = enable;
    hertz = springHertz;
    dampingRatio = ratio;
    if (!enable || !(springHertz > 0.0)) springImpulse = 0.0;
}

void WheelJoint::setLimits(bool enable, double lower, double upper) {
    enableLimit = enable;
    lowerTranslation = lower;
    upperTranslation = upper;
    if (!enable) lowerImpulse = upperImpulse = 0.0;
}

void WheelJoint::setMotor(bool enable, double speed, double maxTorque) {
    enableMotor = enable;
    motorSpeed = speed;
    maxMotorTorque = maxTorque;
    if (!enable) motorImpulse = 0.0;
}

WheelJoint WheelJoint::make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB) {
    WheelJoint j;
    j.localAxis = slideAt("wheel", def.anchor, def.axis, A, B, localA, localB);
    requireSpring(def.hertz, def.dampingRatio);
    requireTranslationLimits("wheel", def.lowerTranslation, def.upperTranslation);
    requireMotor(def.motorSpeed, def.maxMotorTorque);
    j.lastAxis = A.xf.q.apply(j.localAxis);
    j.setSpring(def.enableSpring, def.hertz, def.dampingRatio);
    j.setLimits(def.enableLimit, def.lowerTranslation, def.upperTranslation);
    j.setMotor(def.enableMotor, def.motorSpeed, def.maxMotorTorque);
    return j;
}

void WheelJoint::prepare(JointConstraint& row, const BodyData& A, const BodyData&, double h,
                         const Softness& rodSoftness) const {
    row.softness = rodSoftness;
    row.invH = 1.0 / h;
    row.axis = A.xf.q.apply(localAxis);
    const double turning = row.invIA + row.invIB;
    row.axialMass = turning > 0.0 ? 1.0 / turning : 0.0;
    row.maxImpulse = maxMotorTorque * h;
    row.spring = enableSpring && hertz > 0.0 ? makeSoftness(hertz, dampingRatio, 1.0 / row.invH) : Softness{};
}

void WheelJoint::warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const {
    const SliderFrame f = sliderFrame(row, A, B);
    pushAlong(row, A, B, f.axis, f.a1, f.a2, springImpulse + lowerImpulse - upperImpulse);
    pushAlong(row, A, B, f.normal, f.n1, f.n2, normalImpulse);
    // Summed from +0.0, so a motor capped at zero torque (its impulse clamped to -0.0) adds +0.0 to the spins.
    turn(row, A, B, 0.0 + motorImpulse);
}

void WheelJoint::solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias) {
    const SliderFrame f = sliderFrame(row, A, B);
    lastAxis = f.axis;
    if (enableMotor && row.axialMass > 0.0) {
        const double old = motorImpulse;
        motorImpulse = std::clamp(old - row.axialMass * (B.w - A.w - motorSpeed), -row.maxImpulse, row.maxImpulse);
        turn(row, A, B, motorImpulse - old);
    }
    const double kAxial = rowInverseMass(row, f.a1, f.a2);
    // The suspension: soft in both passes (it is the user's spring, not an error to remove). Its rest: 0.
    if (enableSpring && hertz > 0.0 && kAxial > 0.0) {
        const Softness& soft = row.spring;
        // The mass over kAxial first: the division then waits on nothing the rows before changed.
        const double lambda = -(soft.massScale / kAxial) * (axialRate(f, A, B) + soft.biasRate * f.translation) -
                              soft.impulseScale * springImpulse;
        springImpulse += lambda;
        pushAlong(row, A, B, f.axis, f.a1, f.a2, lambda);
    }
    if (enableLimit) {
        solveAxialLimit(row, f, f.translation - lowerTranslation, 1.0, lowerImpulse, A, B, useBias);
        solveAxialLimit(row, f, upperTranslation - f.translation, -1.0, upperImpulse, A, B, useBias);
    }
    // Across the axis: the anchor stays on A's line.
    const double kNormal = rowInverseMass(row, f.n1, f.n2);
    if (!(kNormal > 0.0)) return;
    double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    if (useBias) {
        bias = row.softness.biasRate * f.offset;
        massScale = row.softness.massScale;
        impulseScale = row.softness.impulseScale;
    }
    const double Cdot = f.normal.dot(B.v - A.v) + f.n2 * B.w - f.n1 * A.w;
    const double lambda = -(massScale / kNormal) * (Cdot + bias) - impulseScale * normalImpulse;
    normalImpulse += lambda;
    pushAlong(row, A, B, f.normal, f.n1, f.n2, lambda);
}

JointReaction WheelJoint::reaction(const JointEndsNow&, double invH) const {
    const double axial = springImpulse + lowerImpulse - upperImpulse;
    return {(axial * lastAxis + normalImpulse * perp(lastAxis)) * invH, motorImpulse * invH};
}

}  // namespace physim
