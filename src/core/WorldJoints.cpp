// The World's API for joints that every kind shares: the one creation path, destruction and the queries. Each kind's
// createXJoint and setters live in its own file (joints/); the rows' dispatch in Joints.hpp.

#include "physim/core/World.hpp"

#include "Joints.hpp"
#include "Slots.hpp"
#include "WorldImpl.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>

namespace physim {
namespace {

// 1 / the last step's substep, 1/s: turns a joint's impulses per substep into forces (0 before the first step).
double substepRate(const WorldImpl& w) { return w.dt > 0.0 ? 1.0 / (w.dt / w.settings.substeps) : 0.0; }

bool breakable(const JointData& j) {
    return j.breakForce < std::numeric_limits<double>::infinity() ||
           j.breakTorque < std::numeric_limits<double>::infinity();
}

void linkJoint(WorldImpl& w, std::uint32_t index) {
    JointData& j = w.joints[index];
    const std::uint32_t ends[2] = {j.a, j.b};
    for (int side = j.twoBodies() ? 0 : 1; side < 2; ++side) {
        BodyData& body = w.bodies[ends[side]];
        const std::int32_t key = static_cast<std::int32_t>(index) * 2 + side;
        j.prev[side] = kNullIndex;
        j.next[side] = body.jointHead;
        if (body.jointHead != kNullIndex)
            w.joints[static_cast<std::size_t>(body.jointHead >> 1)].prev[body.jointHead & 1] = key;
        body.jointHead = key;
    }
}

void unlinkJoint(WorldImpl& w, std::uint32_t index) {
    JointData& j = w.joints[index];
    const std::uint32_t ends[2] = {j.a, j.b};
    for (int side = j.twoBodies() ? 0 : 1; side < 2; ++side) {
        BodyData& body = w.bodies[ends[side]];
        if (j.prev[side] != kNullIndex)
            w.joints[static_cast<std::size_t>(j.prev[side] >> 1)].next[j.prev[side] & 1] = j.next[side];
        else
            body.jointHead = j.next[side];
        if (j.next[side] != kNullIndex)
            w.joints[static_cast<std::size_t>(j.next[side] >> 1)].prev[j.next[side] & 1] = j.prev[side];
    }
}

}  // namespace

std::uint32_t WorldImpl::addJoint(const JointData& data) {
    const std::uint32_t index = takeSlot(joints, freeJoints);
    JointData& j = joints[index];
    const std::uint32_t generation = j.generation;
    j = data;
    j.generation = generation;
    j.alive = true;
    linkJoint(*this, index);
    ++jointCount;
    if (j.isRow()) ++rowJointCount;
    else addForceJoint(j, index, effects);
    if (breakable(j)) ++breakableJoints;
    // The bodies now meet only through the joint: their contacts go (the broad phase offers the pair no more).
    if (j.twoBodies() && !j.collideConnected)
        for (std::int32_t key = bodies[j.a].contactHead; key != kNullIndex;) {
            const std::uint32_t c = static_cast<std::uint32_t>(key >> 1);
            key = contacts[c].next[key & 1];
            if (contacts[c].a() == j.b || contacts[c].b() == j.b) destroyContact(c, false);
        }
    solver.layoutChanged();
    wakeBody(j.b);
    if (j.twoBodies()) {
        wakeBody(j.a);
        if (bodies[j.a].type == BodyType::Dynamic && bodies[j.b].type == BodyType::Dynamic) linkBodies(j.a, j.b);
    }
    return index;
}

JointId World::createJoint(const JointDefinition& definition) {
    WorldImpl& w = *impl_;
    return std::visit(
        [&](const auto& d) {
            using Kind = typename std::decay_t<decltype(d)>::Type;
            const JointEnds ends = Kind::ends(*d.def);
            const BodyData* A = ends.toWorld ? nullptr : &at(ends.a);
            const BodyData& B = at(ends.b);
            w.requireNotStepping(d.call);
            const std::string name = std::string("physim: a ") + Kind::kName + " joint needs ";
            if (ends.toWorld) {
                if (B.type != BodyType::Dynamic) throw std::invalid_argument(name + "a dynamic body");
                A = &B;
            } else {
                if (ends.a == ends.b) throw std::invalid_argument(name + "two different bodies");
                if (A->type != BodyType::Dynamic && B.type != BodyType::Dynamic)
                    throw std::invalid_argument(name + "at least one dynamic body");
            }
            const JointDefBase& base = *d.def;
            if (!(base.breakForce > 0.0))
                throw std::invalid_argument(name + "breakForce > 0 (infinity: never breaks), got " +
                                            std::to_string(base.breakForce));
            if (!(base.breakTorque > 0.0))
                throw std::invalid_argument(name + "breakTorque > 0 (infinity: never breaks), got " +
                                            std::to_string(base.breakTorque));
            JointData joint;
            joint.collideConnected = base.collideConnected;
            joint.breakForce = base.breakForce;
            joint.breakTorque = base.breakTorque;
            joint.a = ends.toWorld ? ends.b.index : ends.a.index;
            joint.b = ends.b.index;
            joint.toWorld = ends.toWorld;
            joint.params = Kind::make(*d.def, *A, B, joint.localA, joint.localB);
            const std::uint32_t index = w.addJoint(joint);
            return JointId{index, w.joints[index].generation};
        },
        definition.kind);
}

bool World::contains(JointId id) const {
    const auto& joints = impl_->joints;
    return !id.isNull() && id.index < joints.size() && joints[id.index].alive &&
           joints[id.index].generation == id.generation;
}

const JointData& World::joint(JointId id) const {
    if (!contains(id))
        throw std::invalid_argument("physim: joint id (index " + std::to_string(id.index) +
                                    ") is not a live joint of this world");
    return impl_->joints[id.index];
}

void World::destroyJoint(JointId id) {
    joint(id);
    impl_->requireNotStepping("destroyJoint");
    impl_->removeJoint(id.index);
}

void WorldImpl::removeJoint(std::uint32_t index) {
    // A gear on this joint reads a coordinate that is going: it goes first (GearJointDef).
    if (joints[index].type() == JointType::Revolute || joints[index].type() == JointType::Prismatic)
        for (const JointId gear : gearsOn(*this, index)) removeJoint(gear.index);
    const JointData& j = joints[index];
    wakeBody(j.b);
    if (j.twoBodies()) {
        wakeBody(j.a);
        if (bodies[j.a].type == BodyType::Dynamic && bodies[j.b].type == BodyType::Dynamic) unlinkBodies(j.a, j.b);
    }
    unlinkJoint(*this, index);
    if (j.isRow()) --rowJointCount;
    else removeForceJoint(j, index, effects);
    if (breakable(j)) --breakableJoints;
    solver.layoutChanged();
    joints[index].alive = false;
    freeJoints.push_back(index);
    --jointCount;
    // Shapes the joint kept apart may pair again: the broad phase asks about their proxies at the next step.
    if (j.twoBodies() && !j.collideConnected && !jointKeepsApart(j.a, j.b))
        for (const std::uint32_t end : {j.a, j.b})
            forEachShape(bodies[end], [&](std::uint32_t, const ShapeData& shape) {
                if (shape.proxy != kNullIndex) broadPhase.requery(shape.proxy);
            });
}

bool WorldImpl::jointKeepsApart(std::uint32_t a, std::uint32_t b) const {
    for (std::int32_t key = bodies[a].jointHead; key != kNullIndex;) {
        const JointData& j = joints[static_cast<std::size_t>(key >> 1)];
        const std::uint32_t other = (key & 1) == 0 ? j.b : j.a;
        if (j.twoBodies() && other == b && !j.collideConnected) return true;
        key = j.next[key & 1];
    }
    return false;
}

void WorldImpl::breakJoints() {
    const double invH = substepRate(*this);
    for (std::uint32_t i = 0; i < joints.size(); ++i) {
        const JointData& j = joints[i];
        if (!j.alive || !breakable(j) || !j.isRow()) continue;
        if (!bodies[j.b].awake() && !(j.twoBodies() && bodies[j.a].awake())) continue;  // asleep: nothing new
        const JointReaction r = jointReaction(j, bodies, invH);
        if (!(r.force.norm() > j.breakForce) && !(std::abs(r.torque) > j.breakTorque)) continue;
        JointBreakEvent event;
        event.joint = JointId{i, j.generation};
        event.bodyA = BodyId{j.a, bodies[j.a].generation};
        event.bodyB = BodyId{j.b, bodies[j.b].generation};
        event.force = r.force;
        event.torque = r.torque;
        jointEvents.broken.push_back(event);
        removeJoint(i);
    }
}

const JointEvents& World::jointEvents() const { return impl_->jointEvents; }

std::size_t World::jointCount() const { return impl_->jointCount; }
JointType World::jointType(JointId id) const { return joint(id).type(); }

double World::jointLength(JointId id) const { return physim::jointLength(joint(id)); }
double World::jointAngle(JointId id) const { return physim::jointAngle(joint(id), impl_->bodies); }
double World::jointTranslation(JointId id) const {
    return physim::jointTranslation(joint(id), impl_->bodies, false);
}
double World::jointSpeed(JointId id) const { return physim::jointTranslation(joint(id), impl_->bodies, true); }

std::pair<Vec2, Vec2> World::jointAnchors(JointId id) const {
    const JointData& j = joint(id);
    const Vec2 onB = impl_->bodies[j.b].xf.apply(j.localB);
    if (!j.twoBodies()) return {j.localA, onB};
    return {impl_->bodies[j.a].xf.apply(j.localA), onB};
}

std::vector<JointId> World::joints() const {
    std::vector<JointId> ids;
    for (std::uint32_t i = 0; i < impl_->joints.size(); ++i)
        if (impl_->joints[i].alive) ids.push_back(JointId{i, impl_->joints[i].generation});
    return ids;
}

namespace {

// The last step's joint reaction: impulses accumulated per substep become a force and a torque over it.
JointReaction reactionOf(const WorldImpl& w, const JointData& j) {
    return jointReaction(j, w.bodies, substepRate(w));
}

}  // namespace

Vec2 World::jointReactionForce(JointId id) const { return reactionOf(*impl_, joint(id)).force; }
double World::jointReactionTorque(JointId id) const { return reactionOf(*impl_, joint(id)).torque; }

double World::jointMotorTorque(JointId id) const {
    return physim::jointMotorTorque(joint(id), substepRate(*impl_));
}
double World::jointMotorForce(JointId id) const { return physim::jointMotorForce(joint(id), substepRate(*impl_)); }

}  // namespace physim
