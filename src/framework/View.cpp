#include "physim/framework/View.hpp"

#include "physim/core/Validate.hpp"

#include <algorithm>

namespace physim {

sf::Transform View::worldToPixels(sf::Vector2u windowSize) const {
    sf::Transform t;
    t.translate(0.5f * static_cast<float>(windowSize.x), 0.5f * static_cast<float>(windowSize.y));
    t.scale(static_cast<float>(pixelsPerMetre), static_cast<float>(-pixelsPerMetre));  // y up in the world
    t.translate(static_cast<float>(-center.x()), static_cast<float>(-center.y()));
    return t;
}

Vec2 View::toWorld(sf::Vector2i pixel, sf::Vector2u windowSize) const {
    return {center.x() + (pixel.x - 0.5 * windowSize.x) / pixelsPerMetre,
            center.y() - (pixel.y - 0.5 * windowSize.y) / pixelsPerMetre};
}

void View::zoom(double factor) {
    requirePositive("zoom factor", factor);
    pixelsPerMetre = std::clamp(pixelsPerMetre * factor, minPixelsPerMetre, maxPixelsPerMetre);
}

void View::zoomAt(double factor, sf::Vector2i pixel, sf::Vector2u windowSize) {
    const Vec2 anchor = toWorld(pixel, windowSize);
    zoom(factor);
    center += anchor - toWorld(pixel, windowSize);  // bring the anchor back under the cursor
}

void View::pan(sf::Vector2i pixels) {
    center += Vec2(-pixels.x, pixels.y) / pixelsPerMetre;  // screen y points down, world y up
}

void View::fit(const Aabb& bounds, const sf::FloatRect& area, sf::Vector2u windowSize, double margin) {
    requireFinite("view bounds lower corner", bounds.lower);
    requireFinite("view bounds upper corner", bounds.upper);
    requireInRange("view margin", margin, 0.0, 0.45);
    if (!(area.width > 0.f && area.height > 0.f)) return;  // a minimised window: nothing to fit into
    const Vec2 size = bounds.upper - bounds.lower;
    const double usable = 1.0 - 2.0 * margin;
    double scale = pixelsPerMetre;
    if (size.x() > 0.0 || size.y() > 0.0) {
        const double sx = size.x() > 0.0 ? usable * area.width / size.x() : INFINITY;
        const double sy = size.y() > 0.0 ? usable * area.height / size.y() : INFINITY;
        scale = std::min(sx, sy);
    }
    pixelsPerMetre = std::clamp(scale, minPixelsPerMetre, maxPixelsPerMetre);
    // The bounds' centre goes to the area's centre, which may be off the window's centre.
    const double offsetX = area.left + 0.5 * area.width - 0.5 * windowSize.x;   // px
    const double offsetY = area.top + 0.5 * area.height - 0.5 * windowSize.y;   // px, down
    center = bounds.center() - Vec2(offsetX, -offsetY) / pixelsPerMetre;
}

}  // namespace physim
