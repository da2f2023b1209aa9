#pragma once
// The circle's room: everything a circle provides (ShapeKind.hpp lists what a kind must). Internal.
// CollideCircles.cpp holds its narrow phase; its kernel side is kernel::kCircle in ContinuousKernel.hpp (circleCircle,
// turningReach, shapeHolds).

#include "ShapeKind.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace physim {

NarrowResult collideCircles(const Circle& a, const Transform& xa, const Circle& b, const Transform& xb,
                            double margin = 0.0);

template <>
struct ShapeKind<Circle> {
    static constexpr const char* name = "circle";
    static constexpr kernel::ShapeKind kernelKind = kernel::kCircle;
    static constexpr int minVertices = 1, maxVertices = 1;
    static constexpr const char* vertexCounts = "1 (its centre)";

    static MassProperties mass(const Circle& c) {
        const double r2 = c.radius * c.radius;
        const double area = M_PI * r2;
        return {area, c.center, 0.5 * area * r2};  // solid disc: I = m r^2 / 2
    }
    static Aabb aabb(const Circle& c, const Transform& xf) {
        const Vec2 center = xf.apply(c.center);
        return {center.array() - c.radius, center.array() + c.radius};
    }
    static double boundingRadius(const Circle& c) { return std::hypot(c.center.x(), c.center.y()) + c.radius; }
    static double coreRadius(const Circle& c) { return c.radius; }
    // The outline turns onto itself, so only the centre's offset counts (a rolling ball is not carried into the
    // ground by its spin).
    static double turningRadius(const Circle& c) { return c.center.norm(); }
    static double extentAbout(const Circle& c, const Vec2& center) { return (c.center - center).norm() + c.radius; }
    static double meanWidth(const Circle& c) { return 2.0 * c.radius; }
    static void validate(const Circle& c);
    static std::vector<Vec2> outline(const Circle& c, const Transform& xf);
    static Circle placed(const Circle& c, const Transform& xf) { return {xf.apply(c.center), c.radius}; }

    static LocalRayHit rayCast(const Circle& c, const LocalRay& ray) { return rayCastDisc(ray, c.center, c.radius); }
    static bool containsPoint(const Circle& c, const Vec2& p) {
        return (p - c.center).squaredNorm() <= c.radius * c.radius;
    }

    // The kernel's circle: its centre is its one vertex.
    static void toKernel(const Circle& c, kernel::Shape& k) {
        k.kind = kernelKind;
        k.count = 1;
        k.radius = c.radius;
        k.vertices[0] = {c.center.x(), c.center.y()};
    }
    static Circle fromBatch(const ContinuousBatch::Shapes& s, std::size_t i) {
        const std::int32_t first = s.firstVertex[i];
        return Circle{{s.vertexX[first], s.vertexY[first]}, s.radius[i]};
    }
    static std::string radiusProblem(double) { return {}; }  // validate() checks the radius
    static std::string kernelProblem(const Circle&) { return {}; }

    static NarrowResult collide(const Circle& a, const Transform& xa, const Circle& b, const Transform& xb,
                                double margin) {
        return collideCircles(a, xa, b, xb, margin);
    }
};

}  // namespace physim
