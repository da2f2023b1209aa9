#pragma once
// Maps world metres (y up) to window pixels (y down). Pixels exist only at the drawing layer.

#include "physim/core/Aabb.hpp"
#include "physim/core/Math.hpp"

#include <SFML/Graphics/Rect.hpp>
#include <SFML/Graphics/Transform.hpp>
#include <SFML/System/Vector2.hpp>

namespace physim {

struct View {
    static constexpr double minPixelsPerMetre = 1e-3;
    static constexpr double maxPixelsPerMetre = 1e6;

    Vec2 center = Vec2::Zero();   ///< world point shown at the window's centre, m
    double pixelsPerMetre = 100;  ///< zoom; the paper's 100 px per metre by default

    /// Metres to pixels for a window of `windowSize` pixels.
    sf::Transform worldToPixels(sf::Vector2u windowSize) const;
    Vec2 toWorld(sf::Vector2i pixel, sf::Vector2u windowSize) const;
    /// factor > 1 zooms in (about the window's centre). The scale stays within [minPixelsPerMetre,
    /// maxPixelsPerMetre]. Throws std::invalid_argument for a factor that is not finite and > 0.
    void zoom(double factor);
    /// Zooms keeping the world point under `pixel` where it is on screen (zoom about the cursor).
    void zoomAt(double factor, sf::Vector2i pixel, sf::Vector2u windowSize);
    /// Moves the scene with a drag of `pixels` (right and down positive, as the mouse moved).
    void pan(sf::Vector2i pixels);
    /// Centres and scales so that `bounds` (m) fills `area` (pixels of a window of `windowSize`) in its
    /// tighter direction, leaving `margin` (a fraction of the area) free on each side. An empty box (a point)
    /// keeps the scale and only centres.
    void fit(const Aabb& bounds, const sf::FloatRect& area, sf::Vector2u windowSize, double margin = 0.04);

    friend bool operator==(const View& a, const View& b) {
        return a.center == b.center && a.pixelsPerMetre == b.pixelsPerMetre;
    }
    friend bool operator!=(const View& a, const View& b) { return !(a == b); }
};

}  // namespace physim
