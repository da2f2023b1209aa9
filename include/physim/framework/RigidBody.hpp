#pragma once
// The paper's RigidBody (section 5.1): a behavior that is an entity's handle to its body in the World.
// Before the entity is added to a simulation the settings are kept in a BodyDef; afterwards every read and
// write goes to the world. SI units: kg, m, s, rad.

#include "physim/core/Body.hpp"
#include "physim/core/Joint.hpp"
#include "physim/core/MassData.hpp"
#include "physim/core/Math.hpp"
#include "physim/core/Shape.hpp"
#include "physim/framework/Behavior.hpp"

#include <optional>
#include <variant>
#include <vector>

namespace physim {

class World;

/// How addForce changes the body (the paper's ForceMode, as in Unity):
/// ACCELERATION m/s^2 and FORCE N act over the step (accumulated, cleared after it);
/// IMPULSE N s and VELOCITY m/s change the velocity at once (VELOCITY ignores mass).
enum class ForceMode { ACCELERATION, FORCE, IMPULSE, VELOCITY };

/// The paper's collision-detection modes (section 5.1): DISCRETE tests only where the body ends each step;
/// CONTINUOUS also finds contacts during the step, by the method below (docs/ccd.md).
enum class CollisionDetectionMode { DISCRETE, CONTINUOUS };
/// SAMPLED: the paper's loop over positions at steps of `precision` (fraction of the step); EXACT: time of
/// impact by conservative advancement (cannot miss a contact the sampling finds; gap below 1e-4 m).
enum class ContinuousMethod { SAMPLED, EXACT };

class RigidBody : public Behavior {
public:
    explicit RigidBody(Entity* parent = nullptr);

    // Mass data follow one rule before and after the entity is added to a simulation (physim/core/MassData.hpp):
    // the mass spread uniformly over the shape, the inertia about the centre of mass (the shape's centroid).
    double mass() const;         ///< kg; 0 means static (immovable), as in the paper
    double inv_mass() const;     ///< 1/kg; 0 for static bodies
    /// kg m^2 about the centre of mass; 0 for static and kinematic bodies. With fixed rotation the shape's
    /// inertia stays and inv_inertia() is 0.
    double inertia() const;
    double inv_inertia() const;
    /// World centre of mass, m: the point the body turns about. It is the body origin (position()) only when the
    /// shape's centroid is at the local origin.
    Vec2 centerOfMass() const;
    /// mass > 0: dynamic with that mass (inertia follows the shape). mass == 0: static (immovable), as in the
    /// paper. Throws std::invalid_argument for negative or NaN mass.
    void setMass(double mass);
    /// kg/m^2, > 0: mass and inertia from the shape's area and second moment. With several shapes (addShape):
    /// before the entity is added, the first shape's density (the others keep their own); afterwards the mean
    /// over all the shapes' area, their densities keeping their ratios (World::setMass).
    void setDensity(double density);

    Vec2 velocity() const;          ///< m/s
    void setVelocity(const Vec2& velocity);
    double angularVelocity() const; ///< rad/s, counter-clockwise
    void setAngularVelocity(double angularVelocity);
    bool useGravity() const;
    void setUseGravity(bool useGravity);
    double restitution() const;
    void setRestitution(double restitution);  ///< [0, 1]; a pair mixes them (WorldSettings: min)
    double staticFriction() const;
    void setStaticFriction(double mu);        ///< >= 0; a pair mixes them (WorldSettings: average)
    double dynamicFriction() const;
    void setDynamicFriction(double mu);       ///< >= 0; a pair mixes them (WorldSettings: average)
    /// Surface materials (docs/guide.md, "Surface materials"): set on every shape of the body once attached (on
    /// its first shape before), read from its first shape.
    double rollingResistance() const;
    void setRollingResistance(double coefficient);  ///< >= 0: rolling is resisted by C_rr N r (docs/collision.md)
    double tangentSpeed() const;
    void setTangentSpeed(double speed);  ///< m/s: a conveyor belt; positive runs clockwise (a top face towards +x)

    void addForce(const Vec2& value, ForceMode mode = ForceMode::FORCE);

    /// Sleeping (World settings): a body at rest for a while stops being simulated until something touches
    /// it or sets its motion. True before the entity is added.
    bool isAwake() const;
    void wakeUp();
    /// false: never sleeps (nor does anything resting on it).
    void setAllowSleep(bool allowSleep);
    bool allowSleep() const;

    /// Locks the rotation (Unity's freezeRotation): contacts and torques no longer turn the body.
    void setFixedRotation(bool fixedRotation);
    bool fixedRotation() const;
    /// Kinematic: moved by its velocity only; gravity, forces and contacts do not change it, and it pushes
    /// dynamic bodies as an infinitely heavy one would. setKinematic(false) makes it dynamic again with the
    /// mass of its shape at its density.
    void setKinematic(bool kinematic);
    bool isKinematic() const;

    /// Chooses how this body's collisions are found. precision (SAMPLED only, but always checked) in (0, 1];
    /// throws std::invalid_argument naming a bad value. Continuous detection acts on dynamic bodies.
    void setCollisionDetectionMode(CollisionDetectionMode mode, ContinuousMethod method = ContinuousMethod::EXACT,
                                   double precision = kDefaultPrecision);
    CollisionDetectionMode collisionDetectionMode() const;
    ContinuousMethod continuousMethod() const;  ///< EXACT while the mode is DISCRETE and nothing else was set
    double precision() const;
    /// The paper's checkDiscreteCollision: would this body, moved to `position` (m, same angle), touch `other`
    /// where it is now?
    bool checkDiscreteCollision(const Vec2& position, const RigidBody& other) const;
    /// The paper's checkContinuousCollision: moving from where it is to `position` (m, same angle), the first
    /// position where this body touches `other`, found by this body's method (SAMPLED with its precision, or
    /// EXACT; a DISCRETE body uses EXACT here); nullopt when it passes clear (or when EXACT can prove neither,
    /// ToiState::Failed).
    std::optional<Vec2> checkContinuousCollision(const Vec2& position, const RigidBody& other) const;

    /// The world body, once the entity has been added to a simulation; null before.
    BodyId bodyId() const { return id_; }
    bool attached() const { return world_ != nullptr; }

    /// The collision geometry of the body's first shape, with the body's material (Object sets it from its shape).
    void setGeometry(const Geometry& shape);
    /// The body's first shape is a chain (ground; the world builds it with World::createChain) with the body's
    /// material: no area, so the body is made static (setMass(0)); it may be made kinematic.
    void setChain(const std::vector<Vec2>& points, bool loop);
    /// One more shape, with its own material, in the body's frame (m, relative to the body origin): created with
    /// the body when the entity is added to a simulation, at once if it already was (World::createShape). The
    /// mass, centre of mass and inertia then come from all the shapes, before and after the body joins a world.
    void addShape(const ShapeDef& def);
    /// A chain's pieces as more shapes (World::createChain), kept and created as addShape's are.
    void addChain(const ChainDef& def);
    /// The body's shapes in its world, in the order added (the first shape or chain first); empty before the
    /// entity is added.
    std::vector<ShapeId> shapeIds() const;
    /// Used by the entity that owns this body (Object): create the body in `world`.
    void attach(World& world);
    void detach();
    /// Joins this body (the joint's body A) to `other` (body B) by a joint of the definition's kind: its bodyA and
    /// bodyB are filled in here, the rest is the definition's (World::createXJoint's rules and errors). Both
    /// entities must have been added to the same simulation (std::logic_error otherwise). The joint lives in the
    /// world (World::jointReactionForce, setJointMotor, destroyJoint ...); destroying either body destroys it.
    JointId join(RigidBody& other, DistanceJointDef def);
    JointId join(RigidBody& other, RevoluteJointDef def);
    JointId join(RigidBody& other, WeldJointDef def);
    JointId join(RigidBody& other, SpringJointDef def);
    JointId join(RigidBody& other, PulleyJointDef def);
    JointId join(RigidBody& other, PrismaticJointDef def);
    JointId join(RigidBody& other, WheelJointDef def);
    JointId join(RigidBody& other, MotorJointDef def);

    /// Which shapes this body collides with (Filter.hpp: category and mask bits, a group), for every shape it has:
    /// kept for the world before the entity is added, set in it at once afterwards (World::setFilter: acts at the
    /// next step). A shape added later keeps its own ShapeDef's or ChainDef's filter. filter() is the first shape's.
    void setFilter(const Filter& filter);
    Filter filter() const;
    /// true: every shape of the body is a sensor (physim/core/Sensor.hpp): it collides with nothing and reports
    /// what overlaps it (Simulation::onSensor, World::sensorEvents); shapes added later keep their own ShapeDef's
    /// isSensor. Allowed before and after the entity is added. isSensor: the first shape's.
    void setSensor(bool sensor);
    bool isSensor() const;

    /// The body origin, m (the point the shape's coordinates are relative to) and its angle, rad.
    Vec2 position() const;
    double angle() const;
    /// Places the body origin at `position` (m) with `angle` (rad): the body turns about its origin here.
    void setPose(const Vec2& position, double angle);

private:
    MassData pendingMassData() const;  // before attach: what the world will compute
    std::vector<Geometry> geometries() const;  // every shape's, body frame: the world's once attached
    void createMoreShapes();  // addShape's and addChain's, in the world

    World* world_ = nullptr;  // non-owning; the simulation owns the world and outlives attachment
    BodyId id_;
    BodyDef def_;
    double massOverride_ = -1.0;  // kg set before attach; < 0: from density
    std::optional<ChainDef> chain_;  // the first shape when it is a chain (def_.withShape false)
    /// Every shape after the first, in order, kept so that a body added again has them again.
    std::vector<std::variant<ShapeDef, ChainDef>> more_;
    ContinuousMethod method_ = ContinuousMethod::EXACT;  // kept while DISCRETE, so switching back restores it
};

}  // namespace physim
