#include "physim/core/CollisionShape.hpp"

#include "physim/core/CapsuleShape.hpp"
#include "physim/core/ChainShape.hpp"
#include "physim/core/CircleShape.hpp"
#include "physim/core/Collide.hpp"
#include "physim/core/GeometryShape.hpp"
#include "physim/core/PolygonShape.hpp"
#include "physim/core/RectangleShape.hpp"
#include "physim/core/SegmentShape.hpp"
#include "physim/core/Validate.hpp"

#include <stdexcept>

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

double positive(const char* name, double value) {
    requirePositive(name, value);
    return value;
}

std::vector<Geometry> chainPieces(const std::vector<Vec2>& points, bool loop) {
    const std::vector<ChainSegment> chain = makeChain(points, loop);
    return {chain.begin(), chain.end()};
}

Polygon polygon(const std::vector<Vec2>& points, double radius) {
    requireNonNegative("polygon radius", radius);
    return radius > 0.0 ? makeRoundedPolygon(points, radius) : makePolygon(points);
}

}  // namespace

CollisionShape::CollisionShape(Geometry geometry) : geometry_(std::move(geometry)) { validate(geometry_); }

CollisionShape::CollisionShape(const std::vector<Geometry>& pieces)
    : geometry_(pieces.empty() ? throw std::invalid_argument("physim: a collision shape needs a piece, got none")
                               : pieces.front()),
      morePieces_(pieces.begin() + 1, pieces.end()) {
    for (const Geometry& g : pieces) validate(g);
}

std::vector<Geometry> CollisionShape::pieces() const {
    std::vector<Geometry> all{geometry_};
    all.insert(all.end(), morePieces_.begin(), morePieces_.end());
    return all;
}

void CollisionShape::setTransform(const Vec2& position, double angle) {
    requireFinite("shape position", position);
    requireFinite("shape angle", angle);
    transform_ = {position, Rotation::fromAngle(angle)};
    angle_ = angle;
}

Aabb CollisionShape::getBounds() const {
    Aabb box = computeAabb(geometry_, transform_);
    for (const Geometry& g : morePieces_) box = Aabb::merged(box, computeAabb(g, transform_));
    return box;
}

bool CollisionShape::aabbCollision(const CollisionShape& other) const {
    return getBounds().overlaps(other.getBounds());
}

Colliding CollisionShape::satCollision(const CollisionShape& other) const {
    if (morePieces_.empty() && other.morePieces_.empty())
        return computeColliding(geometry_, transform_, other.geometry_, other.transform_);
    Colliding deepest;
    for (const Geometry& a : pieces())
        for (const Geometry& b : other.pieces()) {
            const Colliding c = computeColliding(a, transform_, b, other.transform_);
            if (c.collision && (!deepest.collision || c.penetration > deepest.penetration)) deepest = c;
        }
    return deepest;
}

CircleShape::CircleShape(double radius) : CollisionShape(makeCircle(radius)) {}

double CircleShape::radius() const { return std::get<Circle>(geometry()).radius; }

RectangleShape::RectangleShape(const Vec2& size)
    : CollisionShape(rectangle(size)), size_(size) {}

PolygonShape::PolygonShape(const std::vector<Vec2>& points, double radius)
    : CollisionShape(polygon(points, radius)) {}

double PolygonShape::radius() const { return std::get<Polygon>(geometry()).radius; }

Vec2 PolygonShape::getSize() const { return localSize(geometry()); }

std::vector<Vec2> PolygonShape::vertices() const {
    const auto& p = std::get<Polygon>(geometry());
    return {p.vertices.begin(), p.vertices.begin() + p.count};
}

SegmentShape::SegmentShape(const Vec2& point1, const Vec2& point2)
    : CollisionShape(makeSegment(point1, point2)) {}

Vec2 SegmentShape::getSize() const { return localSize(geometry()); }
Vec2 SegmentShape::point1() const { return std::get<Segment>(geometry()).point1; }
Vec2 SegmentShape::point2() const { return std::get<Segment>(geometry()).point2; }

CapsuleShape::CapsuleShape(const Vec2& center1, const Vec2& center2, double radius)
    : CollisionShape(makeCapsule(center1, center2, radius)) {}

CapsuleShape::CapsuleShape(double length, double radius)
    : CapsuleShape({-0.5 * positive("capsule length", length), 0.0}, {0.5 * length, 0.0}, radius) {}

Vec2 CapsuleShape::getSize() const { return localSize(geometry()); }
Vec2 CapsuleShape::center1() const { return std::get<Capsule>(geometry()).center1; }
Vec2 CapsuleShape::center2() const { return std::get<Capsule>(geometry()).center2; }
double CapsuleShape::radius() const { return std::get<Capsule>(geometry()).radius; }

ChainShape::ChainShape(const std::vector<Vec2>& points, bool loop)
    : CollisionShape(chainPieces(points, loop)), points_(points), loop_(loop) {}

Vec2 ChainShape::getSize() const {
    Aabb box{points_.front(), points_.front()};
    for (const Vec2& p : points_) box = Aabb::merged(box, Aabb{p, p});
    return box.upper - box.lower;
}

GeometryShape::GeometryShape(Geometry geometry) : CollisionShape(std::move(geometry)) {}

Vec2 GeometryShape::getSize() const { return localSize(geometry()); }

}  // namespace physim
