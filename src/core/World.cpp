#include "physim/core/World.hpp"

#include "BodyData.hpp"
#include "BroadPhase.hpp"
#include "ContactSolver.hpp"
#include "ContinuousStage.hpp"
#include "DistanceJoint.hpp"
#include "Integrator.hpp"

#include "physim/core/Collide.hpp"
#include "physim/core/Validate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace physim {
namespace {

// Runs `work` as stage `s` only when `needed`, recording whether it ran and its wall-clock time.
template <class Work>
void runStage(StepProfile& profile, Stage s, bool needed, Work&& work) {
    if (!needed) return;
    const auto start = std::chrono::steady_clock::now();
    work();
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    profile.secondsOf(s) += elapsed.count();  // substeps add up
    profile.ran[static_cast<std::size_t>(s)] = true;
}

void validate(const BodyDef& def) {
    requireFinite("body position", def.position);
    requireFinite("body angle", def.angle);
    requireFinite("body velocity", def.velocity);
    requireFinite("body angular velocity", def.angularVelocity);
    if (def.type == BodyType::Dynamic) requirePositive("body density", def.density);
    requireInRange("body restitution", def.restitution, 0.0, 1.0);
    requireNonNegative("body static friction", def.staticFriction);
    requireNonNegative("body dynamic friction", def.dynamicFriction);
    validate(def.shape);
    checkPrecision(def.precision);
}

// Mass and inertia of a dynamic body with `mass` kg spread uniformly over its shape.
void assignMass(BodyData& b, double mass) {
    b.mass = mass;
    b.density = mass / b.unitMass.area;
    b.invMass = 1.0 / mass;
    const double density = mass / b.unitMass.area;
    // Inertia about the centre of mass: the shape's own second moment plus the parallel-axis term for a
    // shape whose centroid is offset from the body origin.
    b.inertia = density * b.unitMass.secondMoment + mass * b.unitMass.centroid.squaredNorm();
    b.invInertia = (b.fixedRotation || b.inertia <= 0.0) ? 0.0 : 1.0 / b.inertia;
}

// Takes a slot for a new element: a freed one if any, else a new one at the end. The slot is reset to a fresh,
// live element whose generation is one past the slot's last, so handles to what lived there before go stale.
template <class Data>
std::uint32_t takeSlot(std::vector<Data>& slots, std::vector<std::uint32_t>& freeList) {
    std::uint32_t index;
    if (!freeList.empty()) {
        index = freeList.back();
        freeList.pop_back();
    } else {
        index = static_cast<std::uint32_t>(slots.size());
        slots.emplace_back();
    }
    const std::uint32_t generation = slots[index].generation + 1;
    slots[index] = Data{};
    slots[index].generation = generation;
    slots[index].alive = true;
    return index;
}

}  // namespace

void validate(const WorldSettings& s) {
    requireFinite("gravity", s.gravity);
    if (s.velocityIterations < 1)
        throw std::invalid_argument("physim: velocityIterations must be >= 1, got " +
                                    std::to_string(s.velocityIterations));
    if (s.substeps < 1)
        throw std::invalid_argument("physim: substeps must be >= 1, got " + std::to_string(s.substeps));
    if (s.positionIterations < 0)
        throw std::invalid_argument("physim: positionIterations must be >= 0, got " +
                                    std::to_string(s.positionIterations));
    requireNonNegative("linearSlop", s.linearSlop);
    requireNonNegative("restitutionThreshold", s.restitutionThreshold);
    requireNonNegative("sleepLinearTolerance", s.sleepLinearTolerance);
    requireNonNegative("sleepAngularTolerance", s.sleepAngularTolerance);
    requirePositive("timeToSleep", s.timeToSleep);
    if (s.threads < 0 || s.threads > 256)
        throw std::invalid_argument("physim: threads must be in [0, 256] (0 = all hardware threads), got " +
                                    std::to_string(s.threads));
}

World::World(const WorldSettings& settings)
    : solver_(std::make_unique<ContactSolver>()), continuous_(std::make_unique<ContinuousStage>()) {
    setSettings(settings);
}
World::~World() = default;

void World::setContinuousSolver(std::shared_ptr<ContinuousSolver> solver) { continuous_->setSolver(std::move(solver)); }

const std::shared_ptr<ContinuousSolver>& World::continuousSolver() const { return continuous_->solver(); }
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

void World::setSettings(const WorldSettings& settings) {
    physim::validate(settings);
    settings_ = settings;
    if (!settings_.enableSleep)
        for (BodyData& b : bodies_) b.awake = true, b.sleepTime = 0.0;
}

// --- bodies ------------------------------------------------------------------------------------------

BodyId World::createBody(const BodyDef& def) {
    validate(def);
    const std::uint32_t index = takeSlot(bodies_, freeList_);
    BodyData& b = bodies_[index];
    b.type = def.type;
    b.xf.p = def.position;
    b.angle = def.angle;
    b.xf.q = Rotation::fromAngle(def.angle);
    b.shape = def.shape;
    b.unitMass = computeMassProperties(def.shape);
    b.restitution = def.restitution;
    b.staticFriction = def.staticFriction;
    b.dynamicFriction = def.dynamicFriction;
    b.useGravity = def.useGravity;
    b.fixedRotation = def.fixedRotation;
    b.allowSleep = def.allowSleep;
    b.detection = def.collisionDetection;
    b.precision = def.precision;
    if (def.type != BodyType::Static) {
        b.v = def.velocity;
        b.w = def.fixedRotation ? 0.0 : def.angularVelocity;
    }
    b.density = def.density;
    if (def.type == BodyType::Dynamic) assignMass(b, def.density * b.unitMass.area);

    ++liveCount_;
    if (b.movable()) ++movableCount_;
    if (b.type == BodyType::Dynamic) ++dynamicCount_;
    if (b.detection != CollisionDetection::Discrete) ++continuousCount_;
    return BodyId{index, b.generation};
}

void World::destroyBody(BodyId id) {
    BodyData& b = at(id);
    --liveCount_;
    if (b.movable()) --movableCount_;
    if (b.type == BodyType::Dynamic) --dynamicCount_;
    if (b.detection != CollisionDetection::Discrete) --continuousCount_;
    b.alive = false;
    freeList_.push_back(id.index);
    // Its joints go, and the bodies they held wake.
    for (std::uint32_t k = 0; k < joints_.size(); ++k) {
        JointData& j = joints_[k];
        if (!j.alive || (j.a != id.index && j.b != id.index)) continue;
        BodyData& other = bodies_[j.a == id.index ? j.b : j.a];
        other.awake = true, other.sleepTime = 0.0;
        j.alive = false;
        jointFreeList_.push_back(k);
        --jointCount_;
    }
    // Bodies that were resting on it must fall: wake everything whose box touches its box.
    const Aabb gone = computeAabb(b.shape, b.xf).fattened(settings_.linearSlop);
    for (BodyData& other : bodies_)
        if (other.alive && !other.awake && computeAabb(other.shape, other.xf).overlaps(gone))
            other.awake = true, other.sleepTime = 0.0;
    // Contacts that name the destroyed body must not be solved or warm-started again.
    auto names = [&](const Manifold& m) { return m.bodyA == id || m.bodyB == id; };
    contacts_.erase(std::remove_if(contacts_.begin(), contacts_.end(), names), contacts_.end());
    previousContacts_.erase(std::remove_if(previousContacts_.begin(), previousContacts_.end(), names),
                            previousContacts_.end());
}

bool World::contains(BodyId id) const {
    return !id.isNull() && id.index < bodies_.size() && bodies_[id.index].alive &&
           bodies_[id.index].generation == id.generation;
}

std::size_t World::bodyCount() const { return liveCount_; }

BodyData& World::at(BodyId id) {
    return const_cast<BodyData&>(static_cast<const World&>(*this).at(id));
}

const BodyData& World::at(BodyId id) const {
    if (!contains(id))
        throw std::invalid_argument("physim: body id (index " + std::to_string(id.index) + ", generation " +
                                    std::to_string(id.generation) + ") is not a live body of this world");
    return bodies_[id.index];
}

BodyData& World::requireDynamic(BodyId id, const char* what) {
    BodyData& b = at(id);
    if (b.type != BodyType::Dynamic)
        throw std::invalid_argument(std::string("physim: ") + what + " needs a dynamic body");
    return b;
}

BodyType World::type(BodyId id) const { return at(id).type; }
const Geometry& World::shape(BodyId id) const { return at(id).shape; }
Transform World::transform(BodyId id) const { return at(id).xf; }
Vec2 World::position(BodyId id) const { return at(id).xf.p; }
double World::angle(BodyId id) const { return at(id).angle; }
Vec2 World::velocity(BodyId id) const { return at(id).v; }
double World::angularVelocity(BodyId id) const { return at(id).w; }
double World::mass(BodyId id) const { return at(id).mass; }
double World::inverseMass(BodyId id) const { return at(id).invMass; }
double World::inertia(BodyId id) const { return at(id).inertia; }
double World::inverseInertia(BodyId id) const { return at(id).invInertia; }
double World::restitution(BodyId id) const { return at(id).restitution; }
double World::staticFriction(BodyId id) const { return at(id).staticFriction; }
double World::dynamicFriction(BodyId id) const { return at(id).dynamicFriction; }
bool World::useGravity(BodyId id) const { return at(id).useGravity; }

void World::setTransform(BodyId id, const Vec2& position, double angle) {
    requireFinite("body position", position);
    requireFinite("body angle", angle);
    BodyData& b = wake(id);
    b.xf.p = position;
    b.angle = angle;
    b.xf.q = Rotation::fromAngle(angle);
}

void World::setVelocity(BodyId id, const Vec2& velocity) {
    requireFinite("body velocity", velocity);
    BodyData& b = wake(id);
    if (b.movable()) b.v = velocity;
}

void World::setAngularVelocity(BodyId id, double angularVelocity) {
    requireFinite("body angular velocity", angularVelocity);
    BodyData& b = wake(id);
    if (b.movable() && !b.fixedRotation) b.w = angularVelocity;
}

void World::setUseGravity(BodyId id, bool useGravity) { at(id).useGravity = useGravity; }

void World::setMaterial(BodyId id, double restitution, double staticFriction, double dynamicFriction) {
    requireInRange("body restitution", restitution, 0.0, 1.0);
    requireNonNegative("body static friction", staticFriction);
    requireNonNegative("body dynamic friction", dynamicFriction);
    BodyData& b = at(id);
    b.restitution = restitution;
    b.staticFriction = staticFriction;
    b.dynamicFriction = dynamicFriction;
}

void World::setType(BodyId id, BodyType type) {
    BodyData& b = wake(id);
    if (b.type == type) return;
    if (b.movable()) --movableCount_;
    if (b.type == BodyType::Dynamic) --dynamicCount_;
    b.type = type;
    if (b.movable()) ++movableCount_;
    if (type == BodyType::Dynamic) {
        ++dynamicCount_;
        assignMass(b, b.density * b.unitMass.area);
    } else {
        b.mass = b.inertia = b.invMass = b.invInertia = 0.0;
    }
    if (type == BodyType::Static) {
        b.v.setZero();
        b.w = 0.0;
    }
}

void World::setMass(BodyId id, double mass) {
    requirePositive("body mass", mass);
    assignMass(requireDynamic(id, "setMass"), mass);
    wake(id);
}

void World::setFixedRotation(BodyId id, bool fixedRotation) {
    BodyData& b = wake(id);
    b.fixedRotation = fixedRotation;
    if (b.type == BodyType::Dynamic) assignMass(b, b.mass);  // recomputes the inverse inertia
    if (fixedRotation) b.w = 0.0;
}

bool World::fixedRotation(BodyId id) const { return at(id).fixedRotation; }

BodyData& World::wake(BodyId id) {
    BodyData& b = at(id);
    b.awake = true;
    b.sleepTime = 0.0;
    return b;
}

bool World::isAwake(BodyId id) const { return at(id).awake; }

void World::setAwake(BodyId id, bool awake) {
    BodyData& b = at(id);
    if (awake || b.type != BodyType::Dynamic || !settings_.enableSleep) {
        wake(id);
        return;
    }
    b.awake = false;
    b.v.setZero();
    b.w = 0.0;
}

void World::setAllowSleep(BodyId id, bool allowSleep) { wake(id).allowSleep = allowSleep; }
bool World::allowSleep(BodyId id) const { return at(id).allowSleep; }

void World::setCollisionDetection(BodyId id, CollisionDetection mode, double precision) {
    checkPrecision(precision);
    BodyData& b = at(id);
    if (b.detection != CollisionDetection::Discrete) --continuousCount_;
    if (mode != CollisionDetection::Discrete) ++continuousCount_;
    b.detection = mode;
    b.precision = precision;
}

CollisionDetection World::collisionDetection(BodyId id) const { return at(id).detection; }
double World::collisionPrecision(BodyId id) const { return at(id).precision; }

void World::applyForce(BodyId id, const Vec2& force) {
    requireFinite("force", force);
    wake(id).force += force;
}

void World::applyForceAtPoint(BodyId id, const Vec2& force, const Vec2& worldPoint) {
    requireFinite("force", force);
    requireFinite("force application point", worldPoint);
    BodyData& b = wake(id);
    b.force += force;
    b.torque += cross(worldPoint - b.xf.p, force);
}

void World::applyTorque(BodyId id, double torque) {
    requireFinite("torque", torque);
    wake(id).torque += torque;
}

void World::applyLinearImpulse(BodyId id, const Vec2& impulse) {
    requireFinite("impulse", impulse);
    BodyData& b = wake(id);
    b.v += b.invMass * impulse;
}

// --- stepping ----------------------------------------------------------------------------------------

void World::step(double dt) {
    beginStep(dt);
    collide();
    finishStep();
}

void World::beginStep(double dt) {
    // Above a second per step is a unit mistake (milliseconds passed as seconds), not a simulation.
    requireInRange("time step dt (s)", dt, 0.0, 1.0);
    if (dt == 0.0) throw std::invalid_argument("physim: time step dt (s) must be > 0, got 0");
    if (phase_ != Phase::Idle) throw std::logic_error("physim: beginStep called before the last step finished");
    dt_ = dt;
    h_ = dt / settings_.substeps;
    profile_ = StepProfile{};
    integrateForces();
    phase_ = Phase::Forces;
}

void World::collide() {
    if (phase_ != Phase::Forces) throw std::logic_error("physim: collide must follow beginStep");
    // Substeps 1 .. n-1 run whole here; the last one stops after its solve, so the framework's
    // checkCollisions sees that substep's contacts, and finishStep moves the bodies.
    for (int k = 0; k < settings_.substeps; ++k) {
        if (k > 0) {
            integrateAndCorrect();
            integrateForces();
        }
        detectAndSolve();
    }
    phase_ = Phase::Collided;
}

void World::finishStep() {
    if (phase_ != Phase::Collided) throw std::logic_error("physim: finishStep must follow collide");
    integrateAndCorrect();
    runStage(profile_, Stage::Sleep, settings_.enableSleep && dynamicCount_ > 0, [&] { updateSleep(); });
    clearForces(bodies_);
    ++stepCount_;
    phase_ = Phase::Idle;
}

// An awake body that can move: pairs with one are collided; a sleeping body touched by one wakes. A kinematic
// body at rest never wakes a sleeper.
bool World::isActive(const BodyData& b) {
    if (!b.alive || !b.awake || b.type == BodyType::Static) return false;
    return b.type == BodyType::Dynamic || b.v != Vec2::Zero() || b.w != 0.0;
}

// A sleeping island touched by an active body wakes whole: wake each sleeper in contact with an active body,
// repeated until nothing changes, so the wake travels through a resting pile in one step.
void World::wakeTouchingSleepers() {
    for (bool woke = true; woke;) {
        woke = false;
        for (const auto& [a, b] : pairs_) {
            BodyData& A = bodies_[a];
            BodyData& B = bodies_[b];
            BodyData* sleeper = (!A.awake && isActive(B)) ? &A : (!B.awake && isActive(A)) ? &B : nullptr;
            if (!sleeper) continue;
            if (physim::collide(A.shape, A.xf, B.shape, B.xf).pointCount == 0) continue;
            sleeper->awake = true;
            sleeper->sleepTime = 0.0;
            woke = true;
        }
    }
}

// Islands are the dynamic bodies joined by the last substep's contacts (static and kinematic bodies do not join
// them). An island sleeps when every body in it has stayed below the speed tolerances for timeToSleep; a body
// that may not sleep, or a moving kinematic body touching the island, keeps it awake.
void World::updateSleep() {
    const std::size_t n = bodies_.size();
    islandParent_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) islandParent_[i] = i;
    auto find = [&](std::uint32_t i) {
        while (islandParent_[i] != i) i = islandParent_[i] = islandParent_[islandParent_[i]];
        return i;
    };
    auto canSleep = [](const BodyData& b) { return b.alive && b.awake && b.type == BodyType::Dynamic; };

    for (BodyData& b : bodies_) {
        if (!canSleep(b)) continue;
        const bool still = b.v.norm() <= settings_.sleepLinearTolerance &&
                           std::abs(b.w) <= settings_.sleepAngularTolerance;
        b.sleepTime = (b.allowSleep && still) ? b.sleepTime + dt_ : 0.0;
    }
    for (const Manifold& m : contacts_) {
        const std::uint32_t a = m.bodyA.index, b = m.bodyB.index;
        if (bodies_[a].type == BodyType::Dynamic && bodies_[b].type == BodyType::Dynamic)
            islandParent_[find(a)] = find(b);
    }
    for (const JointData& j : joints_)
        if (j.alive && bodies_[j.a].type == BodyType::Dynamic && bodies_[j.b].type == BodyType::Dynamic)
            islandParent_[find(j.a)] = find(j.b);
    // An island's sleep time is its least rested body's; a moving kinematic body touching it resets it.
    islandSleepTime_.assign(n, INFINITY);
    for (std::uint32_t i = 0; i < n; ++i)
        if (canSleep(bodies_[i])) islandSleepTime_[find(i)] = std::min(islandSleepTime_[find(i)], bodies_[i].sleepTime);
    for (const Manifold& m : contacts_) {
        const std::uint32_t a = m.bodyA.index, b = m.bodyB.index;
        const bool kinematicA = bodies_[a].type == BodyType::Kinematic;
        const bool kinematicB = bodies_[b].type == BodyType::Kinematic;
        if (kinematicA && isActive(bodies_[a])) islandSleepTime_[find(b)] = 0.0;
        if (kinematicB && isActive(bodies_[b])) islandSleepTime_[find(a)] = 0.0;
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        BodyData& b = bodies_[i];
        if (!canSleep(b) || islandSleepTime_[find(i)] < settings_.timeToSleep) continue;
        b.awake = false;
        b.v.setZero();
        b.w = 0.0;
    }
}

// A joint is solved while one of its bodies is awake and can move; a sleeper held by an active body wakes
// (repeated, so the wake runs along a chain in one step).
void World::activateJoints() {
    for (bool woke = true; woke;) {
        woke = false;
        for (JointData& j : joints_) {
            if (!j.alive) continue;
            BodyData& A = bodies_[j.a];
            BodyData& B = bodies_[j.b];
            BodyData* sleeper = (!A.awake && isActive(B)) ? &A : (!B.awake && isActive(A)) ? &B : nullptr;
            if (!sleeper) continue;
            sleeper->awake = true;
            sleeper->sleepTime = 0.0;
            woke = true;
        }
    }
    for (JointData& j : joints_) j.active = j.alive && (isActive(bodies_[j.a]) || isActive(bodies_[j.b]));
}

// --- joints ------------------------------------------------------------------------------------------

JointId World::createDistanceJoint(const DistanceJointDef& def) {
    const BodyData& A = at(def.bodyA);
    const BodyData& B = at(def.bodyB);
    if (def.bodyA == def.bodyB) throw std::invalid_argument("physim: a distance joint needs two different bodies");
    if (A.type != BodyType::Dynamic && B.type != BodyType::Dynamic)
        throw std::invalid_argument("physim: a distance joint needs at least one dynamic body");
    requireFinite("joint anchor A", def.localAnchorA);
    requireFinite("joint anchor B", def.localAnchorB);
    requireFinite("joint length", def.length);
    double length = def.length;
    if (length <= 0.0) length = (B.xf.apply(def.localAnchorB) - A.xf.apply(def.localAnchorA)).norm();
    if (!(length > 1e-9))
        throw std::invalid_argument("physim: distance joint length must be > 0 m, got " + std::to_string(length));
    const std::uint32_t index = takeSlot(joints_, jointFreeList_);
    JointData& j = joints_[index];
    j.a = def.bodyA.index;
    j.b = def.bodyB.index;
    j.localA = def.localAnchorA;
    j.localB = def.localAnchorB;
    j.length = length;
    ++jointCount_;
    wake(def.bodyA);
    wake(def.bodyB);
    return JointId{index, j.generation};
}

bool World::contains(JointId id) const {
    return !id.isNull() && id.index < joints_.size() && joints_[id.index].alive &&
           joints_[id.index].generation == id.generation;
}

const JointData& World::joint(JointId id) const {
    if (!contains(id))
        throw std::invalid_argument("physim: joint id (index " + std::to_string(id.index) +
                                    ") is not a live joint of this world");
    return joints_[id.index];
}

void World::destroyJoint(JointId id) {
    const JointData& j = joint(id);
    bodies_[j.a].awake = bodies_[j.b].awake = true;
    joints_[id.index].alive = false;
    jointFreeList_.push_back(id.index);
    --jointCount_;
}

double World::jointLength(JointId id) const {
    const JointData& j = joint(id);
    if (j.type != JointType::Distance) throw std::invalid_argument("physim: jointLength needs a distance joint");
    return j.length;
}

JointId World::createMouseJoint(const MouseJointDef& def) {
    requireDynamic(def.body, "a mouse joint");
    requireFinite("mouse joint target", def.target);
    requireFinite("mouse joint local anchor", def.localAnchor);
    requirePositive("mouse joint maxForce (N)", def.maxForce);
    requirePositive("mouse joint hertz", def.hertz);
    requireNonNegative("mouse joint dampingRatio", def.dampingRatio);
    const std::uint32_t index = takeSlot(joints_, jointFreeList_);
    JointData& j = joints_[index];
    j.type = JointType::Mouse;
    j.a = j.b = def.body.index;
    j.mouse.target = def.target;
    j.mouse.localAnchor = def.localAnchor;
    j.mouse.maxForce = def.maxForce;
    j.mouse.hertz = def.hertz;
    j.mouse.dampingRatio = def.dampingRatio;
    ++jointCount_;
    wake(def.body);
    return JointId{index, j.generation};
}

void World::setMouseJointTarget(JointId id, const Vec2& target) {
    requireFinite("mouse joint target", target);
    if (joint(id).type != JointType::Mouse)
        throw std::invalid_argument("physim: setMouseJointTarget needs a mouse joint");
    JointData& j = joints_[id.index];
    j.mouse.target = target;
    bodies_[j.a].awake = true, bodies_[j.a].sleepTime = 0.0;
}

JointType World::jointType(JointId id) const { return joint(id).type; }

std::pair<Vec2, Vec2> World::jointAnchors(JointId id) const {
    const JointData& j = joint(id);
    if (j.type == JointType::Mouse) return {bodies_[j.a].xf.apply(j.mouse.localAnchor), j.mouse.target};
    return {bodies_[j.a].xf.apply(j.localA), bodies_[j.b].xf.apply(j.localB)};
}

std::vector<JointId> World::jointIds() const {
    std::vector<JointId> ids;
    for (std::uint32_t i = 0; i < joints_.size(); ++i)
        if (joints_[i].alive) ids.push_back(JointId{i, joints_[i].generation});
    return ids;
}

std::vector<BodyId> World::bodyIds() const {
    std::vector<BodyId> ids;
    for (std::uint32_t i = 0; i < bodies_.size(); ++i)
        if (bodies_[i].alive) ids.push_back(BodyId{i, bodies_[i].generation});
    return ids;
}

void World::integrateForces() {
    runStage(profile_, Stage::Forces, dynamicCount_ > 0,
             [&] { integrateVelocities(bodies_, settings_.gravity, h_); });
}

void World::detectAndSolve() {
    previousContacts_.swap(contacts_);
    contacts_.clear();
    pairs_.clear();

    runStage(profile_, Stage::BroadPhase, movableCount_ > 0 && liveCount_ >= 2,
             [&] { findCandidatePairs(bodies_, pairs_, sweepOrder_); });

    runStage(profile_, Stage::NarrowPhase, !pairs_.empty(), [&] {
        if (settings_.enableSleep) wakeTouchingSleepers();
        std::size_t previous = 0;  // both lists are sorted by (a, b): match them in one pass
        for (const auto& [a, b] : pairs_) {
            const BodyData& A = bodies_[a];
            const BodyData& B = bodies_[b];
            if (!isActive(A) && !isActive(B)) continue;  // asleep against asleep or static: nothing happens
            Manifold m = physim::collide(A.shape, A.xf, B.shape, B.xf);
            if (m.pointCount == 0) continue;
            m.bodyA = BodyId{a, A.generation};
            m.bodyB = BodyId{b, B.generation};
            // Warm start: carry the last substep's impulses over to points with the same feature id.
            while (previous < previousContacts_.size() &&
                   std::make_pair(previousContacts_[previous].bodyA.index,
                                  previousContacts_[previous].bodyB.index) < std::make_pair(a, b))
                ++previous;
            if (previous < previousContacts_.size() && previousContacts_[previous].bodyA == m.bodyA &&
                previousContacts_[previous].bodyB == m.bodyB) {
                const Manifold& old = previousContacts_[previous];
                for (int i = 0; i < m.pointCount; ++i)
                    for (int j = 0; j < old.pointCount; ++j)
                        if (m.points[i].id == old.points[j].id) {
                            m.points[i].normalImpulse = old.points[j].normalImpulse;
                            m.points[i].tangentImpulse = old.points[j].tangentImpulse;
                        }
            }
            contacts_.push_back(m);
        }
    });
    profile_.candidatePairs = pairs_.size();
    profile_.manifolds = contacts_.size();

    runStage(profile_, Stage::Solve, !contacts_.empty() || jointCount_ > 0, [&] {
        if (jointCount_ > 0) {
            activateJoints();
            prepareJoints(bodies_, joints_, h_);
            for (JointData& j : joints_)
                if (j.alive && j.active && j.type == JointType::Mouse) prepareMouseJoint(bodies_[j.a], j.mouse, h_);
        }
        if (!contacts_.empty()) solver_->prepare(bodies_, contacts_, settings_);
        for (int i = 0; i < settings_.velocityIterations; ++i) {
            if (jointCount_ > 0) solveJointVelocities(bodies_, joints_);
            for (JointData& j : joints_)
                if (j.alive && j.active && j.type == JointType::Mouse) solveMouseJoint(bodies_[j.a], j.mouse);
            if (!contacts_.empty()) solver_->solveVelocities(bodies_, contacts_);
        }
    });
}

void World::integrateAndCorrect() {
    // Continuous detection runs here, after the substep's solve, so the velocities it sweeps are final
    // (ContinuousStage.hpp); it sweeps this substep's motion, h_.
    runStage(profile_, Stage::Continuous, continuousCount_ > 0,
             [&] { continuous_->findImpacts(bodies_, h_, settings_); });
    runStage(profile_, Stage::Integrate, movableCount_ > 0, [&] {
        integratePositions(bodies_, h_);
        if (continuousCount_ > 0) continuous_->placeBodies(bodies_);  // hit bodies end where their impacts left them
        for (int i = 0; i < settings_.positionIterations; ++i) {
            if (jointCount_ > 0) correctJointPositions(bodies_, joints_);
            if (!contacts_.empty())
                solver_->correctPositions(bodies_, contacts_, settings_,
                                          continuousCount_ > 0 ? &continuous_->placed() : nullptr);
        }
    });
}

}  // namespace physim
