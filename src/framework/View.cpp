#include "physim/framework/View.hpp"

#include "physim/core/Validate.hpp"

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
    pixelsPerMetre *= factor;
}

}  // namespace physim
