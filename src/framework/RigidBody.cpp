#include "physim/framework/RigidBody.hpp"

#include "physim/core/Collide.hpp"
#include "physim/core/MassData.hpp"
#include "physim/core/TimeOfImpact.hpp"
#include "physim/core/Validate.hpp"
#include "physim/core/World.hpp"

#include <algorithm>
#include <stdexcept>

namespace physim {

RigidBody::RigidBody(Entity* parent) : Behavior(parent) {}

// Before the body joins a world: the world's own rule (MassData.hpp) on the settings it will be created with.
MassData RigidBody::pendingMassData() const {
    const bool alone = std::none_of(more_.begin(), more_.end(),
                                    [](const auto& m) { return std::holds_alternative<ShapeDef>(m); });
    if (alone && def_.withShape) {
        if (massOverride_ > 0.0) return massDataForMass(computeMassProperties(def_.shape), massOverride_);
        return massDataForDensity(def_.shape, def_.density);
    }
    // Several shapes, each weighted by its density, combined as the world combines them (combineParts). Chains have
    // no area.
    std::vector<WeightedPart> parts;
    if (def_.withShape) parts.push_back({computeMassProperties(def_.shape), def_.density});
    for (const auto& m : more_)
        if (const auto* d = std::get_if<ShapeDef>(&m))
            parts.push_back({computeMassProperties(d->geometry), d->density});
    const MassProperties all = combineParts(parts);
    MassData data;
    data.mass = all.area;
    if (!(data.mass > 0.0)) return data;
    data.center = all.centroid;
    data.inertia = all.secondMoment;
    if (massOverride_ > 0.0) {  // the same distribution, scaled to the mass asked for
        data.inertia *= massOverride_ / data.mass;
        data.mass = massOverride_;
    }
    double area = 0.0;
    for (const WeightedPart& part : parts) area += part.unit.area;
    data.density = data.mass / area;
    return data;
}

std::vector<Geometry> RigidBody::geometries() const {
    std::vector<Geometry> all;
    if (world_) {
        for (const ShapeId s : world_->shapes(id_)) all.push_back(world_->geometry(s));
        return all;
    }
    const auto addChain = [&](const ChainDef& c) {
        for (const ChainSegment& piece : makeChain(c.points, c.loop)) all.push_back(piece);
    };
    if (def_.withShape) all.push_back(def_.shape);
    if (chain_) addChain(*chain_);
    for (const auto& m : more_) {
        if (const auto* d = std::get_if<ShapeDef>(&m)) all.push_back(d->geometry);
        else addChain(std::get<ChainDef>(m));
    }
    return all;
}

double RigidBody::mass() const {
    if (world_) return world_->mass(id_);
    return def_.type == BodyType::Dynamic ? pendingMassData().mass : 0.0;
}
double RigidBody::inv_mass() const {
    if (world_) return world_->inverseMass(id_);
    const double m = mass();
    return m > 0.0 ? 1.0 / m : 0.0;
}
double RigidBody::inertia() const {
    if (world_) return world_->inertia(id_);
    return def_.type == BodyType::Dynamic ? pendingMassData().inertia : 0.0;
}
double RigidBody::inv_inertia() const {
    if (world_) return world_->inverseInertia(id_);
    const double i = inertia();
    return i > 0.0 && !def_.fixedRotation ? 1.0 / i : 0.0;
}
Vec2 RigidBody::centerOfMass() const {
    if (world_) return world_->centerOfMass(id_);
    const Transform xf{def_.position, Rotation::fromAngle(def_.angle)};
    return xf.apply(pendingMassData().center);
}

void RigidBody::setGeometry(const Geometry& shape) {
    if (world_) throw std::logic_error("physim: a body's shape cannot change after it was added to a simulation");
    validate(shape);
    def_.shape = shape;
    def_.withShape = true;
    chain_.reset();
}

void RigidBody::setChain(const std::vector<Vec2>& points, bool loop) {
    if (world_) throw std::logic_error("physim: a body's shape cannot change after it was added to a simulation");
    makeChain(points, loop);  // checks the points now, naming a bad one
    ChainDef c;
    c.points = points;
    c.loop = loop;
    chain_ = c;
    def_.withShape = false;
    setMass(0.0);
}

void RigidBody::addShape(const ShapeDef& def) {
    if (world_) world_->createShape(id_, def);
    else {
        validate(def.geometry);
        requireNonNegative("shape density", def.density);
    }
    more_.emplace_back(def);
}

void RigidBody::addChain(const ChainDef& def) {
    if (world_) world_->createChain(id_, def);
    else makeChain(def.points, def.loop);
    more_.emplace_back(def);
}

void RigidBody::setSensor(bool sensor) {
    if (world_) {
        for (const ShapeId s : world_->shapes(id_)) world_->setSensor(s, sensor);
        return;
    }
    def_.isSensor = sensor;
    for (auto& more : more_)
        if (auto* shape = std::get_if<ShapeDef>(&more)) shape->isSensor = sensor;
}

bool RigidBody::isSensor() const {
    if (!world_) return def_.isSensor;
    const std::vector<ShapeId> shapes = world_->shapes(id_);
    return !shapes.empty() && world_->isSensor(shapes.front());
}

std::vector<ShapeId> RigidBody::shapeIds() const { return world_ ? world_->shapes(id_) : std::vector<ShapeId>{}; }

void RigidBody::createMoreShapes() {
    if (chain_) {
        ChainDef c = *chain_;  // the body's material, as a first shape has
        c.restitution = def_.restitution;
        c.staticFriction = def_.staticFriction;
        c.dynamicFriction = def_.dynamicFriction;
        c.filter = def_.filter;
        c.rollingResistance = def_.rollingResistance;
        c.tangentSpeed = def_.tangentSpeed;
        world_->createChain(id_, c);
    }
    for (const auto& m : more_) {
        if (const auto* d = std::get_if<ShapeDef>(&m)) world_->createShape(id_, *d);
        else world_->createChain(id_, std::get<ChainDef>(m));
    }
}

void RigidBody::setMass(double mass) {
    requireNonNegative("rigid body mass", mass);
    if (world_) {
        world_->setType(id_, mass == 0.0 ? BodyType::Static : BodyType::Dynamic);
        if (mass > 0.0) world_->setMass(id_, mass);
        return;
    }
    def_.type = mass == 0.0 ? BodyType::Static : BodyType::Dynamic;
    massOverride_ = mass;
}

void RigidBody::setDensity(double density) {
    requirePositive("rigid body density", density);
    if (world_) {
        double area = 0.0;  // every shape at this density
        for (const ShapeId s : world_->shapes(id_)) area += computeMassProperties(world_->geometry(s)).area;
        const double mass = density * area;
        world_->setType(id_, BodyType::Dynamic);
        world_->setMass(id_, mass);
        return;
    }
    def_.type = BodyType::Dynamic;
    def_.density = density;
    massOverride_ = -1.0;
}

Vec2 RigidBody::velocity() const { return world_ ? world_->velocity(id_) : def_.velocity; }
void RigidBody::setVelocity(const Vec2& v) {
    requireFinite("rigid body velocity", v);
    if (world_) world_->setVelocity(id_, v);
    else def_.velocity = v;
}
double RigidBody::angularVelocity() const { return world_ ? world_->angularVelocity(id_) : def_.angularVelocity; }
void RigidBody::setAngularVelocity(double w) {
    requireFinite("rigid body angular velocity", w);
    if (world_) world_->setAngularVelocity(id_, w);
    else def_.angularVelocity = w;
}
bool RigidBody::useGravity() const { return world_ ? world_->useGravity(id_) : def_.useGravity; }
void RigidBody::setUseGravity(bool g) {
    if (world_) world_->setUseGravity(id_, g);
    else def_.useGravity = g;
}

double RigidBody::restitution() const { return world_ ? world_->restitution(id_) : def_.restitution; }
double RigidBody::staticFriction() const { return world_ ? world_->staticFriction(id_) : def_.staticFriction; }
double RigidBody::dynamicFriction() const { return world_ ? world_->dynamicFriction(id_) : def_.dynamicFriction; }

void RigidBody::setRestitution(double e) {
    requireInRange("rigid body restitution", e, 0.0, 1.0);
    if (world_) world_->setMaterial(id_, e, staticFriction(), dynamicFriction());
    else def_.restitution = e;
}
void RigidBody::setStaticFriction(double mu) {
    requireNonNegative("rigid body static friction", mu);
    if (world_) world_->setMaterial(id_, restitution(), mu, dynamicFriction());
    else def_.staticFriction = mu;
}
void RigidBody::setDynamicFriction(double mu) {
    requireNonNegative("rigid body dynamic friction", mu);
    if (world_) world_->setMaterial(id_, restitution(), staticFriction(), mu);
    else def_.dynamicFriction = mu;
}

double RigidBody::rollingResistance() const {
    return world_ ? world_->rollingResistance(id_) : def_.rollingResistance;
}
double RigidBody::tangentSpeed() const { return world_ ? world_->tangentSpeed(id_) : def_.tangentSpeed; }
void RigidBody::setRollingResistance(double coefficient) {
    requireNonNegative("rigid body rolling resistance", coefficient);
    if (world_) world_->setRollingResistance(id_, coefficient);
    else def_.rollingResistance = coefficient;
}
void RigidBody::setTangentSpeed(double speed) {
    requireWithin("rigid body tangent speed", speed, kMaxSpeed);
    if (world_) world_->setTangentSpeed(id_, speed);
    else def_.tangentSpeed = speed;
}

void RigidBody::addForce(const Vec2& value, ForceMode mode) {
    requireFinite("addForce value", value);
    if (!world_) throw std::logic_error("physim: addForce needs the entity to be added to a simulation first");
    if (world_->type(id_) != BodyType::Dynamic) return;  // static bodies ignore forces (infinite mass)
    switch (mode) {
        case ForceMode::ACCELERATION: world_->applyForce(id_, world_->mass(id_) * value); break;
        case ForceMode::FORCE: world_->applyForce(id_, value); break;
        case ForceMode::IMPULSE: world_->applyLinearImpulse(id_, value); break;
        case ForceMode::VELOCITY: world_->setVelocity(id_, world_->velocity(id_) + value); break;
    }
}

void RigidBody::setFixedRotation(bool fixedRotation) {
    if (world_) world_->setFixedRotation(id_, fixedRotation);
    def_.fixedRotation = fixedRotation;
}
bool RigidBody::fixedRotation() const { return world_ ? world_->fixedRotation(id_) : def_.fixedRotation; }

void RigidBody::setKinematic(bool kinematic) {
    const BodyType type = kinematic ? BodyType::Kinematic : BodyType::Dynamic;
    if (world_) world_->setType(id_, type);
    else def_.type = type;
}
bool RigidBody::isKinematic() const {
    return (world_ ? world_->type(id_) : def_.type) == BodyType::Kinematic;
}

void RigidBody::setCollisionDetectionMode(CollisionDetectionMode mode, ContinuousMethod method, double precision) {
    checkPrecision(precision);
    method_ = method;
    const CollisionDetection core = mode == CollisionDetectionMode::DISCRETE ? CollisionDetection::Discrete
                                    : method == ContinuousMethod::SAMPLED   ? CollisionDetection::ContinuousSampled
                                                                            : CollisionDetection::ContinuousExact;
    if (world_) world_->setCollisionDetection(id_, core, precision);
    def_.collisionDetection = core;
    def_.precision = precision;
}

CollisionDetectionMode RigidBody::collisionDetectionMode() const {
    const CollisionDetection core = world_ ? world_->collisionDetection(id_) : def_.collisionDetection;
    return core == CollisionDetection::Discrete ? CollisionDetectionMode::DISCRETE : CollisionDetectionMode::CONTINUOUS;
}
ContinuousMethod RigidBody::continuousMethod() const { return method_; }
double RigidBody::precision() const { return world_ ? world_->collisionPrecision(id_) : def_.precision; }

bool RigidBody::checkDiscreteCollision(const Vec2& position, const RigidBody& other) const {
    requireFinite("checkDiscreteCollision position", position);
    const Transform here{position, Rotation::fromAngle(angle())};
    const Transform there{other.position(), Rotation::fromAngle(other.angle())};
    const std::vector<Geometry> theirs = other.geometries();
    for (const Geometry& mine : geometries())
        for (const Geometry& g : theirs)
            if (collide(mine, here, g, there).pointCount > 0) return true;
    return false;
}

std::optional<Vec2> RigidBody::checkContinuousCollision(const Vec2& position, const RigidBody& other) const {
    requireFinite("checkContinuousCollision position", position);
    const Sweep path{this->position(), position, angle(), angle()};
    const Sweep still{other.position(), other.position(), other.angle(), other.angle()};
    const bool sampled = collisionDetectionMode() == CollisionDetectionMode::CONTINUOUS &&
                         method_ == ContinuousMethod::SAMPLED;
    // The earliest touch of any two of the bodies' shapes.
    std::optional<double> first;
    const std::vector<Geometry> theirs = other.geometries();
    for (const Geometry& mine : geometries())
        for (const Geometry& g : theirs) {
            const ToiResult r = sampled ? sampledTimeOfImpact(mine, path, g, still, precision())
                                        : timeOfImpact(mine, path, g, still);
            if (r.state != ToiState::Hit && r.state != ToiState::Touching) continue;  // Failed: none proven
            if (!first || r.t < *first) first = r.t;
        }
    if (!first) return std::nullopt;
    return path.at(*first).p;
}

void RigidBody::setFilter(const Filter& filter) {
    if (world_) {
        world_->setFilter(id_, filter);
        return;
    }
    def_.filter = filter;
    for (auto& m : more_)
        if (auto* d = std::get_if<ShapeDef>(&m)) d->filter = filter;
        else std::get<ChainDef>(m).filter = filter;
}

Filter RigidBody::filter() const {
    if (world_ && !world_->shapes(id_).empty()) return world_->filter(world_->shapes(id_).front());
    return def_.filter;  // the first shape's, a chain's too (createMoreShapes)
}

bool RigidBody::isAwake() const { return world_ ? world_->isAwake(id_) : true; }
void RigidBody::wakeUp() {
    if (world_) world_->setAwake(id_, true);
}
void RigidBody::setAllowSleep(bool allowSleep) {
    if (world_) world_->setAllowSleep(id_, allowSleep);
    def_.allowSleep = allowSleep;
}
bool RigidBody::allowSleep() const { return world_ ? world_->allowSleep(id_) : def_.allowSleep; }

void RigidBody::attach(World& world) {
    if (world_) throw std::logic_error("physim: rigid body is already attached to a world");
    id_ = world.createBody(def_);
    world_ = &world;
    try {
        createMoreShapes();
    } catch (...) {
        world.destroyBody(id_);
        world_ = nullptr;
        id_ = BodyId{};
        throw;
    }
    if (def_.type == BodyType::Dynamic && massOverride_ > 0.0) world.setMass(id_, massOverride_);
    if (chain_ && def_.isSensor)  // a chain's pieces are its first shape: sensors too (ChainDef has no flag)
        for (const ShapeId s : world.shapes(id_)) world.setSensor(s, true);
}

namespace {

// The joint `def` between two attached bodies of one world, by World::createXJoint for its kind.
template <class Def, class Create>
JointId joinBodies(World* world, const World* otherWorld, BodyId a, BodyId b, Def def, Create create) {
    if (!world || !otherWorld)
        throw std::logic_error("physim: RigidBody::join needs both entities added to the simulation first");
    if (world != otherWorld) throw std::logic_error("physim: RigidBody::join joins bodies of one simulation only");
    def.bodyA = a;
    def.bodyB = b;
    return (world->*create)(def);
}

}  // namespace

JointId RigidBody::join(RigidBody& other, DistanceJointDef def) {
    return joinBodies(world_, other.world_, id_, other.id_, def, &World::createDistanceJoint);
}
JointId RigidBody::join(RigidBody& other, RevoluteJointDef def) {
    return joinBodies(world_, other.world_, id_, other.id_, def, &World::createRevoluteJoint);
}
JointId RigidBody::join(RigidBody& other, WeldJointDef def) {
    return joinBodies(world_, other.world_, id_, other.id_, def, &World::createWeldJoint);
}
JointId RigidBody::join(RigidBody& other, SpringJointDef def) {
    return joinBodies(world_, other.world_, id_, other.id_, def, &World::createSpringJoint);
}
JointId RigidBody::join(RigidBody& other, PulleyJointDef def) {
    return joinBodies(world_, other.world_, id_, other.id_, def, &World::createPulleyJoint);
}
JointId RigidBody::join(RigidBody& other, PrismaticJointDef def) {
    return joinBodies(world_, other.world_, id_, other.id_, def, &World::createPrismaticJoint);
}
JointId RigidBody::join(RigidBody& other, WheelJointDef def) {
    return joinBodies(world_, other.world_, id_, other.id_, def, &World::createWheelJoint);
}
JointId RigidBody::join(RigidBody& other, MotorJointDef def) {
    return joinBodies(world_, other.world_, id_, other.id_, def, &World::createMotorJoint);
}

void RigidBody::detach() {
    if (!world_) return;
    def_.position = world_->position(id_);
    def_.angle = world_->angle(id_);
    def_.velocity = world_->velocity(id_);
    def_.angularVelocity = world_->angularVelocity(id_);
    world_->destroyBody(id_);
    world_ = nullptr;
    id_ = BodyId{};
}

Vec2 RigidBody::position() const { return world_ ? world_->position(id_) : def_.position; }
double RigidBody::angle() const { return world_ ? world_->angle(id_) : def_.angle; }
void RigidBody::setPose(const Vec2& position, double angle) {
    requireFinite("position", position);
    requireFinite("rotation", angle);
    if (world_) world_->setTransform(id_, position, angle);
    def_.position = position;
    def_.angle = angle;
}

}  // namespace physim
