#pragma once

#include "physim/core/Body.hpp"
#include "physim/core/Math.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace physim {

/// One point of a contact manifold, in world metres.
struct ContactPoint {
    Vec2 point = Vec2::Zero();   ///< midway between the two surfaces, m
    double separation = 0.0;     ///< signed distance along the normal, m: negative when the shapes overlap
    /// N s (>= 0): what the contact gave B along the normal over the whole step, every substep's impulse and any
    /// bounce's blow summed (the momentum it passed), so normalImpulse / dt is the mean normal force over the step,
    /// N. A box of mass m resting on the ground reads m g dt over its points whatever the substeps.
    double normalImpulse = 0.0;
    /// N s: the friction impulse on B along the tangent perp(normal) over the whole step, likewise (its mean force
    /// is tangentImpulse / dt). The friction acts at the manifold's centre; each point reports an equal share.
    double tangentImpulse = 0.0;
    std::uint32_t id = 0;        ///< feature id: the same touching features keep the same id between steps
};

/// Up to two contact points shared by one pair of shapes (of two bodies). The normal points from A to B.
struct Manifold {
    BodyId bodyA;
    BodyId bodyB;
    ShapeId shapeA;  ///< the shape of bodyA that touches
    ShapeId shapeB;
    Vec2 normal = Vec2::Zero();
    int pointCount = 0;
    std::array<ContactPoint, 2> points{};
};

/// Two bodies that started (begin) or stopped (end) touching during the last step. A pair whose bodies are
/// destroyed ends without an event.
struct ContactEvent {
    BodyId bodyA;
    BodyId bodyB;
    ShapeId shapeA;  ///< the shapes of the two bodies that touch
    ShapeId shapeB;
};

/// A collision in the last step: the bodies met approaching faster than WorldSettings::impactSpeedThreshold.
struct ImpactEvent {
    BodyId bodyA;
    BodyId bodyB;
    ShapeId shapeA;
    ShapeId shapeB;
    Vec2 point = Vec2::Zero();   ///< m, world
    Vec2 normal = Vec2::Zero();  ///< unit, from A to B
    double approachSpeed = 0.0;  ///< m/s, normal speed at which they met (> 0)
};

/// What happened to the contacts in the last step, in a deterministic order (by body index).
struct ContactEvents {
    std::vector<ContactEvent> begin;
    std::vector<ContactEvent> end;
    std::vector<ImpactEvent> impacts;
};

}  // namespace physim
