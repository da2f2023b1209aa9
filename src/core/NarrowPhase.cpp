#include "physim/core/Collide.hpp"

#include <algorithm>
#include <cmath>

namespace physim {
namespace {

Manifold circleCircle(const Circle& a, const Transform& xa, const Circle& b, const Transform& xb) {
    Manifold m;
    const Vec2 ca = xa.apply(a.center);
    const Vec2 cb = xb.apply(b.center);
    const Vec2 d = cb - ca;
    const double dist = d.norm();
    const double separation = dist - a.radius - b.radius;
    if (separation > 0.0) return m;
    // Concentric circles have no preferred direction: pick +y so the normal is always a unit vector.
    m.normal = dist > 1e-12 ? Vec2(d / dist) : Vec2(0.0, 1.0);
    m.pointCount = 1;
    m.points[0].point = ca + m.normal * (a.radius + 0.5 * separation);
    m.points[0].separation = separation;
    return m;
}

// First simple contact for shapes with corners: the overlap of the two world bounding boxes, resolved along
// the axis of least overlap, with up to two points spanning the shared face. Exact for axis-aligned boxes;
// rotated polygons and circle-polygon pairs get the bounding-box approximation until the SAT narrow phase
// (the collision-detection issue) replaces this function.
Manifold boundingBoxContact(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
    Manifold m;
    const Aabb ba = computeAabb(a, xa);
    const Aabb bb = computeAabb(b, xb);
    const Vec2 lo = ba.lower.cwiseMax(bb.lower);
    const Vec2 hi = ba.upper.cwiseMin(bb.upper);
    const Vec2 overlap = hi - lo;
    if (overlap.x() < 0.0 || overlap.y() < 0.0) return m;

    const int axis = overlap.x() < overlap.y() ? 0 : 1;  // separate along the smaller overlap
    const int other = 1 - axis;
    const double direction = bb.center()[axis] >= ba.center()[axis] ? 1.0 : -1.0;
    m.normal = Vec2::Zero();
    m.normal[axis] = direction;

    const double faceMid = 0.5 * (lo[axis] + hi[axis]);
    const double separation = -overlap[axis];
    const bool twoPoints = overlap[other] > 1e-9;
    m.pointCount = twoPoints ? 2 : 1;
    for (int i = 0; i < m.pointCount; ++i) {
        Vec2 p;
        p[axis] = faceMid;
        p[other] = (i == 0) ? lo[other] : hi[other];
        m.points[i].point = p;
        m.points[i].separation = separation;
        m.points[i].id = static_cast<std::uint32_t>(i + 2 * axis);
    }
    return m;
}

}  // namespace

Manifold collide(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
    const auto* ca = std::get_if<Circle>(&a);
    const auto* cb = std::get_if<Circle>(&b);
    if (ca && cb) return circleCircle(*ca, xa, *cb, xb);
    return boundingBoxContact(a, xa, b, xb);
}

}  // namespace physim
