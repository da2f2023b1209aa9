#pragma once
// Joints: constraints solved with the contacts. The distance joint: a massless rigid rod between an anchor on
// each body (a pendulum's string held taut, a rope's links). The mouse joint: a soft spring-damper pulling a
// point of one body towards a target (what a window's mouse drags bodies with).

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

/// Pulls `localAnchor` of a dynamic body towards `target` as a spring-damper of natural frequency `hertz` and
/// damping ratio `dampingRatio` (stiffness from the body's mass), whose force never exceeds `maxForce`: a
/// dragged body pushes others and stops at walls instead of passing through them.
struct MouseJointDef {
    BodyId body;
    Vec2 target = Vec2::Zero();       ///< world point, m
    Vec2 localAnchor = Vec2::Zero();  ///< grabbed point in the body's frame, m (body origin = position())
    double maxForce = 0.0;            ///< N, > 0; e.g. 1000 * mass * |g|
    double hertz = 5.0;               ///< Hz, > 0
    double dampingRatio = 0.7;        ///< >= 0 (1: critically damped)
};

}  // namespace physim
