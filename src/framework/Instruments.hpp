#pragma once
// The window's instruments drawn over the scene, in pixels: trails, the tape measure and protractor with readings.
// Internal to the runner.

#include "physim/framework/View.hpp"

namespace sf {
class RenderTarget;
}

namespace physim {

class Measurement;
class Overlay;
class Trails;

/// Each trail as a line fading from the oldest position (clear) to the newest.
void drawTrails(sf::RenderTarget& target, const View& view, const Trails& trails);

/// Draws `measurement` (nothing for none) with its reading, into a target whose current view is the pixel view.
void drawMeasurement(sf::RenderTarget& target, const View& view, const Measurement& measurement,
                     const Overlay& overlay);

}  // namespace physim
