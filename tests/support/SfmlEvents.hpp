#pragma once
// SFML events as a window delivers them, made by hand so tests can drive the runner's controls and the
// gallery's panel without a user.

#include <physim/framework/View.hpp>

#include <SFML/Window/Event.hpp>

#include <cmath>

namespace physim::test {

/// The pixel (rounded) where `view` draws world point p (m) in a window of `window` pixels: where a click on it lands.
inline sf::Vector2i pixelOf(const View& view, const Vec2& p, sf::Vector2u window) {
    const sf::Vector2f px = view.worldToPixels(window).transformPoint(float(p.x()), float(p.y()));
    return {static_cast<int>(std::lround(px.x)), static_cast<int>(std::lround(px.y))};
}

inline sf::Event mouseButton(sf::Event::EventType type, sf::Mouse::Button button, sf::Vector2i at) {
    sf::Event e;
    e.type = type;
    e.mouseButton = {button, at.x, at.y};
    return e;
}

inline sf::Event mouseMove(sf::Vector2i at) {
    sf::Event e;
    e.type = sf::Event::MouseMoved;
    e.mouseMove = {at.x, at.y};
    return e;
}

inline sf::Event wheel(float delta, sf::Vector2i at) {
    sf::Event e;
    e.type = sf::Event::MouseWheelScrolled;
    e.mouseWheelScroll = {sf::Mouse::VerticalWheel, delta, at.x, at.y};
    return e;
}

inline sf::Event keyPress(sf::Keyboard::Key code, bool shift = false) {
    sf::Event e;
    e.type = sf::Event::KeyPressed;
    e.key = {code, false, false, shift, false};  // alt, control, shift, system
    return e;
}

}  // namespace physim::test
