#pragma once
// The paper's Object (section 4.5): an entity with a mesh to draw, a collision shape and a rigid body.
// The mesh drawn may differ from the collision shape.

#include "physim/core/CollisionShape.hpp"
#include "physim/framework/Entity.hpp"
#include "physim/framework/Mesh.hpp"
#include "physim/framework/RigidBody.hpp"

#include <memory>

namespace physim {

class Object : public Entity {
public:
    Mesh mesh;
    /// Placed at the body's pose after every fixed step, so the paper's shape queries see current poses.
    std::unique_ptr<CollisionShape> shape;
    RigidBody rb;

    /// Throws std::invalid_argument for a null shape.
    Object(const Mesh& mesh, std::unique_ptr<CollisionShape> shape);
    Object(const Mesh& mesh, const CollisionShape& shape);
    /// A box of `size` (m) with a matching mesh.
    explicit Object(const Vec2& size);
    /// A 1 m x 1 m box.
    Object();

    /// Places the body origin, m: the point the shape's and the mesh's coordinates are relative to (as a body's
    /// position in Box2D or a transform's in Unity). It is the centre of mass only for a shape centred on its
    /// origin (boxes, circles, centred polygons); getCenterOfMass() says where that is. Allowed before and after
    /// the object is added to a simulation.
    void setPosition(const Vec2& position);
    /// Sets the angle, rad (counter-clockwise), turning the object about its origin (the origin stays put).
    void setRotation(double angle);
    Vec2 getPosition() const { return rb.position(); }  ///< the body origin, m
    double getRotation() const { return rb.angle(); }
    /// World centre of mass, m: the point the body turns about as it moves.
    Vec2 getCenterOfMass() const { return rb.centerOfMass(); }

    void fixedUpdate() override;
    void render(sf::RenderWindow* window) override;

protected:
    void onAttach(World& world) override;
    void onDetach(World& world) override;

private:
    void syncShape();
};

}  // namespace physim
