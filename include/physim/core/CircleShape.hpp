#pragma once

#include "physim/core/CollisionShape.hpp"

namespace physim {

class CircleShape final : public CollisionShape {
public:
    /// radius in metres, > 0 (throws std::invalid_argument otherwise).
    explicit CircleShape(double radius);

    ShapeType getType() const override { return ShapeType::CIRCLE; }
    Vec2 getSize() const override { return {radius(), 0.0}; }
    std::unique_ptr<CollisionShape> clone() const override { return std::make_unique<CircleShape>(*this); }
    double radius() const;
};

}  // namespace physim
