// Ownership, ids and behaviors: the paper's AddBehavior / TryGetBehavior with clear ownership.

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>

#include <gtest/gtest.h>

#include <set>
#include <type_traits>

namespace physim {
namespace {

struct Counter : Behavior {
    int updates = 0;
    void update() override { ++updates; }
};
struct Other : Behavior {};

TEST(Entity, IdsAreUniqueAndInOrderOfAdding) {
    Simulation sim;
    std::set<int> ids;
    for (int i = 0; i < 50; ++i) ids.insert(sim.spawn<Entity>().id());
    EXPECT_EQ(ids.size(), 50u);
    EXPECT_EQ(*ids.begin(), 1);
    EXPECT_EQ(*ids.rbegin(), 50);
    // Ids are not reused after removal.
    sim.removeEntity(7);
    EXPECT_EQ(sim.spawn<Entity>().id(), 51);
    EXPECT_EQ(sim.findEntity(7), nullptr);
    EXPECT_NE(sim.findEntity(51), nullptr);
}

TEST(Entity, IdsArePerSimulationNotGlobal) {
    Simulation a, b;
    EXPECT_EQ(a.spawn<Entity>().id(), 1);
    EXPECT_EQ(b.spawn<Entity>().id(), 1);
}

TEST(Entity, TryGetBehaviorFindsByType) {
    Entity e;
    Counter& c = e.AddBehavior<Counter>();
    EXPECT_EQ(e.TryGetBehavior<Counter>(), &c);
    EXPECT_EQ(e.TryGetBehavior<Other>(), nullptr);
    EXPECT_EQ(e.TryGetBehavior<Behavior>(), &c);  // a base type finds the first behavior
    EXPECT_EQ(c.entity, &e);
}

TEST(Entity, ObjectExposesItsMemberBehaviors) {
    Object o;
    EXPECT_EQ(o.TryGetBehavior<RigidBody>(), &o.rb);
    EXPECT_EQ(o.TryGetBehavior<Mesh>(), &o.mesh);
    EXPECT_EQ(o.rb.entity, &o);
}

TEST(Entity, BehaviorOfAnotherEntityIsRejected) {
    Entity a, b;
    auto behavior = std::make_unique<Counter>();
    behavior->entity = &a;  // as the paper's Behavior(Entity* parent) constructor would
    EXPECT_THROW(b.AddBehavior(std::move(behavior)), std::invalid_argument);
    EXPECT_TRUE(b.behaviors().empty());
    EXPECT_THROW(a.AddBehavior(nullptr), std::invalid_argument);
}

TEST(Entity, BehaviorsUpdateAfterTheirEntity) {
    Simulation sim;
    Counter& c = sim.spawn<Entity>().AddBehavior<Counter>();
    sim.updateEntities();
    sim.updateEntities();
    EXPECT_EQ(c.updates, 2);
}

TEST(Entity, NullEntityIsRejected) {
    Simulation sim;
    EXPECT_THROW(sim.addEntity(std::unique_ptr<Entity>()), std::invalid_argument);
    EXPECT_TRUE(sim.entities().empty());
    EXPECT_THROW(sim.removeEntity(3), std::invalid_argument);
}

// Adding one entity twice cannot even be written: the simulation takes ownership through a unique_ptr, so a
// second add would need a second owner. These checks keep it that way.
template <class S, class Arg, class = void>
struct CanAdd : std::false_type {};
template <class S, class Arg>
struct CanAdd<S, Arg, std::void_t<decltype(std::declval<S&>().addEntity(std::declval<Arg>()))>> : std::true_type {};
static_assert(CanAdd<Simulation, std::unique_ptr<Entity>>::value);
static_assert(!CanAdd<Simulation, std::unique_ptr<Entity>&>::value, "an owned entity cannot be added again");
static_assert(!CanAdd<Simulation, Entity*>::value, "raw pointers would make ownership unclear");
static_assert(!std::is_copy_constructible_v<Entity>);

TEST(Entity, RemovedEntityLeavesTheWorldAndCanJoinAnother) {
    Simulation a, b;
    auto& obj = a.spawn<Object>();
    EXPECT_EQ(a.world().bodyCount(), 1u);
    obj.setPosition({1.0, 2.0});
    std::unique_ptr<Entity> e = a.removeEntity(obj.id());
    EXPECT_EQ(a.world().bodyCount(), 0u);
    EXPECT_EQ(e->simulation(), nullptr);
    Object& moved = b.addEntity(std::unique_ptr<Object>(static_cast<Object*>(e.release())));
    EXPECT_EQ(b.world().bodyCount(), 1u);
    EXPECT_EQ(moved.getPosition(), Vec2(1.0, 2.0));
}

TEST(Entity, RemovingDuringAPhaseIsALogicError) {
    struct SelfRemover : Entity {
        void fixedUpdate() override { simulation()->removeEntity(id()); }
    };
    Simulation sim;
    sim.spawn<SelfRemover>();
    EXPECT_THROW(sim.fixedStep(), std::logic_error);
}

TEST(Object, BadBodySettingsLeaveTheSimulationUnchanged) {
    Simulation sim;
    EXPECT_THROW(Object(Mesh::CircleMesh(1.0, sf::Color::Red), std::unique_ptr<CollisionShape>()),
                 std::invalid_argument);
    auto obj = std::make_unique<Object>(Mesh::CircleMesh(0.5, sf::Color::Red), CircleShape(0.5));
    EXPECT_THROW(obj->rb.setDensity(-2.0), std::invalid_argument);
    EXPECT_THROW(obj->rb.setMass(NAN), std::invalid_argument);
    EXPECT_THROW(obj->rb.setRestitution(1.5), std::invalid_argument);
    EXPECT_THROW(obj->setPosition({INFINITY, 0.0}), std::invalid_argument);
    EXPECT_THROW(obj->rb.addForce({1.0, 0.0}), std::logic_error) << "no body before it is in a simulation";
    sim.addEntity(std::move(obj));
    EXPECT_EQ(sim.world().bodyCount(), 1u);
}

TEST(Object, RigidBodyMassFromDensityAndShape) {
    Object box(Vec2(2.0, 1.0));
    box.rb.setDensity(3.0);
    EXPECT_NEAR(box.rb.mass(), 6.0, 1e-12);
    EXPECT_NEAR(box.rb.inertia(), 6.0 * (4.0 + 1.0) / 12.0, 1e-12);
    Simulation sim;
    auto& added = sim.addEntity(std::make_unique<Object>(Vec2(2.0, 1.0)));
    added.rb.setMass(10.0);
    EXPECT_NEAR(added.rb.mass(), 10.0, 1e-12);
    EXPECT_NEAR(added.rb.inertia(), 10.0 * 5.0 / 12.0, 1e-12);
}

TEST(Object, ForceModes) {
    Simulation sim;
    auto& o = sim.spawn<Object>();  // 1 m^2 at density 1: 1 kg
    o.rb.setMass(2.0);
    o.rb.setUseGravity(false);
    o.rb.addForce({1.0, 0.0}, ForceMode::IMPULSE);  // 1 N s on 2 kg: 0.5 m/s
    EXPECT_NEAR(o.rb.velocity().x(), 0.5, 1e-15);
    o.rb.addForce({1.0, 0.0}, ForceMode::VELOCITY);  // mass ignored
    EXPECT_NEAR(o.rb.velocity().x(), 1.5, 1e-15);
    const double dt = sim.fixedTimeStep();
    o.rb.addForce({0.0, 4.0}, ForceMode::FORCE);         // 2 m/s^2 for one step
    o.rb.addForce({0.0, 3.0}, ForceMode::ACCELERATION);  // 3 m/s^2 for one step
    sim.fixedStep();
    EXPECT_NEAR(o.rb.velocity().y(), 5.0 * dt, 1e-12);
    sim.fixedStep();  // forces were cleared after the step
    EXPECT_NEAR(o.rb.velocity().y(), 5.0 * dt, 1e-12);
}

}  // namespace
}  // namespace physim

namespace physim {
namespace {

TEST(Object, RigidBodySleepControls) {
    Simulation sim;
    sim.setPhysicsRate(60.0);
    auto& ground = sim.spawn<Object>(Vec2(10.0, 1.0));
    ground.rb.setMass(0.0);
    ground.setPosition({0.0, -0.5});
    auto& box = sim.spawn<Object>();
    box.setPosition({0.0, 0.5});
    auto& keeper = sim.spawn<Object>();
    keeper.setPosition({3.0, 0.5});
    keeper.rb.setAllowSleep(false);
    EXPECT_FALSE(keeper.rb.allowSleep());
    for (int i = 0; i < 180; ++i) sim.fixedStep();
    EXPECT_FALSE(box.rb.isAwake());
    EXPECT_TRUE(keeper.rb.isAwake());
    box.rb.wakeUp();
    EXPECT_TRUE(box.rb.isAwake());
    box.rb.addForce({0.0, 1.0}, ForceMode::IMPULSE);  // sleeps again later, but this wakes it now
    EXPECT_TRUE(box.rb.isAwake());
}

}  // namespace
}  // namespace physim
