#pragma once
// SFML events as a window delivers them, made by hand so tests can drive the runner's controls and the
// gallery's panel without a user.

#include <SFML/Window/Event.hpp>

namespace physim::test {

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
