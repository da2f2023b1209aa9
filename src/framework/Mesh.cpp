#include "physim/framework/Mesh.hpp"

#include "physim/core/ChainShape.hpp"
#include "physim/core/CircleShape.hpp"
#include "physim/core/CollisionShape.hpp"
#include "physim/core/Validate.hpp"

#include <SFML/Graphics/RenderTarget.hpp>
#include <SFML/Graphics/Vertex.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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
    if (const auto* s = std::get_if<Segment>(&geometry))
        return LineMesh({s->point1, s->point2}, false, kLineWidth, color);
    if (const auto* c = std::get_if<ChainSegment>(&geometry))
        return LineMesh({c->segment.point1, c->segment.point2}, false, kLineWidth, color);
    return PolygonMesh(outline(geometry, Transform{}), color);
}

Mesh Mesh::LineMesh(const std::vector<Vec2>& points, bool loop, double width, sf::Color color) {
    return bandMesh(points, loop, width, color, true);
}

// The band of LineMesh, centred on the polyline or (centred false) wholly on its right: a chain's solid side, so
// a body resting on the chain touches the band's edge.
Mesh Mesh::bandMesh(const std::vector<Vec2>& points, bool loop, double width, sf::Color color, bool centred) {
    if (points.size() < 2)
        throw std::invalid_argument("physim: line mesh needs at least 2 points, got " + std::to_string(points.size()));
    requirePositive("line mesh width", width);
    for (const Vec2& p : points) requireFinite("line mesh point", p);
    const std::size_t n = points.size();
    // The unit normal of the piece from point i to i + 1 (zero for a repeated point: that piece draws nothing).
    auto normal = [&](std::size_t i) -> Vec2 {
        const Vec2 d = points[(i + 1) % n] - points[i];
        const double length = d.norm();
        return length > 0.0 ? Vec2(Vec2(-d.y(), d.x()) / length) : Vec2(Vec2::Zero());
    };
    // Each point's offset to the band's left edge: along the mean of its pieces' normals, lengthened so the band
    // keeps its width through a turn (a mitre), at most twice the half-width at sharp turns.
    const double half = 0.5 * width;
    std::vector<Vec2> offset(n);
    for (std::size_t i = 0; i < n; ++i) {
        const bool hasBefore = loop || i > 0, hasAfter = loop || i + 1 < n;
        const Vec2 before = hasBefore ? normal((i + n - 1) % n) : normal(i);
        const Vec2 after = hasAfter ? normal(i) : before;
        const Vec2 mean = before + after;
        const double length = mean.norm();  // 2 cos(half the turn) for two unit normals
        offset[i] = length < 1e-9 ? Vec2(half * after) : Vec2((half / std::max(0.5, 0.5 * length)) * (mean / length));
    }
    sf::ConvexShape empty(0);
    empty.setFillColor(color);  // what fillColor() says of the line
    Mesh m(empty);
    const auto vertex = [&](const Vec2& p) {
        m.band_.append(sf::Vertex(sf::Vector2f(static_cast<float>(p.x()), static_cast<float>(p.y())), color));
    };
    const double left = centred ? 1.0 : 0.0, right = centred ? 1.0 : 2.0;  // the band's edges, in offsets
    const std::size_t pieces = loop ? n : n - 1;
    for (std::size_t i = 0; i < pieces; ++i) {
        const std::size_t j = (i + 1) % n;
        const Vec2 a = points[i] + left * offset[i], b = points[i] - right * offset[i];
        const Vec2 c = points[j] + left * offset[j], d = points[j] - right * offset[j];
        for (const Vec2& p : {a, b, c, c, b, d}) vertex(p);
    }
    return m;
}

Mesh Mesh::ShapeMesh(const CollisionShape& shape, sf::Color color) {
    switch (shape.getType()) {
        case ShapeType::CIRCLE: {
            const Circle& c = std::get<Circle>(shape.geometry());
            if (c.center == Vec2::Zero()) return CircleMesh(c.radius, color);
            break;
        }
        case ShapeType::RECTANGLE: return RectangleMesh(shape.getSize(), color);
        case ShapeType::CHAIN: {
            const auto& chain = static_cast<const ChainShape&>(shape);
            return bandMesh(chain.points(), chain.loop(), kLineWidth, color, false);
        }
        default: break;
    }
    return GeometryMesh(shape.geometry(), color);
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
    if (band_.getVertexCount() > 0) target.draw(band_, t);
    if (showRotation_) {
        const float r = std::get<sf::CircleShape>(shape_).getRadius();
        const sf::Vertex line[] = {sf::Vertex({0.f, 0.f}, kOutlineColor), sf::Vertex({r, 0.f}, kOutlineColor)};
        target.draw(line, 2, sf::Lines, t);
    }
}

}  // namespace physim
