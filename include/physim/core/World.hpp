#pragma once
// The physics world: owns every body's data and steps it. No SFML, no ROOT.
//
// One step, World::step(dt), runs the stages in this order, each skipped when the world's content does not call
// for it (profile() tells which ran):
//   BroadPhase   proxies that left their enlarged boxes find new candidate pairs; new pairs become contacts
//   NarrowPhase  every awake contact's manifold, found once per step with a speculative margin; touching begins
//                and ends (contactEvents()), touched sleepers wake
//   Forces       gravity and accumulated forces become accelerations for the step; the force effects the world
//                holds (force callbacks at the step's start; gravitation, springs and drag every substep) act
//                (docs/effects.md)
//   Solve        the soft step (docs/architecture.md): `substeps` times integrate, warm start, solve, integrate
//   Integrate    positions, relax; then restitution; poses and boxes updated
//   Continuous   time of impact for fast bodies (docs/ccd.md)
//   Sensors      while the world holds a sensor: what overlaps each, entered and left when (Sensor.hpp)
//   Sleep        islands at rest stop being simulated
// Forces and impulses added between steps act in the next step. Changing the world from inside its step (from a
// continuous solver, say) is refused with std::logic_error naming the call.

#include "physim/core/Body.hpp"
#include "physim/core/Contact.hpp"
#include "physim/core/ContactHooks.hpp"
#include "physim/core/EnergyLedger.hpp"
#include "physim/core/Filter.hpp"
#include "physim/core/ForceCallback.hpp"
#include "physim/core/Gravitation.hpp"
#include "physim/core/Joint.hpp"
#include "physim/core/Sensor.hpp"
#include "physim/core/Snapshot.hpp"
#include "physim/core/Query.hpp"
#include "physim/core/StepProfile.hpp"
#include "physim/core/WorldSettings.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace physim {

struct WorldImpl;        // internal, src/core/WorldImpl.hpp
struct BodyData;
struct JointData;
struct JointDefinition;
class ContinuousSolver;  // physim/core/ContinuousBatch.hpp

class World {
public:
    explicit World(const WorldSettings& settings = {});
    ~World();
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // --- bodies -------------------------------------------------------------------------------------
    /// Validates the definition (throws std::invalid_argument naming the bad value) and adds the body.
    /// Everywhere in the World, positions, points, anchors and lengths must lie within kMaxCoordinate and speeds
    /// within kMaxSpeed (Validate.hpp); other values must be finite.
    BodyId createBody(const BodyDef& def);
    void destroyBody(BodyId id);
    bool contains(BodyId id) const;
    std::size_t bodyCount() const;
    /// The live bodies in creation-slot order (for drawing and inspection).
    std::vector<BodyId> bodies() const;

    BodyType type(BodyId id) const;
    /// The geometry of the body's first shape (its BodyDef's); throws std::invalid_argument for a body with none.
    const Geometry& shape(BodyId id) const;
    Transform transform(BodyId id) const;
    /// The body origin, m (the point its shapes' coordinates are relative to).
    Vec2 position(BodyId id) const;
    double angle(BodyId id) const;
    /// World centre of mass, m: the point the body rotates about.
    Vec2 centerOfMass(BodyId id) const;
    /// Centre of mass in the body frame, m (its shapes' centroid, each weighted by its density).
    Vec2 localCenterOfMass(BodyId id) const;
    /// Velocity of the centre of mass, m/s.
    Vec2 velocity(BodyId id) const;
    /// Velocity of a world point (m) fixed to the body, m/s.
    Vec2 velocityAt(BodyId id, const Vec2& worldPoint) const;
    double angularVelocity(BodyId id) const;
    /// Kinetic energy, J: m v^2 / 2 of the centre of mass's motion plus I w^2 / 2 of the turn about it (0 for an
    /// immovable body).
    double kineticEnergy(BodyId id) const;
    /// World bounding box of the body's shapes at its pose, m (a shapeless body's is its origin).
    Aabb bounds(BodyId id) const;
    double mass(BodyId id) const;         ///< kg; 0 for static and kinematic bodies (immovable)
    double inverseMass(BodyId id) const;  ///< 1/kg; 0 when immovable
    /// kg m^2 about the centre of mass (MassData.hpp); 0 for static and kinematic bodies. A body with fixed
    /// rotation keeps its shapes' inertia; its inverse inertia is 0.
    double inertia(BodyId id) const;
    double inverseInertia(BodyId id) const;
    /// The material of the body's first shape (each shape has its own: restitution(ShapeId) ...).
    double restitution(BodyId id) const;
    double staticFriction(BodyId id) const;
    double dynamicFriction(BodyId id) const;
    bool useGravity(BodyId id) const;

    void setTransform(BodyId id, const Vec2& position, double angle);
    void setVelocity(BodyId id, const Vec2& velocity);
    void setAngularVelocity(BodyId id, double angularVelocity);
    void setUseGravity(BodyId id, bool useGravity);
    /// Restitution in [0, 1], friction coefficients >= 0 (throws std::invalid_argument naming a bad value), for
    /// every shape of the body.
    void setMaterial(BodyId id, double restitution, double staticFriction, double dynamicFriction);
    /// Sleeping (WorldSettings::enableSleep): a sleeping body is not simulated until touched by an awake body,
    /// or until a force, impulse, velocity, pose or type is set on it (each of those wakes it).
    bool isAwake(BodyId id) const;
    /// Wakes the body (true), or puts it to sleep now (false: it stops, and stays until something wakes it).
    void setAwake(BodyId id, bool awake);
    /// false: the body never sleeps, and neither does any island it touches. Wakes it.
    void setAllowSleep(BodyId id, bool allowSleep);
    bool allowSleep(BodyId id) const;
    /// Changes a body's type. Becoming static stops it; static and kinematic bodies are immovable by contacts;
    /// becoming dynamic gives it the mass of its shapes at their densities (throws std::invalid_argument naming the
    /// density when that is not a positive finite mass, e.g. a body made with density 0). A value outside the enum
    /// is refused.
    void setType(BodyId id, BodyType type);
    /// Sets the mass (kg, > 0) of a dynamic body; inertia scales with it (the shapes keep their density ratios;
    /// createShape and destroyShape give the body its shapes' own mass again).
    void setMass(BodyId id, double mass);
    /// Locks (true) or frees the body's rotation: locked, its inverse inertia is 0, so contacts and torques
    /// do not turn it, and its angular velocity is zeroed.
    void setFixedRotation(BodyId id, bool fixedRotation);
    bool fixedRotation(BodyId id) const;

    /// Discrete or continuous (sampled with `precision`, a fraction of the step in (0, 1], or exact) collision
    /// detection; continuous detection acts on dynamic bodies. Throws std::invalid_argument for a bad precision.
    void setCollisionDetection(BodyId id, CollisionDetection mode, double precision = kDefaultPrecision);
    CollisionDetection collisionDetection(BodyId id) const;
    double collisionPrecision(BodyId id) const;
    /// Who solves the continuous stage's exact time-of-impact pairs, batched per substep (ContinuousBatch.hpp):
    /// null (the default) solves them on this thread; physim::cuda::makeContinuousSolver gives the GPU's.
    /// Every solver runs the same kernel code, so the choice changes speed, not results (docs/cuda.md).
    void setContinuousSolver(std::shared_ptr<ContinuousSolver> solver);
    const std::shared_ptr<ContinuousSolver>& continuousSolver() const;

    /// Force (N) at the centre of mass, accumulated until the next step, which applies it and clears it.
    void applyForce(BodyId id, const Vec2& force);
    /// Force (N) applied at a world point (m): also adds the torque r x F.
    void applyForceAtPoint(BodyId id, const Vec2& force, const Vec2& worldPoint);
    void applyTorque(BodyId id, double torque);
    /// Instant change of momentum (N s) at the centre of mass.
    void applyLinearImpulse(BodyId id, const Vec2& impulse);
    /// Instant change of momentum (N s) at a world point (m): also changes the angular velocity.
    void applyLinearImpulseAtPoint(BodyId id, const Vec2& impulse, const Vec2& worldPoint);

    // --- shapes (Shape.hpp): a body may have several ------------------------------------------------
    /// Adds a shape to the body (validated: std::invalid_argument naming a bad value, the world unchanged). A
    /// dynamic body's mass, centre of mass and inertia are recomputed from all its shapes (a body whose mass was
    /// set with setMass gets its shapes' mass again); its origin stays where it is. Wakes the body.
    ShapeId createShape(BodyId body, const ShapeDef& def);
    /// Adds a chain's pieces (ChainDef) to the body as shapes, in order; validated first (std::invalid_argument
    /// naming the bad point or value, the world unchanged). Wakes the body.
    std::vector<ShapeId> createChain(BodyId body, const ChainDef& def);
    /// Removes a shape; its contacts end and what they held wakes. A dynamic body keeps at least one shape with mass
    /// (std::invalid_argument otherwise).
    void destroyShape(ShapeId id);
    bool contains(ShapeId id) const;
    std::size_t shapeCount() const;
    /// The body's shapes, in the order they were added.
    std::vector<ShapeId> shapes(BodyId body) const;
    BodyId body(ShapeId id) const;
    /// In the body's frame, m.
    const Geometry& geometry(ShapeId id) const;
    /// World bounding box of the shape at its body's pose, m.
    Aabb bounds(ShapeId id) const;
    double density(ShapeId id) const;
    double restitution(ShapeId id) const;
    double staticFriction(ShapeId id) const;
    double dynamicFriction(ShapeId id) const;
    /// As setMaterial(BodyId, ...), for one shape. Wakes its body.
    void setMaterial(ShapeId id, double restitution, double staticFriction, double dynamicFriction);
    /// Surface materials (ShapeDef, docs/collision.md): rolling resistance >= 0, tangent speed finite (m/s). A set
    /// call wakes the shape's body and takes effect at the next step; the BodyId forms set every shape of the body
    /// and read its first.
    double rollingResistance(ShapeId id) const;
    double tangentSpeed(ShapeId id) const;
    void setRollingResistance(ShapeId id, double coefficient);
    void setTangentSpeed(ShapeId id, double speed);
    double rollingResistance(BodyId id) const;
    double tangentSpeed(BodyId id) const;
    void setRollingResistance(BodyId id, double coefficient);
    void setTangentSpeed(BodyId id, double speed);

    // --- collision filtering (Filter.hpp, ContactHooks.hpp): each costs nothing while unused -----------------
    /// The shape's filter. A change takes effect at the next step: its contacts the new filter refuses end (with
    /// end events, waking their bodies), and the pairs it allows are found again. Wakes the shape's body (a static
    /// body's: what its shape overlaps). A destroyed or stale id is refused with std::invalid_argument naming it.
    void setFilter(ShapeId id, const Filter& filter);
    const Filter& filter(ShapeId id) const;
    /// Every shape of the body gets `filter`, as setFilter(ShapeId, ...); filter(BodyId) is its first shape's.
    void setFilter(BodyId id, const Filter& filter);
    const Filter& filter(BodyId id) const;
    /// Asked once when a pair whose filters allow it would become a contact (PairFilterCallback); null: none. Takes
    /// effect at the next step, as a filter change does: existing contacts it refuses end, and every pair is asked
    /// again.
    void setPairFilter(PairFilterCallback callback);
    /// Called for each awake contact with points before the solver, every step (PreSolveCallback); false disables
    /// the contact for that step (a one-way platform). Null: none.
    void setPreSolve(PreSolveCallback callback);

    // --- effects (docs/effects.md): each costs nothing while no body uses it ---------------------------
    /// Finite; the body feels scale times the world's gravity (when useGravity). Wakes it.
    void setGravityScale(BodyId id, double scale);
    double gravityScale(BodyId id) const;
    /// Validates (std::invalid_argument naming the field) and gives the body this drag; all zero removes it.
    /// Wakes it.
    void setDrag(BodyId id, const DragDef& drag);
    DragDef drag(BodyId id) const;
    /// false: the body touches nothing (its contacts end, waking what they held); true: it collides again.
    void setCollides(BodyId id, bool collides);
    bool collides(BodyId id) const;
    /// true: the body pulls, and is pulled by, every other attracting body (gravitation()); such a body never
    /// sleeps. Static and kinematic bodies have no mass, so they neither pull nor are pulled. Wakes it.
    void setAttracting(BodyId id, bool attracting);
    bool attracting(BodyId id) const;
    std::size_t attractingCount() const;
    /// Validates (std::invalid_argument naming the field) and sets the law of gravitation between bodies.
    void setGravitation(const GravitationSettings& settings);
    const GravitationSettings& gravitation() const;
    /// A force written by the user, called at the start of every step (ForceCallback.hpp). Throws
    /// std::invalid_argument for an empty callback.
    ForceCallbackId addForceCallback(ForceCallback callback);
    /// Throws std::invalid_argument for an unknown id.
    void removeForceCallback(ForceCallbackId id);
    std::size_t forceCallbackCount() const;

    // --- joints -------------------------------------------------------------------------------------
    /// A rigid rod between two anchors. Throws std::invalid_argument for an unknown or repeated body, two
    /// immovable bodies, non-finite anchors or length, or a zero length. Destroying either body removes it.
    JointId createDistanceJoint(const DistanceJointDef& def);
    /// A soft spring pulling an anchor of a dynamic body towards a target point, its force capped at maxForce
    /// (dragging with the mouse). Throws std::invalid_argument naming a bad value.
    JointId createMouseJoint(const MouseJointDef& def);
    /// A Hooke spring with damping (SpringJointDef), a force. Throws std::invalid_argument naming a bad value
    /// (unknown or repeated body, no dynamic body, stiffness <= 0, negative damping, non-finite anchors).
    JointId createSpringJoint(const SpringJointDef& def);
    /// A pin (RevoluteJointDef). Throws std::invalid_argument naming a bad value (unknown or repeated body, two
    /// immovable bodies, non-finite anchor, lowerAngle > upperAngle, negative maxMotorTorque).
    JointId createRevoluteJoint(const RevoluteJointDef& def);
    /// A weld (WeldJointDef). Throws std::invalid_argument as createRevoluteJoint.
    JointId createWeldJoint(const WeldJointDef& def);
    /// Revolute and weld joints: angle(B) - angle(A) minus its value at creation, rad; motor joints: minus the
    /// angular offset (0 on target).
    double jointAngle(JointId id) const;
    /// Revolute joints: the motor (rad/s of B relative to A, N m >= 0). Wakes the bodies.
    void setJointMotor(JointId id, bool enable, double speed, double maxTorque);
    /// Revolute joints: the limits, rad, lower <= upper. Wakes the bodies.
    void setJointLimits(JointId id, bool enable, double lower, double upper);
    /// Moves a mouse joint's target (m); wakes its body.
    void setMouseJointTarget(JointId id, const Vec2& target);
    /// Destroys the joint, and any gear on it (GearJointDef). Wakes its bodies.
    void destroyJoint(JointId id);
    bool contains(JointId id) const;
    std::size_t jointCount() const;
    JointType jointType(JointId id) const;
    /// The joint's rod length (distance joints), rest length (springs) or rope length (pulleys: lengthA + ratio *
    /// lengthB when taut), m; other joints are refused with std::invalid_argument.
    double jointLength(JointId id) const;
    /// The joint's anchors in world coordinates, m (a mouse joint's, or a spring to a point's, first anchor is
    /// its target).
    std::pair<Vec2, Vec2> jointAnchors(JointId id) const;
    /// The joints in creation-slot order (for drawing and inspection).
    std::vector<JointId> joints() const;
    /// The force the joint applied to body B in the last step, N, at B's anchor (its reaction, -force, acts on A,
    /// or on the world point): the joint's impulse over a substep divided by the substep, so a pendulum's rod at
    /// rest reports its bob's weight; zero before the first step. A spring reports its force now.
    Vec2 jointReactionForce(JointId id) const;
    /// The torque the joint applied to body B in the last step besides its force's moment, N m (its reaction acts on
    /// A): a revolute joint's spring, motor and limits, a weld's, prismatic joint's or motor joint's hold on the angle,
    /// a wheel's motor, a gear's on B's angle; 0 for the other kinds. A pulley's force is its rope's pull on B; A's
    /// side pulls A along its own side, 1/ratio as hard.
    double jointReactionTorque(JointId id) const;
    /// What the joint's motor applied to body B in the last step (its reaction acts on A), N m: revolute joints
    /// and wheel joints (0 while the motor is off), motor joints; other kinds are refused with std::invalid_argument.
    double jointMotorTorque(JointId id) const;
    /// What the joint's linear motor applied to body B along its axis in the last step, N: prismatic joints (0 while
    /// the motor is off), motor joints (the size of their force); kinds without one are refused with
    /// std::invalid_argument.
    double jointMotorForce(JointId id) const;
    /// The joints that broke in the last step (JointDefBase::breakForce, breakTorque), beside contactEvents().
    const JointEvents& jointEvents() const;
    /// A rope over two pulleys (PulleyJointDef). Throws std::invalid_argument naming a bad value (as
    /// createRevoluteJoint, and non-finite anchors, ratio <= 0, a side of zero length, a length too short).
    JointId createPulleyJoint(const PulleyJointDef& def);
    /// Pulley joints: each side's length now, |anchor - ground anchor| (m), A's then B's.
    std::pair<double, double> jointPulleyLengths(JointId id) const;
    /// Drives one body's pose relative to another (MotorJointDef). Throws std::invalid_argument naming a bad value.
    JointId createMotorJoint(const MotorJointDef& def);
    /// Motor joints: the target pose of B relative to A (m in A's frame, rad). Wakes the bodies.
    void setMotorJointOffsets(JointId id, const Vec2& linearOffset, double angularOffset);
    /// Revolute joints: the rotary spring (Hz >= 0, damping ratio >= 0; RevoluteJointDef). Wakes the bodies.
    void setJointSpring(JointId id, bool enable, double hertz, double dampingRatio);
    /// A slider (PrismaticJointDef). Throws std::invalid_argument naming a bad value (unknown or repeated body, two
    /// immovable bodies, non-finite anchor, a zero or non-finite axis, lowerTranslation > upperTranslation, negative
    /// maxMotorForce, hertz or dampingRatio).
    JointId createPrismaticJoint(const PrismaticJointDef& def);
    /// Prismatic joints: the limits, m, lower <= upper; the motor (m/s, N >= 0); the spring (Hz >= 0, damping ratio
    /// >= 0, target m). Each wakes the bodies.
    void setPrismaticLimits(JointId id, bool enable, double lower, double upper);
    void setPrismaticMotor(JointId id, bool enable, double speed, double maxForce);
    void setPrismaticSpring(JointId id, bool enable, double hertz, double dampingRatio, double targetTranslation);
    /// A wheel on a suspension (WheelJointDef). Throws std::invalid_argument as createPrismaticJoint (a negative
    /// maxMotorTorque too).
    JointId createWheelJoint(const WheelJointDef& def);
    /// Wheel joints: the suspension spring (Hz >= 0, damping ratio >= 0), the limits (m), the motor (rad/s,
    /// N m >= 0). Each wakes the bodies.
    void setWheelSpring(JointId id, bool enable, double hertz, double dampingRatio);
    void setWheelLimits(JointId id, bool enable, double lower, double upper);
    void setWheelMotor(JointId id, bool enable, double speed, double maxTorque);
    /// Prismatic and wheel joints: the translation of B's anchor along the axis from A's, minus its value at
    /// creation (m), and its rate (m/s); other kinds are refused with std::invalid_argument.
    double jointTranslation(JointId id) const;
    double jointSpeed(JointId id) const;
    /// Couples two revolute or prismatic joints (GearJointDef). Throws std::invalid_argument naming a bad value
    /// (a joint that is not live or of another kind, a ratio that is zero or not finite, joints that move more than
    /// two bodies between them).
    JointId createGearJoint(const GearJointDef& def);
    /// The joint's bodies, A then B (a joint to a world point: B twice), for drawing and inspection.
    std::pair<BodyId, BodyId> jointBodies(JointId id) const;
    /// Prismatic and wheel joints: the axis in the world now (unit; it turns with A); other kinds are refused with
    /// std::invalid_argument.
    Vec2 jointAxis(JointId id) const;
    /// Revolute (rad, of jointAngle), prismatic and wheel (m, of jointTranslation) joints: the limits and whether
    /// they are on; other kinds are refused with std::invalid_argument.
    JointLimits jointLimits(JointId id) const;
    /// Pulley joints: the fixed points A's and B's sides hang from, m; other kinds are refused with
    /// std::invalid_argument.
    std::pair<Vec2, Vec2> jointPulleyGroundAnchors(JointId id) const;

    // --- sensors (Sensor.hpp): shapes that report overlaps and collide with nothing ---------------------
    /// Makes the shape a sensor (its contacts end now, waking what they held) or an ordinary shape again (its
    /// overlaps end without events; it collides from the next step). Wakes its body. Throws
    /// std::invalid_argument naming a shape that is not live.
    void setSensor(ShapeId id, bool sensor);
    bool isSensor(ShapeId id) const;
    /// Sensor shapes in the world. While there are none the Sensors stage does not run and costs nothing.
    std::size_t sensorCount() const;
    /// The shapes overlapping the sensor after the last step, by shape index. Throws std::invalid_argument for a
    /// shape that is not live or not a sensor.
    std::vector<ShapeId> sensorOverlaps(ShapeId sensor) const;
    /// Visitors that began and ended overlapping sensors during the last step, with the time within the step.
    const SensorEvents& sensorEvents() const;

    // --- stepping -----------------------------------------------------------------------------------
    /// Advances the world by dt seconds, in [1e-9, 1]: larger steps are a unit mistake (milliseconds as seconds),
    /// smaller ones leave the range of doubles in the substep's arithmetic.
    void step(double dt);

    /// The contacts of awake bodies that touch after the last step or pushed during it (a point still apart when
    /// the step began stops or bounces a body that closes the gap within it); a sleeping pile's are in
    /// sleepingContacts(). Points may lie slightly apart (positive separation): a contact touches within the
    /// speculative distance.
    /// Each point's normalImpulse and tangentImpulse are its impulses over the whole step (ContactPoint), so
    /// divided by the step's dt they are the mean contact force, N.
    const std::vector<Manifold>& contacts() const;
    /// The contacts whose bodies all sleep (or are static), as contacts() would list them after the last step that
    /// solved them, as that step left them:
    /// their impulses are that step's, so a pile at rest still reports its weight. Built on each call (it visits
    /// every contact), in contacts()' order.
    std::vector<Manifold> sleepingContacts() const;
    /// Contacts that began and ended touching, and impacts, during the last step.
    const ContactEvents& contactEvents() const;
    const StepProfile& profile() const;
    const WorldSettings& settings() const;
    /// Validates (std::invalid_argument naming the field) and applies the settings.
    void setSettings(const WorldSettings& settings);
    /// Number of completed steps.
    std::uint64_t stepCount() const;
    /// Bodies currently simulated (awake dynamic and kinematic bodies).
    std::size_t awakeBodyCount() const;

    // --- energy (EnergyLedger.hpp) --------------------------------------------------------------------
    /// J: the kinetic energy of every body (translation and rotation), now.
    double kineticEnergy() const;
    /// J: the potential energy of gravity, spring joints and gravitation between attracting bodies, now (the
    /// ledger's, EnergyLedger.hpp); gravity's zero is at the origin.
    double potentialEnergy() const;
    /// Switches the energy ledger on (its start becomes the energy now, its totals zero) or off. Off, stepping
    /// costs nothing for it. Edits between steps (setVelocity, restore...) are no step's: the ledger measures each
    /// step from the state it starts from, so the totals sum the steps' changes.
    void setEnergyLedger(bool enabled);
    /// The energies after the last step and where each step's change went; `enabled` false while off.
    const EnergyLedger& energyLedger() const;
    /// Puts back a ledger read earlier (energyLedger()), after restore() put back the state it went with, so that
    /// its totals go on from there (restore() alone starts the ledger again from the restored state).
    void restoreEnergyLedger(const EnergyLedger& ledger);

    // --- time travel (Snapshot.hpp) -----------------------------------------------------------------
    /// The whole state now (not during the step, nor from a force callback: std::logic_error).
    WorldSnapshot snapshot() const;
    /// Puts back a snapshot's state, this world's or another's: stepping on gives bit for bit what followed it
    /// there. The thread count stays this world's (results do not depend on it). Throws std::invalid_argument for an
    /// empty snapshot and std::logic_error during the step or from a force callback, the world unchanged.
    void restore(const WorldSnapshot& snapshot);
    /// A 64-bit hash (FNV-1a) of the bits of the step count and, in slot order, of every live body's position,
    /// rotation (cosine, sine), angle, velocity, angular velocity and whether it is awake. Equal hashes mean the
    /// bodies are in bit-identical states (up to a 2^-64 chance); it does not cover contacts' or joints' impulses.
    std::uint64_t stateHash() const;

    // --- queries (Query.hpp, docs/collision.md "Queries"): const, refused during the step -------------------
    // They see the shapes of bodies that collide (not after setCollides(false)), through the broad phase, but not
    // sensor shapes; `filter` hides shapes as shouldQuery (Filter.hpp) says. A ray starting inside a shape does
    // not hit it (overlapPoint finds what it starts in). A chain piece is seen by rays and
    // casts from its front only (the side it collides on). Bad input (a NaN or infinite origin, point, box or
    // pose, a zero or non-finite translation, an invalid geometry) throws std::invalid_argument naming the value.
    /// The first shape the ray origin + f * translation, f in [0, 1] (m), enters; nullopt when none.
    std::optional<RayHit> castRayClosest(const Vec2& origin, const Vec2& translation,
                                         const QueryFilter& filter = {}) const;
    /// Every shape the ray enters (one hit per shape), nearest first.
    std::vector<RayHit> castRayAll(const Vec2& origin, const Vec2& translation, const QueryFilter& filter = {}) const;
    /// Each hit goes to `callback`, which may ignore it, clip the ray or stop (RayCallback).
    void castRay(const Vec2& origin, const Vec2& translation, const QueryFilter& filter,
                 const RayCallback& callback) const;
    /// The first shape that `geometry`, placed by `pose` and moved by `translation` (m, no rotation), touches: its
    /// fraction lies at most kToiTolerance (1e-4 m) of travel before the true contact, never past it (conservative
    /// advancement, TimeOfImpact.hpp); point is midway between the two surfaces there, normal the target's outward
    /// normal. A shape the cast starts touching or overlapping is hit at fraction 0 with a zero normal.
    std::optional<RayHit> castShape(const Geometry& geometry, const Transform& pose, const Vec2& translation,
                                    const QueryFilter& filter = {}) const;
    /// castShape's callback form: every shape the swept shape touches, each at its first contact, clipped as
    /// castRay's callback says.
    void castShape(const Geometry& geometry, const Transform& pose, const Vec2& translation,
                   const QueryFilter& filter, const RayCallback& callback) const;
    /// Shapes whose tight bounding box (bounds(ShapeId)) overlaps `box`, touching included, in no particular order.
    std::vector<ShapeId> overlapAabb(const Aabb& box, const QueryFilter& filter = {}) const;
    void overlapAabb(const Aabb& box, const QueryFilter& filter, const OverlapCallback& callback) const;
    /// Shapes that contain the point (m), boundary included; segments and chain pieces have no inside.
    std::vector<ShapeId> overlapPoint(const Vec2& point, const QueryFilter& filter = {}) const;
    /// Shapes that `geometry` placed by `pose` touches or overlaps (exact distance 0; chain pieces on both sides).
    std::vector<ShapeId> overlapShape(const Geometry& geometry, const Transform& pose,
                                      const QueryFilter& filter = {}) const;

private:
    const BodyData& at(BodyId id) const;
    std::uint32_t firstShape(BodyId id) const;  // slot of the body's first shape; throws for a shapeless body
    std::uint32_t shapeSlot(ShapeId id) const;  // checked
    /// createShape's and createChain's one path: appends the shapes (validated by the caller) to the body.
    std::vector<ShapeId> addShapes(BodyId body, const std::vector<ShapeDef>& defs, const char* call);
    BodyData& mutableBody(BodyId id, const char* call);  // checked, not during the step
    BodyData& wake(BodyId id, const char* call);         // mutableBody, and its island woken
    const JointData& joint(JointId id) const;
    /// Every createXJoint's one path (src/core/WorldJoints.cpp): checks the bodies and that no step runs, lets the
    /// kind check its definition and fill its data, and adds the joint (linked to its bodies, which wake and join
    /// one island).
    JointId createJoint(const JointDefinition& definition);

    std::unique_ptr<WorldImpl> impl_;
};

}  // namespace physim
