#pragma once
// Per-body record inside World, one slot per body id. Internal: not installed.
//
// The record holds the authoritative pose and velocity of every body. During a step the solver gathers the
// awake bodies into contiguous SolverBody arrays (SolverData.hpp), works on those, and scatters the result back.

#include "physim/core/Aabb.hpp"
#include "physim/core/Body.hpp"
#include "physim/core/Geometry.hpp"
#include "physim/core/Math.hpp"
#include "physim/core/TimeOfImpact.hpp"

#include <cstdint>

namespace physim {

constexpr std::int32_t kNullIndex = -1;

struct BodyData {
    // Motion. The body rotates about its centre of mass; xf places its origin (what position() reports and what
    // the shape's local coordinates are relative to).
    Transform xf;                   // origin pose
    Vec2 center = Vec2::Zero();     // centre of mass, world, m (= xf.apply(localCenter))
    double angle = 0.0;             // rad, unwrapped (xf.q caches its cosine and sine)
    Vec2 v = Vec2::Zero();          // velocity of the centre of mass, m/s
    double w = 0.0;                 // rad/s
    // Read for every pair by the broad and narrow phases, so kept with the motion in the record's first lines.
    double extent = 0.0;            // largest distance from the centre of mass to any of its shapes, m
    CollisionDetection detection = CollisionDetection::Discrete;
    BodyType type = BodyType::Dynamic;
    std::int32_t awakeIndex = kNullIndex;  // position in the awake list (World::awake_); kNullIndex: static, asleep
    bool collides = true;                  // its shapes have broad-phase proxies (World::setCollides)
    Vec2 force = Vec2::Zero();      // N at the centre of mass, accumulated until the next step uses it
    double torque = 0.0;            // N m
    // How far (m) from the centre of mass the body's turn moves its outline: its shapes' cores' reach. A round part
    // turns onto itself about its core, so a wheel about its centre reaches 0 however fast it spins. <= extent.
    double turnReach = 0.0;

    // Mass. Zero inverse mass or inertia means immovable (static, kinematic) or not rotating (fixedRotation).
    Vec2 localCenter = Vec2::Zero();  // centre of mass in the body frame, m
    double mass = 0.0;              // kg, 0 when immovable
    double invMass = 0.0;           // 1/kg
    double inertia = 0.0;           // kg m^2 about the centre of mass
    double invInertia = 0.0;
    double density = 1.0;          // kg/m^2, the reference density: mass = density * unitMass.area
    MassProperties unitMass;        // of all its shapes, each weighted by its density over the reference density

    // Shapes (ShapeData.hpp): an intrusive list, in the order they were added.
    std::int32_t shapeHead = kNullIndex;
    std::int32_t shapeTail = kNullIndex;
    std::int32_t shapeCount = 0;
    double coreRadius = 0.0;        // least over its shapes of the largest circle about a shape's centroid inside it, m
    double precision = kDefaultPrecision;

    bool useGravity = true;
    double gravityScale = 1.0;
    bool attracting = false;        // in the gravitation effect: never sleeps (the others pull it all the time)
    bool fixedRotation = false;
    bool allowSleep = true;
    bool alive = false;
    std::uint32_t generation = 0;

    Aabb aabb;                      // the tight box of all its shapes at the current pose, while it collides

    // Constraint graph: intrusive lists of the body's contacts and joints (edge key = index * 2 + side).
    std::int32_t contactHead = kNullIndex;
    std::int32_t contactCount = 0;
    std::int32_t jointHead = kNullIndex;

    // Island (dynamic bodies only): intrusive list of the island's bodies.
    std::int32_t island = kNullIndex;
    std::int32_t islandPrev = kNullIndex;
    std::int32_t islandNext = kNullIndex;
    double sleepTime = 0.0;         // s spent below the sleep tolerances

    bool movable() const { return type != BodyType::Static; }
    /// Multiplies the world's gravity for this body.
    double gravityFactor() const { return useGravity ? gravityScale : 0.0; }
    /// J, translation and rotation (0 for an immovable body: no mass).
    double kineticEnergy() const { return 0.5 * mass * v.squaredNorm() + 0.5 * inertia * w * w; }
    bool canSleep() const { return allowSleep && !attracting; }
    bool awake() const { return awakeIndex != kNullIndex; }
};

}  // namespace physim
