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

    /// Centre of mass, m. Allowed before and after the object is added to a simulation.
    void setPosition(const Vec2& position);
    /// Rotation about the centre of mass, rad (counter-clockwise).
    void setRotation(double angle);
    Vec2 getPosition() const { return rb.position(); }
    double getRotation() const { return rb.angle(); }

    void fixedUpdate() override;
    void render(sf::RenderWindow* window) override;

protected:
    void onAttach(World& world) override;
    void onDetach(World& world) override;

private:
    void syncShape();
};

}  // namespace physim
