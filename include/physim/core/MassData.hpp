#pragma once
// The one mass rule: how a body's mass, centre of mass and rotational inertia follow from its shape. The World
// uses it when a body is created or its mass or type changes, and the framework's RigidBody uses it for a body
// not yet in a world, so both report the same values.

#include "physim/core/Geometry.hpp"
#include "physim/core/Math.hpp"

#include <vector>

namespace physim {

/// A dynamic body's mass data: its mass spread uniformly over its shape. The body turns about its centre of mass
/// (the shape's centroid, which need not be the body origin), so the inertia is taken about that point.
struct MassData {
    double mass = 0.0;           ///< kg
    double density = 0.0;        ///< kg/m^2: mass / area
    Vec2 center = Vec2::Zero();  ///< centre of mass, m, body-local (the shape's centroid)
    double inertia = 0.0;        ///< kg m^2 about the centre of mass
};

/// `mass` kg (> 0) spread over a shape of per-unit-density properties `unit` (computeMassProperties).
inline MassData massDataForMass(const MassProperties& unit, double mass) {
    const double density = mass / unit.area;
    return {mass, density, unit.centroid, density * unit.secondMoment};
}

/// A shape of `density` kg/m^2 (> 0): mass = density * area, then massDataForMass: the same rule as
/// World::createBody for a body made from a BodyDef.
inline MassData massDataForDensity(const Geometry& shape, double density) {
    const MassProperties unit = computeMassProperties(shape);
    return massDataForMass(unit, density * unit.area);
}

/// One part of a body of several shapes: its properties per unit density (computeMassProperties) and its weight,
/// its density (or its density over a reference density).
struct WeightedPart {
    MassProperties unit;
    double weight = 1.0;
};

/// The parts as one: the weighted area, the weighted centroid, and the second moment about that centroid, each
/// part's own plus its weighted area times its offset squared (the parallel axis theorem). With densities as the
/// weights the area is the mass (kg) and the second moment the inertia (kg m^2). Zero area (and the centroid at the
/// origin) when no part has weighted area. The World (World::createShape) and the framework's RigidBody combine a
/// body's shapes with it.
inline MassProperties combineParts(const std::vector<WeightedPart>& parts) {
    MassProperties m;
    Vec2 moment = Vec2::Zero();
    for (const WeightedPart& p : parts) {
        m.area += p.weight * p.unit.area;
        moment += p.weight * p.unit.area * p.unit.centroid;
    }
    if (!(m.area > 0.0)) return m;
    m.centroid = moment / m.area;
    for (const WeightedPart& p : parts) {
        const Vec2 offset = p.unit.centroid - m.centroid;
        m.secondMoment += p.weight * (p.unit.secondMoment + p.unit.area * offset.squaredNorm());
    }
    return m;
}

}  // namespace physim
