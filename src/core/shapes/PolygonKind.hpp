#pragma once
// The convex polygon's room: everything a polygon provides (ShapeKind.hpp lists what a kind must). Internal.
// Polygon.cpp builds polygons (makeBox, makePolygon), CollidePolygons.cpp and CollideCircles.cpp hold its narrow
// phase; its kernel side is kernel::kPolygon in ContinuousKernel.hpp (polygonCircle, polygonPolygon, polygonHolds).

#include "ShapeKind.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace physim {

static_assert(Polygon::maxVertices == kernel::kMaxVertices, "the kernel holds every polygon the core makes");

/// Normal from the polygon to the circle.
NarrowResult collidePolygonAndCircle(const Polygon& a, const Transform& xa, const Circle& b, const Transform& xb,
                                     double margin = 0.0);
NarrowResult collidePolygons(const Polygon& a, const Transform& xa, const Polygon& b, const Transform& xb,
                             double margin = 0.0);

template <>
struct ShapeKind<Polygon> {
    static constexpr const char* name = "polygon";
    static constexpr kernel::ShapeKind kernelKind = kernel::kPolygon;
    static constexpr int minVertices = 3, maxVertices = Polygon::maxVertices;
    static constexpr const char* vertexCounts = "3 to 8";

    static MassProperties mass(const Polygon& p);
    static Aabb aabb(const Polygon& p, const Transform& xf) {
        Vec2 lower = xf.apply(p.vertices[0]);
        Vec2 upper = lower;
        for (int i = 1; i < p.count; ++i) {
            const Vec2 v = xf.apply(p.vertices[i]);
            lower = lower.cwiseMin(v);
            upper = upper.cwiseMax(v);
        }
        return {lower, upper};
    }
    static double boundingRadius(const Polygon& p) {
        double r = 0.0;
        for (int i = 0; i < p.count; ++i) r = std::max(r, std::hypot(p.vertices[i].x(), p.vertices[i].y()));
        return r;
    }
    static double coreRadius(const Polygon& p);
    static double turningRadius(const Polygon& p) { return boundingRadius(p); }
    static double extentAbout(const Polygon& p, const Vec2& center);
    static double meanWidth(const Polygon& p);
    static void validate(const Polygon& p);
    static std::vector<Vec2> outline(const Polygon& p, const Transform& xf);

    static void toKernel(const Polygon& p, kernel::Shape& k) {
        k.kind = kernelKind;
        k.count = p.count;
        k.radius = 0.0;
        for (int i = 0; i < p.count; ++i) {
            k.vertices[i] = {p.vertices[i].x(), p.vertices[i].y()};
            k.normals[i] = {p.normals[i].x(), p.normals[i].y()};
        }
    }
    static Polygon fromBatch(const ContinuousBatch::Shapes& s, std::size_t i);
    static std::string radiusProblem(double radius) { return radius != 0.0 ? "a polygon has radius 0" : ""; }
    static std::string kernelProblem(const Polygon& p);

    static NarrowResult collide(const Polygon& a, const Transform& xa, const Circle& b, const Transform& xb,
                                double margin) {
        return collidePolygonAndCircle(a, xa, b, xb, margin);
    }
    static NarrowResult collide(const Polygon& a, const Transform& xa, const Polygon& b, const Transform& xb,
                                double margin) {
        return collidePolygons(a, xa, b, xb, margin);
    }
};

}  // namespace physim
