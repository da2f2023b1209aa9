#include "physim/framework/Entity.hpp"

#include <stdexcept>
#include <string>

namespace physim {

Entity::~Entity() = default;

Behavior& Entity::AddBehavior(std::unique_ptr<Behavior> behavior) {
    if (!behavior) throw std::invalid_argument("physim: AddBehavior got a null behavior");
    registerMemberBehavior(*behavior);
    owned_.push_back(std::move(behavior));
    return *owned_.back();
}

void Entity::registerMemberBehavior(Behavior& behavior) {
    if (behavior.entity != nullptr && behavior.entity != this)
        throw std::invalid_argument("physim: this behavior belongs to entity " +
                                    std::to_string(behavior.entity->id()) +
                                    "; it cannot be added to entity " + std::to_string(id_));
    for (const Behavior* b : behaviors_)
        if (b == &behavior) throw std::invalid_argument("physim: behavior added twice to entity " + std::to_string(id_));
    behavior.entity = this;
    behaviors_.push_back(&behavior);
}

void Entity::render(sf::RenderWindow*) {}
void Entity::onAttach(World&) {}
void Entity::onDetach(World&) {}

}  // namespace physim
