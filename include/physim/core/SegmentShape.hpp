#pragma once

#include "physim/core/CollisionShape.hpp"

namespace physim {

/// A line between two points (makeSegment): zero thickness, two-sided, no area, so no mass. Ground and walls: an
/// Object of this shape alone is static. The points are in the shape's own frame (the body's), metres.
class SegmentShape final : public CollisionShape {
public:
    /// Throws std::invalid_argument for a non-finite point or point1 == point2.
    SegmentShape(const Vec2& point1, const Vec2& point2);

    ShapeType getType() const override { return ShapeType::SEGMENT; }
    /// Width and height of the bounding box in the shape's own frame, m (one of them 0 for an axis-aligned line).
    Vec2 getSize() const override;
    std::unique_ptr<CollisionShape> clone() const override { return std::make_unique<SegmentShape>(*this); }
    Vec2 point1() const;
    Vec2 point2() const;
};

}  // namespace physim
