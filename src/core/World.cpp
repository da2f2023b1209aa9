// The World's public API: bodies and settings, checked at the boundary, and step() running the stages. Joints:
// WorldJoints.cpp and joints/; effects: WorldEffects.cpp.

#include "physim/core/World.hpp"

#include "Slots.hpp"
#include "WorldImpl.hpp"
#include "shapes/ShapeKinds.hpp"

#include "physim/core/Collide.hpp"
#include "physim/core/MassData.hpp"
#include "physim/core/Validate.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>

namespace physim {
namespace {

template <class Work>
void runStage(StepProfile& profile, Stage s, bool needed, Work&& work) {
    if (!needed) return;
    const auto start = std::chrono::steady_clock::now();
    work();
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    profile.secondsOf(s) += elapsed.count();
    profile.ran[static_cast<std::size_t>(s)] = true;
}

// The body's first shape, from the shape fields of its definition.
ShapeDef firstShapeDef(const BodyDef& def) {
    ShapeDef shape;
    shape.geometry = def.shape;
    shape.density = def.density;
    shape.restitution = def.restitution;
    shape.staticFriction = def.staticFriction;
    shape.dynamicFriction = def.dynamicFriction;
    shape.filter = def.filter;
    shape.isSensor = def.isSensor;
    shape.rollingResistance = def.rollingResistance;
    shape.tangentSpeed = def.tangentSpeed;
    return shape;
}

void requireBodyType(BodyType type) {
    if (type != BodyType::Static && type != BodyType::Kinematic && type != BodyType::Dynamic)
        throw std::invalid_argument("physim: body type must be Static, Kinematic or Dynamic, got " +
                                    std::to_string(static_cast<int>(type)));
}

void requireDetection(CollisionDetection mode) {
    if (mode != CollisionDetection::Discrete && mode != CollisionDetection::ContinuousSampled &&
        mode != CollisionDetection::ContinuousExact)
        throw std::invalid_argument("physim: collision detection must be Discrete, ContinuousSampled or "
                                    "ContinuousExact, got " + std::to_string(static_cast<int>(mode)));
}

void validate(const BodyDef& def) {
    requireBodyType(def.type);
    requireDetection(def.collisionDetection);
    requireWithin("body position", def.position, kMaxCoordinate);
    requireFinite("body angle", def.angle);
    requireWithin("body velocity", def.velocity, kMaxSpeed);
    requireWithin("body angular velocity", def.angularVelocity, kMaxSpeed);
    if (def.type == BodyType::Dynamic) requirePositive("body density", def.density);
    else requireNonNegative("body density", def.density);
    requireInRange("body restitution", def.restitution, 0.0, 1.0);
    requireNonNegative("body static friction", def.staticFriction);
    requireNonNegative("body dynamic friction", def.dynamicFriction);
    requireNonNegative("body rolling resistance", def.rollingResistance);
    requireWithin("body tangent speed", def.tangentSpeed, kMaxSpeed);
    requireFinite("body gravity scale", def.gravityScale);
    validate(def.drag);
    if (def.withShape) validate(def.shape);
    else if (def.type == BodyType::Dynamic)
        throw std::invalid_argument("physim: a dynamic body needs a shape (BodyDef::withShape is false)");
    checkPrecision(def.precision);
}

}  // namespace

void assignMass(BodyData& b, double mass) {
    requireInRange("body mass (kg)", mass, kMinMass, kMaxMass);
    const MassData data = massDataForMass(b.unitMass, mass);
    requireInRange("body inertia (kg m^2, from the mass and shape)", data.inertia, kMinInertia,
                   std::numeric_limits<double>::max());
    b.mass = mass;
    b.density = data.density;
    b.invMass = 1.0 / mass;
    b.inertia = data.inertia;
    b.invInertia = b.fixedRotation ? 0.0 : 1.0 / data.inertia;
}

void clearMass(BodyData& b) { b.mass = b.inertia = b.invMass = b.invInertia = 0.0; }


void validate(const WorldSettings& s) {
    requireFinite("gravity", s.gravity);
    auto requireCount = [](const char* name, int value, int lo, int hi) {
        if (value < lo || value > hi)
            throw std::invalid_argument(std::string("physim: ") + name + " must be in [" + std::to_string(lo) +
                                        ", " + std::to_string(hi) + "], got " + std::to_string(value));
    };
    requireCount("substeps", s.substeps, 1, WorldSettings::maxSubsteps);
    requireCount("velocityIterations", s.velocityIterations, 1, WorldSettings::maxIterations);
    requireCount("relaxIterations", s.relaxIterations, 0, WorldSettings::maxIterations);
    requireCount("threads", s.threads, 0, 256);
    requirePositive("contactHertz", s.contactHertz);
    requireNonNegative("contactDampingRatio", s.contactDampingRatio);
    requirePositive("contactPushMaxVelocity", s.contactPushMaxVelocity);
    requirePositive("jointHertz", s.jointHertz);
    requireNonNegative("jointDampingRatio", s.jointDampingRatio);
    if (!(s.directChainMassRatio >= 1.0))
        throw std::invalid_argument("physim: directChainMassRatio must be >= 1 (infinity: no direct chains), got " +
                                    std::to_string(s.directChainMassRatio));
    requireNonNegative("linearSlop", s.linearSlop);
    requireNonNegative("restitutionThreshold", s.restitutionThreshold);
    requireNonNegative("impactSpeedThreshold", s.impactSpeedThreshold);
    requireNonNegative("sleepLinearTolerance", s.sleepLinearTolerance);
    requireNonNegative("sleepAngularTolerance", s.sleepAngularTolerance);
    requirePositive("timeToSleep", s.timeToSleep);
    auto requireMixing = [](const char* name, MixingRule rule) {
        if (rule != MixingRule::Average && rule != MixingRule::GeometricMean && rule != MixingRule::Min &&
            rule != MixingRule::Max && rule != MixingRule::Multiply)
            throw std::invalid_argument(std::string("physim: ") + name +
                                        " must be Average, GeometricMean, Min, Max or Multiply, got " +
                                        std::to_string(static_cast<int>(rule)));
    };
    requireMixing("frictionMixing", s.frictionMixing);
    requireMixing("restitutionMixing", s.restitutionMixing);
}

// --- WorldImpl helpers ---------------------------------------------------------------------------------

void WorldImpl::requireNotStepping(const char* call) const {
    if (stepping) throw std::logic_error(std::string("physim: World::") + call + " called during the world's step");
}

void WorldImpl::wakeOverlapping(const Aabb& box) {
    found.clear();
    broadPhase.query(box, [&](std::uint32_t shape) {
        found.push_back(shapes[shape].body);
        return true;
    });
    std::sort(found.begin(), found.end());
    for (const std::uint32_t body : found)
        if (bodies[body].type == BodyType::Dynamic && !bodies[body].awake()) wakeBody(body);
}

// --- World -------------------------------------------------------------------------------------------

World::World(const WorldSettings& settings) : impl_(std::make_unique<WorldImpl>()) { setSettings(settings); }
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

void World::setSettings(const WorldSettings& settings) {
    physim::validate(settings);
    impl_->requireNotStepping("setSettings");
    const bool sleepWasOn = impl_->settings.enableSleep;
    const bool remix = settings.frictionMixing != impl_->settings.frictionMixing ||
                       settings.restitutionMixing != impl_->settings.restitutionMixing;
    impl_->settings = settings;
    if (remix) impl_->remixContacts();
    impl_->executor.setThreads(settings.threads);
    impl_->solver.layoutChanged();  // the rows' groups depend on the thread count
    if (!settings.enableSleep) {
        for (std::uint32_t i = 0; i < impl_->bodies.size(); ++i)
            if (impl_->bodies[i].alive) impl_->wakeBody(i);
        impl_->rebuildIslands();  // clears them: no island bookkeeping while sleep is off
    } else if (!sleepWasOn || impl_->islands.empty()) {
        impl_->rebuildIslands();
    }
}

const WorldSettings& World::settings() const { return impl_->settings; }
const StepProfile& World::profile() const { return impl_->profile; }
const ContactEvents& World::contactEvents() const { return impl_->events; }
std::uint64_t World::stepCount() const { return impl_->stepCount; }
std::size_t World::awakeBodyCount() const { return impl_->awake.size(); }

void World::setContinuousSolver(std::shared_ptr<ContinuousSolver> solver) {
    impl_->requireNotStepping("setContinuousSolver");
    impl_->continuous.setSolver(std::move(solver));
}
const std::shared_ptr<ContinuousSolver>& World::continuousSolver() const { return impl_->continuous.solver(); }

// --- bodies ------------------------------------------------------------------------------------------

BodyId World::createBody(const BodyDef& def) {
    validate(def);
    WorldImpl& w = *impl_;
    w.requireNotStepping("createBody");
    BodyData massed;  // the mass is checked before a slot is taken, so a refused body leaves no trace
    if (def.withShape) massed.unitMass = computeMassProperties(def.shape);
    massed.fixedRotation = def.fixedRotation;
    if (def.type == BodyType::Dynamic) assignMass(massed, def.density * massed.unitMass.area);
    const std::uint32_t index = takeSlot(w.bodies, w.freeBodies);
    BodyData& b = w.bodies[index];
    b.type = def.type;
    if (def.withShape) {
        const std::uint32_t s = takeSlot(w.shapes, w.freeShapes);
        assignShape(w.shapes[s], index, firstShapeDef(def), massed.unitMass);
        b.shapeHead = b.shapeTail = static_cast<std::int32_t>(s);
        b.shapeCount = 1;
        ++w.shapeLiveCount;
    }
    b.xf = {def.position, Rotation::fromAngle(def.angle)};
    b.angle = def.angle;
    b.useGravity = def.useGravity;
    b.gravityScale = def.gravityScale;
    b.fixedRotation = def.fixedRotation;
    b.allowSleep = def.allowSleep;
    b.detection = def.collisionDetection;
    b.precision = def.precision;
    b.density = def.density;
    w.updateMass(index);  // mass, centre, extent and core radius from its shape: the mass was checked above
    if (def.type != BodyType::Static) {
        b.v = def.velocity;
        b.w = def.fixedRotation ? 0.0 : def.angularVelocity;
    }
    w.updateBoxes(b);
    b.collides = def.collides;
    if (def.collides) w.createProxies(index);
    if (def.withShape && def.isSensor) w.sensors.add(static_cast<std::uint32_t>(b.shapeHead));
    w.addAwakeBody(index);
    if (def.type == BodyType::Static) w.wakeShapesOverlapping(index);
    if (def.type == BodyType::Dynamic && w.settings.enableSleep) w.createIsland(index);
    w.setDrag(index, def.drag);
    if (def.attracting) {
        b.attracting = true;
        w.effects.gravitation.add(index);
    }

    w.touched.push_back(index);
    ++w.shapeRevision;
    ++w.liveCount;
    if (b.type == BodyType::Dynamic) ++w.dynamicCount;
    if (b.detection != CollisionDetection::Discrete) ++w.continuousCount;
    w.touchingValid = false;
    const BodyId id{index, b.generation};
    if (!def.awake) setAwake(id, false);  // created asleep (a dynamic body in a world that sleeps: else no effect)
    return id;
}

void World::destroyBody(BodyId id) {
    WorldImpl& w = *impl_;
    at(id);
    w.requireNotStepping("destroyBody");
    const std::uint32_t index = id.index;
    // Its joints go, and the bodies they held wake.
    while (w.bodies[index].jointHead != kNullIndex) {
        const std::uint32_t j = static_cast<std::uint32_t>(w.bodies[index].jointHead >> 1);
        destroyJoint(JointId{j, w.joints[j].generation});
    }
    // Its contacts go; whatever rested on it wakes and falls.
    while (w.bodies[index].contactHead != kNullIndex)
        w.destroyContact(static_cast<std::uint32_t>(w.bodies[index].contactHead >> 1), true);
    BodyData& b = w.bodies[index];
    w.removeFromIsland(index);
    w.removeAwakeBody(index);
    w.destroyProxies(index);
    w.forEachShape(b, [&](std::uint32_t slot, ShapeData& shape) {
        if (shape.sensor) w.sensors.remove(slot);
        shape.alive = false;
        w.freeShapes.push_back(slot);
        --w.shapeLiveCount;
    });
    b.shapeHead = b.shapeTail = kNullIndex;
    b.shapeCount = 0;
    w.effects.bodyDestroyed(index);
    --w.liveCount;
    if (b.type == BodyType::Dynamic) --w.dynamicCount;
    if (b.detection != CollisionDetection::Discrete) --w.continuousCount;
    b.alive = false;
    ++w.shapeRevision;
    w.freeBodies.push_back(index);
    w.touchingValid = false;
}

bool World::contains(BodyId id) const {
    const auto& bodies = impl_->bodies;
    return !id.isNull() && id.index < bodies.size() && bodies[id.index].alive &&
           bodies[id.index].generation == id.generation;
}

std::size_t World::bodyCount() const { return impl_->liveCount; }

std::vector<BodyId> World::bodies() const {
    std::vector<BodyId> ids;
    ids.reserve(impl_->liveCount);
    for (std::uint32_t i = 0; i < impl_->bodies.size(); ++i)
        if (impl_->bodies[i].alive) ids.push_back(BodyId{i, impl_->bodies[i].generation});
    return ids;
}

const BodyData& World::at(BodyId id) const {
    if (!contains(id))
        throw std::invalid_argument("physim: body id (index " + std::to_string(id.index) + ", generation " +
                                    std::to_string(id.generation) + ") is not a live body of this world");
    return impl_->bodies[id.index];
}

BodyData& World::mutableBody(BodyId id, const char* call) {
    at(id);
    impl_->requireNotStepping(call);
    impl_->touchingValid = false;
    impl_->touched.push_back(id.index);
    return impl_->bodies[id.index];
}

BodyData& World::wake(BodyId id, const char* call) {
    BodyData& b = mutableBody(id, call);
    impl_->wakeBody(id.index);
    return b;
}

BodyType World::type(BodyId id) const { return at(id).type; }
const Geometry& World::shape(BodyId id) const { return impl_->shapes[firstShape(id)].geometry; }
Transform World::transform(BodyId id) const { return at(id).xf; }
Vec2 World::position(BodyId id) const { return at(id).xf.p; }
double World::angle(BodyId id) const { return at(id).angle; }
Vec2 World::centerOfMass(BodyId id) const { return at(id).center; }
Vec2 World::localCenterOfMass(BodyId id) const { return at(id).localCenter; }
Vec2 World::velocity(BodyId id) const { return at(id).v; }
double World::kineticEnergy(BodyId id) const {
    return at(id).kineticEnergy();
}
Vec2 World::velocityAt(BodyId id, const Vec2& worldPoint) const {
    const BodyData& b = at(id);
    return b.v + cross(b.w, worldPoint - b.center);
}
double World::angularVelocity(BodyId id) const { return at(id).w; }
Aabb World::bounds(BodyId id) const { return impl_->bodyBounds(at(id)); }
double World::mass(BodyId id) const { return at(id).mass; }
double World::inverseMass(BodyId id) const { return at(id).invMass; }
double World::inertia(BodyId id) const { return at(id).inertia; }
double World::inverseInertia(BodyId id) const { return at(id).invInertia; }
double World::restitution(BodyId id) const { return impl_->shapes[firstShape(id)].restitution; }
double World::staticFriction(BodyId id) const { return impl_->shapes[firstShape(id)].staticFriction; }
double World::dynamicFriction(BodyId id) const { return impl_->shapes[firstShape(id)].dynamicFriction; }
bool World::useGravity(BodyId id) const { return at(id).useGravity; }

void World::setTransform(BodyId id, const Vec2& position, double angle) {
    requireWithin("body position", position, kMaxCoordinate);
    requireFinite("body angle", angle);
    BodyData& b = wake(id, "setTransform");
    b.xf = {position, Rotation::fromAngle(angle)};
    b.angle = angle;
    b.center = b.xf.apply(b.localCenter);
    impl_->updateBoxes(b);
    impl_->moveProxies(b);
    if (b.type == BodyType::Static) impl_->wakeShapesOverlapping(id.index);
}

void World::setVelocity(BodyId id, const Vec2& velocity) {
    requireWithin("body velocity", velocity, kMaxSpeed);
    BodyData& b = wake(id, "setVelocity");
    if (b.movable()) b.v = velocity;
}

void World::setAngularVelocity(BodyId id, double angularVelocity) {
    requireWithin("body angular velocity", angularVelocity, kMaxSpeed);
    BodyData& b = wake(id, "setAngularVelocity");
    if (b.movable() && !b.fixedRotation) b.w = angularVelocity;
}

void World::setUseGravity(BodyId id, bool useGravity) { wake(id, "setUseGravity").useGravity = useGravity; }

void World::setMaterial(BodyId id, double restitution, double staticFriction, double dynamicFriction) {
    requireInRange("body restitution", restitution, 0.0, 1.0);
    requireNonNegative("body static friction", staticFriction);
    requireNonNegative("body dynamic friction", dynamicFriction);
    const BodyData& b = wake(id, "setMaterial");
    impl_->forEachShape(b, [&](std::uint32_t slot, const ShapeData&) {
        impl_->setShapeMaterial(slot, restitution, staticFriction, dynamicFriction);
    });
}

void World::setType(BodyId id, BodyType type) {
    requireBodyType(type);
    BodyData& current = mutableBody(id, "setType");
    if (current.type == type) return;
    // Check the new mass before changing anything.
    BodyData trial = current;
    trial.type = type;
    if (type == BodyType::Dynamic) assignMass(trial, current.density * current.unitMass.area);
    else clearMass(trial);

    WorldImpl& w = *impl_;
    const std::uint32_t index = id.index;
    w.wakeBody(index);
    // Contacts depend on the pair's types (two immovable bodies have none): rebuild them from the broad phase.
    while (w.bodies[index].contactHead != kNullIndex)
        w.destroyContact(static_cast<std::uint32_t>(w.bodies[index].contactHead >> 1), true);
    w.removeFromIsland(index);
    w.removeAwakeBody(index);
    BodyData& b = w.bodies[index];
    if (b.type == BodyType::Dynamic) --w.dynamicCount;
    const bool wasStatic = b.type == BodyType::Static;
    b.type = type;
    w.solver.layoutChanged();
    b.mass = trial.mass;
    b.density = trial.density;
    b.invMass = trial.invMass;
    b.inertia = trial.inertia;
    b.invInertia = trial.invInertia;
    if (type == BodyType::Static) {
        b.v.setZero();
        b.w = 0.0;
    }
    if (type == BodyType::Dynamic) ++w.dynamicCount;
    if (!b.collides) {
        // touches nothing: no proxy to rebuild
    } else if (wasStatic != (type == BodyType::Static)) {
        w.destroyProxies(index);
        w.createProxies(index);
    } else {
        w.forEachShape(b, [&](std::uint32_t, const ShapeData& shape) {
            w.broadPhase.moveProxy(shape.proxy, w.broadPhase.fatBox(shape.proxy));  // find its pairs again
        });
    }
    w.addAwakeBody(index);
    if (type == BodyType::Dynamic && w.settings.enableSleep) w.createIsland(index);
}

void World::setMass(BodyId id, double mass) {
    requirePositive("body mass", mass);
    BodyData& b = mutableBody(id, "setMass");
    if (b.type != BodyType::Dynamic) throw std::invalid_argument("physim: setMass needs a dynamic body");
    assignMass(b, mass);
    impl_->wakeBody(id.index);
}

void World::setFixedRotation(BodyId id, bool fixedRotation) {
    BodyData& b = wake(id, "setFixedRotation");
    b.fixedRotation = fixedRotation;
    if (b.type == BodyType::Dynamic) assignMass(b, b.mass);  // recomputes the inverse inertia
    if (fixedRotation) b.w = 0.0;
}

bool World::fixedRotation(BodyId id) const { return at(id).fixedRotation; }

bool World::isAwake(BodyId id) const {
    const BodyData& b = at(id);
    return b.type == BodyType::Static || b.awake();
}

void World::setAwake(BodyId id, bool awake) {
    BodyData& b = mutableBody(id, "setAwake");
    WorldImpl& w = *impl_;
    if (awake || b.type != BodyType::Dynamic || !w.settings.enableSleep) {
        w.wakeBody(id.index);
        return;
    }
    if (b.island != kNullIndex && b.awake()) w.sleepIsland(static_cast<std::uint32_t>(b.island));
}

void World::setAllowSleep(BodyId id, bool allowSleep) { wake(id, "setAllowSleep").allowSleep = allowSleep; }
bool World::allowSleep(BodyId id) const { return at(id).allowSleep; }

void World::setCollisionDetection(BodyId id, CollisionDetection mode, double precision) {
    requireDetection(mode);
    checkPrecision(precision);
    BodyData& b = mutableBody(id, "setCollisionDetection");
    if (b.detection != CollisionDetection::Discrete) --impl_->continuousCount;
    if (mode != CollisionDetection::Discrete) ++impl_->continuousCount;
    b.detection = mode;
    b.precision = precision;
    impl_->solver.layoutChanged();  // an exact-continuous body's island keeps the warm start on its rows
}

CollisionDetection World::collisionDetection(BodyId id) const { return at(id).detection; }
double World::collisionPrecision(BodyId id) const { return at(id).precision; }

void World::applyForce(BodyId id, const Vec2& force) {
    requireFinite("force", force);
    wake(id, "applyForce").force += force;
}

void World::applyForceAtPoint(BodyId id, const Vec2& force, const Vec2& worldPoint) {
    requireFinite("force", force);
    requireWithin("force application point", worldPoint, kMaxCoordinate);
    BodyData& b = wake(id, "applyForceAtPoint");
    b.force += force;
    b.torque += cross(worldPoint - b.center, force);
}

void World::applyTorque(BodyId id, double torque) {
    requireFinite("torque", torque);
    wake(id, "applyTorque").torque += torque;
}

void World::applyLinearImpulse(BodyId id, const Vec2& impulse) {
    requireFinite("impulse", impulse);
    BodyData& b = wake(id, "applyLinearImpulse");
    b.v += b.invMass * impulse;
}

void World::applyLinearImpulseAtPoint(BodyId id, const Vec2& impulse, const Vec2& worldPoint) {
    requireFinite("impulse", impulse);
    requireWithin("impulse application point", worldPoint, kMaxCoordinate);
    BodyData& b = wake(id, "applyLinearImpulseAtPoint");
    b.v += b.invMass * impulse;
    b.w += b.invInertia * cross(worldPoint - b.center, impulse);
}

// --- stepping ----------------------------------------------------------------------------------------

namespace {

// Contact c as the user reads it: its manifold with the points' impulses over the step (WorldImpl::contactImpulses)
// in place of the last substep's, which the manifold keeps for the solver's warm start.
Manifold reportedContact(const WorldImpl& w, std::uint32_t c) {
    Manifold m = w.contacts[c].manifold;
    const StepImpulses& total = w.contactImpulses[c];
    for (int p = 0; p < m.pointCount; ++p) {
        m.points[p].normalImpulse = total.normal[p];
        m.points[p].tangentImpulse = total.tangent[p];
    }
    return m;
}

// Whether contact c pushed in the last step that solved it: a speculative point (not yet touching when the step
// began) can stop, or bounce, a body that closes the gap within the step.
bool pushed(const WorldImpl& w, std::uint32_t c) {
    for (int p = 0; p < w.contacts[c].manifold.pointCount; ++p)
        if (w.contactImpulses[c].normal[p] != 0.0) return true;
    return false;
}

void sortByBodies(std::vector<Manifold>& list) {
    std::sort(list.begin(), list.end(), [](const Manifold& x, const Manifold& y) {
        return std::make_tuple(x.bodyA.index, x.bodyB.index, x.shapeA.index, x.shapeB.index) <
               std::make_tuple(y.bodyA.index, y.bodyB.index, y.shapeA.index, y.shapeB.index);
    });
}

}  // namespace

const std::vector<Manifold>& World::contacts() const {
    WorldImpl& w = *impl_;
    if (!w.touchingValid) {
        w.touchingManifolds.clear();
        for (const std::uint32_t c : w.awakeContacts)
            if (w.contacts[c].touching || pushed(w, c)) w.touchingManifolds.push_back(reportedContact(w, c));
        sortByBodies(w.touchingManifolds);
        w.touchingValid = true;
    }
    return w.touchingManifolds;
}

std::vector<Manifold> World::sleepingContacts() const {
    const WorldImpl& w = *impl_;
    std::vector<Manifold> list;
    for (std::uint32_t c = 0; c < w.contacts.size(); ++c) {
        const ContactData& contact = w.contacts[c];
        if (contact.alive && contact.awakeIndex == kNullIndex && (contact.touching || pushed(w, c)))
            list.push_back(reportedContact(w, c));
    }
    sortByBodies(list);
    return list;
}

void World::step(double dt) {
    // Above a second per step is a unit mistake (milliseconds passed as seconds), not a simulation. Below a
    // nanosecond the substep's powers and inverses leave the doubles' range (1e-300 s turned a mouse-held body NaN).
    requireInRange("time step dt (s)", dt, 1e-9, 1.0);
    WorldImpl& w = *impl_;
    w.requireNotStepping("step");
    if (w.effects.callbacks.running()) throw std::logic_error("physim: World::step called from a force callback");
    w.profile = StepProfile{};
    const double energyBefore = w.ledger.enabled ? w.ledgerEnergy() : 0.0;
    // The user's forces first, outside the step proper: they may apply forces as between steps.
    if (w.effects.callbacks.active()) {
        const auto start = std::chrono::steady_clock::now();
        w.effects.callbacks.run(*this, dt);
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        recordEffect(w.profile, Effect::Callbacks, elapsed.count());
    }
    struct SteppingGuard {
        WorldImpl& w;
        explicit SteppingGuard(WorldImpl& world) : w(world) { w.stepping = true; }
        ~SteppingGuard() { w.stepping = false; }
    } guard(w);

    w.dt = dt;
    w.events.begin.clear();
    w.events.end.clear();
    w.events.impacts.clear();
    w.jointEvents.broken.clear();
    w.sensors.clearEvents();
    w.touchingValid = false;
    // Filters changed since the last step act now, so their contacts' end events are this step's.
    if (!w.refiltered.empty() || w.refilterAll) w.applyFilterChanges();

    // Bodies made or changed since the last step got proxies before dt was known: grow them for this step's motion.
    for (const std::uint32_t slot : w.touched) {
        const BodyData& b = w.bodies[slot];
        if (b.alive && b.movable() && w.proxyOutgrown(b)) w.moveProxies(b);
    }
    w.touched.clear();
    // Pairs need a moved proxy and an awake body: a static body moved next to sleepers wakes them itself.
    runStage(w.profile, Stage::BroadPhase, w.broadPhase.moveCount() > 0 && w.liveCount >= 2 && !w.awake.empty(),
             [&] { w.updatePairs(); });
    w.profile.candidatePairs = w.awakeContacts.size();
    // One team for both (Executor::run): the pool's threads are woken once per step, and not at all when all sleep.
    const bool narrowPhase = !w.awakeContacts.empty(), solve = !w.awake.empty();
    if (narrowPhase || solve)
        w.executor.run([&] {
            runStage(w.profile, Stage::NarrowPhase, narrowPhase, [&] { w.updateContacts(); });
            if (solve) {
                if (w.sensors.active()) w.sensors.recordStarts(w);  // the start of the paths sensors look along
                w.solver.solve(w);
            }
        });
    runStage(w.profile, Stage::Continuous, (w.continuousCount > 0 || w.solver.fastBodies()) && !w.awake.empty(),
             [&] { w.continuous.run(w); });
    runStage(w.profile, Stage::Integrate, !w.awake.empty(), [&] { w.solver.moveDeferredProxies(w); });
    if (w.breakableJoints > 0) w.breakJoints();
    runStage(w.profile, Stage::Sensors, w.sensors.active(), [&] { w.sensors.run(w); });
    runStage(w.profile, Stage::Sleep, w.settings.enableSleep && !w.awake.empty(), [&] { w.updateSleep(); });
    w.profile.manifolds = w.profile.didRun(Stage::Solve) ? w.solver.rowCount() : 0;
    if (w.ledger.enabled) w.closeLedgerStep(energyBefore, solve);
    ++w.stepCount;
}

}  // namespace physim
