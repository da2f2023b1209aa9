#pragma once
// Per-shape record inside World, one slot per shape id. Internal: not installed.
//
// A shape is what the broad phase holds (one proxy each) and what a contact joins (a pair of shapes of two bodies);
// its body holds the motion and the mass. A body's shapes form an intrusive list in the order they were added.

#include "BodyData.hpp"

#include "physim/core/Aabb.hpp"
#include "physim/core/Geometry.hpp"
#include "physim/core/Shape.hpp"

#include <cstdint>

namespace physim {

struct ShapeData {
    // Read for every pair by the broad and narrow phases.
    std::uint32_t body = 0;                // the owning body's slot
    std::int32_t proxy = kNullIndex;       // broad-phase proxy key; kNullIndex while its body collides with nothing
    Aabb aabb;                             // the tight box at the body's pose while it collides, m
    Geometry geometry;                     // body frame, m

    double density = 0.0;                  // kg/m^2
    double restitution = 0.0;
    double staticFriction = 0.0;
    double dynamicFriction = 0.0;
    MassProperties unitMass;               // per unit density
    Filter filter;                         // which shapes it may pair with
    bool sensor = false;                   // reports overlaps, never collides
    double rollingResistance = 0.0;        // dimensionless (ShapeDef)
    double tangentSpeed = 0.0;             // m/s, clockwise around the shape (ShapeDef)

    std::int32_t next = kNullIndex;        // the body's next shape
    std::uint32_t generation = 0;
    bool alive = false;
};

/// A new shape of `body` from its definition (validated by the caller) and its mass per unit density.
inline void assignShape(ShapeData& s, std::uint32_t body, const ShapeDef& def, const MassProperties& unitMass) {
    s.body = body;
    s.geometry = def.geometry;
    s.unitMass = unitMass;
    s.density = def.density;
    s.restitution = def.restitution;
    s.staticFriction = def.staticFriction;
    s.dynamicFriction = def.dynamicFriction;
    s.filter = def.filter;
    s.sensor = def.isSensor;
    s.rollingResistance = def.rollingResistance;
    s.tangentSpeed = def.tangentSpeed;
}

}  // namespace physim
