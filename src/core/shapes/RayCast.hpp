#pragma once
// Ray against one shape, and point inside one shape: the geometry the kinds' rayCast and containsPoint share
// (ShapeKind.hpp). Internal. Everything is in the shape's own frame: the kinds move the ray in and the hit out.
//
// A ray is origin + f * translation for f in [0, maxFraction]. It hits a shape where it enters it from outside:
// a ray that starts inside (or on the boundary going out) does not hit that shape, as in Box2D, so a ray cast from
// a body's centre sees what lies around the body. A segment has no inside: it is hit from either side.

#include "RoundedCore.hpp"

#include "physim/core/Geometry.hpp"

namespace physim {

/// The ray in a shape's frame, m.
struct LocalRay {
    Vec2 origin = Vec2::Zero();
    Vec2 translation = Vec2::Zero();  ///< not zero
    double maxFraction = 1.0;         ///< hits past origin + maxFraction * translation are not wanted
};

/// A hit in the shape's frame: the fraction of the translation, the point and the outward unit normal there.
struct LocalRayHit {
    bool hit = false;
    double fraction = 0.0;
    Vec2 point = Vec2::Zero();
    Vec2 normal = Vec2::Zero();
};

/// The ray moved into the frame xf places a shape in.
inline LocalRay toLocal(const Vec2& origin, const Vec2& translation, double maxFraction, const Transform& xf) {
    return {xf.applyInverse(origin), xf.q.applyInverse(translation), maxFraction};
}
/// A local hit moved out to the world by xf.
inline LocalRayHit toWorld(const LocalRayHit& h, const Transform& xf) {
    return {h.hit, h.fraction, xf.apply(h.point), xf.q.apply(h.normal)};
}

/// Entry into the disc of `radius` about `center` (no hit from inside).
LocalRayHit rayCastDisc(const LocalRay& ray, const Vec2& center, double radius);
/// Entry into a convex polygon of radius 0 (vertices counter-clockwise, outward normals), by clipping the ray
/// against each edge's half-plane.
LocalRayHit rayCastConvex(const LocalRay& ray, const Vec2* vertices, const Vec2* normals, int count);
/// The two-sided segment p1-p2 (zero thickness): the normal faces the ray's origin.
LocalRayHit rayCastSegment(const LocalRay& ray, const Vec2& p1, const Vec2& p2);
/// Entry into a rounded core (radius > 0, 1 to 8 vertices): the first of its edges pushed out by the radius and
/// its corner discs, unless the origin is inside.
LocalRayHit rayCastRounded(const RoundedCore& core, const LocalRay& ray);

/// Distance (m) from p to the core's polygon (0 inside it; for 2 vertices, to the segment; for 1, to the point).
double distanceToCore(const RoundedCore& core, const Vec2& p);

}  // namespace physim
