#pragma once
// The paper's Object (section 4.5): an entity with a mesh to draw, a collision shape and a rigid body.
// The mesh drawn may differ from the collision shape. A compound object (a hammer, a cup, an L) has more shapes,
// each with its own place, material and mesh (addShape); its body's mass, centre and inertia come from all of them.

#include "physim/core/CollisionShape.hpp"
#include "physim/framework/Entity.hpp"
#include "physim/framework/Mesh.hpp"
#include "physim/framework/RigidBody.hpp"

#include <memory>
#include <optional>
#include <vector>

namespace physim {

/// What a shape of a compound object is made of: its density and its surface (ShapeDef's meanings).
struct Material {
    double density = 1.0;          ///< kg/m^2, >= 0
    double restitution = 0.0;      ///< in [0, 1]; a pair mixes them (WorldSettings: min)
    double staticFriction = 0.6;   ///< >= 0; a pair mixes them (WorldSettings: average)
    double dynamicFriction = 0.4;  ///< >= 0; a pair mixes them (WorldSettings: average)
    double rollingResistance = 0.0;  ///< >= 0 (ShapeDef::rollingResistance)
    double tangentSpeed = 0.0;       ///< m/s, a belt's surface speed (ShapeDef::tangentSpeed)
};

class Object : public Entity {
public:
    /// A shape after the first: its collision shape (placed in the world after every fixed step, as `shape` is),
    /// its pose in the object's frame and its mesh.
    struct Part {
        std::unique_ptr<CollisionShape> shape;
        Vec2 offset = Vec2::Zero();  ///< m, the shape's origin in the object's frame
        double angle = 0.0;          ///< rad, the shape's turn in the object's frame
        Mesh mesh;
    };

    Mesh mesh;
    /// Placed at the body's pose after every fixed step, so the paper's shape queries see current poses.
    std::unique_ptr<CollisionShape> shape;
    RigidBody rb;

    /// Throws std::invalid_argument for a null shape. A shape without area (SegmentShape, ChainShape) makes a
    /// static body: it has no mass (it may be made kinematic).
    Object(const Mesh& mesh, std::unique_ptr<CollisionShape> shape);
    Object(const Mesh& mesh, const CollisionShape& shape);
    /// The shape drawn as itself (Mesh::ShapeMesh) in `color`.
    Object(const CollisionShape& shape, sf::Color color);
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
    /// World centre of mass, m: the point the body turns about as it moves (of all its shapes).
    Vec2 getCenterOfMass() const { return rb.centerOfMass(); }

    /// Adds a shape (a compound object): `shape`, in its own frame, placed at `offset` (m) turned by `angle` (rad)
    /// in the object's frame, of `material`, drawn by `partMesh` (in the shape's frame) or, without one, as itself
    /// (Mesh::ShapeMesh) in the main mesh's colour. The body's mass, centre of mass and inertia then come from
    /// all the shapes (World::createShape), before and after the object is added to a simulation; a mass or
    /// density set on rb after the object joined a simulation gives way to the shapes' own (the world's rule), so
    /// put a compound object together before adding it. Returns the part. Throws std::invalid_argument for a
    /// null shape or a bad material, naming the value.
    Part& addShape(std::unique_ptr<CollisionShape> shape, const Material& material, const Vec2& offset = Vec2::Zero(),
                   double angle = 0.0, std::optional<Mesh> partMesh = std::nullopt);
    Part& addShape(const CollisionShape& shape, const Material& material, const Vec2& offset = Vec2::Zero(),
                   double angle = 0.0, std::optional<Mesh> partMesh = std::nullopt);
    /// Joins this object's body to `other`'s by a joint (RigidBody::join: this one is body A): e.g.
    /// `wheel.join(axle, RevoluteJointDef{...})`. Both objects must have been added to the simulation.
    template <class Def>
    JointId join(Object& other, const Def& def) {
        return rb.join(other.rb, def);
    }
    /// The shapes after the first, in the order added.
    const std::vector<std::unique_ptr<Part>>& parts() const { return parts_; }

    void fixedUpdate() override;
    void render(sf::RenderWindow* window) override;

protected:
    void onAttach(World& world) override;
    void onDetach(World& world) override;

private:
    void syncShape();

    std::vector<std::unique_ptr<Part>> parts_;
};

}  // namespace physim
