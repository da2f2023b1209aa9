#include "SpringJoint.hpp"

#include "../JointData.hpp"
#include "../effects/Effects.hpp"

#include "physim/core/Validate.hpp"
#include "physim/core/World.hpp"

namespace physim {

JointId World::createSpringJoint(const SpringJointDef& def) {
    return createJoint({KindDefinition<SpringJoint>{&def, "createSpringJoint"}});
}

void SpringJoint::addTo(Effects& effects, std::uint32_t joint) { effects.springs.add(joint); }
void SpringJoint::removeFrom(Effects& effects, std::uint32_t joint) { effects.springs.remove(joint); }

SpringJoint SpringJoint::make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB) {
    const bool toPoint = def.bodyA.isNull();
    requireWithin(toPoint ? "spring point" : "spring anchor A", def.localAnchorA, kMaxCoordinate);
    requireWithin("spring anchor B", def.localAnchorB, kMaxCoordinate);
    requireWithin("spring restLength", def.restLength, kMaxCoordinate);
    requirePositive("spring stiffness", def.stiffness);
    requireNonNegative("spring damping", def.damping);
    localA = def.localAnchorA;
    localB = def.localAnchorB;
    const Vec2 endA = toPoint ? def.localAnchorA : A.xf.apply(def.localAnchorA);
    SpringJoint j;
    j.restLength = def.restLength >= 0.0 ? def.restLength : (B.xf.apply(def.localAnchorB) - endA).norm();
    j.stiffness = def.stiffness;
    j.damping = def.damping;
    return j;
}

JointReaction SpringJoint::reaction(const JointEndsNow& now, double) const {
    const Vec2 d = now.pointB - now.pointA;
    const double length = d.norm();
    if (!(length > 1e-12)) return {};  // coincident anchors: no direction, no force
    const Vec2 u = d / length;
    const double stretchRate = u.dot(now.velocityB - now.velocityA);
    return {-tension(length, stretchRate) * u, 0.0};
}

}  // namespace physim
