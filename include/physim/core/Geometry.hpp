#pragma once
// Collision geometry as plain data in body-local metres. The body's origin is its centre of mass, so the
// factories below build shapes centred on the local origin unless an offset is asked for.

#include "physim/core/Aabb.hpp"
#include "physim/core/Math.hpp"

#include <array>
#include <variant>

namespace physim {

struct Circle {
    Vec2 center = Vec2::Zero();  ///< local position of the centre, m
    double radius = 0.0;         ///< m, > 0
};

/// Convex polygon, counter-clockwise, at most maxVertices vertices, with outward unit edge normals:
/// normals[i] is the normal of the edge vertices[i] -> vertices[(i + 1) % count].
struct Polygon {
    static constexpr int maxVertices = 8;
    std::array<Vec2, maxVertices> vertices{};
    std::array<Vec2, maxVertices> normals{};
    int count = 0;
};

using Geometry = std::variant<Circle, Polygon>;

/// A circle of the given radius (m) centred at `center`. Throws std::invalid_argument for radius <= 0 or NaN.
Circle makeCircle(double radius, const Vec2& center = Vec2::Zero());

/// A rectangle of half-extents (m) centred on the local origin. Throws for non-positive or non-finite sizes.
Polygon makeBox(double halfWidth, double halfHeight);

/// Mass properties per unit density (kg/m^2): area (m^2), centroid (m, local) and the second moment of area
/// about the centroid (m^4). Multiply area and secondMoment by a density to get mass and inertia.
struct MassProperties {
    double area = 0.0;
    Vec2 centroid = Vec2::Zero();
    double secondMoment = 0.0;
};

MassProperties computeMassProperties(const Geometry& g);

/// World-space bounding box of a geometry placed by `xf`.
Aabb computeAabb(const Geometry& g, const Transform& xf);

}  // namespace physim

namespace physim {

/// Throws std::invalid_argument naming the problem: non-positive or non-finite radius, a polygon with fewer
/// than 3 or more than Polygon::maxVertices vertices, non-finite coordinates.
void validate(const Geometry& g);

}  // namespace physim
