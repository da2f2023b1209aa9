#pragma once
// A peers scene (Scenes.hpp) built in a physim World: the one way peer_bench, query_bench and snapshot_bench make
// physim's side. Header only, so that scripts/ab.sh compiles it into each renamed build of the engine adapter.

#include "Scenes.hpp"

#include "physim/core/World.hpp"

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

/// Adds the scene's bodies (statics, then the chain, then the dynamic bodies), pins and wheel joints to `world`;
/// returns the dynamic bodies' ids in the scene's order.
inline std::vector<physim::BodyId> buildPhysim(physim::World& world, const Scene& scene) {
    if (scene.gravity != kGravity || scene.sleep) {
        physim::WorldSettings settings = world.settings();
        settings.gravity = {0.0, scene.gravity};
        settings.enableSleep = scene.sleep;
        world.setSettings(settings);
    }
    auto add = [&](const ShapeSpec& s, physim::BodyType type) {
        physim::BodyDef d;
        d.type = type;
        d.position = {s.x, s.y};
        if (type == physim::BodyType::Dynamic) {
            d.velocity = {s.vx, s.vy};
            d.awake = !s.asleep;
        }
        if (s.isCircle())
            d.shape = physim::makeCircle(s.radius);
        else if (s.isCapsule())
            d.shape = physim::makeCapsule({-s.halfLength, 0.0}, {s.halfLength, 0.0}, s.radius);
        else
            d.shape = physim::makeBox(s.halfWidth, s.halfHeight);
        d.density = s.density > 0.0 ? s.density : kDensity;
        d.staticFriction = kFriction;
        d.dynamicFriction = kFriction;
        d.collides = scene.collisions;
        return world.createBody(d);
    };
    std::vector<physim::BodyId> statics, dynamics;
    for (const ShapeSpec& s : scene.statics) statics.push_back(add(s, physim::BodyType::Static));
    if (!scene.chain.empty()) {
        physim::BodyDef d;
        d.type = physim::BodyType::Static;
        d.withShape = false;
        physim::ChainDef chain;
        for (const ChainPoint& p : scene.chain) chain.points.emplace_back(p.x, p.y);
        chain.staticFriction = chain.dynamicFriction = kFriction;
        world.createChain(world.createBody(d), chain);
    }
    dynamics.reserve(scene.dynamics.size());
    for (const ShapeSpec& s : scene.dynamics) dynamics.push_back(add(s, physim::BodyType::Dynamic));
    auto body = [&](const BodyRef& r) { return r.isStatic ? statics[r.index] : dynamics[r.index]; };
    for (const PinSpec& p : scene.pins) {
        physim::RevoluteJointDef d;
        d.bodyA = body(p.a);
        d.bodyB = body(p.b);
        d.anchor = {p.x, p.y};
        world.createRevoluteJoint(d);
    }
    for (const WheelSpec& w : scene.wheels) {
        physim::WheelJointDef d;
        d.bodyA = dynamics[w.chassis];
        d.bodyB = dynamics[w.wheel];
        d.anchor = {w.x, w.y};
        d.axis = {w.axisX, w.axisY};
        d.hertz = w.hertz;
        d.dampingRatio = w.dampingRatio;
        d.enableMotor = w.enableMotor;
        d.motorSpeed = w.motorSpeed;
        d.maxMotorTorque = w.maxMotorTorque;
        world.createWheelJoint(d);
    }
    return dynamics;
}

}  // namespace peers
