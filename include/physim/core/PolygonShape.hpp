#pragma once

#include "physim/core/CollisionShape.hpp"

#include <vector>

namespace physim {

/// A convex polygon of 3 to Polygon::maxVertices vertices, given in either winding (see makePolygon).
/// The points are in the shape's own frame (the body's frame: the body origin is the local origin), metres, and
/// are kept as given. A body with this shape turns about its centroid (getMassProperties().centroid), wherever
/// that lies.
class PolygonShape final : public CollisionShape {
public:
    /// Throws std::invalid_argument naming the problem (count, non-finite, coincident, collinear, non-convex).
    explicit PolygonShape(const std::vector<Vec2>& points);

    ShapeType getType() const override { return ShapeType::POLYGON; }
    /// Width and height of the bounding box in the shape's own frame, m.
    Vec2 getSize() const override;
    std::unique_ptr<CollisionShape> clone() const override { return std::make_unique<PolygonShape>(*this); }
    /// The vertices, counter-clockwise, in the shape's own frame, m.
    std::vector<Vec2> vertices() const;
};

}  // namespace physim
