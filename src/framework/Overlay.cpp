#include "Overlay.hpp"

#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Text.hpp>

#include <algorithm>
#include <iostream>

namespace physim {
namespace {

constexpr unsigned kFontSize = 14;
constexpr float kPadding = 6.f;   // px around the text
constexpr float kGap = 22.f;      // px between items on a line
const char* const kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

}  // namespace

Overlay::Overlay() {
    available_ = font_.loadFromFile(kFontFile);
    if (!available_)
        std::cerr << "physim: " << kFontFile << " not found (Debian: fonts-dejavu-core); the overlay is off\n";
}

std::vector<sf::Vector2f> Overlay::layout(const std::vector<Item>& items, float width, float& height) const {
    std::vector<sf::Vector2f> at;
    const float line = font_.getLineSpacing(kFontSize);
    float x = kPadding, y = kPadding;
    for (const Item& item : items) {
        const float w = sf::Text(item.text, font_, kFontSize).getLocalBounds().width;
        if (x > kPadding && (item.newLine || x + w > width - kPadding)) {  // wrap; a too wide item gets a line
            x = kPadding;
            y += line;
        }
        at.emplace_back(x, y);
        x += w + kGap;
    }
    height = items.empty() ? 0.f : y + line + kPadding;
    return at;
}

float Overlay::barHeight(const std::vector<Item>& items, float width) const {
    if (!available_) return 0.f;
    float height = 0.f;
    layout(items, width, height);
    return height;
}

float Overlay::drawBar(sf::RenderTarget& target, float left, float width, const std::vector<Item>& items) const {
    if (!available_) return 0.f;
    float height = 0.f;
    const std::vector<sf::Vector2f> at = layout(items, width, height);
    sf::RectangleShape bar({width, height});
    bar.setPosition(left, 0.f);
    bar.setFillColor(sf::Color(250, 250, 250));
    bar.setOutlineColor(sf::Color(190, 190, 190));
    bar.setOutlineThickness(-1.f);
    target.draw(bar);
    for (std::size_t i = 0; i < items.size(); ++i) {
        sf::Text text(items[i].text, font_, kFontSize);
        text.setFillColor(items[i].color);
        text.setPosition(left + at[i].x, at[i].y);
        target.draw(text);
    }
    return height;
}

void Overlay::drawPanel(sf::RenderTarget& target, float top, const std::string& text) const {
    if (!available_) return;
    sf::Text t(text, font_, kFontSize);
    t.setFillColor(sf::Color(30, 30, 30));
    const sf::FloatRect bounds = t.getLocalBounds();
    const float w = bounds.width + 2 * kPadding, h = bounds.top + bounds.height + 2 * kPadding;
    const float x = static_cast<float>(target.getSize().x) - w - kPadding;
    sf::RectangleShape box({w, h});
    box.setPosition(x, top + kPadding);
    box.setFillColor(sf::Color(255, 255, 255, 225));
    box.setOutlineColor(sf::Color(190, 190, 190));
    box.setOutlineThickness(-1.f);
    target.draw(box);
    t.setPosition(x + kPadding, top + 2 * kPadding);
    target.draw(t);
}

void Overlay::drawLabel(sf::RenderTarget& target, sf::Vector2f at, const std::string& text) const {
    if (!available_) return;
    sf::Text t(sf::String::fromUtf8(text.begin(), text.end()), font_, kFontSize);
    t.setFillColor(sf::Color(30, 30, 30));
    const sf::FloatRect bounds = t.getLocalBounds();
    const float pad = 0.5f * kPadding;
    sf::RectangleShape box({bounds.width + 2 * pad, bounds.top + bounds.height + 2 * pad});
    box.setPosition(at);
    box.setFillColor(sf::Color(255, 255, 255, 215));
    box.setOutlineColor(sf::Color(190, 190, 190));
    box.setOutlineThickness(-1.f);
    target.draw(box);
    t.setPosition(at.x + pad, at.y + pad);
    target.draw(t);
}

}  // namespace physim
