#pragma once

namespace physim {

class Entity;

/// A component that gives an entity a property or a small task (the paper's section 5). Added to an entity
/// with Entity::AddBehavior, found again with Entity::TryGetBehavior<T>().
class Behavior {
public:
    /// The owning entity (non-owning pointer); set by AddBehavior, or given here as in the paper.
    Entity* entity = nullptr;

    explicit Behavior(Entity* parent = nullptr) : entity(parent) {}
    virtual ~Behavior() = default;
    /// A copy belongs to no entity until it is added to one.
    Behavior(const Behavior&) : entity(nullptr) {}
    Behavior& operator=(const Behavior&) { return *this; }

    /// Called once per frame after its entity's update().
    virtual void update() {}
};

}  // namespace physim
