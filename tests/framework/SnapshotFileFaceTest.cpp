// The paper's face of snapshot files: Simulation::writeSnapshot and readSnapshot carry the world, its branch, the
// time, the results and the subclass's writeState into a simulation built alike, whose fixed steps then repeat what
// followed bit for bit (equal state hashes: the step is deterministic, so anything else is state the file missed);
// bad files, another physics rate and other entities are refused with the simulation unchanged.

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>
#include <string>

namespace physim {
namespace {

// Kicks its ball up every 10th step, harder each time: `kicks` steers the physics, so its file must hold it.
class Kicker : public Simulation {
public:
    int kicks = 0;
    Object* ball = nullptr;
    bool writeKicks = true;

    Kicker() {
        ball = &spawn<Object>(CircleShape(0.2), sf::Color::Black);
        ball->setPosition({0.0, 1.0});
        Object& ground = spawn<Object>(RectangleShape({10.0, 0.2}), sf::Color::Black);
        ground.rb.setMass(0.0);
    }
    void step() {
        if (world().stepCount() % 10 == 0) {
            ++kicks;
            world().applyLinearImpulse(ball->rb.bodyId(), Vec2(0.0, 0.1 * kicks));
        }
        fixedStep();
        setResult("kicks", kicks, kicks % 2 == 0 ? std::optional<double>(1.0) : std::nullopt, "1");
    }
    void writeState(StateWriter& out) const override {
        if (writeKicks) out.putInt(kicks);
    }
    void readState(StateReader& in) override {
        if (writeKicks) kicks = static_cast<int>(in.getInt());
    }
};

std::string fileOf(const Simulation& sim) {
    std::ostringstream out(std::ios::binary);
    sim.writeSnapshot(out);
    return out.str();
}

void readInto(Simulation& sim, const std::string& bytes) {
    std::istringstream in(bytes, std::ios::binary);
    sim.readSnapshot(in);
}

TEST(SnapshotFileFace, AnotherSimulationResumesExactly) {
    Kicker first;
    for (int i = 0; i < 35; ++i) first.step();
    first.startBranch(first.snapshot(), [&](World& w) { w.setVelocity(first.ball->rb.bodyId(), Vec2(0.01, 0.0)); });
    for (int i = 0; i < 10; ++i) first.step();
    const std::string bytes = fileOf(first);
    for (int i = 0; i < 40; ++i) first.step();

    Kicker second;
    second.step();  // elsewhere: the file puts it back
    readInto(second, bytes);
    EXPECT_EQ(second.kicks, 5);
    EXPECT_EQ(second.results().at(0).measured, 5.0);
    EXPECT_FALSE(second.results().at(0).predicted.has_value());
    EXPECT_EQ(second.time, 45 * second.fixedTimeStep());
    ASSERT_NE(second.branch(), nullptr);
    for (int i = 0; i < 40; ++i) second.step();
    EXPECT_EQ(second.world().stateHash(), first.world().stateHash());
    EXPECT_EQ(second.branch()->stateHash(), first.branch()->stateHash());
    EXPECT_EQ(second.time, first.time);
    EXPECT_EQ(second.results().at(0).measured, first.results().at(0).measured);
    EXPECT_EQ(second.results().at(0).predicted, first.results().at(0).predicted);
}

// Without the member written, the kicks after reading come softer: the replay differs (the hook is what makes it
// exact, not luck).
TEST(SnapshotFileFace, AnUnwrittenSteeringMemberChangesTheReplay) {
    Kicker first;
    first.writeKicks = false;
    for (int i = 0; i < 35; ++i) first.step();
    const std::string bytes = fileOf(first);
    for (int i = 0; i < 40; ++i) first.step();
    Kicker second;
    second.writeKicks = false;
    readInto(second, bytes);
    for (int i = 0; i < 40; ++i) second.step();
    EXPECT_NE(second.world().stateHash(), first.world().stateHash());
}

// Restoring `bytes` into a fresh Kicker stepped 3 times throws E naming `word`; its world and time stay.
template <class E>
void expectRefused(const std::string& bytes, const std::string& word, Kicker& target) {
    const std::uint64_t hash = target.world().stateHash();
    const double time = target.time;
    try {
        readInto(target, bytes);
        ADD_FAILURE() << word << ": no exception";
    } catch (const E& e) {
        EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
    EXPECT_EQ(target.world().stateHash(), hash) << word;
    EXPECT_EQ(target.time, time) << word;
}

TEST(SnapshotFileFace, BadFilesAndOtherScenesAreRefused) {
    Kicker source;
    for (int i = 0; i < 12; ++i) source.step();
    const std::string bytes = fileOf(source);
    Kicker target;
    for (int i = 0; i < 3; ++i) target.step();

    std::string magic = bytes;
    magic[1] = 'x';
    expectRefused<std::runtime_error>(magic, "magic", target);
    std::string version = bytes;
    version[8] = 9;
    expectRefused<std::runtime_error>(version, "version 9", target);
    for (const std::size_t n : {std::size_t{0}, std::size_t{5}, std::size_t{27}, bytes.size() / 2, bytes.size() - 1})
        expectRefused<std::runtime_error>(bytes.substr(0, n), "truncated", target);
    for (const std::size_t at : {std::size_t{40}, bytes.size() / 2, bytes.size() - 1}) {
        std::string flipped = bytes;
        flipped[at] ^= 0x20;
        expectRefused<std::runtime_error>(flipped, "checksum", target);
    }

    Kicker faster;
    faster.setPhysicsRate(60.0);
    expectRefused<std::logic_error>(bytes, "physics rate", faster);
    Kicker more;
    more.spawn<Object>(CircleShape(0.1), sf::Color::Black);
    expectRefused<std::logic_error>(bytes, "entities", more);
}

}  // namespace
}  // namespace physim
