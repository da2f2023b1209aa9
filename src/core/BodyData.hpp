#pragma once
// Per-body storage inside World, laid out for the step's loops. Internal: not installed.

#include "physim/core/Aabb.hpp"
#include "physim/core/Body.hpp"
#include "physim/core/Geometry.hpp"
#include "physim/core/Math.hpp"
#include "physim/core/TimeOfImpact.hpp"

#include <cstdint>

namespace physim {

struct BodyData {
    // Hot: read and written by every stage.
    Transform xf;                   // position of the centre of mass and rotation
    double angle = 0.0;             // rad, unwrapped (xf.q caches its cosine and sine)
    Vec2 v = Vec2::Zero();          // m/s
    double w = 0.0;                 // rad/s
    Vec2 v0 = Vec2::Zero();         // m/s and rad/s before this substep's forces: what restitution reverses
    double w0 = 0.0;
    double invMass = 0.0;           // 1/kg, 0 = immovable
    double invInertia = 0.0;        // 1/(kg m^2), 0 = does not rotate
    Vec2 force = Vec2::Zero();      // N, accumulated until the end of the step
    double torque = 0.0;            // N m
    Aabb aabb;                      // world bounds at the last broad phase
    BodyType type = BodyType::Dynamic;
    bool useGravity = true;
    bool fixedRotation = false;
    bool alive = false;
    bool awake = true;              // asleep: skipped by integration, and its pairs by the narrow phase
    bool allowSleep = true;
    double sleepTime = 0.0;         // s spent below the sleep tolerances

    // Cold: material and shape.
    double mass = 0.0;              // kg, 0 when immovable
    double density = 1.0;           // kg/m^2, for mass when the body becomes dynamic
    double inertia = 0.0;           // kg m^2 about the centre of mass
    double restitution = 0.0;
    double staticFriction = 0.0;
    double dynamicFriction = 0.0;
    MassProperties unitMass;        // of the shape, per unit density
    Geometry shape;
    std::uint32_t generation = 0;
    CollisionDetection detection = CollisionDetection::Discrete;
    double precision = kDefaultPrecision;  // sampled continuous detection: spacing, fraction of the step

    bool movable() const { return type != BodyType::Static; }
};

}  // namespace physim
