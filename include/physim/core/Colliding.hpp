#pragma once
// The paper's collision result (section 5.1.7), in world metres.

#include "physim/core/Math.hpp"

namespace physim {

/// The contact points of a collision: up to two, world metres.
struct CollidingPoints {
    Vec2 pointA = Vec2::Zero();  ///< first contact point (valid when contactCount >= 1)
    Vec2 pointB = Vec2::Zero();  ///< second contact point (valid when contactCount == 2)
    int contactCount = 0;
};

struct Colliding {
    bool collision = false;      ///< the shapes touch or overlap
    double penetration = 0.0;    ///< deepest overlap along the normal, m (>= 0): moving B this far along the
                                 ///< normal separates the shapes
    double overlap = 0.0;        ///< shallowest contact point's overlap, m (>= 0; equals penetration with one point)
    Vec2 normal = Vec2::Zero();  ///< unit vector from the first shape towards the second
    CollidingPoints collidingPoints;
};

}  // namespace physim
