// Narrow-phase dispatch on the pair of geometry types, and the paper's Colliding built from the result.

#include "Manifolds.hpp"

#include "physim/core/Collide.hpp"

#include <algorithm>

namespace physim {
namespace {

NarrowResult swapped(NarrowResult r) {
    // The routine ran with the shapes swapped: the same points, the normal reversed to run from a to b.
    r.manifold.normal = -r.manifold.normal;
    return r;
}

}  // namespace

NarrowResult collideGeometries(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb,
                               double margin) {
    const auto* ca = std::get_if<Circle>(&a);
    const auto* cb = std::get_if<Circle>(&b);
    if (ca && cb) return collideCircles(*ca, xa, *cb, xb, margin);
    if (cb) return collidePolygonAndCircle(std::get<Polygon>(a), xa, *cb, xb, margin);
    if (ca) return swapped(collidePolygonAndCircle(std::get<Polygon>(b), xb, *ca, xa, margin));
    return collidePolygons(std::get<Polygon>(a), xa, std::get<Polygon>(b), xb, margin);
}

Manifold collide(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
    return collideGeometries(a, xa, b, xb).manifold;
}

Colliding computeColliding(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
    const NarrowResult r = collideGeometries(a, xa, b, xb);
    const Manifold& m = r.manifold;
    Colliding c;
    if (m.pointCount == 0) return c;
    c.collision = true;
    c.normal = m.normal;
    c.penetration = std::max(-r.separation, 0.0);
    double shallowest = -m.points[0].separation;
    for (int i = 1; i < m.pointCount; ++i) shallowest = std::min(shallowest, -m.points[i].separation);
    c.overlap = std::max(shallowest, 0.0);
    c.collidingPoints.contactCount = m.pointCount;
    c.collidingPoints.pointA = m.points[0].point;
    if (m.pointCount > 1) c.collidingPoints.pointB = m.points[1].point;
    return c;
}

}  // namespace physim
