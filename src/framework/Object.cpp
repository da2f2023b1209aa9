#include "physim/framework/Object.hpp"

#include "physim/core/ChainShape.hpp"
#include "physim/core/RectangleShape.hpp"
#include "physim/core/Validate.hpp"
#include "physim/framework/Simulation.hpp"

#include <SFML/Graphics/RenderWindow.hpp>

#include <stdexcept>

namespace physim {
namespace {
std::unique_ptr<CollisionShape> requireShape(std::unique_ptr<CollisionShape> shape) {
    if (!shape) throw std::invalid_argument("physim: Object needs a collision shape, got null");
    return shape;
}

void validate(const Material& m) {
    requireNonNegative("material density", m.density);
    requireInRange("material restitution", m.restitution, 0.0, 1.0);
    requireNonNegative("material static friction", m.staticFriction);
    requireNonNegative("material dynamic friction", m.dynamicFriction);
    requireNonNegative("material rolling resistance", m.rollingResistance);
    requireWithin("material tangent speed", m.tangentSpeed, kMaxSpeed);
}
}  // namespace

Object::Object(const Mesh& m, std::unique_ptr<CollisionShape> s) : mesh(m), shape(requireShape(std::move(s))) {
    registerMemberBehavior(mesh);
    registerMemberBehavior(rb);
    rb.setFilter(shape->filter());
    if (shape->getType() == ShapeType::CHAIN) {
        const auto& chain = static_cast<const ChainShape&>(*shape);
        rb.setChain(chain.points(), chain.loop());
        return;
    }
    rb.setGeometry(shape->geometry());
    if (!(shape->getMassProperties().area > 0.0)) rb.setMass(0.0);  // a segment: no mass, so static
    if (shape->isSensor()) rb.setSensor(true);
}

Object::Object(const Mesh& m, const CollisionShape& s) : Object(m, s.clone()) {}

Object::Object(const CollisionShape& s, sf::Color color) : Object(Mesh::ShapeMesh(s, color), s.clone()) {}

Object::Part& Object::addShape(std::unique_ptr<CollisionShape> s, const Material& material, const Vec2& offset,
                               double angle, std::optional<Mesh> partMesh) {
    s = requireShape(std::move(s));
    validate(material);
    requireFinite("part offset", offset);
    requireFinite("part angle", angle);
    const Transform local{offset, Rotation::fromAngle(angle)};
    const bool moved = offset != Vec2::Zero() || angle != 0.0;
    if (s->getType() == ShapeType::CHAIN) {
        const auto& chain = static_cast<const ChainShape&>(*s);
        ChainDef def;
        for (const Vec2& p : chain.points()) def.points.push_back(local.apply(p));
        def.loop = chain.loop();
        def.restitution = material.restitution;
        def.staticFriction = material.staticFriction;
        def.dynamicFriction = material.dynamicFriction;
        def.filter = s->filter();
        def.rollingResistance = material.rollingResistance;
        def.tangentSpeed = material.tangentSpeed;
        rb.addChain(def);
    } else {
        ShapeDef def;
        def.geometry = moved ? transformed(s->geometry(), local) : s->geometry();
        def.density = material.density;
        def.restitution = material.restitution;
        def.staticFriction = material.staticFriction;
        def.dynamicFriction = material.dynamicFriction;
        def.filter = s->filter();
        def.isSensor = s->isSensor();
        def.rollingResistance = material.rollingResistance;
        def.tangentSpeed = material.tangentSpeed;
        rb.addShape(def);
    }
    Mesh drawn = partMesh ? *partMesh : Mesh::ShapeMesh(*s, mesh.shape().getFillColor());
    parts_.push_back(std::make_unique<Part>(Part{std::move(s), offset, angle, std::move(drawn)}));
    syncShape();
    return *parts_.back();
}

Object::Part& Object::addShape(const CollisionShape& s, const Material& material, const Vec2& offset, double angle,
                               std::optional<Mesh> partMesh) {
    return addShape(s.clone(), material, offset, angle, std::move(partMesh));
}

Object::Object(const Vec2& size)
    : Object(Mesh::RectangleMesh(size, sf::Color(70, 130, 180)), std::make_unique<RectangleShape>(size)) {}

Object::Object() : Object(Vec2(1.0, 1.0)) {}

void Object::setPosition(const Vec2& position) {
    rb.setPose(position, rb.angle());
    syncShape();
}

void Object::setRotation(double angle) {
    rb.setPose(rb.position(), angle);
    syncShape();
}

void Object::syncShape() {
    const Vec2 origin = rb.position();
    const double turn = rb.angle();
    shape->setTransform(origin, turn);
    const Rotation q = Rotation::fromAngle(turn);
    for (const auto& part : parts_) part->shape->setTransform(origin + q.apply(part->offset), turn + part->angle);
}

void Object::fixedUpdate() { syncShape(); }

void Object::render(sf::RenderWindow* window) {
    if (!window || !simulation()) return;
    const sf::Transform toPixels = simulation()->view.worldToPixels(window->getSize());
    mesh.draw(*window, toPixels, rb.position(), rb.angle());
    const Rotation q = Rotation::fromAngle(rb.angle());
    for (const auto& part : parts_)
        part->mesh.draw(*window, toPixels, rb.position() + q.apply(part->offset), rb.angle() + part->angle);
}

void Object::onAttach(World& world) {
    rb.attach(world);
    syncShape();
}

void Object::onDetach(World&) { rb.detach(); }

}  // namespace physim
