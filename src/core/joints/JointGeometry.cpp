// World's getters of a joint's geometry for drawing and inspection: its bodies, a slider's axis, the limits, a
// pulley's ground anchors. Each reads the kind's own data; kinds without the item are refused.

#include "PrismaticJoint.hpp"
#include "PulleyJoint.hpp"
#include "RevoluteJoint.hpp"
#include "WheelJoint.hpp"

#include "../WorldImpl.hpp"

#include "physim/core/World.hpp"

#include <stdexcept>
#include <string>
#include <variant>

namespace physim {

std::pair<BodyId, BodyId> World::jointBodies(JointId id) const {
    const JointData& j = joint(id);
    const BodyId b{j.b, impl_->bodies[j.b].generation};
    return {j.twoBodies() ? BodyId{j.a, impl_->bodies[j.a].generation} : b, b};
}

Vec2 World::jointAxis(JointId id) const {
    const JointData& j = joint(id);
    const Rotation& q = impl_->bodies[j.a].xf.q;
    if (const auto* p = std::get_if<PrismaticJoint>(&j.params)) return q.apply(p->localAxis);
    if (const auto* w = std::get_if<WheelJoint>(&j.params)) return q.apply(w->localAxis);
    throw std::invalid_argument("physim: jointAxis needs a prismatic or wheel joint");
}

JointLimits World::jointLimits(JointId id) const {
    const JointData& j = joint(id);
    if (const auto* r = std::get_if<RevoluteJoint>(&j.params)) return {r->enableLimit, r->lowerAngle, r->upperAngle};
    if (const auto* p = std::get_if<PrismaticJoint>(&j.params))
        return {p->enableLimit, p->lowerTranslation, p->upperTranslation};
    if (const auto* w = std::get_if<WheelJoint>(&j.params))
        return {w->enableLimit, w->lowerTranslation, w->upperTranslation};
    throw std::invalid_argument("physim: jointLimits needs a revolute, prismatic or wheel joint");
}

std::pair<Vec2, Vec2> World::jointPulleyGroundAnchors(JointId id) const {
    const JointData& j = joint(id);
    if (j.type() != JointType::Pulley)
        throw std::invalid_argument("physim: jointPulleyGroundAnchors needs a pulley joint");
    const PulleyJoint& p = std::get<PulleyJoint>(j.params);
    return {p.groundA, p.groundB};
}

}  // namespace physim
