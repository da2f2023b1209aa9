// Going back in the window after changing the run by hand: a body dragged with the mouse, and a key the scene
// answers by throwing a ball. The replay of steps from an earlier snapshot cannot repeat either, so the runner marks
// each on the timeline (Timeline::mark, and Timeline::noteChange for a drag's moves); a scrub back never replays
// across one, and lands on exactly a state the run had (equal World::stateHash). The timeline's snapshots are spaced by settings here, not by measured cost, so that
// no snapshot but the marks lies between a change and the moment scrubbed to, whatever the host's speed.

#include "RunnerAccess.hpp"
#include "support/SfmlEvents.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>

namespace physim {
namespace {

constexpr double kFrame = 1.0 / 40.0;  // one fixed step per frame at 40 Hz
const sf::Vector2u kWindow(800, 600);

// A box on a floor, and a ball the J key throws up.
class Scene : public Simulation {
public:
    void onCreate() override {
        auto& floor = spawn<Object>(Vec2(8.0, 1.0));
        floor.rb.setMass(0.0);
        floor.setPosition({0.0, -3.5});
        box = &spawn<Object>(Vec2(1.0, 1.0));
        box->setPosition({0.0, -2.5});
        ball = &spawn<Object>(CircleShape(0.2), sf::Color::Blue);
        ball->setPosition({3.0, -2.8});
    }
    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::J) ball->rb.setVelocity({0.0, 5.0});
    }
    Object* box = nullptr;  // owned by the simulation
    Object* ball = nullptr;
};

Runner makeRunner() {
    RunOptions options;
    options.headless = true;
    options.hz = 40.0;
    options.width = static_cast<int>(kWindow.x);
    options.height = static_cast<int>(kWindow.y);
    return Runner([] { return std::make_unique<Scene>(); }, options);
}

sf::Vector2i pixelOf(const Simulation& sim, const Vec2& p) { return test::pixelOf(sim.view, p, kWindow); }

long long stepOf(const Simulation& sim) { return std::llround(sim.time / sim.fixedTimeStep()); }

TEST(RunnerTimeline, ScrubbingBackOverADragAndASceneKeyLandsOnTheRunsStates) {
    Runner runner = makeRunner();
    Timeline::Settings sparse;
    sparse.minInterval = 1000;  // only the restart's snapshot and the marks
    RunnerAccess::recordTimeline(runner, sparse);
    runner.restart();
    Scene& sim = static_cast<Scene&>(runner.simulation());
    std::map<long long, std::uint64_t> hashAtStep;
    auto frames = [&](int n) {
        for (int i = 0; i < n; ++i) {
            runner.frame(kFrame, nullptr);
            hashAtStep[stepOf(sim)] = sim.world().stateHash();
        }
    };
    frames(10);
    // Drag the box up and to the left over 20 frames, then let go.
    runner.handleEvent(
        test::mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left, pixelOf(sim, sim.box->getPosition())),
        nullptr);
    ASSERT_TRUE(RunnerAccess::controls(runner).dragJoint());
    for (int i = 0; i < 20; ++i) {
        runner.handleEvent(test::mouseMove(pixelOf(sim, {-0.1 * i, -2.5 + 0.1 * i})), nullptr);
        frames(1);
    }
    EXPECT_GT(sim.box->getPosition().y(), -1.0) << "the drag lifted the box";
    runner.handleEvent(test::mouseButton(sf::Event::MouseButtonReleased, sf::Mouse::Left, pixelOf(sim, {-2.0, -0.5})),
                       nullptr);
    frames(10);
    runner.handleEvent(test::keyPress(sf::Keyboard::J), nullptr);  // the scene throws the ball
    frames(10);
    EXPECT_GT(sim.ball->getPosition().y(), -2.0) << "the key threw the ball";
    frames(30);
    ASSERT_EQ(stepOf(sim), 80);
    // Back to moments after the key and after the drag (each marked with a snapshot), latest first (a scrub drops
    // what follows): exactly there.
    for (const long long step : {70LL, 45LL, 35LL}) {
        runner.scrubTo(step * sim.fixedTimeStep());
        ASSERT_EQ(stepOf(runner.simulation()), step);
        EXPECT_EQ(runner.simulation().world().stateHash(), hashAtStep.at(step)) << "step " << step;
    }
    // Into the drag: its moves are noted each frame, with a snapshot only where one is due (none, here), so the scrub
    // stops at the first move after the drag began, on the state the run had then.
    runner.scrubTo(22 * sim.fixedTimeStep());
    const long long landed = stepOf(runner.simulation());
    EXPECT_GT(landed, 10);
    EXPECT_LE(landed, 22);
    EXPECT_EQ(runner.simulation().world().stateHash(), hashAtStep.at(landed)) << "step " << landed;
}

}  // namespace
}  // namespace physim
