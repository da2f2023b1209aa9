#pragma once
// Maps world metres (y up) to window pixels (y down). Pixels exist only at the drawing layer.

#include "physim/core/Math.hpp"

#include <SFML/Graphics/Transform.hpp>
#include <SFML/System/Vector2.hpp>

namespace physim {

struct View {
    Vec2 center = Vec2::Zero();   ///< world point shown at the window's centre, m
    double pixelsPerMetre = 100;  ///< zoom; the paper's 100 px per metre by default

    /// Metres to pixels for a window of `windowSize` pixels.
    sf::Transform worldToPixels(sf::Vector2u windowSize) const;
    Vec2 toWorld(sf::Vector2i pixel, sf::Vector2u windowSize) const;
    void zoom(double factor);  ///< factor > 1 zooms in
};

}  // namespace physim
