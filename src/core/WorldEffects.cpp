// The World's API for the force effects (docs/effects.md) and the revolute, weld and spring joints, checked at
// the boundary. The effects themselves live in effects/, the joint rows in Joints.cpp.

#include "physim/core/World.hpp"

#include "WorldImpl.hpp"

#include "physim/core/Validate.hpp"

#include <stdexcept>
#include <string>

namespace physim {
namespace {

// Two different live bodies, at least one of which can move: a joint between them can do something.
void requireJoinable(const char* joint, BodyId a, const BodyData& A, BodyId b, const BodyData& B) {
    if (a == b) throw std::invalid_argument(std::string("physim: a ") + joint + " joint needs two different bodies");
    if (A.type != BodyType::Dynamic && B.type != BodyType::Dynamic)
        throw std::invalid_argument(std::string("physim: a ") + joint + " joint needs at least one dynamic body");
}

void requireLimits(double lower, double upper) {
    requireFinite("revolute joint lowerAngle", lower);
    requireFinite("revolute joint upperAngle", upper);
    if (lower > upper)
        throw std::invalid_argument("physim: revolute joint lowerAngle must be <= upperAngle, got " +
                                    std::to_string(lower) + " > " + std::to_string(upper));
}

void requireMotor(double speed, double maxTorque) {
    requireFinite("revolute joint motorSpeed", speed);
    requireNonNegative("revolute joint maxMotorTorque", maxTorque);
}

}  // namespace

// --- bodies ------------------------------------------------------------------------------------------

void World::setGravityScale(BodyId id, double scale) {
    requireFinite("body gravity scale", scale);
    wake(id, "setGravityScale").gravityScale = scale;
}

double World::gravityScale(BodyId id) const { return at(id).gravityScale; }

void World::setDrag(BodyId id, const DragDef& drag) {
    physim::validate(drag);
    const BodyData& b = wake(id, "setDrag");
    impl_->effects.drag.set(id.index, drag, b.shape);
}

DragDef World::drag(BodyId id) const {
    at(id);
    return impl_->effects.drag.get(id.index);
}

void World::setCollides(BodyId id, bool collides) {
    BodyData& b = mutableBody(id, "setCollides");
    WorldImpl& w = *impl_;
    if (collides == (b.proxy != kNullIndex)) return;
    const std::uint32_t index = id.index;
    if (!collides) {
        // Its contacts go; whatever they held wakes.
        while (w.bodies[index].contactHead != kNullIndex)
            w.destroyContact(static_cast<std::uint32_t>(w.bodies[index].contactHead >> 1), true);
        w.broadPhase.destroyProxy(w.bodies[index].proxy);
        w.bodies[index].proxy = kNullIndex;
        w.wakeBody(index);
        return;
    }
    b.proxy = w.broadPhase.createProxy(w.proxyBox(b, kAabbMargin), index, b.type == BodyType::Static);
    w.wakeBody(index);
    if (b.type == BodyType::Static) w.wakeOverlapping(w.broadPhase.fatBox(b.proxy));
}

bool World::collides(BodyId id) const { return at(id).proxy != kNullIndex; }

void World::setAttracting(BodyId id, bool attracting) {
    BodyData& b = wake(id, "setAttracting");
    b.attracting = attracting;
    if (attracting) impl_->effects.gravitation.add(id.index);
    else impl_->effects.gravitation.remove(id.index);
}

bool World::attracting(BodyId id) const { return at(id).attracting; }
std::size_t World::attractingCount() const { return impl_->effects.gravitation.count(); }

void World::setGravitation(const GravitationSettings& settings) {
    physim::validate(settings);
    impl_->requireNotStepping("setGravitation");
    impl_->effects.gravitation.setSettings(settings);
}

const GravitationSettings& World::gravitation() const { return impl_->effects.gravitation.settings(); }

ForceCallbackId World::addForceCallback(ForceCallback callback) {
    impl_->requireNotStepping("addForceCallback");
    return impl_->effects.callbacks.add(std::move(callback));
}

void World::removeForceCallback(ForceCallbackId id) {
    impl_->requireNotStepping("removeForceCallback");
    impl_->effects.callbacks.remove(id);
}

std::size_t World::forceCallbackCount() const { return impl_->effects.callbacks.count(); }

// --- joints ------------------------------------------------------------------------------------------

JointId World::createSpringJoint(const SpringJointDef& def) {
    const BodyData& B = at(def.bodyB);
    const bool toPoint = def.bodyA.isNull();
    impl_->requireNotStepping("createSpringJoint");
    if (toPoint) {
        if (B.type != BodyType::Dynamic)
            throw std::invalid_argument("physim: a spring to a point needs a dynamic body");
    } else {
        requireJoinable("spring", def.bodyA, at(def.bodyA), def.bodyB, B);
    }
    requireFinite(toPoint ? "spring point" : "spring anchor A", def.localAnchorA);
    requireFinite("spring anchor B", def.localAnchorB);
    requireFinite("spring restLength", def.restLength);
    requirePositive("spring stiffness", def.stiffness);
    requireNonNegative("spring damping", def.damping);
    JointData j;
    j.kind = JointKind::Spring;
    j.toPoint = toPoint;
    j.a = toPoint ? def.bodyB.index : def.bodyA.index;
    j.b = def.bodyB.index;
    j.target = toPoint ? def.localAnchorA : Vec2::Zero();
    j.localA = toPoint ? Vec2::Zero() : def.localAnchorA;
    j.localB = def.localAnchorB;
    const Vec2 endA = toPoint ? def.localAnchorA : impl_->bodies[j.a].xf.apply(def.localAnchorA);
    j.length = def.restLength >= 0.0 ? def.restLength : (B.xf.apply(def.localAnchorB) - endA).norm();
    j.stiffness = def.stiffness;
    j.damping = def.damping;
    const std::uint32_t index = impl_->addJoint(j);
    impl_->effects.springs.add(index);
    return JointId{index, impl_->joints[index].generation};
}

namespace {

// The pin or weld's common part: both bodies keep the world anchor where it is now.
JointData pinnedAt(JointKind kind, const std::vector<BodyData>& bodies, BodyId a, BodyId b, const Vec2& anchor) {
    JointData j;
    j.kind = kind;
    j.a = a.index;
    j.b = b.index;
    j.localA = bodies[a.index].xf.applyInverse(anchor);
    j.localB = bodies[b.index].xf.applyInverse(anchor);
    j.referenceAngle = bodies[b.index].angle - bodies[a.index].angle;
    return j;
}

}  // namespace

JointId World::createRevoluteJoint(const RevoluteJointDef& def) {
    requireJoinable("revolute", def.bodyA, at(def.bodyA), def.bodyB, at(def.bodyB));
    impl_->requireNotStepping("createRevoluteJoint");
    requireFinite("revolute joint anchor", def.anchor);
    requireLimits(def.lowerAngle, def.upperAngle);
    requireMotor(def.motorSpeed, def.maxMotorTorque);
    JointData j = pinnedAt(JointKind::Revolute, impl_->bodies, def.bodyA, def.bodyB, def.anchor);
    j.enableLimit = def.enableLimit;
    j.lowerAngle = def.lowerAngle;
    j.upperAngle = def.upperAngle;
    j.enableMotor = def.enableMotor;
    j.motorSpeed = def.motorSpeed;
    j.maxMotorTorque = def.maxMotorTorque;
    const std::uint32_t index = impl_->addJoint(j);
    return JointId{index, impl_->joints[index].generation};
}

JointId World::createWeldJoint(const WeldJointDef& def) {
    requireJoinable("weld", def.bodyA, at(def.bodyA), def.bodyB, at(def.bodyB));
    impl_->requireNotStepping("createWeldJoint");
    requireFinite("weld joint anchor", def.anchor);
    const std::uint32_t index = impl_->addJoint(pinnedAt(JointKind::Weld, impl_->bodies, def.bodyA, def.bodyB,
                                                         def.anchor));
    return JointId{index, impl_->joints[index].generation};
}

double World::jointAngle(JointId id) const {
    const JointData& j = joint(id);
    if (j.kind != JointKind::Revolute && j.kind != JointKind::Weld)
        throw std::invalid_argument("physim: jointAngle needs a revolute or weld joint");
    return impl_->bodies[j.b].angle - impl_->bodies[j.a].angle - j.referenceAngle;
}

namespace {

// The revolute joint a setter changes (std::invalid_argument for another kind), its bodies woken.
JointData& revoluteToChange(WorldImpl& w, const JointData& j, JointId id, const char* call) {
    w.requireNotStepping(call);
    if (j.kind != JointKind::Revolute)
        throw std::invalid_argument(std::string("physim: ") + call + " needs a revolute joint");
    w.wakeBody(j.a);
    w.wakeBody(j.b);
    return w.joints[id.index];
}

}  // namespace

void World::setJointMotor(JointId id, bool enable, double speed, double maxTorque) {
    requireMotor(speed, maxTorque);
    JointData& m = revoluteToChange(*impl_, joint(id), id, "setJointMotor");
    m.enableMotor = enable;
    m.motorSpeed = speed;
    m.maxMotorTorque = maxTorque;
    if (!enable) m.motorImpulse = 0.0;
}

void World::setJointLimits(JointId id, bool enable, double lower, double upper) {
    requireLimits(lower, upper);
    JointData& m = revoluteToChange(*impl_, joint(id), id, "setJointLimits");
    m.enableLimit = enable;
    m.lowerAngle = lower;
    m.upperAngle = upper;
    if (!enable) m.lowerImpulse = m.upperImpulse = 0.0;
}

}  // namespace physim
