#include "MouseJoint.hpp"

#include "../WorldImpl.hpp"

#include "physim/core/Validate.hpp"
#include "physim/core/World.hpp"

#include <stdexcept>

namespace physim {

JointId World::createMouseJoint(const MouseJointDef& def) {
    return createJoint({KindDefinition<MouseJoint>{&def, "createMouseJoint"}});
}

void World::setMouseJointTarget(JointId id, const Vec2& target) {
    requireWithin("mouse joint target", target, kMaxCoordinate);
    const JointData& j = joint(id);
    impl_->requireNotStepping("setMouseJointTarget");
    if (j.type() != JointType::Mouse) throw std::invalid_argument("physim: setMouseJointTarget needs a mouse joint");
    impl_->joints[id.index].localA = target;
    impl_->wakeBody(j.b);
}

MouseJoint MouseJoint::make(const Def& def, const BodyData&, const BodyData&, Vec2& localA, Vec2& localB) {
    requireWithin("mouse joint target", def.target, kMaxCoordinate);
    requireWithin("mouse joint anchor", def.localAnchor, kMaxCoordinate);
    requirePositive("mouse joint maxForce", def.maxForce);
    requirePositive("mouse joint hertz", def.hertz);
    requireNonNegative("mouse joint dampingRatio", def.dampingRatio);
    localA = def.target;
    localB = def.localAnchor;
    MouseJoint j;
    j.maxForce = def.maxForce;
    j.hertz = def.hertz;
    j.dampingRatio = def.dampingRatio;
    return j;
}

void MouseJoint::prepare(JointConstraint& row, const BodyData&, const BodyData&, double h, const Softness&) const {
    row.softness = makeSoftness(hertz, dampingRatio, h);
    row.maxImpulse = maxForce * h;
}

void MouseJoint::warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const {
    applyImpulse(row, A, B, Vec2::Zero(), B.dq.apply(row.anchorB), linearImpulse);
}

void MouseJoint::solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool) {
    const Vec2 rB = B.dq.apply(row.anchorB);
    const Vec2 C = row.deltaCenter + B.dp + rB;  // anchor minus target, m
    const Vec2 Cdot = B.v + cross(B.w, rB);
    Vec2 solved;
    if (!solvePointMass(row, Vec2::Zero(), rB, Cdot + row.softness.biasRate * C, solved)) return;
    const Vec2 old = linearImpulse;
    Vec2 total = old - row.softness.massScale * solved - row.softness.impulseScale * old;
    const double magnitude = total.norm();
    if (magnitude > row.maxImpulse) total *= row.maxImpulse / magnitude;
    linearImpulse = total;
    applyImpulse(row, A, B, Vec2::Zero(), rB, total - old);
}

JointReaction MouseJoint::reaction(const JointEndsNow&, double invH) const { return {linearImpulse * invH, 0.0}; }

}  // namespace physim
