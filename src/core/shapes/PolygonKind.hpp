#pragma once
// The convex polygon's room: everything a polygon provides (ShapeKind.hpp lists what a kind must). Internal.
// Polygon.cpp builds polygons (makeBox, makePolygon, the rounded ones), CollidePolygons.cpp and CollideCircles.cpp
// hold its narrow phase at radius 0, CollideRounded.cpp with a radius; its kernel side is kernel::kPolygon in
// ContinuousKernel.hpp (polygonCircle, polygonPolygon, polygonHolds). A rounded polygon is its core (vertices,
// normals) grown by radius: every query below adds the radius to the core's answer.

#include "RoundedCore.hpp"
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
        if (p.radius > 0.0) return {lower.array() - p.radius, upper.array() + p.radius};
        return {lower, upper};
    }
    static double boundingRadius(const Polygon& p) { return turningRadius(p) + p.radius; }
    static double coreRadius(const Polygon& p);
    // The round corners turn onto themselves: only the core's vertices count (as a circle's centre).
    static double turningRadius(const Polygon& p) {
        double r = 0.0;
        for (int i = 0; i < p.count; ++i) r = std::max(r, std::hypot(p.vertices[i].x(), p.vertices[i].y()));
        return r;
    }
    static double extentAbout(const Polygon& p, const Vec2& center);
    static double meanWidth(const Polygon& p);
    static void validate(const Polygon& p);
    static std::vector<Vec2> outline(const Polygon& p, const Transform& xf);
    static Polygon placed(const Polygon& p, const Transform& xf) {
        Polygon q = p;
        for (int i = 0; i < p.count; ++i) {
            q.vertices[i] = xf.apply(p.vertices[i]);
            q.normals[i] = xf.q.apply(p.normals[i]);
        }
        return q;
    }

    static LocalRayHit rayCast(const Polygon& p, const LocalRay& ray) {
        if (p.radius == 0.0) return rayCastConvex(ray, p.vertices.data(), p.normals.data(), p.count);
        return rayCastRounded(coreOf(p), ray);
    }
    static bool containsPoint(const Polygon& p, const Vec2& q) {
        if (p.radius > 0.0) return distanceToCore(coreOf(p), q) <= p.radius;
        for (int i = 0; i < p.count; ++i)
            if (p.normals[i].dot(q - p.vertices[i]) > 0.0) return false;
        return true;
    }

    static void toKernel(const Polygon& p, kernel::Shape& k) {
        k.kind = kernelKind;
        k.count = p.count;
        k.radius = p.radius;
        for (int i = 0; i < p.count; ++i) {
            k.vertices[i] = {p.vertices[i].x(), p.vertices[i].y()};
            k.normals[i] = {p.normals[i].x(), p.normals[i].y()};
        }
    }
    static Polygon fromBatch(const ContinuousBatch::Shapes& s, std::size_t i);
    static std::string radiusProblem(double radius) {
        return std::isfinite(radius) && radius >= 0.0 ? "" : "a polygon's radius is finite and >= 0";
    }
    static std::string kernelProblem(const Polygon& p);

    // Radius 0: the polygon routines as they were; rounded: the rounded cores' routine.
    static NarrowResult collide(const Polygon& a, const Transform& xa, const Circle& b, const Transform& xb,
                                double margin) {
        if (a.radius == 0.0) return collidePolygonAndCircle(a, xa, b, xb, margin);
        return collideRounded(coreOf(a), xa, coreOf(b), xb, margin);
    }
    static NarrowResult collide(const Polygon& a, const Transform& xa, const Polygon& b, const Transform& xb,
                                double margin) {
        if (a.radius == 0.0 && b.radius == 0.0) return collidePolygons(a, xa, b, xb, margin);
        return collideRounded(coreOf(a), xa, coreOf(b), xb, margin);
    }
};

}  // namespace physim
