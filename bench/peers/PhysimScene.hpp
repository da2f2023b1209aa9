#pragma once
// A peers scene (Scenes.hpp) built in a physim World: the one way peer_bench, query_bench and snapshot_bench make
// physim's side. Header only, so that scripts/ab.sh compiles it into each renamed build of the engine adapter.

#include "Scenes.hpp"

#include "physim/core/World.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace peers {

/// physim as the peers' scenes run it: default iterations, springs and slop; sleep off; the scenes' gravity.
inline physim::WorldSettings physimSettings(int threads, int substeps = physim::WorldSettings{}.substeps) {
    physim::WorldSettings s;
    s.gravity = {0.0, kGravity};
    s.enableSleep = false;
    s.threads = threads;
    s.substeps = substeps;
    return s;
}

/// The ids of a scene's bodies in a physim World, in the scene's order; a wave's bodies are null until it comes.
struct PhysimBodies {
    std::vector<physim::BodyId> statics, dynamics, kinematics;
};

inline physim::Filter physimFilter(const Material& m) {
    physim::Filter f;
    f.categoryBits = m.category;
    f.maskBits = m.mask;
    f.groupIndex = m.group;
    return f;
}

inline physim::Geometry physimGeometry(const PartSpec& p) {
    std::vector<physim::Vec2> points;
    for (const ChainPoint& c : p.points) points.emplace_back(c.x, c.y);
    switch (p.kind) {
    case PartSpec::Kind::Circle: return physim::makeCircle(p.radius, points.at(0));
    case PartSpec::Kind::Capsule: return physim::makeCapsule(points.at(0), points.at(1), p.radius);
    case PartSpec::Kind::Segment: return physim::makeSegment(points.at(0), points.at(1));
    case PartSpec::Kind::Polygon: break;
    case PartSpec::Kind::Loop: throw std::invalid_argument("peers: a loop is a chain, not one shape");
    }
    return p.radius > 0.0 ? physim::computeHull(points, p.radius) : physim::computeHull(points);
}

/// One body of the scene (and its further parts), with the scene's collisions on or off.
inline physim::BodyId addPhysimBody(physim::World& world, const ShapeSpec& s, physim::BodyType type, bool collides) {
    physim::BodyDef d;
    d.type = type;
    d.position = {s.x, s.y};
    if (type != physim::BodyType::Static) {
        d.velocity = {s.vx, s.vy};
        d.angularVelocity = s.angularVelocity;
        d.allowSleep = s.allowSleep;
    }
    if (type == physim::BodyType::Dynamic) d.awake = !s.asleep;
    Material m = s.material;
    // A compound's first part is the body's first shape, unless it is a loop: a chain, added after.
    const bool firstIsShape = s.isCompound() && s.parts.front().kind != PartSpec::Kind::Loop;
    if (firstIsShape) {
        d.shape = physimGeometry(s.parts.front());
        m = s.parts.front().material;
    } else if (s.isShapeless() || s.isCompound()) {
        d.withShape = false;
    } else if (s.isCircle()) {
        d.shape = physim::makeCircle(s.radius);
    } else if (s.isCapsule()) {
        d.shape = physim::makeCapsule({-s.halfLength, 0.0}, {s.halfLength, 0.0}, s.radius);
    } else {
        d.shape = physim::makeBox(s.halfWidth, s.halfHeight);
    }
    d.density = m.density;
    d.staticFriction = d.dynamicFriction = m.friction;
    d.restitution = m.restitution;
    d.filter = physimFilter(m);
    d.collides = collides;
    const physim::BodyId id = world.createBody(d);
    for (std::size_t i = firstIsShape ? 1 : 0; i < s.parts.size(); ++i) {
        const PartSpec& p = s.parts[i];
        if (p.kind == PartSpec::Kind::Loop) {
            physim::ChainDef chain;
            for (const ChainPoint& c : p.points) chain.points.emplace_back(c.x, c.y);
            chain.loop = true;
            chain.staticFriction = chain.dynamicFriction = p.material.friction;
            chain.restitution = p.material.restitution;
            chain.filter = physimFilter(p.material);
            world.createChain(id, chain);
            continue;
        }
        physim::ShapeDef sd;
        sd.geometry = physimGeometry(p);
        sd.density = p.material.density;
        sd.staticFriction = sd.dynamicFriction = p.material.friction;
        sd.restitution = p.material.restitution;
        sd.filter = physimFilter(p.material);
        world.createShape(id, sd);
    }
    // Box2D's damping is a rate (1/s); physim's linear drag a force per speed (N s/m): times the mass.
    if (s.linearDamping > 0.0 && type == physim::BodyType::Dynamic) {
        physim::DragDef drag;
        drag.linear = s.linearDamping * world.mass(id);
        world.setDrag(id, drag);
    }
    return id;
}

inline void addPhysimPin(physim::World& world, const PinSpec& p, const PhysimBodies& bodies) {
    auto body = [&](const BodyRef& r) { return r.isStatic ? bodies.statics[r.index] : bodies.dynamics[r.index]; };
    physim::RevoluteJointDef d;
    d.bodyA = body(p.a);
    d.bodyB = body(p.b);
    d.anchor = {p.x, p.y};
    d.enableLimit = p.enableLimit;
    d.lowerAngle = p.lowerAngle;
    d.upperAngle = p.upperAngle;
    d.enableMotor = p.enableMotor;
    d.motorSpeed = p.motorSpeed;
    d.maxMotorTorque = p.maxMotorTorque;
    d.enableSpring = p.enableSpring;
    d.springHertz = p.springHertz;
    d.springDampingRatio = p.springDampingRatio;
    d.springTargetAngle = p.springTargetAngle;
    world.createRevoluteJoint(d);
}

/// Adds the scene's bodies (statics, then the chain, then the dynamic and kinematic bodies but those of
/// waves), pins (but those of waves) and wheel joints to `world`.
inline PhysimBodies buildPhysimBodies(physim::World& world, const Scene& scene) {
    if (scene.gravity != kGravity || scene.sleep) {
        physim::WorldSettings settings = world.settings();
        settings.gravity = {0.0, scene.gravity};
        settings.enableSleep = scene.sleep;
        world.setSettings(settings);
    }
    PhysimBodies out;
    for (const ShapeSpec& s : scene.statics)
        out.statics.push_back(addPhysimBody(world, s, physim::BodyType::Static, scene.collisions));
    if (!scene.chain.empty()) {
        physim::BodyDef d;
        d.type = physim::BodyType::Static;
        d.withShape = false;
        physim::ChainDef chain;
        for (const ChainPoint& p : scene.chain) chain.points.emplace_back(p.x, p.y);
        chain.staticFriction = chain.dynamicFriction = kFriction;
        world.createChain(world.createBody(d), chain);
    }
    out.dynamics.resize(scene.dynamics.size());
    for (std::size_t i = 0; i < scene.firstWaveBody(); ++i)
        out.dynamics[i] = addPhysimBody(world, scene.dynamics[i], physim::BodyType::Dynamic, scene.collisions);
    for (const ShapeSpec& s : scene.kinematics)
        out.kinematics.push_back(addPhysimBody(world, s, physim::BodyType::Kinematic, scene.collisions));
    for (std::size_t i = 0; i < scene.firstWavePin(); ++i) addPhysimPin(world, scene.pins[i], out);
    for (const WheelSpec& w : scene.wheels) {
        physim::WheelJointDef d;
        d.bodyA = out.dynamics[w.chassis];
        d.bodyB = out.dynamics[w.wheel];
        d.anchor = {w.x, w.y};
        d.axis = {w.axisX, w.axisY};
        d.hertz = w.hertz;
        d.dampingRatio = w.dampingRatio;
        d.enableMotor = w.enableMotor;
        d.motorSpeed = w.motorSpeed;
        d.maxMotorTorque = w.maxMotorTorque;
        world.createWheelJoint(d);
    }
    return out;
}

/// buildPhysimBodies' dynamic bodies.
inline std::vector<physim::BodyId> buildPhysim(physim::World& world, const Scene& scene) {
    return buildPhysimBodies(world, scene).dynamics;
}

/// What the scene does before the world's step n (n steps taken): steers its sweeps, renews its wave.
inline void physimBeforeStep(physim::World& world, const Scene& scene, PhysimBodies& bodies, long n) {
    for (const SweepSpec& sw : scene.sweeps) {
        const ShapeSpec& k = scene.kinematics[sw.kinematic];
        const physim::BodyId id = bodies.kinematics[sw.kinematic];
        const physim::Vec2 target(k.x + sw.amplitude * std::sin(sw.rate * n * kTimeStep), k.y);
        world.setVelocity(id, (target - world.position(id)) / kTimeStep);
    }
    const long w = scene.waveBefore(n);
    if (w < 0) return;
    const WaveSpec& wave = scene.waves[static_cast<std::size_t>(w)];
    for (std::size_t i = wave.firstBody; i < wave.firstBody + wave.bodyCount; ++i) {
        if (!bodies.dynamics[i].isNull()) world.destroyBody(bodies.dynamics[i]);  // its pins go with it
        bodies.dynamics[i] = addPhysimBody(world, scene.dynamics[i], physim::BodyType::Dynamic, scene.collisions);
    }
    for (std::size_t i = wave.firstPin; i < wave.firstPin + wave.pinCount; ++i) addPhysimPin(world, scene.pins[i], bodies);
}

}  // namespace peers
