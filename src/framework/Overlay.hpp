#pragma once
// The window's text: a bar across the top (status, then the keys) that the scene is fitted below, so it never
// covers the scene, and the statistics panel shown on demand. Internal to the runner.

#include <SFML/Graphics/Color.hpp>
#include <SFML/Graphics/Font.hpp>
#include <SFML/System/Vector2.hpp>

#include <string>
#include <vector>

namespace sf {
class RenderTarget;
}

namespace physim {

class Overlay {
public:
    struct Item {
        std::string text;
        sf::Color color = sf::Color(30, 30, 30);
        bool newLine = false;  ///< starts a new line
    };

    /// Loads DejaVu Sans; without it (Debian fonts-dejavu-core) nothing is drawn and the bar takes no room.
    Overlay();
    bool available() const { return available_; }

    /// Height (px) of the bar showing `items` laid out in lines of `width` px.
    float barHeight(const std::vector<Item>& items, float width) const;
    /// Draws the bar over [left, left + width) at the top; returns its height.
    float drawBar(sf::RenderTarget& target, float left, float width, const std::vector<Item>& items) const;
    /// A box of text at the window's right edge, `top` px down.
    void drawPanel(sf::RenderTarget& target, float top, const std::string& text) const;
    /// A small box of UTF-8 text with its top-left corner at `at` (px), for a reading beside what it measures.
    void drawLabel(sf::RenderTarget& target, sf::Vector2f at, const std::string& text) const;

private:
    // Each item's position (px from the bar's top-left), items wrapped greedily into lines of `width`.
    std::vector<sf::Vector2f> layout(const std::vector<Item>& items, float width, float& height) const;

    sf::Font font_;
    bool available_ = false;
};

}  // namespace physim
