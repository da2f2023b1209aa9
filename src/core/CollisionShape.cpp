#include "physim/core/CollisionShape.hpp"

#include "physim/core/CircleShape.hpp"
#include "physim/core/Collide.hpp"
#include "physim/core/RectangleShape.hpp"
#include "physim/core/Validate.hpp"

#include <algorithm>

namespace physim {

CollisionShape::CollisionShape(Geometry geometry) : geometry_(std::move(geometry)) { validate(geometry_); }

void CollisionShape::setTransform(const Vec2& position, double angle) {
    requireFinite("shape position", position);
    requireFinite("shape angle", angle);
    transform_ = {position, Rotation::fromAngle(angle)};
    angle_ = angle;
}

Aabb CollisionShape::getBounds() const { return computeAabb(geometry_, transform_); }

bool CollisionShape::aabbCollision(const CollisionShape& other) const {
    return getBounds().overlaps(other.getBounds());
}

Colliding CollisionShape::satCollision(const CollisionShape& other) const {
    const Manifold m = collide(geometry_, transform_, other.geometry_, other.transform_);
    Colliding c;
    if (m.pointCount == 0) return c;
    c.collision = true;
    c.normal = m.normal;
    c.collidingPoints.contactCount = m.pointCount;
    c.collidingPoints.pointA = m.points[0].point;
    if (m.pointCount > 1) c.collidingPoints.pointB = m.points[1].point;
    double deepest = 0.0, shallowest = -m.points[0].separation;
    for (int i = 0; i < m.pointCount; ++i) {
        deepest = std::max(deepest, -m.points[i].separation);
        shallowest = std::min(shallowest, -m.points[i].separation);
    }
    c.penetration = deepest;
    c.overlap = std::max(shallowest, 0.0);
    return c;
}

CircleShape::CircleShape(double radius) : CollisionShape(makeCircle(radius)) {}

double CircleShape::radius() const { return std::get<Circle>(geometry()).radius; }

RectangleShape::RectangleShape(const Vec2& size)
    : CollisionShape(makeBox(0.5 * size.x(), 0.5 * size.y())), size_(size) {}

}  // namespace physim
