#pragma once

#include "physim/core/CollisionShape.hpp"

#include <vector>

namespace physim {

/// Ground or walls as a polyline of many pieces (makeChain; World::createChain builds it in a world): smooth where
/// the pieces meet, colliding on the left of the direction of travel (ground listed left to right is solid below,
/// a counter-clockwise loop holds bodies inside). No area, so no mass: an Object of this shape is static. Points in
/// the shape's own frame (the body's), metres.
class ChainShape final : public CollisionShape {
public:
    /// Throws std::invalid_argument as makeChain does: fewer than 2 points (3 for a loop), a non-finite point, two
    /// consecutive points that coincide.
    explicit ChainShape(const std::vector<Vec2>& points, bool loop = false);

    ShapeType getType() const override { return ShapeType::CHAIN; }
    /// Width and height of the points' bounding box in the shape's own frame, m.
    Vec2 getSize() const override;
    std::unique_ptr<CollisionShape> clone() const override { return std::make_unique<ChainShape>(*this); }
    const std::vector<Vec2>& points() const { return points_; }
    bool loop() const { return loop_; }

private:
    std::vector<Vec2> points_;
    bool loop_ = false;
};

}  // namespace physim
