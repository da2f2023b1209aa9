#include "PulleyJoint.hpp"

#include "../WorldImpl.hpp"

#include "physim/core/Validate.hpp"
#include "physim/core/World.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <variant>

namespace physim {
namespace {

// Below this a side has no direction: it neither pulls nor is pulled (only reachable by a slack rope's body
// passing through its ground anchor).
constexpr double kShortestSide = 1e-9;  // m

// A side's unit direction from its ground anchor to its body's anchor (zero when too short to have one).
Vec2 sideDirection(const Vec2& d, double length) {
    return length > kShortestSide ? Vec2(d / length) : Vec2(Vec2::Zero());
}

// Both sides now, from the start of the step and the displacements since.
struct Sides {
    Vec2 rA, rB, uA, uB;
    double lengthA, lengthB;
};

Sides sides(const JointConstraint& row, const MotionSide& A, const MotionSide& B) {
    Sides s;
    s.rA = A.dq.apply(row.anchorA);
    s.rB = B.dq.apply(row.anchorB);
    const Vec2 dA = A.dp + s.rA - row.deltaCenter;  // deltaCenter: ground anchor A minus A's centre at the start
    const Vec2 dB = B.dp + s.rB - row.groundB;
    s.lengthA = dA.norm();
    s.lengthB = dB.norm();
    s.uA = sideDirection(dA, s.lengthA);
    s.uB = sideDirection(dB, s.lengthB);
    return s;
}

// The rope's pull `tension` (N s, >= 0) on each side: A towards its ground anchor, B towards its own ratio times
// as hard. The ground anchors take the reaction, so A and B get no equal and opposite pair here.
void pull(const JointConstraint& row, const Sides& s, double ratio, double tension, MotionSide& A, MotionSide& B) {
    const Vec2 PA = -tension * s.uA, PB = -(ratio * tension) * s.uB;
    A.v += row.invMassA * PA;
    A.w += row.invIA * cross(s.rA, PA);
    B.v += row.invMassB * PB;
    B.w += row.invIB * cross(s.rB, PB);
}

}  // namespace

JointId World::createPulleyJoint(const PulleyJointDef& def) {
    return createJoint({KindDefinition<PulleyJoint>{&def, "createPulleyJoint"}});
}

std::pair<double, double> World::jointPulleyLengths(JointId id) const {
    const JointData& j = joint(id);
    if (j.type() != JointType::Pulley)
        throw std::invalid_argument("physim: jointPulleyLengths needs a pulley joint");
    const PulleyJoint& p = std::get<PulleyJoint>(j.params);
    return {(impl_->bodies[j.a].xf.apply(j.localA) - p.groundA).norm(),
            (impl_->bodies[j.b].xf.apply(j.localB) - p.groundB).norm()};
}

PulleyJoint PulleyJoint::make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB) {
    requireWithin("pulley joint groundAnchorA", def.groundAnchorA, kMaxCoordinate);
    requireWithin("pulley joint groundAnchorB", def.groundAnchorB, kMaxCoordinate);
    requireWithin("pulley joint localAnchorA", def.localAnchorA, kMaxCoordinate);
    requireWithin("pulley joint localAnchorB", def.localAnchorB, kMaxCoordinate);
    requirePositive("pulley joint ratio", def.ratio);
    requireWithin("pulley joint length", def.length, kMaxCoordinate);
    const double lengthA = (A.xf.apply(def.localAnchorA) - def.groundAnchorA).norm();
    const double lengthB = (B.xf.apply(def.localAnchorB) - def.groundAnchorB).norm();
    if (!(lengthA > kShortestSide))
        throw std::invalid_argument("physim: pulley joint side A (anchor to groundAnchorA) must be longer than 0 m, "
                                    "got " + std::to_string(lengthA));
    if (!(lengthB > kShortestSide))
        throw std::invalid_argument("physim: pulley joint side B (anchor to groundAnchorB) must be longer than 0 m, "
                                    "got " + std::to_string(lengthB));
    PulleyJoint j;
    j.groundA = def.groundAnchorA;
    j.groundB = def.groundAnchorB;
    j.ratio = def.ratio;
    j.length = def.length > 0.0 ? def.length : lengthA + def.ratio * lengthB;
    if (!(j.length > kShortestSide))
        throw std::invalid_argument("physim: pulley joint length must be > 0 m, got " + std::to_string(j.length));
    localA = def.localAnchorA;
    localB = def.localAnchorB;
    return j;
}

void PulleyJoint::prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                          const Softness& rodSoftness) const {
    row.softness = rodSoftness;
    row.invH = 1.0 / h;
    row.deltaCenter = groundA - A.center;
    row.groundB = groundB - B.center;
}

void PulleyJoint::warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const {
    pull(row, sides(row, A, B), ratio, impulse, A, B);
}

void PulleyJoint::solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias) {
    const Sides s = sides(row, A, B);
    const double ra = cross(s.rA, s.uA), rb = cross(s.rB, s.uB);
    const double k = row.invMassA + row.invIA * ra * ra + ratio * ratio * (row.invMassB + row.invIB * rb * rb);
    if (!(k > 0.0)) return;
    const double C = length - s.lengthA - ratio * s.lengthB;  // >= 0: slack
    double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    if (C > 0.0) {
        bias = C * row.invH;  // speculative: the bodies may take up the slack within the substep
    } else if (useBias) {
        bias = row.softness.biasRate * C;
        massScale = row.softness.massScale;
        impulseScale = row.softness.impulseScale;
    }
    const double Cdot = -s.uA.dot(A.v + cross(A.w, s.rA)) - ratio * s.uB.dot(B.v + cross(B.w, s.rB));
    const double lambda = -massScale * (Cdot + bias) / k - impulseScale * impulse;
    const double total = std::max(impulse + lambda, 0.0);
    pull(row, s, ratio, total - impulse, A, B);
    impulse = total;
}

JointReaction PulleyJoint::reaction(const JointEndsNow& now, double invH) const {
    const Vec2 d = now.pointB - groundB;
    return {-(ratio * impulse * invH) * sideDirection(d, d.norm()), 0.0};
}

}  // namespace physim
