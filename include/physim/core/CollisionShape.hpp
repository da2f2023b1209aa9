#pragma once
// The paper's CollisionShape (section 5.2): a shape placed in the world, with the paper's queries.
// It wraps plain Geometry (what the World stores) and a pose; the World's narrow phase and these queries call
// the same collide() and so agree.

#include "physim/core/Aabb.hpp"
#include "physim/core/Colliding.hpp"
#include "physim/core/Filter.hpp"
#include "physim/core/Geometry.hpp"
#include "physim/core/Math.hpp"

#include <memory>
#include <vector>

namespace physim {

/// The paper's ShapeType (CIRCLE, RECTANGLE), grown with the other kinds (a rounded polygon is a POLYGON with a
/// radius). GEOMETRY is a GeometryShape, which holds any Geometry kind (geometry() says which).
enum class ShapeType { CIRCLE, RECTANGLE, POLYGON, GEOMETRY, SEGMENT, CAPSULE, CHAIN };

class CollisionShape {
public:
    virtual ~CollisionShape() = default;

    virtual ShapeType getType() const = 0;
    /// The paper's getSize: full width and height for a rectangle, (radius, 0) for a circle (its length is the
    /// radius), the bounding box size in the shape's own frame for a polygon or a GeometryShape. Metres.
    virtual Vec2 getSize() const = 0;
    virtual std::unique_ptr<CollisionShape> clone() const = 0;

    /// The paper's AABB test (section 5.2.1) on the world-space bounding boxes; works for any rotation.
    bool aabbCollision(const CollisionShape& other) const;
    /// The full narrow phase (the paper's SAT, section 5.2.2): normal from this shape towards `other`. For a
    /// shape of several pieces (a chain) the deepest overlap of any two pieces.
    Colliding satCollision(const CollisionShape& other) const;
    /// World-space bounding box, tight for any rotation, of all the pieces. (The paper returned the SFML sprite;
    /// drawing belongs to Mesh here.)
    Aabb getBounds() const;
    /// Area (m^2), centroid (m, shape frame) and second moment of area about the centroid (m^4): mass and
    /// moment of inertia per unit density (kg/m^2). Zero area for a segment or a chain.
    MassProperties getMassProperties() const { return computeMassProperties(geometry_); }

    /// The shape's geometry, in its own frame; a chain's first piece (pieces() has them all).
    const Geometry& geometry() const { return geometry_; }
    /// Every piece of the shape, in its own frame: the geometry alone for all kinds but a chain.
    std::vector<Geometry> pieces() const;
    const Transform& transform() const { return transform_; }
    Vec2 getPosition() const { return transform_.p; }
    double getRotation() const { return angle_; }  ///< rad
    /// Places the shape: its local origin (the body origin) at `position`, rotated by `angle` rad.
    void setTransform(const Vec2& position, double angle);
    /// true: the shape is a sensor when it becomes a body's (Object: the body's first shape, or a part): it
    /// collides with nothing and reports overlaps (physim/core/Sensor.hpp). The paper's queries ignore the flag.
    void setSensor(bool sensor) { sensor_ = sensor; }
    bool isSensor() const { return sensor_; }

    /// The collision filter its body's shape gets (Filter.hpp): an Object reads it when it is made from this shape
    /// or adds it as a part. Once the object is in a simulation, RigidBody::setFilter or World::setFilter change it.
    const Filter& filter() const { return filter_; }
    void setFilter(const Filter& filter) { filter_ = filter; }

protected:
    explicit CollisionShape(Geometry geometry);
    /// A shape of several pieces (a chain), at least one; each validated.
    explicit CollisionShape(const std::vector<Geometry>& pieces);

private:
    Geometry geometry_;
    std::vector<Geometry> morePieces_;  // after the first: only a chain has them
    Transform transform_;
    double angle_ = 0.0;
    Filter filter_;
    bool sensor_ = false;
};

}  // namespace physim
