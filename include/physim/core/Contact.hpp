#pragma once

#include "physim/core/Body.hpp"
#include "physim/core/Math.hpp"

#include <array>
#include <cstdint>

namespace physim {

/// One point of a contact manifold, in world metres.
struct ContactPoint {
    Vec2 point = Vec2::Zero();   ///< midway between the two surfaces, m
    double separation = 0.0;     ///< signed distance along the normal, m: negative when the shapes overlap
    double normalImpulse = 0.0;  ///< accumulated over the step's solver iterations, N s (>= 0)
    double tangentImpulse = 0.0; ///< accumulated friction impulse, N s
    std::uint32_t id = 0;        ///< feature id: the same touching features keep the same id between steps
};

/// Up to two contact points shared by one pair of bodies. The normal points from A to B.
struct Manifold {
    BodyId bodyA;
    BodyId bodyB;
    Vec2 normal = Vec2::Zero();
    int pointCount = 0;
    std::array<ContactPoint, 2> points{};
};

}  // namespace physim
