// Narrow phase for pairs with a circle: circle-circle and polygon-circle, both exact.

#include "CircleKind.hpp"
#include "PolygonKind.hpp"

#include <cmath>
#include <limits>

namespace physim {
namespace {

// Unit vector along v, whose length (std::hypot's) the caller has, or `fallback` when v is zero. std::hypot does
// not underflow for tiny components, so any non-zero finite v gives a unit vector (never NaN).
Vec2 directionOr(const Vec2& v, double length, const Vec2& fallback) {
    return length > 0.0 ? Vec2(v / length) : fallback;
}

}  // namespace

NarrowResult collideCircles(const Circle& a, const Transform& xa, const Circle& b, const Transform& xb,
                            double margin) {
    NarrowResult r;
    const Vec2 ca = xa.apply(a.center);
    const Vec2 cb = xb.apply(b.center);
    const Vec2 d = cb - ca;
    const double distance = std::hypot(d.x(), d.y());
    r.separation = distance - a.radius - b.radius;
    if (r.separation > margin) return r;
    Manifold& m = r.manifold;
    // Concentric circles have no preferred direction: +y keeps the normal a unit vector, and every direction
    // needs the same push (the sum of the radii).
    m.normal = directionOr(d, distance, Vec2(0.0, 1.0));
    m.pointCount = 1;
    m.points[0].point = ca + (a.radius + 0.5 * r.separation) * m.normal;
    m.points[0].separation = r.separation;
    m.points[0].id = 0;
    return r;
}

// Works in the polygon's frame. The face of greatest separation s_i = n_i . (c - v_i) decides: s_i > radius
// means a separating axis; s_i <= 0 means the centre is inside (or on) the polygon and that face is the
// nearest way out; otherwise the closest point of the polygon lies on that face's edge (for a convex polygon
// the face of greatest separation bounds the Voronoi region holding the centre), at an end vertex or inside.
NarrowResult collidePolygonAndCircle(const Polygon& a, const Transform& xa, const Circle& b,
                                     const Transform& xb, double margin) {
    NarrowResult r;
    const Vec2 c = xa.applyInverse(xb.apply(b.center));
    int face = 0;
    double faceSeparation = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < a.count; ++i) {
        const double s = a.normals[i].dot(c - a.vertices[i]);
        if (s > faceSeparation) {
            faceSeparation = s;
            face = i;
        }
    }
    if (faceSeparation > b.radius + margin) {
        r.separation = faceSeparation - b.radius;
        return r;
    }

    const Vec2& v1 = a.vertices[face];
    const Vec2& v2 = a.vertices[(face + 1) % a.count];
    Vec2 normal = a.normals[face];  // local to the polygon
    Vec2 surface;                   // closest point of the polygon's boundary to the centre, local
    double distance;                // signed distance from that boundary to the centre along `normal`
    std::uint32_t feature;          // 0..7 faces, 8..15 vertices
    const double u1 = (c - v1).dot(v2 - v1), u2 = (c - v2).dot(v1 - v2);
    if (faceSeparation <= 0.0 || (u1 > 0.0 && u2 > 0.0)) {
        surface = c - faceSeparation * normal;
        distance = faceSeparation;
        feature = static_cast<std::uint32_t>(face);
    } else {
        const int vertex = u1 <= 0.0 ? face : (face + 1) % a.count;
        surface = a.vertices[vertex];
        const Vec2 d = c - surface;
        distance = std::hypot(d.x(), d.y());
        if (distance > b.radius + margin) {
            r.separation = distance - b.radius;
            return r;
        }
        normal = directionOr(d, distance, normal);  // d is non-zero here: faceSeparation > 0 puts c off the boundary
        feature = 8u + static_cast<std::uint32_t>(vertex);
    }

    r.separation = distance - b.radius;
    Manifold& m = r.manifold;
    m.normal = xa.q.apply(normal);
    m.pointCount = 1;
    // Midway between the polygon's surface point and the circle's deepest point (c - radius * normal).
    m.points[0].point = xa.apply(surface + 0.5 * r.separation * normal);
    m.points[0].separation = r.separation;
    m.points[0].id = feature;
    return r;
}

}  // namespace physim
