#pragma once
// The paper's Entity (section 4): the base of everything in a simulation. Owned by its Simulation; owns its
// behaviors.

#include "physim/framework/Behavior.hpp"

#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace sf {
class RenderWindow;
}

namespace physim {

class Simulation;
class World;

class Entity {
public:
    Entity() = default;
    virtual ~Entity();
    Entity(const Entity&) = delete;
    Entity& operator=(const Entity&) = delete;

    /// Unique within its simulation, from 1 upwards in the order entities were added; 0 until added.
    int id() const { return id_; }
    /// The simulation that owns this entity, or nullptr before it is added.
    Simulation* simulation() const { return simulation_; }

    /// Takes ownership of `behavior` and makes this entity its owner. Throws std::invalid_argument for a null
    /// behavior or one that already names another entity as its owner.
    Behavior& AddBehavior(std::unique_ptr<Behavior> behavior);
    /// Constructs a T (its constructor receives the arguments) and adds it.
    template <class T, class... Args>
    T& AddBehavior(Args&&... args) {
        static_assert(std::is_base_of_v<Behavior, T>, "T must derive from physim::Behavior");
        auto owned = std::make_unique<T>(std::forward<Args>(args)...);
        T& ref = *owned;
        AddBehavior(std::unique_ptr<Behavior>(std::move(owned)));
        return ref;
    }
    /// The first behavior that is a T, or nullptr (the paper's TryGetBehavior).
    template <class T>
    T* TryGetBehavior() const {
        for (Behavior* b : behaviors_)
            if (auto* found = dynamic_cast<T*>(b)) return found;
        return nullptr;
    }
    const std::vector<Behavior*>& behaviors() const { return behaviors_; }

    // The paper's phases. update: once per frame. beforeFixedUpdate, checkCollisions, fixedUpdate: once per
    // fixed step, in that order, each for all entities before the next. render: once per drawn frame.
    virtual void update() {}
    virtual void beforeFixedUpdate() {}
    virtual void checkCollisions() {}
    virtual void fixedUpdate() {}
    virtual void render(sf::RenderWindow* window);

protected:
    /// Called when the simulation takes ownership; create physics bodies in `world` here.
    virtual void onAttach(World& world);
    /// Called before the simulation releases the entity; remove physics bodies here.
    virtual void onDetach(World& world);
    /// Registers a behavior that is a member of a derived class (not owned through AddBehavior).
    void registerMemberBehavior(Behavior& behavior);

private:
    friend class Simulation;
    int id_ = 0;
    Simulation* simulation_ = nullptr;
    std::vector<std::unique_ptr<Behavior>> owned_;
    std::vector<Behavior*> behaviors_;  // every behavior, owned or member, in the order added
};

}  // namespace physim
