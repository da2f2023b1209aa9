#pragma once

#include "physim/core/CollisionShape.hpp"

namespace physim {

/// A rectangle centred on its centre of mass, so it rotates about its centre (not a corner).
class RectangleShape final : public CollisionShape {
public:
    /// Full width and height in metres, both > 0 (throws std::invalid_argument otherwise).
    explicit RectangleShape(const Vec2& size);

    ShapeType getType() const override { return ShapeType::RECTANGLE; }
    Vec2 getSize() const override { return size_; }
    std::unique_ptr<CollisionShape> clone() const override { return std::make_unique<RectangleShape>(*this); }

private:
    Vec2 size_;
};

}  // namespace physim
