#pragma once
// The capsule's room: everything a capsule provides (ShapeKind.hpp lists what a kind must). Internal.
// CapsuleKind.cpp holds its factory, mass, checks and outline; CollideRounded.cpp its narrow phase (a 2-vertex core
// with the capsule's radius).

#include "SegmentKind.hpp"

#include <cmath>

namespace physim {

template <>
struct ShapeKind<Capsule> {
    static constexpr const char* name = "capsule";
    static constexpr kernel::ShapeKind kernelKind = kernel::kCapsule;
    static constexpr int minVertices = 2, maxVertices = 2;
    static constexpr const char* vertexCounts = "2 (its centres)";

    static MassProperties mass(const Capsule& c);
    static Aabb aabb(const Capsule& c, const Transform& xf) {
        return TwoPoints::aabb(c.center1, c.center2, c.radius, xf);
    }
    static double boundingRadius(const Capsule& c) { return turningRadius(c) + c.radius; }
    static double coreRadius(const Capsule& c) { return c.radius; }  // about the midpoint, the centroid
    // The round ends turn onto themselves: only the centres' offsets count (as for a circle).
    static double turningRadius(const Capsule& c) {
        return TwoPoints::farthest(c.center1, c.center2, Vec2::Zero());
    }
    static double extentAbout(const Capsule& c, const Vec2& p) {
        return TwoPoints::farthest(c.center1, c.center2, p) + c.radius;
    }
    // Cauchy: perimeter / pi, the perimeter being 2 L + 2 pi r.
    static double meanWidth(const Capsule& c) {
        return 2.0 * TwoPoints::length(c.center1, c.center2) / M_PI + 2.0 * c.radius;
    }
    static void validate(const Capsule& c);
    static std::vector<Vec2> outline(const Capsule& c, const Transform& xf);
    static Capsule placed(const Capsule& c, const Transform& xf) {
        return {xf.apply(c.center1), xf.apply(c.center2), c.radius};
    }

    static LocalRayHit rayCast(const Capsule& c, const LocalRay& ray) { return rayCastRounded(coreOf(c), ray); }
    static bool containsPoint(const Capsule& c, const Vec2& p) { return distanceToCore(coreOf(c), p) <= c.radius; }

    static void toKernel(const Capsule& c, kernel::Shape& k) {
        TwoPoints::toKernel(kernelKind, c.center1, c.center2, c.radius, k);
    }
    static Capsule fromBatch(const ContinuousBatch::Shapes& s, std::size_t i) {
        return Capsule{TwoPoints::vertex(s, i, 0), TwoPoints::vertex(s, i, 1), s.radius[i]};
    }
    static std::string radiusProblem(double radius) {
        return radius > 0.0 && std::isfinite(radius) ? "" : "a capsule's radius is positive and finite";
    }
    static std::string kernelProblem(const Capsule&) { return {}; }

    template <class T>
    static NarrowResult collide(const Capsule& a, const Transform& xa, const T& b, const Transform& xb,
                                double margin) {
        return collideRounded(coreOf(a), xa, coreOf(b), xb, margin);
    }
};

}  // namespace physim
