#pragma once
// The narrow phase's common form for every pair but the radius-0 circle/polygon pairs (which keep their own
// routines): a rounded convex polygon of 1 to 8 core vertices, i.e. every point within `radius` of the core. A
// circle is 1 vertex, a segment, capsule or chain segment 2 (its two edges are the same segment both ways), a
// polygon 3 to 8. Internal.

#include "../Manifolds.hpp"

#include "physim/core/Geometry.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

namespace physim {

/// Entries past `count` are unset: nothing reads them (a core is built for each collision, so it is not cleared).
struct RoundedCore {
    std::array<Vec2, Polygon::maxVertices> vertices;
    /// count >= 2: normals[i] is the outward unit normal of edge i -> (i + 1) % count; a 2-vertex core's normals are
    /// each other's negatives.
    std::array<Vec2, Polygon::maxVertices> normals;
    int count = 0;
    double radius = 0.0;  ///< m, >= 0
};

RoundedCore coreOf(const Circle& c);
RoundedCore coreOf(const Polygon& p);
RoundedCore coreOf(const Segment& s);
RoundedCore coreOf(const Capsule& c);
/// The 2-vertex core through p1 and p2 with the given radius (m).
RoundedCore coreOf(const Vec2& p1, const Vec2& p2, double radius);

/// A manifold in the first shape's frame, before it is placed in the world.
struct LocalManifold {
    Vec2 normal = Vec2::Zero();  ///< unit, from a to b, a's frame
    int pointCount = 0;
    std::array<Vec2, 2> points{Vec2::Zero(), Vec2::Zero()};
    std::array<double, 2> separations{};
    std::array<std::uint32_t, 2> ids{};
    double separation = 0.0;  ///< m along normal; only meaningful when pointCount > 0
};

/// b's core placed in a's frame (xa^-1 xb applied to b's vertices and normals).
RoundedCore relativeCore(const RoundedCore& b, const Transform& xa, const Transform& xb);

/// The manifold of two rounded cores, b already in a's frame (relativeCore); `margin` as in Manifolds.hpp.
LocalManifold collideCores(const RoundedCore& a, const RoundedCore& b, double margin);

/// The manifold that takes a's face `face` as the reference: b's edge most antiparallel to that face's normal
/// (or its one vertex), clipped to the face's span; nothing of b outside the span counts. b in a's frame.
LocalManifold collideWithFace(const RoundedCore& a, int face, const RoundedCore& b, double margin);

/// Where a manifold puts a point of the incident core `separation` (m) off the reference face (unit normal n), the
/// cores' radii `refRadius` and `incRadius` (their sum `radii`): midway between the two surfaces.
inline Vec2 midwayPoint(const Vec2& incident, const Vec2& n, double refRadius, double incRadius, double radii,
                        double separation) {
    return incident + (0.5 * (refRadius - incRadius) - 0.5 * (separation + radii)) * n;
}

/// The separation (m) a manifold records for its one point when none of its candidates lies within the keep
/// distance (clip): the deepest candidate's, but no more than the pair's separation, nor less than 0 for that.
inline double deepestSeparation(double deepest, double pair) { return std::min(deepest, std::max(pair, 0.0)); }

/// The local manifold placed by a's transform.
NarrowResult placed(const LocalManifold& m, const Transform& xa);

/// collideCores for shapes placed in the world: normal from a to b.
NarrowResult collideRounded(const RoundedCore& a, const Transform& xa, const RoundedCore& b, const Transform& xb,
                            double margin);

}  // namespace physim
