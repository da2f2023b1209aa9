#include "physim/core/Geometry.hpp"

#include "physim/core/Validate.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace physim {

Circle makeCircle(double radius, const Vec2& center) {
    requirePositive("circle radius", radius);
    requireFinite("circle center", center);
    return Circle{center, radius};
}

Polygon makeBox(double halfWidth, double halfHeight) {
    requirePositive("box half-width", halfWidth);
    requirePositive("box half-height", halfHeight);
    Polygon p;
    p.count = 4;
    p.vertices[0] = {-halfWidth, -halfHeight};
    p.vertices[1] = {halfWidth, -halfHeight};
    p.vertices[2] = {halfWidth, halfHeight};
    p.vertices[3] = {-halfWidth, halfHeight};
    p.normals[0] = {0.0, -1.0};
    p.normals[1] = {1.0, 0.0};
    p.normals[2] = {0.0, 1.0};
    p.normals[3] = {-1.0, 0.0};
    return p;
}

namespace {

MassProperties massOf(const Circle& c) {
    const double r2 = c.radius * c.radius;
    const double area = M_PI * r2;
    return {area, c.center, 0.5 * area * r2};  // solid disc: I = m r^2 / 2
}

// Decompose into triangles fanned from the first vertex; sum their areas, centroids and second moments.
MassProperties massOf(const Polygon& p) {
    const Vec2 origin = p.vertices[0];
    double area = 0.0;
    Vec2 weighted = Vec2::Zero();
    double momentAboutOrigin = 0.0;  // second moment about `origin`
    for (int i = 1; i + 1 < p.count; ++i) {
        const Vec2 e1 = p.vertices[i] - origin;
        const Vec2 e2 = p.vertices[i + 1] - origin;
        const double a = 0.5 * cross(e1, e2);
        area += a;
        weighted += a * (e1 + e2) / 3.0;
        momentAboutOrigin += a / 6.0 * (e1.squaredNorm() + e1.dot(e2) + e2.squaredNorm());
    }
    const Vec2 centroidFromOrigin = weighted / area;
    const double aboutCentroid = momentAboutOrigin - area * centroidFromOrigin.squaredNorm();
    return {area, origin + centroidFromOrigin, aboutCentroid};
}

}  // namespace

MassProperties computeMassProperties(const Geometry& g) {
    return std::visit([](const auto& shape) { return massOf(shape); }, g);
}

Aabb computeAabb(const Geometry& g, const Transform& xf) {
    if (const auto* c = std::get_if<Circle>(&g)) {
        const Vec2 center = xf.apply(c->center);
        return {center.array() - c->radius, center.array() + c->radius};
    }
    const auto& p = std::get<Polygon>(g);
    Vec2 lower = xf.apply(p.vertices[0]);
    Vec2 upper = lower;
    for (int i = 1; i < p.count; ++i) {
        const Vec2 v = xf.apply(p.vertices[i]);
        lower = lower.cwiseMin(v);
        upper = upper.cwiseMax(v);
    }
    return {lower, upper};
}

}  // namespace physim

namespace physim {

void validate(const Geometry& g) {
    if (const auto* c = std::get_if<Circle>(&g)) {
        requirePositive("circle radius", c->radius);
        requireFinite("circle center", c->center);
        return;
    }
    const auto& p = std::get<Polygon>(g);
    if (p.count < 3 || p.count > Polygon::maxVertices)
        throw std::invalid_argument("physim: polygon vertex count must be in [3, " +
                                    std::to_string(Polygon::maxVertices) + "], got " + std::to_string(p.count));
    for (int i = 0; i < p.count; ++i) requireFinite("polygon vertex", p.vertices[i]);
}

}  // namespace physim
