#include "physim/core/CollisionShape.hpp"

#include "physim/core/CircleShape.hpp"
#include "physim/core/Collide.hpp"
#include "physim/core/GeometryShape.hpp"
#include "physim/core/PolygonShape.hpp"
#include "physim/core/RectangleShape.hpp"
#include "physim/core/Validate.hpp"

namespace physim {
namespace {

Polygon rectangle(const Vec2& size) {
    requirePositive("rectangle width", size.x());
    requirePositive("rectangle height", size.y());
    return makeBox(0.5 * size.x(), 0.5 * size.y());
}

// Width and height of the bounding box in the shape's own frame, m: any kind, through its room.
Vec2 localSize(const Geometry& g) {
    const Aabb local = computeAabb(g, Transform{});
    return local.upper - local.lower;
}

}  // namespace

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
    return computeColliding(geometry_, transform_, other.geometry_, other.transform_);
}

CircleShape::CircleShape(double radius) : CollisionShape(makeCircle(radius)) {}

double CircleShape::radius() const { return std::get<Circle>(geometry()).radius; }

RectangleShape::RectangleShape(const Vec2& size)
    : CollisionShape(rectangle(size)), size_(size) {}

PolygonShape::PolygonShape(const std::vector<Vec2>& points) : CollisionShape(makePolygon(points)) {}

Vec2 PolygonShape::getSize() const { return localSize(geometry()); }

std::vector<Vec2> PolygonShape::vertices() const {
    const auto& p = std::get<Polygon>(geometry());
    return {p.vertices.begin(), p.vertices.begin() + p.count};
}

GeometryShape::GeometryShape(Geometry geometry) : CollisionShape(std::move(geometry)) {}

Vec2 GeometryShape::getSize() const { return localSize(geometry()); }

}  // namespace physim
