#pragma once
// Pixel-space lines of a fixed width (quads: GL lines are one pixel wide), gathered and drawn in one call. Shared
// by the debug drawing and the window's instruments. Internal to the framework.

#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/VertexArray.hpp>

#include <algorithm>
#include <cmath>

namespace physim {

class Lines {
public:
    static constexpr float defaultWidth = 2.f;  // px

    explicit Lines(float width = defaultWidth) : width_(width) {}

    void add(sf::Vector2f a, sf::Vector2f b, sf::Color c) { add(a, b, c, c); }
    /// A line whose colour goes from `ca` at `a` to `cb` at `b`.
    void add(sf::Vector2f a, sf::Vector2f b, sf::Color ca, sf::Color cb) {
        const sf::Vector2f d = b - a;
        const float len = std::hypot(d.x, d.y);
        if (len <= 0.f) return;
        const sf::Vector2f n = (0.5f * width_ / len) * sf::Vector2f(-d.y, d.x);
        lines_.append(sf::Vertex(a + n, ca));
        lines_.append(sf::Vertex(b + n, cb));
        lines_.append(sf::Vertex(b - n, cb));
        lines_.append(sf::Vertex(a - n, ca));
    }
    void arrow(sf::Vector2f from, sf::Vector2f to, sf::Color c) {
        add(from, to, c);
        const sf::Vector2f d = to - from;
        const float len = std::hypot(d.x, d.y);
        if (len < 1.f) return;
        const sf::Vector2f u = d / len, n(-u.y, u.x);
        const float head = std::min(8.f, 0.4f * len);
        add(to, to - head * u + 0.5f * head * n, c);
        add(to, to - head * u - 0.5f * head * n, c);
    }
    bool empty() const { return lines_.getVertexCount() == 0; }
    void draw(sf::RenderTarget& target) const { target.draw(lines_); }

private:
    float width_;
    sf::VertexArray lines_{sf::Quads};
};

}  // namespace physim
