#pragma once
// Body description handed to World::createBody, and the handle the world gives back.

#include "physim/core/Drag.hpp"
#include "physim/core/Geometry.hpp"
#include "physim/core/Math.hpp"
#include "physim/core/Shape.hpp"
#include "physim/core/TimeOfImpact.hpp"

#include <cstdint>
#include <limits>

namespace physim {

/// Static: never moves, infinite mass (the paper's mass 0). Kinematic: moves by its velocity, immovable by
/// contacts and forces. Dynamic: moved by forces and contacts.
enum class BodyType { Static, Kinematic, Dynamic };

/// Handle to a body in one World. The generation makes a handle to a destroyed body detectably stale.
struct BodyId {
    std::uint32_t index = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t generation = 0;

    bool isNull() const { return index == std::numeric_limits<std::uint32_t>::max(); }
    friend bool operator==(const BodyId& a, const BodyId& b) {
        return a.index == b.index && a.generation == b.generation;
    }
    friend bool operator!=(const BodyId& a, const BodyId& b) { return !(a == b); }
};

struct BodyDef {
    BodyType type = BodyType::Dynamic;
    Vec2 position = Vec2::Zero();      ///< body origin, m (the shape's local coordinates are relative to it)
    double angle = 0.0;                ///< rad, counter-clockwise
    Vec2 velocity = Vec2::Zero();      ///< m/s
    double angularVelocity = 0.0;      ///< rad/s
    /// The body's first shape and its material (World::createShape adds more: Shape.hpp).
    Geometry shape = Circle{Vec2::Zero(), 0.5};
    /// false: the body starts with no shape, and gets its shapes from World::createShape or createChain (ground
    /// made of a chain); only static and kinematic bodies may have none. shape is then unused.
    bool withShape = true;
    double density = 1.0;              ///< kg/m^2, > 0 for dynamic bodies; mass = density * area
    double restitution = 0.0;          ///< in [0, 1]; a pair mixes them (WorldSettings::restitutionMixing: min)
    double staticFriction = 0.6;       ///< >= 0; a pair mixes them (WorldSettings::frictionMixing: average)
    double dynamicFriction = 0.4;      ///< >= 0; a pair mixes them (WorldSettings::frictionMixing: average)
    Filter filter{};                   ///< the first shape's collision filter (Filter.hpp)
    bool isSensor = false;             ///< true: the first shape collides with nothing, reports overlaps instead
    bool useGravity = true;
    double gravityScale = 1.0;         ///< finite: the body feels gravityScale times the world's gravity
    bool fixedRotation = false;        ///< infinite inertia: contacts and torques do not rotate it
    bool allowSleep = true;            ///< false: this body, and any island it touches, never sleeps
    /// false: a dynamic body starts asleep (where the world sleeps: WorldSettings::enableSleep), still until
    /// something touches or wakes it (a grid of bodies waiting to be struck, as Box2D's smash benchmark has)
    bool awake = true;
    /// Discrete, or continuous (sampled or exact time of impact; dynamic bodies only, docs/ccd.md).
    CollisionDetection collisionDetection = CollisionDetection::Discrete;
    double precision = kDefaultPrecision;  ///< sampled method's spacing, fraction of the step, in (0, 1]
    /// false: the body touches nothing (no broad-phase proxy, no contacts): a star, a tracer particle.
    bool collides = true;
    /// true: the body takes part in Newtonian gravitation between bodies (GravitationSettings, World.hpp).
    bool attracting = false;
    DragDef drag{};                    ///< air drag (none by default)
    double rollingResistance = 0.0;    ///< the first shape's rolling resistance, >= 0 (ShapeDef)
    double tangentSpeed = 0.0;         ///< the first shape's surface speed, m/s (ShapeDef: a conveyor belt)
};

}  // namespace physim
