// The paper's face of snapshots: Simulation::snapshot and restore carry the world, the time, the results and the
// subclass's saveState; a member that steers the physics and is saved replays exactly, and restore refuses a
// snapshot whose entities are gone or an empty one, leaving the simulation as it was.

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>

#include <gtest/gtest.h>

#include <any>
#include <stdexcept>

namespace physim {
namespace {

// Kicks its ball up every 10th step, harder each time: `kicks` steers the physics, so it must be saved.
class Kicker : public Simulation {
public:
    int kicks = 0;
    Object* ball = nullptr;
    bool saveKicks = true;

    Kicker() {
        ball = &spawn<Object>(CircleShape(0.2), sf::Color::Black);
        ball->setPosition({0.0, 1.0});
    }
    void step() {
        if (world().stepCount() % 10 == 0) {
            ++kicks;
            world().applyLinearImpulse(ball->rb.bodyId(), Vec2(0.0, 0.1 * kicks));
        }
        fixedStep();
        setResult("kicks", kicks, std::nullopt, "");
    }
    std::any saveState() const override { return saveKicks ? std::any(kicks) : std::any(); }
    void restoreState(const std::any& state) override {
        if (state.has_value()) kicks = std::any_cast<int>(state);
    }
};

TEST(SnapshotFace, SavedMembersTimeAndResultsReplayExactly) {
    Kicker sim;
    for (int i = 0; i < 35; ++i) sim.step();
    const Simulation::Snapshot s = sim.snapshot();
    for (int i = 0; i < 40; ++i) sim.step();
    const std::uint64_t first = sim.world().stateHash();
    const double time = sim.time;
    sim.restore(s);
    EXPECT_EQ(sim.kicks, 4);
    EXPECT_EQ(sim.results().at(0).measured, 4.0);
    EXPECT_DOUBLE_EQ(sim.time, 35 * sim.fixedTimeStep());
    for (int i = 0; i < 40; ++i) sim.step();
    EXPECT_EQ(sim.world().stateHash(), first);
    EXPECT_EQ(sim.time, time);
}

// Without the member saved, the kicks after a restore come harder: the replay differs (the hook is what makes it
// exact, not luck).
TEST(SnapshotFace, AnUnsavedSteeringMemberChangesTheReplay) {
    Kicker sim;
    sim.saveKicks = false;
    for (int i = 0; i < 35; ++i) sim.step();
    const Simulation::Snapshot s = sim.snapshot();
    for (int i = 0; i < 40; ++i) sim.step();
    const std::uint64_t first = sim.world().stateHash();
    sim.restore(s);
    for (int i = 0; i < 40; ++i) sim.step();
    EXPECT_NE(sim.world().stateHash(), first);
}

TEST(SnapshotFace, RestoreRefusesChangedEntitiesAndEmptySnapshots) {
    Kicker sim;
    for (int i = 0; i < 5; ++i) sim.step();
    const Simulation::Snapshot s = sim.snapshot();
    Object& extra = sim.spawn<Object>(CircleShape(0.1), sf::Color::Black);
    sim.step();
    const std::uint64_t now = sim.world().stateHash();
    EXPECT_THROW(sim.restore(s), std::logic_error);
    EXPECT_EQ(sim.world().stateHash(), now);
    EXPECT_THROW(sim.restore(Simulation::Snapshot{}), std::invalid_argument);
    sim.removeEntity(extra.id());
    EXPECT_NO_THROW(sim.restore(s));
    EXPECT_EQ(sim.world().stepCount(), 5u);
}

}  // namespace
}  // namespace physim

namespace physim {
namespace {

// A branch with nothing changed is the same run: bit-identical states all along (distance exactly 0, equal hashes),
// since the step is deterministic. One whose ball is 1 mm/s faster sideways drifts apart by what that velocity
// says: 1 mm/s for 2 s is 2 mm (within 1e-9 m: the ball flies freely, only gravity acts).
TEST(BranchFace, AnUnchangedBranchIsTheSameRunAndAChangedOneDrifts) {
    Simulation sim;
    Object& ball = sim.spawn<Object>(CircleShape(0.2), sf::Color::Black);
    ball.setPosition({0.0, 200.0});  // falls 82 m in the run: never lands
    Object& bouncer = sim.spawn<Object>(CircleShape(0.2), sf::Color::Black);
    bouncer.setPosition({3.0, 0.5});
    Object& ground = sim.spawn<Object>(RectangleShape({10.0, 0.2}), sf::Color::Black);
    ground.rb.setMass(0.0);
    sim.world().setVelocity(bouncer.rb.bodyId(), Vec2(0.0, -4.0));  // bounces on the ground within the run
    for (int i = 0; i < 5; ++i) sim.fixedStep();
    sim.startBranch(sim.snapshot());
    for (int i = 0; i < 80; ++i) {
        sim.fixedStep();
        ASSERT_EQ(sim.branchDistance(), 0.0) << "step " << i;
    }
    EXPECT_EQ(sim.branch()->stateHash(), sim.world().stateHash());

    const BodyId id = ball.rb.bodyId();
    sim.startBranch(sim.snapshot(), [&](World& w) { w.setVelocity(id, w.velocity(id) + Vec2(0.001, 0.0)); });
    for (int i = 0; i < 80; ++i) sim.fixedStep();  // 2 s at 40 Hz
    EXPECT_NEAR(sim.branchDistance(), 0.002, 1e-9);
    sim.endBranch();
    EXPECT_EQ(sim.branch(), nullptr);
    EXPECT_EQ(sim.branchDistance(), 0.0);
    EXPECT_THROW(sim.startBranch(Simulation::Snapshot{}), std::invalid_argument);
}

}  // namespace
}  // namespace physim
