#include "physim/core/Geometry.hpp"

#include "PolygonCheck.hpp"

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
    if (p.count >= 3 && p.count <= Polygon::maxVertices && signedArea(p.vertices.data(), p.count) < 0.0)
        throw std::invalid_argument("physim: polygon vertices must be counter-clockwise, got clockwise "
                                    "(makePolygon accepts either winding)");
    checkConvexCounterClockwise(p.vertices.data(), p.count, "polygon");
    // The narrow phase trusts the normals: each must be its edge's outward unit normal. 1e-9 allows the
    // rounding of normalising a finite edge, nothing more.
    for (int i = 0; i < p.count; ++i) {
        const Vec2 edge = p.vertices[(i + 1) % p.count] - p.vertices[i];
        const Vec2 expected = Vec2(edge.y(), -edge.x()).normalized();
        if (!std::isfinite(p.normals[i].x()) || !std::isfinite(p.normals[i].y()) ||
            (p.normals[i] - expected).norm() > 1e-9)
            throw std::invalid_argument("physim: polygon normal " + std::to_string(i) +
                                        " must be the outward unit normal of edge " + std::to_string(i) + " (" +
                                        std::to_string(expected.x()) + ", " + std::to_string(expected.y()) +
                                        "), got (" + std::to_string(p.normals[i].x()) + ", " +
                                        std::to_string(p.normals[i].y()) + ")");
    }
}

}  // namespace physim
