#pragma once
// Joints: constraints solved with the contacts. The distance joint is a massless rigid rod between an anchor on
// each body (a pendulum's string held taut, a rope's links); the mouse joint is a soft spring with a force cap
// pulling a body's anchor towards a target point (dragging a body with the mouse).

#include "physim/core/Body.hpp"
#include "physim/core/Math.hpp"

#include <cstdint>
#include <limits>

namespace physim {

/// Handle to a joint in one World; stale after the joint, or either of its bodies, is destroyed.
struct JointId {
    std::uint32_t index = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t generation = 0;
    bool isNull() const { return index == std::numeric_limits<std::uint32_t>::max(); }
    friend bool operator==(const JointId& a, const JointId& b) {
        return a.index == b.index && a.generation == b.generation;
    }
};

enum class JointType { Distance, Mouse };

struct DistanceJointDef {
    BodyId bodyA;
    BodyId bodyB;
    Vec2 localAnchorA = Vec2::Zero();  ///< m, in A's frame (its centre of mass is the origin)
    Vec2 localAnchorB = Vec2::Zero();  ///< m, in B's frame
    /// m, > 0; <= 0 (the default) takes the anchors' distance when the joint is created.
    double length = 0.0;
};

struct MouseJointDef {
    BodyId body;                       ///< a dynamic body
    Vec2 target = Vec2::Zero();        ///< world point the anchor is pulled towards, m
    Vec2 localAnchor = Vec2::Zero();   ///< grabbed point in the body's frame (origin-relative), m
    double maxForce = 0.0;             ///< N, > 0: the pull never exceeds it (e.g. 1000 m |g|)
    double hertz = 5.0;                ///< spring frequency, Hz, > 0 (capped at a quarter of the substep rate)
    double dampingRatio = 0.7;         ///< >= 0; 1 is critical damping
};

}  // namespace physim
