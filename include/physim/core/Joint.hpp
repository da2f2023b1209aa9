#pragma once
// Joints: constraints between two bodies, solved with the contacts. For now the distance joint: a massless
// rigid rod between an anchor on each body (a pendulum's string held taut, a rope's links).

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

struct DistanceJointDef {
    BodyId bodyA;
    BodyId bodyB;
    Vec2 localAnchorA = Vec2::Zero();  ///< m, in A's frame (its centre of mass is the origin)
    Vec2 localAnchorB = Vec2::Zero();  ///< m, in B's frame
    /// m, > 0; <= 0 (the default) takes the anchors' distance when the joint is created.
    double length = 0.0;
};

}  // namespace physim
