#pragma once
// The segment's room: everything a segment provides (ShapeKind.hpp lists what a kind must). Internal.
// SegmentKind.cpp holds its factory, checks and outline; CollideRounded.cpp its narrow phase (a 2-vertex core of
// radius 0). TwoPoints below is shared with the capsule and the chain segment, the other kinds made of two points.

#include "RoundedCore.hpp"
#include "ShapeKind.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace physim {

/// Throws std::invalid_argument unless p1 and p2 are finite and apart (`what` names them: "segment").
void requireTwoPoints(const char* what, const char* first, const Vec2& p1, const char* second, const Vec2& p2);

/// The parts common to the kinds made of two points and a radius (0 for segments). Internal.
struct TwoPoints {
    static double length(const Vec2& p1, const Vec2& p2) { return std::hypot(p2.x() - p1.x(), p2.y() - p1.y()); }
    static Aabb aabb(const Vec2& p1, const Vec2& p2, double radius, const Transform& xf) {
        const Vec2 a = xf.apply(p1), b = xf.apply(p2);
        return {a.cwiseMin(b).array() - radius, a.cwiseMax(b).array() + radius};
    }
    static double farthest(const Vec2& p1, const Vec2& p2, const Vec2& from) {
        return std::max((p1 - from).norm(), (p2 - from).norm());
    }
    // Kernel layout (ContinuousKernel.hpp): the two points, normals[0] the outward normal of edge 0 -> 1 taken as a
    // counter-clockwise polygon, normals[1] its negative.
    static void toKernel(kernel::ShapeKind kind, const Vec2& p1, const Vec2& p2, double radius, kernel::Shape& k) {
        const RoundedCore core = coreOf(p1, p2, radius);
        k.kind = kind;
        k.count = 2;
        k.radius = radius;
        for (int i = 0; i < 2; ++i) {
            k.vertices[i] = {core.vertices[i].x(), core.vertices[i].y()};
            k.normals[i] = {core.normals[i].x(), core.normals[i].y()};
        }
    }
    static Vec2 vertex(const ContinuousBatch::Shapes& s, std::size_t i, int k) {
        const std::int32_t first = s.firstVertex[i];
        return {s.vertexX[first + k], s.vertexY[first + k]};
    }
};

template <>
struct ShapeKind<Segment> {
    static constexpr const char* name = "segment";
    static constexpr kernel::ShapeKind kernelKind = kernel::kSegment;
    static constexpr int minVertices = 2, maxVertices = 2;
    static constexpr const char* vertexCounts = "2 (its end points)";

    // Zero area: a segment adds no mass (only static and kinematic bodies may have nothing else).
    static MassProperties mass(const Segment& s) { return {0.0, 0.5 * (s.point1 + s.point2), 0.0}; }
    static Aabb aabb(const Segment& s, const Transform& xf) { return TwoPoints::aabb(s.point1, s.point2, 0.0, xf); }
    static double boundingRadius(const Segment& s) { return TwoPoints::farthest(s.point1, s.point2, Vec2::Zero()); }
    static double coreRadius(const Segment&) { return 0.0; }
    static double turningRadius(const Segment& s) { return boundingRadius(s); }
    static double extentAbout(const Segment& s, const Vec2& c) { return TwoPoints::farthest(s.point1, s.point2, c); }
    // Cauchy: perimeter / pi, the perimeter of a segment being twice its length.
    static double meanWidth(const Segment& s) { return 2.0 * TwoPoints::length(s.point1, s.point2) / M_PI; }
    static void validate(const Segment& s);
    static std::vector<Vec2> outline(const Segment& s, const Transform& xf);
    static Segment placed(const Segment& s, const Transform& xf) { return {xf.apply(s.point1), xf.apply(s.point2)}; }

    static LocalRayHit rayCast(const Segment& s, const LocalRay& ray) {
        return rayCastSegment(ray, s.point1, s.point2);
    }
    static bool containsPoint(const Segment&, const Vec2&) { return false; }  // no area

    static void toKernel(const Segment& s, kernel::Shape& k) {
        TwoPoints::toKernel(kernelKind, s.point1, s.point2, 0.0, k);
    }
    static Segment fromBatch(const ContinuousBatch::Shapes& s, std::size_t i) {
        return Segment{TwoPoints::vertex(s, i, 0), TwoPoints::vertex(s, i, 1)};
    }
    static std::string radiusProblem(double radius) { return radius != 0.0 ? "a segment has radius 0" : ""; }
    static std::string kernelProblem(const Segment&) { return {}; }

    template <class T>
    static NarrowResult collide(const Segment& a, const Transform& xa, const T& b, const Transform& xb,
                                double margin) {
        return collideRounded(coreOf(a), xa, coreOf(b), xb, margin);
    }
};

}  // namespace physim
