#include "physim/framework/Object.hpp"

#include "physim/core/RectangleShape.hpp"
#include "physim/framework/Simulation.hpp"

#include <SFML/Graphics/RenderWindow.hpp>

#include <stdexcept>

namespace physim {
namespace {
std::unique_ptr<CollisionShape> requireShape(std::unique_ptr<CollisionShape> shape) {
    if (!shape) throw std::invalid_argument("physim: Object needs a collision shape, got null");
    return shape;
}
}  // namespace

Object::Object(const Mesh& m, std::unique_ptr<CollisionShape> s) : mesh(m), shape(requireShape(std::move(s))) {
    registerMemberBehavior(mesh);
    registerMemberBehavior(rb);
    rb.setGeometry(shape->geometry());
}

Object::Object(const Mesh& m, const CollisionShape& s) : Object(m, s.clone()) {}

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

void Object::syncShape() { shape->setTransform(rb.position(), rb.angle()); }

void Object::fixedUpdate() { syncShape(); }

void Object::render(sf::RenderWindow* window) {
    if (!window || !simulation()) return;
    mesh.draw(*window, simulation()->view.worldToPixels(window->getSize()), rb.position(), rb.angle());
}

void Object::onAttach(World& world) {
    rb.attach(world);
    syncShape();
}

void Object::onDetach(World&) { rb.detach(); }

}  // namespace physim
