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
#include <SFML/Graphics/VertexArray.hpp>

#include <variant>
#include <vector>

namespace sf {
class RenderTarget;
class Transform;
}  // namespace sf

namespace physim {

class CollisionShape;

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
    /// fills shapes: a mesh for any kind, those without a factory above included (a capsule's round ends and a
    /// rounded polygon's round corners are arcs of its outline). A segment or a chain's piece, which has no area,
    /// is drawn as a line (LineMesh, kLineWidth wide). Throws std::invalid_argument when validate(geometry) does.
    static Mesh GeometryMesh(const Geometry& geometry, sf::Color color);
    /// A polyline through `points` (m, body-local, at least 2), closed when `loop`, drawn as a band `width` m
    /// wide (> 0) centred on it, mitred where it turns: segments and chains. shape() is then empty (no points).
    static Mesh LineMesh(const std::vector<Vec2>& points, bool loop, double width, sf::Color color);
    /// What a collision shape looks like: a CircleMesh (with its radius line) for a CircleShape, a RectangleMesh
    /// for a RectangleShape, for a ChainShape a band kLineWidth wide on its solid side (the right of the direction
    /// its points run: what rests on it touches the band's edge), GeometryMesh otherwise.
    static Mesh ShapeMesh(const CollisionShape& shape, sf::Color color);

    /// Width of a segment's or chain's line drawn by GeometryMesh and ShapeMesh, m (4 px at 100 px/m).
    static constexpr double kLineWidth = 0.04;

    sf::Shape& shape();
    const sf::Shape& shape() const;

    /// The line band of a LineMesh (triangles, m, body-local); empty for the other meshes.
    const sf::VertexArray& band() const { return band_; }

    /// Draws at a world pose through the view's metres-to-pixels transform.
    void draw(sf::RenderTarget& target, const sf::Transform& worldToPixels, const Vec2& position,
              double angle) const;

private:
    static Mesh bandMesh(const std::vector<Vec2>& points, bool loop, double width, sf::Color color, bool centred);

    Shape shape_;
    sf::VertexArray band_{sf::Triangles};  // a LineMesh's band, drawn after the shape
    bool showRotation_ = false;
};

}  // namespace physim
