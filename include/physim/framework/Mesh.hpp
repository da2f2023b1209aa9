#pragma once
// The paper's Mesh (section 5.3): what is drawn for an entity, which may differ from its collision shape.
// Sizes are in metres; the view turns them into pixels when drawing.

#include "physim/core/Geometry.hpp"
#include "physim/core/Math.hpp"
#include "physim/framework/Behavior.hpp"

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/Color.hpp>
#include <SFML/Graphics/ConvexShape.hpp>
#include <SFML/Graphics/RectangleShape.hpp>

#include <variant>
#include <vector>

namespace sf {
class RenderTarget;
class Transform;
}  // namespace sf

namespace physim {

class Mesh : public Behavior {
public:
    using Shape = std::variant<sf::RectangleShape, sf::CircleShape, sf::ConvexShape>;

    /// `shape` in metres, in the body's frame: its origin is drawn at the body origin.
    explicit Mesh(Shape shape);

    /// A rectangle of `size` (m), centred.
    static Mesh RectangleMesh(const Vec2& size, sf::Color color);
    /// A circle of `radius` (m), centred, with a radius line so its rotation is visible.
    static Mesh CircleMesh(double radius, sf::Color color);
    /// A convex polygon through `points` (m, body-local).
    static Mesh PolygonMesh(const std::vector<Vec2>& points, sf::Color color);
    /// The outline of `geometry` (outline(), m, body-local) filled as one convex polygon, as the debug drawing
    /// fills shapes: a mesh for any kind, those without a factory above included. Throws std::invalid_argument
    /// when validate(geometry) does.
    static Mesh GeometryMesh(const Geometry& geometry, sf::Color color);

    sf::Shape& shape();
    const sf::Shape& shape() const;

    /// Draws at a world pose through the view's metres-to-pixels transform.
    void draw(sf::RenderTarget& target, const sf::Transform& worldToPixels, const Vec2& position,
              double angle) const;

private:
    Shape shape_;
    bool showRotation_ = false;
};

}  // namespace physim
