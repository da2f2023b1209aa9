#pragma once
// Joints. Constraints solved with the contacts:
//   distance  a massless rigid rod between an anchor on each body (a pendulum's string held taut, the paper's
//             rope's links), or with `hertz` > 0 a soft one (a spring solved implicitly: a soft rope's links);
//   mouse     a soft spring with a force cap pulling a body's anchor towards a target point (dragging);
//   revolute  a pin: two bodies share a point and turn freely about it, within optional angle limits, driven by
//             an optional motor;
//   weld      two bodies share a point and their relative angle: glued;
//   pulley    two bodies hang from two fixed points by one rope: lengthA + ratio * lengthB stays at most its length;
//   motor     drives one body's pose relative to another's, within a force and a torque;
//   prismatic a slider: B moves along an axis fixed in A without turning relative to it, within optional limits,
//             driven by an optional motor, pulled by an optional spring;
//   wheel     a wheel on a suspension: B's anchor moves along an axis fixed in A (a spring along it) and B turns
//             freely, driven by an optional motor;
//   gear      couples two revolute or prismatic joints: coordinate1 + ratio coordinate2 stays constant.
// And one force, evaluated every substep (docs/effects.md):
//   spring    Hooke's law with damping between an anchor on each body, or from a body's anchor to a world point.

#include "physim/core/Body.hpp"
#include "physim/core/Math.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace physim {

/// Handle to a joint in one World; stale after the joint, or either of its bodies, is destroyed.
struct JointId {
    std::uint32_t index = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t generation = 0;
    bool isNull() const { return index == std::numeric_limits<std::uint32_t>::max(); }
    friend bool operator==(const JointId& a, const JointId& b) {
        return a.index == b.index && a.generation == b.generation;
    }
};

/// A joint's kind (World::jointType); each has its definition below and its World::createXJoint.
enum class JointType { Distance, Mouse, Spring, Revolute, Weld, Pulley, Motor, Prismatic, Wheel, Gear };

/// What every joint definition has besides its kind's own values.
struct JointDefBase {
    /// Whether the joint's two bodies still collide with each other. Off by default: a wheel on its axle, or a link
    /// overlapping its neighbour at the pin, meets the other body only through the joint.
    bool collideConnected = false;
    /// N, > 0: the joint breaks when the force it applies exceeds this (it is destroyed at the end of the step and
    /// reported in World::jointEvents). Infinity (the default): never.
    double breakForce = std::numeric_limits<double>::infinity();
    /// N m, > 0: likewise for the torque it applies besides its force's moment.
    double breakTorque = std::numeric_limits<double>::infinity();
};

/// A joint that broke in the last step: what it applied crossed its JointDefBase::breakForce or breakTorque, so it
/// was destroyed at the end of the step (its id is stale now).
struct JointBreakEvent {
    JointId joint;
    BodyId bodyA, bodyB;
    Vec2 force = Vec2::Zero();  ///< N, what it applied to B in that step (JointReaction's force)
    double torque = 0.0;        ///< N m, besides the force's moment
};

/// What happened to the joints in the last step, in the joints' slot order.
struct JointEvents {
    std::vector<JointBreakEvent> broken;
};

struct DistanceJointDef : JointDefBase {
    BodyId bodyA;
    BodyId bodyB;
    Vec2 localAnchorA = Vec2::Zero();  ///< m, in A's frame (relative to its body origin)
    Vec2 localAnchorB = Vec2::Zero();  ///< m, in B's frame
    /// m, > 0; <= 0 (the default) takes the anchors' distance when the joint is created.
    double length = 0.0;
    /// Hz, >= 0. 0: a rigid rod. > 0: a soft link that pulls back like a spring of this frequency for the masses
    /// it joins (stiffness k = m_eff (2 pi hertz)^2, m_eff the link's effective mass: m for one body of mass m
    /// against a fixed one, m / 2 between two of mass m), solved implicitly, so any stiffness is stable.
    double hertz = 0.0;
    double dampingRatio = 1.0;  ///< >= 0, of the soft link; 1 is critical
};

struct MouseJointDef : JointDefBase {
    BodyId body;                       ///< a dynamic body
    Vec2 target = Vec2::Zero();        ///< world point the anchor is pulled towards, m
    Vec2 localAnchor = Vec2::Zero();   ///< grabbed point in the body's frame (origin-relative), m
    double maxForce = 0.0;             ///< N, > 0: the pull never exceeds it (e.g. 1000 m |g|)
    double hertz = 5.0;                ///< spring frequency, Hz, > 0 (capped at a quarter of the substep rate)
    double dampingRatio = 0.7;         ///< >= 0; 1 is critical damping
};

/// A Hooke spring: F on B = -(stiffness (L - restLength) + damping dL/dt) u, L = |anchorB - anchorA| and u the
/// unit vector from anchorA to anchorB (N; its reaction, -F, acts on A). Evaluated every substep as a force
/// (explicit): stable while the spring's frequency sqrt(k / m) stays well below the substep rate; for stiffer
/// links use a soft distance joint (DistanceJointDef::hertz).
struct SpringJointDef : JointDefBase {
    BodyId bodyA;                      ///< null: the spring's first end is the world point localAnchorA
    BodyId bodyB;                      ///< a body
    Vec2 localAnchorA = Vec2::Zero();  ///< m, in A's frame (origin-relative), or a world point when bodyA is null
    Vec2 localAnchorB = Vec2::Zero();  ///< m, in B's frame (origin-relative)
    double restLength = -1.0;          ///< m, >= 0; < 0 (the default) takes the anchors' distance at creation
    double stiffness = 0.0;            ///< k, N/m, > 0
    double damping = 0.0;              ///< c, N s/m, >= 0 (along the spring)
};

/// A pin at a world point: each body keeps the point where it is at creation, and the bodies turn freely about
/// it. The joint angle is angle(B) - angle(A) minus its value at creation, rad.
struct RevoluteJointDef : JointDefBase {
    BodyId bodyA, bodyB;
    Vec2 anchor = Vec2::Zero();        ///< the pin, world point, m
    bool enableLimit = false;
    double lowerAngle = 0.0;           ///< rad, <= upperAngle
    double upperAngle = 0.0;           ///< rad
    bool enableMotor = false;
    double motorSpeed = 0.0;           ///< rad/s of B relative to A
    double maxMotorTorque = 0.0;       ///< N m, >= 0
    /// A rotary spring pulling the joint angle towards springTargetAngle (World::setJointSpring): its frequency for
    /// the joint's effective inertia 1 / (1/I_A + 1/I_B) (a disc pinned to the ground: its own I), solved
    /// implicitly, so any stiffness is stable (capped at a quarter of the substep rate as jointHertz).
    bool enableSpring = false;
    double springHertz = 0.0;          ///< Hz, >= 0; 0: the spring does nothing
    double springDampingRatio = 0.0;   ///< >= 0; 1 is critical (no overshoot)
    double springTargetAngle = 0.0;    ///< rad, relative to the angle at creation
};

/// Glues two bodies at a world point: their relative pose stays what it is at creation.
struct WeldJointDef : JointDefBase {
    BodyId bodyA, bodyB;
    Vec2 anchor = Vec2::Zero();        ///< world point, m
};

/// Two bodies hanging from two fixed world points by one rope over two pulleys: lengthA = |anchor A - groundAnchorA|,
/// lengthB likewise, and lengthA + ratio * lengthB never exceeds `length` (a rope: it pulls, never pushes, and goes
/// slack). A ratio r makes a block and tackle: B's side moves 1/r as far as A's. jointLength is `length`;
/// World::jointPulleyLengths gives the sides now. jointReactionForce is the rope's pull on B (A's side pulls A with
/// 1/ratio of it, along its own side); the ground anchors take the rest.
struct PulleyJointDef : JointDefBase {
    BodyId bodyA, bodyB;
    Vec2 groundAnchorA = Vec2::Zero();  ///< world point A's side hangs from, m
    Vec2 groundAnchorB = Vec2::Zero();  ///< world point B's side hangs from, m
    Vec2 localAnchorA = Vec2::Zero();   ///< m, in A's frame (origin-relative)
    Vec2 localAnchorB = Vec2::Zero();   ///< m, in B's frame
    double ratio = 1.0;                 ///< > 0
    /// m, the rope's length lengthA + ratio * lengthB; <= 0 (the default) takes its value at creation. Each side
    /// must be longer than 0 at creation.
    double length = 0.0;
};

/// Drives B's pose relative to A's towards a target: B's origin towards A's point at linearOffset (in A's frame)
/// and angle(B) - angle(A) towards angularOffset, as a velocity that removes correctionFactor of the error each
/// substep, within maxForce and maxTorque (a top-down character pushed by the player, a platform following a path).
/// World::setMotorJointOffsets moves the target; jointMotorForce and jointMotorTorque read what it applied.
struct MotorJointDef : JointDefBase {
    BodyId bodyA, bodyB;
    Vec2 linearOffset = Vec2::Zero();  ///< m, B's origin in A's frame
    double angularOffset = 0.0;        ///< rad, angle(B) - angle(A)
    double maxForce = 1.0;             ///< N, >= 0
    double maxTorque = 1.0;            ///< N m, >= 0
    double correctionFactor = 0.3;     ///< in [0, 1]: the fraction of the pose error removed per substep
};

/// A slider through a world point along a world axis: B keeps its angle relative to A and its anchor moves only
/// along the axis, which turns with A. The translation (World::jointTranslation) is axis . (anchorB - anchorA), m,
/// 0 at creation.
struct PrismaticJointDef : JointDefBase {
    BodyId bodyA, bodyB;
    Vec2 anchor = Vec2::Zero();        ///< world point, m
    Vec2 axis = Vec2(1.0, 0.0);        ///< world direction at creation, any length > 0 (stored as a unit vector)
    bool enableLimit = false;
    double lowerTranslation = 0.0;     ///< m, <= upperTranslation
    double upperTranslation = 0.0;     ///< m
    bool enableMotor = false;
    double motorSpeed = 0.0;           ///< m/s of B relative to A along the axis
    double maxMotorForce = 0.0;        ///< N, >= 0
    /// A spring along the axis pulling the translation towards targetTranslation, solved implicitly: frequency
    /// hertz for the slider's effective mass (k = m_eff (2 pi hertz)^2), dampingRatio 1 critical.
    bool enableSpring = false;
    double hertz = 0.0;                ///< Hz, >= 0 (0: no spring)
    double dampingRatio = 0.0;         ///< >= 0
    double targetTranslation = 0.0;    ///< m
};

/// A wheel (bodyB) on a chassis (bodyA): the wheel's anchor (usually its centre) moves only along an axis fixed in
/// the chassis, held there by a suspension spring, and the wheel turns freely, driven by an optional motor. The
/// translation along the axis is 0 at creation, the spring's rest.
struct WheelJointDef : JointDefBase {
    BodyId bodyA, bodyB;
    Vec2 anchor = Vec2::Zero();        ///< world point, m
    Vec2 axis = Vec2(0.0, 1.0);        ///< the suspension's world direction at creation, any length > 0
    bool enableSpring = true;
    double hertz = 1.0;                ///< Hz, >= 0, for the effective mass along the axis (0: no spring)
    double dampingRatio = 0.7;         ///< >= 0
    bool enableLimit = false;
    double lowerTranslation = 0.0;     ///< m, <= upperTranslation
    double upperTranslation = 0.0;     ///< m
    bool enableMotor = false;
    double motorSpeed = 0.0;           ///< rad/s of B relative to A
    double maxMotorTorque = 0.0;       ///< N m, >= 0
};

/// Couples two existing joints, each revolute (its coordinate: the joint angle, rad) or prismatic (its
/// translation, m), so that coordinate1 + ratio coordinate2 stays what it is at creation: meshed gears, a rack and
/// pinion. The gear acts between the bodies the two joints move, which must be two: say each joint's bodyA static,
/// or a planet pinned to a carrier that the other joint turns. A prismatic joint's bodyA must be static (its axis
/// fixed); a static body's pose counts as it is at the gear's creation. Destroying either joint destroys the gear.
struct GearJointDef : JointDefBase {
    JointId joint1, joint2;
    double ratio = 1.0;                ///< finite, != 0 (units of coordinate1 per unit of coordinate2)
};

/// A joint's limits (World::jointLimits): rad for revolute joints, m for prismatic and wheel joints.
struct JointLimits {
    bool enabled = false;
    double lower = 0.0, upper = 0.0;
};

}  // namespace physim
