#include "GearJoint.hpp"

#include "../WorldImpl.hpp"

#include "physim/core/World.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <variant>

namespace physim {
namespace {

// A geared joint as the gear sees it: its two bodies, and for each the coordinate's dependence on its pose.
struct GearedEnd {
    std::uint32_t body = 0;
    bool moves = false;  // not static: one of the gear's two bodies
    double angular = 0.0;
    Vec2 linear = Vec2::Zero();
    Vec2 anchor = Vec2::Zero();  // in the body's frame, m (a prismatic joint's moving anchor)
};

// The two ends of geared joint `which` (1 or 2), weighted by `weight` (1 or the ratio). Throws for a joint that is
// not live, or not revolute or prismatic, or a prismatic joint whose axis body moves.
void gearedEnds(const WorldImpl& w, JointId id, int which, double weight, GearedEnd ends[2]) {
    const std::string name = "physim: createGearJoint joint" + std::to_string(which);
    if (id.isNull() || id.index >= w.joints.size() || !w.joints[id.index].alive ||
        w.joints[id.index].generation != id.generation)
        throw std::invalid_argument(name + " (index " + std::to_string(id.index) +
                                    ") is not a live joint of this world");
    const JointData& j = w.joints[id.index];
    const BodyData& A = w.bodies[j.a];
    const BodyData& B = w.bodies[j.b];
    ends[0] = {j.a, A.type != BodyType::Static, 0.0, Vec2::Zero(), Vec2::Zero()};
    ends[1] = {j.b, B.type != BodyType::Static, 0.0, Vec2::Zero(), Vec2::Zero()};
    if (j.type() == JointType::Revolute) {
        ends[0].angular = -weight;  // angle(B) - angle(A)
        ends[1].angular = weight;
    } else if (j.type() == JointType::Prismatic) {
        // translation = axis . (anchorB - anchorA): with A static, the axis and A's anchor are constants.
        if (ends[0].moves)
            throw std::invalid_argument(name + " is a prismatic joint whose bodyA is not static: a gear reads a "
                                               "prismatic joint's translation along a fixed axis");
        ends[1].linear = weight * A.xf.q.apply(std::get<PrismaticJoint>(j.params).localAxis);
        ends[1].anchor = j.localB;
    } else {
        throw std::invalid_argument(name + " must be a revolute or prismatic joint, not a " +
                                    std::string(std::visit([](const auto& k) { return k.kName; }, j.params)) +
                                    " joint");
    }
}

// The coordinate sum's Jacobian on the row's two bodies now: linear and angular parts on A and B.
struct GearJacobian {
    Vec2 rA, rB;
    double wA, wB;
};

GearJacobian jacobian(const GearJoint& g, const JointConstraint& row, const MotionSide& A, const MotionSide& B) {
    GearJacobian J;
    J.rA = A.dq.apply(row.anchorA);
    J.rB = B.dq.apply(row.anchorB);
    J.wA = g.angularA + cross(J.rA, g.linearA);
    J.wB = g.angularB + cross(J.rB, g.linearB);
    return J;
}

void push(const JointConstraint& row, const GearJoint& g, const GearJacobian& J, MotionSide& A, MotionSide& B,
          double impulse) {
    A.v += row.invMassA * impulse * g.linearA;
    A.w += row.invIA * impulse * J.wA;
    B.v += row.invMassB * impulse * g.linearB;
    B.w += row.invIB * impulse * J.wB;
}

}  // namespace

JointId World::createGearJoint(const GearJointDef& def) {
    const WorldImpl& w = *impl_;
    w.requireNotStepping("createGearJoint");
    if (!std::isfinite(def.ratio) || def.ratio == 0.0)
        throw std::invalid_argument("physim: createGearJoint ratio must be finite and != 0, got " +
                                    std::to_string(def.ratio));
    if (def.joint1 == def.joint2)
        throw std::invalid_argument("physim: createGearJoint joint1 and joint2 must be two different joints");
    GearedEnd ends[4];
    gearedEnds(w, def.joint1, 1, 1.0, ends);
    gearedEnds(w, def.joint2, 2, def.ratio, ends + 2);
    // The bodies the two joints move, in order of appearance: the gear's A and B. Each end adds its parts there.
    GearDefinition gear;
    static_cast<GearJointDef&>(gear) = def;
    std::uint32_t bodies[2] = {0, 0};
    int count = 0;
    for (const GearedEnd& end : ends) {
        if (!end.moves) continue;
        int side = 0;
        while (side < count && bodies[side] != end.body) ++side;
        if (side == count) {
            if (count == 2)
                throw std::invalid_argument("physim: createGearJoint joint1 and joint2 move more than two bodies "
                                            "between them (a gear acts between two: give each joint a static "
                                            "bodyA, or make one joint's bodyA the other's bodyB)");
            bodies[count++] = end.body;
        }
        (side == 0 ? gear.angularA : gear.angularB) += end.angular;
        if (end.linear != Vec2::Zero()) {
            (side == 0 ? gear.linearA : gear.linearB) = end.linear;
            (side == 0 ? gear.anchorA : gear.anchorB) = end.anchor;
        }
    }
    if (count < 2)
        throw std::invalid_argument("physim: createGearJoint joint1 and joint2 move only one body between them: "
                                    "a gear needs two");
    gear.bodyA = BodyId{bodies[0], w.bodies[bodies[0]].generation};
    gear.bodyB = BodyId{bodies[1], w.bodies[bodies[1]].generation};
    return createJoint({KindDefinition<GearJoint>{&gear, "createGearJoint"}});
}

GearJoint GearJoint::make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB) {
    GearJoint g;
    g.joint1 = def.joint1;
    g.joint2 = def.joint2;
    g.ratio = def.ratio;
    g.angularA = def.angularA;
    g.angularB = def.angularB;
    g.linearA = def.linearA;
    g.linearB = def.linearB;
    localA = def.anchorA;
    localB = def.anchorB;
    g.initial = g.angularA * A.angle + g.angularB * B.angle + g.linearA.dot(A.xf.apply(localA)) +
                g.linearB.dot(B.xf.apply(localB));
    return g;
}

void GearJoint::prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                        const Softness& rodSoftness) const {
    row.softness = rodSoftness;
    row.invH = 1.0 / h;
    // The error at the start (rad or m: coordinate1's unit); the solve adds what the displacements since change.
    row.deltaAngle = angularA * A.angle + angularB * B.angle + linearA.dot(A.center + row.anchorA) +
                     linearB.dot(B.center + row.anchorB) - initial;
}

void GearJoint::warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const {
    push(row, *this, jacobian(*this, row, A, B), A, B, impulse);
}

void GearJoint::solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias) {
    const GearJacobian J = jacobian(*this, row, A, B);
    const double k = row.invMassA * linearA.squaredNorm() + row.invIA * J.wA * J.wA +
                     row.invMassB * linearB.squaredNorm() + row.invIB * J.wB * J.wB;
    if (!(k > 0.0)) return;
    double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    if (useBias) {
        const double C = row.deltaAngle + angularA * A.dAngle + angularB * B.dAngle +
                         linearA.dot(A.dp + J.rA - row.anchorA) + linearB.dot(B.dp + J.rB - row.anchorB);
        bias = row.softness.biasRate * C;
        massScale = row.softness.massScale;
        impulseScale = row.softness.impulseScale;
    }
    const double Cdot = linearA.dot(A.v) + J.wA * A.w + linearB.dot(B.v) + J.wB * B.w;
    const double lambda = -massScale * (Cdot + bias) / k - impulseScale * impulse;
    impulse += lambda;
    push(row, *this, J, A, B, lambda);
}

JointReaction GearJoint::reaction(const JointEndsNow&, double invH) const {
    return {impulse * invH * linearB, impulse * invH * angularB};
}

std::vector<JointId> gearsOn(const WorldImpl& w, std::uint32_t index) {
    std::vector<JointId> gears;
    const JointData& joint = w.joints[index];
    const JointId id{index, joint.generation};
    // A gear acts on every body its joints move, so it lies in the list of the joint's moving body.
    const std::uint32_t body = w.bodies[joint.a].type != BodyType::Static ? joint.a : joint.b;
    for (std::int32_t key = w.bodies[body].jointHead; key != kNullIndex;) {
        const JointData& other = w.joints[static_cast<std::size_t>(key >> 1)];
        if (const auto* gear = std::get_if<GearJoint>(&other.params))
            if (gear->joint1 == id || gear->joint2 == id)
                gears.push_back(JointId{static_cast<std::uint32_t>(key >> 1), other.generation});
        key = other.next[key & 1];
    }
    return gears;
}

}  // namespace physim
