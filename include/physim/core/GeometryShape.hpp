#pragma once

#include "physim/core/CollisionShape.hpp"

namespace physim {

/// A collision shape of any Geometry kind, those added after the paper's included: what an Object takes for a
/// kind without a wrapper of its own (CircleShape, RectangleShape and PolygonShape are the paper's).
class GeometryShape final : public CollisionShape {
public:
    /// Throws std::invalid_argument naming the problem when validate(geometry) does.
    explicit GeometryShape(Geometry geometry);

    ShapeType getType() const override { return ShapeType::GEOMETRY; }
    /// Width and height of the bounding box in the shape's own frame, m: (2r, 2r) for a circle of radius r.
    Vec2 getSize() const override;
    std::unique_ptr<CollisionShape> clone() const override { return std::make_unique<GeometryShape>(*this); }
};

}  // namespace physim
