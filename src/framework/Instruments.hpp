#pragma once
// The window's instruments drawn over the scene, in pixels: trails, arrows, the tape measure and protractor with
// their readings. Internal to the runner.

#include "physim/framework/View.hpp"

#include <string>

namespace sf {
class RenderTarget;
}

namespace physim {

class ArrowScale;
class Measurement;
class Overlay;
class Trails;
class World;

/// Each dynamic body's velocity (green), weight (red) and contact force (blue) as arrows from its centre of mass,
/// after a step of `dt` s; the scales are updated so the longest arrow stays within about 90 px. Returns the
/// legend for the bar (arrowsLegendText).
std::string drawArrows(sf::RenderTarget& target, const View& view, const World& world, double dt,
                       ArrowScale& velocityScale, ArrowScale& forceScale);
/// "arrows: velocity (green) 1 m = 2 m/s ...": what one metre of arrow stands for.
std::string arrowsLegendText(double velocityPerMetre, double forcePerMetre);

/// Each trail as a line fading from the oldest position (clear) to the newest.
void drawTrails(sf::RenderTarget& target, const View& view, const Trails& trails);

/// Draws `measurement` (nothing for none) with its reading, into a target whose current view is the pixel view.
void drawMeasurement(sf::RenderTarget& target, const View& view, const Measurement& measurement,
                     const Overlay& overlay);

}  // namespace physim
