#pragma once
// The window's arrows (key V): each dynamic body's velocity, weight and contact force, drawn from its centre of
// mass at scales the overlay states ("1 m = 2 m/s"). Internal to the runner; window-free, so it can be tested
// headless.

#include "physim/core/Body.hpp"
#include "physim/core/Math.hpp"

#include <vector>

namespace physim {

class World;

struct BodyArrows {
    BodyId body;
    Vec2 at = Vec2::Zero();        ///< centre of mass, m
    Vec2 velocity = Vec2::Zero();  ///< of the centre of mass, m/s
    Vec2 weight = Vec2::Zero();    ///< m g (with the body's gravity scale), N
    /// The contacts' mean force on the body over the last step (their impulses over `dt`, friction included), N.
    Vec2 contact = Vec2::Zero();
};

/// Every dynamic body's arrows after a step of `dt` seconds (the contacts of sleeping piles included). Throws
/// std::invalid_argument for a `dt` that is not positive.
std::vector<BodyArrows> bodyArrows(const World& world, double dt);

/// A joint's force on each of its bodies at its anchors (World::jointReactionForce: on B at B's anchor, the opposite
/// on A at A's), N; a joint to a world point has only B's.
struct JointArrows {
    Vec2 atA = Vec2::Zero(), atB = Vec2::Zero();  ///< the anchors, m
    Vec2 onB = Vec2::Zero();                      ///< N; A gets -onB
    bool toWorld = false;                         ///< no body A to draw on
};
std::vector<JointArrows> jointArrows(const World& world);

/// The mean force on one body over the last step of `dt` seconds from its contacts (N; sleeping ones' included),
/// and from its joints (each joint's World::jointReactionForce, on B, its opposite on A): what --record's
/// contact_force and joint_force read.
Vec2 contactForceOn(const World& world, BodyId body, double dt);
Vec2 jointForceOn(const World& world, BodyId body);

/// The smallest of 1, 2 or 5 times a power of ten at least `value` (> 0, finite; std::invalid_argument otherwise).
double roundScaleUp(double value);

/// How much one metre of arrow stands for (m/s or N per m). Kept while the longest arrow stays between a tenth of
/// the wanted length and the wanted length, so the legend does not flicker as the scene moves.
class ArrowScale {
public:
    /// `largest`: the largest magnitude to draw (>= 0); `maxLength` (m, > 0): the longest arrow wanted. Returns
    /// perMetre().
    double update(double largest, double maxLength);
    double perMetre() const { return perMetre_; }

private:
    double perMetre_ = 0.0;  // 0: none chosen yet
};

}  // namespace physim
