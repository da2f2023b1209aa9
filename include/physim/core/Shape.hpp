#pragma once
// A body's shapes: what collides, and the material of each part. A body starts with the shape of its BodyDef and
// may gain more (World::createShape, World::createChain): its mass, centre of mass and inertia come from all of
// them, and each keeps its own material, so a hammer's steel head and wooden handle are one body.

#include "physim/core/Filter.hpp"
#include "physim/core/Geometry.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace physim {

/// Handle to a shape in one World. The generation makes a handle to a destroyed shape detectably stale.
struct ShapeId {
    std::uint32_t index = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t generation = 0;

    bool isNull() const { return index == std::numeric_limits<std::uint32_t>::max(); }
    friend bool operator==(const ShapeId& a, const ShapeId& b) {
        return a.index == b.index && a.generation == b.generation;
    }
    friend bool operator!=(const ShapeId& a, const ShapeId& b) { return !(a == b); }
};

/// One more shape for a body (World::createShape). The geometry is in the body's frame, m, relative to the body
/// origin: its offset from the other shapes is where it lies.
struct ShapeDef {
    Geometry geometry = Circle{Vec2::Zero(), 0.5};
    double density = 1.0;              ///< kg/m^2, >= 0; the shape's mass is density * area
    double restitution = 0.0;          ///< in [0, 1]; a pair mixes them (WorldSettings::restitutionMixing: min)
    double staticFriction = 0.6;       ///< >= 0; a pair mixes them (WorldSettings::frictionMixing: average)
    double dynamicFriction = 0.4;      ///< >= 0; a pair mixes them (WorldSettings::frictionMixing: average)
    Filter filter{};                   ///< which shapes it may collide with (Filter.hpp)
    bool isSensor = false;             ///< true: collides with nothing, reports overlaps instead
    /// Rolling resistance coefficient, >= 0 (dimensionless): a pair resists rolling with a torque of at most the
    /// larger coefficient times the normal force times the rounder shape's radius (docs/collision.md).
    double rollingResistance = 0.0;
    /// m/s, finite: the surface runs along itself at this speed (a conveyor belt); positive runs clockwise around
    /// the shape, so a belt's top face carries things towards +x.
    double tangentSpeed = 0.0;
};

/// A chain (World::createChain): ground or walls as a polyline of many pieces (makeChain, Geometry.hpp), smooth
/// where pieces meet, colliding on the left of the direction of travel: ground listed left to right is solid
/// below, a counter-clockwise loop holds bodies inside. Its pieces have no area, so no mass.
struct ChainDef {
    std::vector<Vec2> points;          ///< m, in the body's frame
    bool loop = false;                 ///< true: the last point joins the first
    double restitution = 0.0;          ///< in [0, 1]
    double staticFriction = 0.6;       ///< >= 0
    double dynamicFriction = 0.4;      ///< >= 0
    Filter filter{};                   ///< every piece's collision filter (Filter.hpp)
    double rollingResistance = 0.0;    ///< >= 0 (ShapeDef)
    double tangentSpeed = 0.0;         ///< m/s (ShapeDef): positive runs the way the points are listed
};

}  // namespace physim
