#include "physim/framework/Mesh.hpp"

#include "physim/core/Validate.hpp"

#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Vertex.hpp>

#include <cmath>
#include <stdexcept>

namespace physim {
namespace {
constexpr float kOutline = 0.02f;  // m: 2 px at the default 100 px/m
const sf::Color kOutlineColor(20, 20, 20);
}  // namespace

Mesh::Mesh(Shape shape) : shape_(std::move(shape)) {}

Mesh Mesh::RectangleMesh(const Vec2& size, sf::Color color) {
    requirePositive("mesh width", size.x());
    requirePositive("mesh height", size.y());
    sf::RectangleShape r(sf::Vector2f(static_cast<float>(size.x()), static_cast<float>(size.y())));
    r.setOrigin(0.5f * r.getSize());
    r.setFillColor(color);
    r.setOutlineColor(kOutlineColor);
    r.setOutlineThickness(-kOutline);
    return Mesh(r);
}

Mesh Mesh::CircleMesh(double radius, sf::Color color) {
    requirePositive("mesh radius", radius);
    const auto r = static_cast<float>(radius);
    sf::CircleShape c(r, 48);
    c.setOrigin(r, r);
    c.setFillColor(color);
    c.setOutlineColor(kOutlineColor);
    c.setOutlineThickness(-kOutline);
    Mesh m(c);
    m.showRotation_ = true;
    return m;
}

Mesh Mesh::PolygonMesh(const std::vector<Vec2>& points, sf::Color color) {
    if (points.size() < 3) throw std::invalid_argument("physim: polygon mesh needs at least 3 points, got " +
                                                       std::to_string(points.size()));
    sf::ConvexShape p(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        requireFinite("mesh point", points[i]);
        p.setPoint(i, sf::Vector2f(static_cast<float>(points[i].x()), static_cast<float>(points[i].y())));
    }
    p.setFillColor(color);
    p.setOutlineColor(kOutlineColor);
    p.setOutlineThickness(-kOutline);
    return Mesh(p);
}

Mesh Mesh::GeometryMesh(const Geometry& geometry, sf::Color color) {
    validate(geometry);
    return PolygonMesh(outline(geometry, Transform{}), color);
}

sf::Shape& Mesh::shape() {
    return std::visit([](auto& s) -> sf::Shape& { return s; }, shape_);
}
const sf::Shape& Mesh::shape() const {
    return std::visit([](const auto& s) -> const sf::Shape& { return s; }, shape_);
}

void Mesh::draw(sf::RenderTarget& target, const sf::Transform& worldToPixels, const Vec2& position,
                double angle) const {
    sf::Transform t = worldToPixels;
    t.translate(static_cast<float>(position.x()), static_cast<float>(position.y()));
    t.rotate(static_cast<float>(angle * 180.0 / M_PI));
    target.draw(shape(), t);
    if (showRotation_) {
        const float r = std::get<sf::CircleShape>(shape_).getRadius();
        const sf::Vertex line[] = {sf::Vertex({0.f, 0.f}, kOutlineColor), sf::Vertex({r, 0.f}, kOutlineColor)};
        target.draw(line, 2, sf::Lines, t);
    }
}

}  // namespace physim
