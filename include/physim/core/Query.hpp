#pragma once
// What the world's queries answer (World::castRay..., castShape, overlap...): hits along a ray or a swept shape.
// Queries see every shape whose body collides, through the broad phase, except sensor shapes (which report
// overlaps instead of being seen) and shapes their QueryFilter hides (Filter.hpp).

#include "physim/core/Body.hpp"
#include "physim/core/Math.hpp"
#include "physim/core/Shape.hpp"

#include <functional>

namespace physim {

/// Where a ray (or a swept shape) meets a shape, world metres.
struct RayHit {
    ShapeId shape;
    BodyId body;
    Vec2 point = Vec2::Zero();   ///< on the shape's surface, m
    Vec2 normal = Vec2::Zero();  ///< the surface's outward unit normal there (zero for a cast that starts touching)
    double fraction = 0.0;       ///< of the translation, in [0, 1]: the hit is at origin + fraction * translation
};

/// The callback form of World::castRay: called for each hit, in no particular order, with the ray clipped by the
/// answers so far. It returns -1 (any negative value) to ignore the hit, 0 to stop, a fraction in (0, 1] to clip
/// the ray there (hits farther than the shortest clip are not reported), or 1 to go on.
using RayCallback = std::function<double(const RayHit&)>;

/// The callback form of the overlap queries: called once per shape found; returns false to stop.
using OverlapCallback = std::function<bool(ShapeId)>;

}  // namespace physim
