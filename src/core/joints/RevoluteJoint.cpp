#include "RevoluteJoint.hpp"

#include "../WorldImpl.hpp"

#include "physim/core/Validate.hpp"
#include "physim/core/World.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <variant>

namespace physim {
namespace {

void requireLimits(double lower, double upper) {
    requireFinite("revolute joint lowerAngle", lower);
    requireFinite("revolute joint upperAngle", upper);
    if (lower > upper)
        throw std::invalid_argument("physim: revolute joint lowerAngle must be <= upperAngle, got " +
                                    std::to_string(lower) + " > " + std::to_string(upper));
}

void requireSpring(double hertz, double dampingRatio) {
    requireNonNegative("revolute joint springHertz", hertz);
    requireNonNegative("revolute joint springDampingRatio", dampingRatio);
}

void requireMotor(double speed, double maxTorque) {
    requireFinite("revolute joint motorSpeed", speed);
    requireNonNegative("revolute joint maxMotorTorque", maxTorque);
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

}  // namespace

JointId World::createRevoluteJoint(const RevoluteJointDef& def) {
    return createJoint({KindDefinition<RevoluteJoint>{&def, "createRevoluteJoint"}});
}

void World::setJointMotor(JointId id, bool enable, double speed, double maxTorque) {
    requireMotor(speed, maxTorque);
    impl_->changeJoint<RevoluteJoint>(joint(id), id, "setJointMotor",
                                      [&](RevoluteJoint& j) { j.setMotor(enable, speed, maxTorque); });
}

void World::setJointLimits(JointId id, bool enable, double lower, double upper) {
    requireLimits(lower, upper);
    impl_->changeJoint<RevoluteJoint>(joint(id), id, "setJointLimits",
                                      [&](RevoluteJoint& j) { j.setLimits(enable, lower, upper); });
}

void World::setJointSpring(JointId id, bool enable, double hertz, double dampingRatio) {
    requireSpring(hertz, dampingRatio);
    impl_->changeJoint<RevoluteJoint>(joint(id), id, "setJointSpring",
                                      [&](RevoluteJoint& j) { j.setSpring(enable, hertz, dampingRatio); });
}

void RevoluteJoint::setSpring(bool enable, double hertz, double dampingRatio) {
    enableSpring = enable;
    springHertz = hertz;
    springDampingRatio = dampingRatio;
    if (!enable) springImpulse = 0.0;
}

void RevoluteJoint::setMotor(bool enable, double speed, double maxTorque) {
    enableMotor = enable;
    motorSpeed = speed;
    maxMotorTorque = maxTorque;
    if (!enable) motorImpulse = 0.0;
}

void RevoluteJoint::setLimits(bool enable, double lower, double upper) {
    enableLimit = enable;
    lowerAngle = lower;
    upperAngle = upper;
    if (!enable) lowerImpulse = upperImpulse = 0.0;
}

RevoluteJoint RevoluteJoint::make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA,
                                  Vec2& localB) {
    requireWithin("revolute joint anchor", def.anchor, kMaxCoordinate);
    requireLimits(def.lowerAngle, def.upperAngle);
    requireMotor(def.motorSpeed, def.maxMotorTorque);
    requireSpring(def.springHertz, def.springDampingRatio);
    requireFinite("revolute joint springTargetAngle", def.springTargetAngle);
    RevoluteJoint j;
    j.referenceAngle = pinAt(def.anchor, A, B, localA, localB);
    j.setLimits(def.enableLimit, def.lowerAngle, def.upperAngle);
    j.setMotor(def.enableMotor, def.motorSpeed, def.maxMotorTorque);
    j.setSpring(def.enableSpring, def.springHertz, def.springDampingRatio);
    j.springTargetAngle = def.springTargetAngle;
    return j;
}

void RevoluteJoint::prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                            const Softness& rodSoftness) const {
    preparePinned(row, referenceAngle, A, B, h, rodSoftness);
    row.maxImpulse = maxMotorTorque * h;
    row.spring = enableSpring && springHertz > 0.0 ? makeSoftness(springHertz, springDampingRatio, 1.0 / row.invH)
                                                   : Softness{};
}

void RevoluteJoint::warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const {
    applyImpulse(row, A, B, A.dq.apply(row.anchorA), B.dq.apply(row.anchorB), linearImpulse);
    // Summed from +0.0, so a motor capped at zero torque (its impulse clamped to -0.0) adds +0.0 to the spins.
    turn(row, A, B, 0.0 + springImpulse + motorImpulse + lowerImpulse - upperImpulse);
}

void RevoluteJoint::solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias) {
    if (enableSpring && springHertz > 0.0 && row.axialMass > 0.0) {
        // Its own spring in both passes (as a soft distance joint): the relax pass must not take its pull back.
        const Softness& spring = row.spring;
        const double C = row.deltaAngle + B.dAngle - A.dAngle - springTargetAngle;
        const double lambda = -row.axialMass * spring.massScale * (B.w - A.w + spring.biasRate * C) -
                              spring.impulseScale * springImpulse;
        springImpulse += lambda;
        turn(row, A, B, lambda);
    }
    if (enableMotor && row.axialMass > 0.0) {
        const double Cdot = B.w - A.w - motorSpeed;
        const double old = motorImpulse;
        motorImpulse = std::clamp(old - row.axialMass * Cdot, -row.maxImpulse, row.maxImpulse);
        turn(row, A, B, motorImpulse - old);
    }
    if (enableLimit && row.axialMass > 0.0) {
        const double angle = row.deltaAngle + B.dAngle - A.dAngle;
        solveLimit(row, angle - lowerAngle, 1.0, lowerImpulse, A, B, useBias);
        solveLimit(row, upperAngle - angle, -1.0, upperImpulse, A, B, useBias);
    }
    solvePoint(row, linearImpulse, A, B, useBias);
}

JointReaction RevoluteJoint::reaction(const JointEndsNow&, double invH) const {
    return {linearImpulse * invH, (motorImpulse + lowerImpulse - upperImpulse + springImpulse) * invH};
}

}  // namespace physim
