#pragma once
// The physics world: owns every body's data and steps it. No SFML, no ROOT.
//
// One fixed step runs as three phases, so the framework can call the paper's entity hooks between them:
//   beginStep(dt)  forces -> velocities
//   collide()      broad phase -> narrow phase -> contact solve
//   finishStep()   continuous (time of impact, after the solve) -> velocities -> positions, position
//                  correction, sleep
// step(dt) runs all three. Each phase skips the stages the world's content does not call for.
// With settings().substeps = n > 1 every phase's work is done n times with dt / n: beginStep applies the
// first substep's forces, collide runs substeps 1 .. n-1 whole and the last one up to its solve, and
// finishStep moves the bodies by the last substep (docs/dynamics.md says why substeps).

#include "physim/core/Body.hpp"
#include "physim/core/Contact.hpp"
#include "physim/core/Joint.hpp"
#include "physim/core/StepProfile.hpp"
#include "physim/core/WorldSettings.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace physim {

struct BodyData;       // internal storage, src/core/BodyData.hpp
struct JointData;      // internal, src/core/DistanceJoint.hpp
class ContactSolver;  // internal, src/core/ContactSolver.hpp
class ContinuousStage;  // internal, src/core/ContinuousStage.hpp
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
    BodyId createBody(const BodyDef& def);
    void destroyBody(BodyId id);
    bool contains(BodyId id) const;
    std::size_t bodyCount() const;

    BodyType type(BodyId id) const;
    const Geometry& shape(BodyId id) const;
    Transform transform(BodyId id) const;
    Vec2 position(BodyId id) const;
    double angle(BodyId id) const;
    Vec2 velocity(BodyId id) const;
    double angularVelocity(BodyId id) const;
    double mass(BodyId id) const;         ///< kg; 0 for static and kinematic bodies (immovable)
    double inverseMass(BodyId id) const;  ///< 1/kg; 0 when immovable
    double inertia(BodyId id) const;      ///< kg m^2 about the centre of mass; 0 when it cannot rotate
    double inverseInertia(BodyId id) const;
    double restitution(BodyId id) const;
    double staticFriction(BodyId id) const;
    double dynamicFriction(BodyId id) const;
    bool useGravity(BodyId id) const;

    void setTransform(BodyId id, const Vec2& position, double angle);
    void setVelocity(BodyId id, const Vec2& velocity);
    void setAngularVelocity(BodyId id, double angularVelocity);
    void setUseGravity(BodyId id, bool useGravity);
    /// Restitution in [0, 1], friction coefficients >= 0 (throws std::invalid_argument naming a bad value).
    void setMaterial(BodyId id, double restitution, double staticFriction, double dynamicFriction);
    /// Sleeping (WorldSettings::enableSleep): a sleeping body is not simulated until touched by an awake body,
    /// or until a force, impulse, velocity, pose or type is set on it (each of those wakes it).
    bool isAwake(BodyId id) const;
    /// Wakes the body (true), or puts it to sleep now (false: it stops, and stays until something wakes it).
    void setAwake(BodyId id, bool awake);
    /// false: the body never sleeps, and neither does any island it touches. Wakes it.
    void setAllowSleep(BodyId id, bool allowSleep);
    bool allowSleep(BodyId id) const;
    /// Changes a body's type. Becoming static or kinematic stops it and makes it immovable by contacts;
    /// becoming dynamic gives it the mass of its shape at its density.
    void setType(BodyId id, BodyType type);
    /// Sets the mass (kg, > 0) of a dynamic body; inertia scales with it (same shape, uniform density).
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

    /// Force (N) at the centre of mass, accumulated until the end of the current step.
    void applyForce(BodyId id, const Vec2& force);
    /// Force (N) applied at a world point (m): also adds the torque r x F.
    void applyForceAtPoint(BodyId id, const Vec2& force, const Vec2& worldPoint);
    void applyTorque(BodyId id, double torque);
    /// Instant change of momentum (N s) at the centre of mass.
    void applyLinearImpulse(BodyId id, const Vec2& impulse);

    // --- joints -------------------------------------------------------------------------------------
    /// A rigid rod between two anchors. Throws std::invalid_argument for an unknown or repeated body, two
    /// immovable bodies, non-finite anchors or length, or a zero length. Destroying either body removes it.
    JointId createDistanceJoint(const DistanceJointDef& def);
    void destroyJoint(JointId id);
    bool contains(JointId id) const;
    std::size_t jointCount() const { return jointCount_; }
    /// The joint's rod length, m (distance joints).
    double jointLength(JointId id) const;
    /// A soft pull of a dynamic body's point towards a target (MouseJointDef). Throws std::invalid_argument
    /// naming the bad value: a body that is not live and dynamic, a non-finite target or anchor, maxForce or
    /// hertz not > 0, dampingRatio < 0. Wakes the body. Removed by destroyJoint, or with its body.
    JointId createMouseJoint(const MouseJointDef& def);
    /// Moves a mouse joint's target (m, finite) and wakes its body.
    void setMouseJointTarget(JointId id, const Vec2& target);
    JointType jointType(JointId id) const;
    /// World points, m: a distance joint's anchors on A and B; a mouse joint's grabbed point and its target.
    std::pair<Vec2, Vec2> jointAnchors(JointId id) const;
    /// The live joints and bodies, in slot order (for drawing and statistics).
    std::vector<JointId> jointIds() const;
    std::vector<BodyId> bodyIds() const;

    // --- stepping -----------------------------------------------------------------------------------
    void step(double dt);
    void beginStep(double dt);
    void collide();
    void finishStep();

    const std::vector<Manifold>& contacts() const { return contacts_; }
    const StepProfile& profile() const { return profile_; }
    const WorldSettings& settings() const { return settings_; }
    void setSettings(const WorldSettings& settings);
    /// Number of completed steps.
    std::uint64_t stepCount() const { return stepCount_; }

private:
    enum class Phase { Idle, Forces, Collided };

    BodyData& at(BodyId id);
    const BodyData& at(BodyId id) const;
    BodyData& requireDynamic(BodyId id, const char* what);
    BodyData& wake(BodyId id);  // at(id), woken: used by every setter that changes a body's motion
    void wakeTouchingSleepers();
    void activateJoints();
    const JointData& joint(JointId id) const;
    static bool isActive(const BodyData& b);
    void updateSleep();
    // One substep's parts (settings_.substeps of them per step, each of h_ seconds).
    void integrateForces();
    void detectAndSolve();
    void integrateAndCorrect();

    WorldSettings settings_;
    std::vector<BodyData> bodies_;            // slot per index; dead slots are on freeList_
    std::vector<std::uint32_t> freeList_;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;  // broad-phase output: slot index pairs
    std::vector<std::uint32_t> sweepOrder_;
    std::vector<std::uint32_t> islandParent_;  // sleep stage scratch: union-find over touching bodies
    std::vector<double> islandSleepTime_;   // broad-phase scratch, kept to avoid per-step allocation
    std::vector<Manifold> contacts_;
    std::vector<Manifold> previousContacts_;  // for warm starting
    std::unique_ptr<ContactSolver> solver_;
    std::vector<JointData> joints_;          // slot per index; dead slots are on jointFreeList_
    std::vector<std::uint32_t> jointFreeList_;
    std::size_t jointCount_ = 0;
    std::unique_ptr<ContinuousStage> continuous_;
    StepProfile profile_;
    std::size_t liveCount_ = 0;
    std::size_t movableCount_ = 0;  // dynamic + kinematic
    std::size_t dynamicCount_ = 0;
    std::size_t continuousCount_ = 0;  // bodies whose detection is not Discrete
    Phase phase_ = Phase::Idle;
    double dt_ = 0.0;
    double h_ = 0.0;  // substep, s
    std::uint64_t stepCount_ = 0;
};

}  // namespace physim
