#pragma once

#include "physim/core/CollisionShape.hpp"

namespace physim {

/// A capsule (makeCapsule): every point within `radius` of the segment between its two centres, a stadium with
/// round ends. Centres in the shape's own frame (the body's), metres.
class CapsuleShape final : public CollisionShape {
public:
    /// Throws std::invalid_argument for a non-finite centre, center1 == center2 (use a CircleShape) or a radius
    /// <= 0 or NaN.
    CapsuleShape(const Vec2& center1, const Vec2& center2, double radius);
    /// Lying along x, centred on the origin: the centres `length` m apart (> 0), total length length + 2 radius.
    CapsuleShape(double length, double radius);

    ShapeType getType() const override { return ShapeType::CAPSULE; }
    /// Width and height of the bounding box in the shape's own frame, m: (length + 2r, 2r) for the second form.
    Vec2 getSize() const override;
    std::unique_ptr<CollisionShape> clone() const override { return std::make_unique<CapsuleShape>(*this); }
    Vec2 center1() const;
    Vec2 center2() const;
    double radius() const;  ///< m
};

}  // namespace physim
