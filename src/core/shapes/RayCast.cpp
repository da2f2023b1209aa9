// Ray against one shape, and a point's distance to a rounded core: the shared geometry of the kinds' queries.

#include "RayCast.hpp"

#include <algorithm>
#include <cmath>

namespace physim {

LocalRayHit rayCastDisc(const LocalRay& ray, const Vec2& center, double radius) {
    const Vec2 s = ray.origin - center;
    const Vec2& d = ray.translation;
    const double b = s.dot(d);
    const double c = s.squaredNorm() - radius * radius;
    // Inside (c < 0), or outside and not closing in: no entry.
    if (c < 0.0 || b >= 0.0) return {};
    const double disc = b * b - d.squaredNorm() * c;
    if (disc < 0.0) return {};
    // The smaller root (-b - sqrt(disc)) / |d|^2, written as c / (-b + sqrt(disc)) so that it does not cancel.
    const double t = c / (-b + std::sqrt(disc));
    if (t > ray.maxFraction) return {};
    const Vec2 point = ray.origin + t * d;
    const Vec2 out = point - center;
    const double length = out.norm();
    return {true, t, point, length > 0.0 ? Vec2(out / length) : Vec2(-d.normalized())};
}

LocalRayHit rayCastConvex(const LocalRay& ray, const Vec2* vertices, const Vec2* normals, int count) {
    // The ray inside every edge's half-plane is [lower, upper]; it enters through the edge that raised lower last.
    double lower = 0.0, upper = ray.maxFraction;
    int entry = -1;
    for (int i = 0; i < count; ++i) {
        const double numerator = normals[i].dot(vertices[i] - ray.origin);  // > 0: origin inside this half-plane
        const double denominator = normals[i].dot(ray.translation);
        if (denominator == 0.0) {
            if (numerator < 0.0) return {};  // parallel and outside
        } else if (denominator < 0.0 && numerator < lower * denominator) {
            lower = numerator / denominator;
            entry = i;
        } else if (denominator > 0.0 && numerator < upper * denominator) {
            upper = numerator / denominator;
        }
        if (upper < lower) return {};
    }
    if (entry < 0) return {};  // the origin is inside (or on an edge going out)
    return {true, lower, ray.origin + lower * ray.translation, normals[entry]};
}

LocalRayHit rayCastSegment(const LocalRay& ray, const Vec2& p1, const Vec2& p2) {
    const Vec2 e = p2 - p1;
    const Vec2 n = Vec2(e.y(), -e.x()).normalized();
    const double denominator = n.dot(ray.translation);
    if (denominator == 0.0) return {};  // parallel: grazing along the line is not a hit
    const double t = n.dot(p1 - ray.origin) / denominator;
    if (t < 0.0 || t > ray.maxFraction) return {};
    const Vec2 point = ray.origin + t * ray.translation;
    const double s = (point - p1).dot(e) / e.squaredNorm();
    if (s < 0.0 || s > 1.0) return {};
    return {true, t, point, denominator > 0.0 ? Vec2(-n) : n};
}

LocalRayHit rayCastRounded(const RoundedCore& core, const LocalRay& ray) {
    const double r = core.radius;
    if (core.count == 1) return rayCastDisc(ray, core.vertices[0], r);
    if (distanceToCore(core, ray.origin) < r) return {};
    // The boundary is the edges pushed out by r and the arcs of the corner discs: the entry is the first of them
    // met (each lies inside the shape, so none is met before the true entry).
    LocalRay clipped = ray;
    LocalRayHit best;
    for (int i = 0; i < core.count; ++i) {
        const Vec2& n = core.normals[i];
        const double denominator = n.dot(ray.translation);
        if (denominator < 0.0) {
            const Vec2 a = core.vertices[i] + r * n;
            const Vec2 b = core.vertices[(i + 1) % core.count] + r * n;
            const double t = n.dot(a - ray.origin) / denominator;
            if (t >= 0.0 && t <= clipped.maxFraction) {
                const Vec2 point = ray.origin + t * ray.translation;
                const Vec2 e = b - a;
                const double s = (point - a).dot(e) / e.squaredNorm();
                if (s >= 0.0 && s <= 1.0) {
                    best = {true, t, point, n};
                    clipped.maxFraction = t;
                }
            }
        }
        const LocalRayHit corner = rayCastDisc(clipped, core.vertices[i], r);
        if (corner.hit && (!best.hit || corner.fraction < best.fraction)) {
            best = corner;
            clipped.maxFraction = corner.fraction;
        }
    }
    return best;
}

namespace {

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 e = b - a;
    const double s = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
    return (p - (a + s * e)).norm();
}

}  // namespace

double distanceToCore(const RoundedCore& core, const Vec2& p) {
    if (core.count == 1) return (p - core.vertices[0]).norm();
    if (core.count == 2) return distanceToSegment(p, core.vertices[0], core.vertices[1]);
    bool inside = true;
    for (int i = 0; i < core.count; ++i) inside = inside && core.normals[i].dot(p - core.vertices[i]) <= 0.0;
    if (inside) return 0.0;
    double best = INFINITY;
    for (int i = 0; i < core.count; ++i)
        best = std::min(best, distanceToSegment(p, core.vertices[i], core.vertices[(i + 1) % core.count]));
    return best;
}

}  // namespace physim
