#pragma once
// Debug drawing over a scene: what the engine knows that the meshes do not show. Drawn from the World's public
// getters only, in pixels (fixed line widths at any zoom).

#include "physim/core/Contact.hpp"
#include "physim/core/Query.hpp"
#include "physim/framework/View.hpp"

#include <optional>
#include <vector>

namespace sf {
class RenderTarget;
}

namespace physim {

class World;

struct DebugDrawOptions {
    bool contacts = false;    ///< contact points (red) and normals (blue, from A to B); resting ones dimmed
    bool boxes = false;       ///< bounding boxes
    bool velocities = false;  ///< velocity arrows from each centre of mass: the distance it covers in 0.1 s
    /// joints by kind: a revolute pin's ring (and limits' rays), a prismatic or wheel joint's axis (and limits'
    /// ticks), a pulley's rope, a gear's line between its bodies, a weld's square; the others a line between anchors
    bool joints = false;
    bool centres = false;     ///< centres of mass (the body origin only for a shape centred on it)
    bool sleep = false;       ///< sleeping bodies dimmed
    bool sensors = false;     ///< sensor shapes outlined, not filled (amber; bright while something overlaps one)
    /// rays cast through Simulation::castRay: the ray up to its hit (orange) and on to its end (faint), the hit
    /// point and the surface normal there
    bool rays = false;

    bool any() const { return contacts || boxes || velocities || joints || centres || sleep || sensors || rays; }
};

/// A ray to draw: origin + f * translation for f in [0, 1] (m), and what it hit.
struct DebugRay {
    Vec2 origin = Vec2::Zero();
    Vec2 translation = Vec2::Zero();
    std::optional<RayHit> hit;
};

/// Draws what `options` asks for, over the scene, into a target whose current view is the pixel view; `rays` are
/// drawn when options.rays is on.
void drawDebug(sf::RenderTarget& target, const View& view, const World& world, const DebugDrawOptions& options,
               const std::vector<DebugRay>& rays = {});

/// Every movable body of `world` (a branch's: Simulation::startBranch) as a translucent ghost, over the scene.
void drawGhosts(sf::RenderTarget& target, const View& view, const World& world);

/// Contacts of bodies at rest, which the step no longer computes (a sleeping body against a sleeping or
/// static one): the manifolds of every such touching pair, from the same narrow phase the step uses.
std::vector<Manifold> restingContacts(const World& world);

}  // namespace physim
