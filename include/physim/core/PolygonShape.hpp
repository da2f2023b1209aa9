#pragma once

#include "physim/core/CollisionShape.hpp"

#include <vector>

namespace physim {

/// A convex polygon of 3 to Polygon::maxVertices vertices, given in either winding (see makePolygon), or with a
/// radius a rounded polygon: every point within `radius` of that polygon (makeRoundedPolygon), round corners.
/// The points are in the shape's own frame (the body's frame: the body origin is the local origin), metres, and
/// are kept as given. A body with this shape turns about its centroid (getMassProperties().centroid), wherever
/// that lies.
class PolygonShape final : public CollisionShape {
public:
    /// radius in metres, >= 0 (0: sharp corners). Throws std::invalid_argument naming the problem (count,
    /// non-finite, coincident, collinear, non-convex, a negative or NaN radius).
    explicit PolygonShape(const std::vector<Vec2>& points, double radius = 0.0);

    ShapeType getType() const override { return ShapeType::POLYGON; }
    /// Width and height of the bounding box in the shape's own frame (the radius included), m.
    Vec2 getSize() const override;
    std::unique_ptr<CollisionShape> clone() const override { return std::make_unique<PolygonShape>(*this); }
    /// The vertices of the core polygon (the corners' centres when rounded), counter-clockwise, own frame, m.
    std::vector<Vec2> vertices() const;
    /// m; 0 for sharp corners.
    double radius() const;
};

}  // namespace physim
