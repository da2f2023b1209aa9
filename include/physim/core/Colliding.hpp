#pragma once
// The paper's collision result (section 5.1.7), in world metres.

#include "physim/core/Math.hpp"

namespace physim {

/// The contact points of a collision: up to two, world metres.
/// Each point lies midway between the two surfaces, measured along the normal. pointA and pointB are the
/// manifold's first and second points (not "a point on shape A" and "a point on shape B"). Unused points are
/// (0, 0).
struct CollidingPoints {
    Vec2 pointA = Vec2::Zero();  ///< first contact point, m (valid when contactCount >= 1)
    Vec2 pointB = Vec2::Zero();  ///< second contact point, m (valid when contactCount == 2)
    int contactCount = 0;        ///< 0 when not colliding, 1 (vertex or curved contact) or 2 (edge against edge)
};

/// Everything is zero when collision is false. All lengths in metres, world frame.
struct Colliding {
    bool collision = false;      ///< the shapes touch (distance 0) or overlap
    double penetration = 0.0;    ///< m, >= 0: the minimum translation distance, i.e. moving the second shape
                                 ///< by penetration * normal separates them (to touching), and no shorter move
                                 ///< in any direction does. For two nearly parallel facing polygon edges it may
                                 ///< exceed that minimum by up to 1e-4 m (a stable reference face; see
                                 ///< docs/collision.md). The deepest contact point's overlap equals it (up to
                                 ///< rounding and that tolerance).
    double overlap = 0.0;        ///< m, >= 0: overlap of the shallowest contact point along the normal
                                 ///< (<= penetration; equal to it with one point or for parallel edges)
    Vec2 normal = Vec2::Zero();  ///< unit vector from the first shape towards the second: the direction to push
                                 ///< the second shape (or the opposite one to push the first)
    CollidingPoints collidingPoints;
};

}  // namespace physim
