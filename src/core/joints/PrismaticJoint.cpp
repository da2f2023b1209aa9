#include "PrismaticJoint.hpp"

#include "../WorldImpl.hpp"

#include "physim/core/Validate.hpp"
#include "physim/core/World.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <variant>

namespace physim {
namespace {

void requireMotor(double speed, double maxForce) {
    requireFinite("prismatic joint motorSpeed", speed);
    requireNonNegative("prismatic joint maxMotorForce", maxForce);
}

void requireSpring(double hertz, double dampingRatio, double target) {
    requireNonNegative("prismatic joint hertz", hertz);
    requireNonNegative("prismatic joint dampingRatio", dampingRatio);
    requireFinite("prismatic joint targetTranslation", target);
}

}  // namespace

JointId World::createPrismaticJoint(const PrismaticJointDef& def) {
    return createJoint({KindDefinition<PrismaticJoint>{&def, "createPrismaticJoint"}});
}

void World::setPrismaticLimits(JointId id, bool enable, double lower, double upper) {
    requireTranslationLimits("prismatic", lower, upper);
    impl_->changeJoint<PrismaticJoint>(joint(id), id, "setPrismaticLimits",
                                          [&](PrismaticJoint& j) { j.setLimits(enable, lower, upper); });
}

void World::setPrismaticMotor(JointId id, bool enable, double speed, double maxForce) {
    requireMotor(speed, maxForce);
    impl_->changeJoint<PrismaticJoint>(joint(id), id, "setPrismaticMotor",
                                          [&](PrismaticJoint& j) { j.setMotor(enable, speed, maxForce); });
}

void World::setPrismaticSpring(JointId id, bool enable, double hertz, double dampingRatio, double target) {
    requireSpring(hertz, dampingRatio, target);
    impl_->changeJoint<PrismaticJoint>(joint(id), id, "setPrismaticSpring",
                                          [&](PrismaticJoint& j) { j.setSpring(enable, hertz, dampingRatio, target); });
}

void PrismaticJoint::setLimits(bool enable, double lower, double upper) {
    enableLimit = enable;
    lowerTranslation = lower;
    upperTranslation = upper;
    if (!enable) lowerImpulse = upperImpulse = 0.0;
}

void PrismaticJoint::setMotor(bool enable, double speed, double maxForce) {
    enableMotor = enable;
    motorSpeed = speed;
    maxMotorForce = maxForce;
    if (!enable) motorImpulse = 0.0;
}

void PrismaticJoint::setSpring(bool enable, double springHertz, double ratio, double target) {
    enableSpring = enable;
    hertz = springHertz;
    dampingRatio = ratio;
    targetTranslation = target;
    if (!enable || !(springHertz > 0.0)) springImpulse = 0.0;
}

PrismaticJoint PrismaticJoint::make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA,
                                    Vec2& localB) {
    PrismaticJoint j;
    j.localAxis = slideAt("prismatic", def.anchor, def.axis, A, B, localA, localB);
    requireTranslationLimits("prismatic", def.lowerTranslation, def.upperTranslation);
    requireMotor(def.motorSpeed, def.maxMotorForce);
    requireSpring(def.hertz, def.dampingRatio, def.targetTranslation);
    j.referenceAngle = B.angle - A.angle;
    j.lastAxis = A.xf.q.apply(j.localAxis);
    j.setLimits(def.enableLimit, def.lowerTranslation, def.upperTranslation);
    j.setMotor(def.enableMotor, def.motorSpeed, def.maxMotorForce);
    j.setSpring(def.enableSpring, def.hertz, def.dampingRatio, def.targetTranslation);
    return j;
}

void PrismaticJoint::prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                             const Softness& rodSoftness) const {
    row.softness = rodSoftness;
    row.invH = 1.0 / h;
    row.axis = A.xf.q.apply(localAxis);
    row.deltaAngle = B.angle - A.angle - referenceAngle;
    row.maxImpulse = maxMotorForce * h;
    row.spring = enableSpring && hertz > 0.0 ? makeSoftness(hertz, dampingRatio, 1.0 / row.invH) : Softness{};
}

void PrismaticJoint::warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const {
    const SliderFrame f = sliderFrame(row, A, B);
    // Summed from +0.0, so a motor capped at zero force (its impulse clamped to -0.0) adds +0.0.
    const double axial = 0.0 + springImpulse + motorImpulse + lowerImpulse - upperImpulse;
    pushAlong(row, A, B, f.axis, f.a1, f.a2, axial);
    pushAlong(row, A, B, f.normal, f.n1, f.n2, blockImpulse.x());
    turn(row, A, B, blockImpulse.y());
}

void PrismaticJoint::solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias) {
    SliderFrame f = sliderFrame(row, A, B);
    lastAxis = f.axis;
    const double kAxial = rowInverseMass(row, f.a1, f.a2);
    // The spring: soft in both passes (it is the user's spring, not an error to remove).
    if (enableSpring && hertz > 0.0 && kAxial > 0.0) {
        const Softness& soft = row.spring;
        const double C = f.translation - targetTranslation;
        const double lambda =
            -soft.massScale * (axialRate(f, A, B) + soft.biasRate * C) / kAxial - soft.impulseScale * springImpulse;
        springImpulse += lambda;
        pushAlong(row, A, B, f.axis, f.a1, f.a2, lambda);
    }
    if (enableMotor && kAxial > 0.0) {
        const double old = motorImpulse;
        motorImpulse = std::clamp(old - (axialRate(f, A, B) - motorSpeed) / kAxial, -row.maxImpulse, row.maxImpulse);
        pushAlong(row, A, B, f.axis, f.a1, f.a2, motorImpulse - old);
    }
    if (enableLimit) {
        solveAxialLimit(row, f, f.translation - lowerTranslation, 1.0, lowerImpulse, A, B, useBias);
        solveAxialLimit(row, f, upperTranslation - f.translation, -1.0, upperImpulse, A, B, useBias);
    }
    // Across the axis and the angle together: K = J M^-1 J^T for the rows [normal; angle].
    const double k11 = rowInverseMass(row, f.n1, f.n2);
    const double k12 = row.invIA * f.n1 + row.invIB * f.n2;
    double k22 = row.invIA + row.invIB;
    if (k22 == 0.0) k22 = 1.0;  // neither body turns: the angle row does nothing, keep K invertible
    const double det = k11 * k22 - k12 * k12;
    if (!(det > 0.0)) return;
    Vec2 bias = Vec2::Zero();
    double massScale = 1.0, impulseScale = 0.0;
    if (useBias) {
        bias = row.softness.biasRate * Vec2(f.offset, row.deltaAngle + B.dAngle - A.dAngle);
        massScale = row.softness.massScale;
        impulseScale = row.softness.impulseScale;
    }
    const Vec2 Cdot(f.normal.dot(B.v - A.v) + f.n2 * B.w - f.n1 * A.w, B.w - A.w);
    const Vec2 rhs = Cdot + bias;
    const Vec2 solved((k22 * rhs.x() - k12 * rhs.y()) / det, (k11 * rhs.y() - k12 * rhs.x()) / det);
    const Vec2 impulse = -massScale * solved - impulseScale * blockImpulse;
    blockImpulse += impulse;
    pushAlong(row, A, B, f.normal, f.n1, f.n2, impulse.x());
    turn(row, A, B, impulse.y());
}

JointReaction PrismaticJoint::reaction(const JointEndsNow&, double invH) const {
    const double axial = springImpulse + motorImpulse + lowerImpulse - upperImpulse;
    return {(axial * lastAxis + blockImpulse.x() * perp(lastAxis)) * invH, blockImpulse.y() * invH};
}

double PrismaticJoint::jointTranslation(const BodyData& A, const BodyData& B, const Vec2& localA,
                                        const Vec2& localB) const {
    return sliderTranslation(localAxis, A, B, localA, localB);
}

double PrismaticJoint::jointSpeed(const BodyData& A, const BodyData& B, const Vec2& localA,
                                  const Vec2& localB) const {
    return sliderSpeed(localAxis, A, B, localA, localB);
}

}  // namespace physim
