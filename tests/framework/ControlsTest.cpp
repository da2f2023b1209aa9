// The window's controls driven by synthesized SFML events through the Runner, as a window would deliver them
// (no display needed: without a window the runner uses --size's pixels). Checked against what each control
// promises: a dragged body follows the cursor, O runs exactly one step, the time scale sets how many steps a
// real second runs, zoom keeps the point under the cursor, a pan drags the scene with the cursor.

#include "RunnerAccess.hpp"
#include "support/Scenes.hpp"
#include "support/SfmlEvents.hpp"

#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace physim {
namespace {

constexpr double kFrame = 1.0 / 60.0;  // s, a 60 Hz display's frame

// A 1 m box at the origin in zero gravity and a static floor 3 m below, at 40 Hz; one parameter.
class Scene : public Simulation {
public:
    Scene() { parameters.add("width", "box width (m)", 1.0, 0.5, 2.0); }
    void onCreate() override {
        WorldSettings settings = world().settings();
        settings.gravity = Vec2::Zero();
        world().setSettings(settings);
        auto& floor = spawn<Object>(Vec2(8.0, 1.0));
        floor.rb.setMass(0.0);
        floor.setPosition({0.0, -3.5});
        box = &spawn<Object>(Vec2(parameters.get("width"), 1.0));
    }
    Object* box = nullptr;  // owned by the simulation
};

Runner makeRunner() {
    RunOptions options;
    options.headless = true;
    options.hz = 40.0;
    options.width = 800;
    options.height = 600;
    return Runner([] { return std::make_unique<Scene>(); }, options);
}

Scene& scene(Runner& runner) { return static_cast<Scene&>(runner.simulation()); }

const sf::Vector2u kWindow(800, 600);

sf::Vector2i pixelOf(const Simulation& sim, const Vec2& p) { return test::pixelOf(sim.view, p, kWindow); }

using test::keyPress;
using test::mouseButton;
using test::mouseMove;
using test::wheel;

int runFrames(Runner& runner, int frames) {
    int steps = 0;
    for (int i = 0; i < frames; ++i) steps += runner.frame(kFrame, nullptr);
    return steps;
}

// Press on the box, move the cursor 2 m right and 1 m up, hold: the box's grabbed point settles on the cursor
// (zero gravity: no sag). It comes to rest, and sleeps, once slower than the 1 cm/s sleep tolerance, when the
// 5 Hz spring's gap is below about v / w = 0.3 mm. Grabbed at its centre so the pull starts no spin (a spinning
// body's point would circle the cursor, the spring stretched by the centripetal force). Release: the joint is
// gone.
TEST(Controls, DragMovesTheBodyToTheCursor) {
    Runner runner = makeRunner();
    runner.restart();
    Simulation& sim = runner.simulation();
    const Vec2 grabbed = Vec2::Zero();
    runner.handleEvent(mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left, pixelOf(sim, grabbed)), nullptr);
    ASSERT_TRUE(RunnerAccess::controls(runner).dragJoint().has_value()) << "the press landed on the box";
    EXPECT_EQ(sim.world().jointType(*RunnerAccess::controls(runner).dragJoint()), JointType::Mouse);
    const sf::Vector2i target = pixelOf(sim, grabbed + Vec2(2.0, 1.0));
    runner.handleEvent(mouseMove(target), nullptr);
    runFrames(runner, 180);
    const auto [cursor, anchor] = sim.world().jointAnchors(*RunnerAccess::controls(runner).dragJoint());
    EXPECT_NEAR((cursor - sim.view.toWorld(target, kWindow)).norm(), 0.0, 1e-12) << "target = cursor";
    EXPECT_LT((anchor - cursor).norm(), 3e-4) << "the grabbed point is on the cursor";
    EXPECT_GT(scene(runner).box->getPosition().x(), 1.5) << "the box itself moved";

    runner.handleEvent(mouseButton(sf::Event::MouseButtonReleased, sf::Mouse::Left, target), nullptr);
    EXPECT_FALSE(RunnerAccess::controls(runner).dragJoint().has_value());
    EXPECT_EQ(sim.world().jointCount(), 0u);

    // A press on empty space grabs nothing; a press on the static floor neither.
    runner.handleEvent(mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left, pixelOf(sim, {-3.0, 2.0})), nullptr);
    EXPECT_FALSE(RunnerAccess::controls(runner).dragJoint().has_value());
    runner.handleEvent(mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left, pixelOf(sim, {0.0, -3.5})), nullptr);
    EXPECT_FALSE(RunnerAccess::controls(runner).dragJoint().has_value());
}

// The pull is a force, so contacts stay in charge: dragged towards a point 2.5 m inside the floor, the box stops
// on it. Resting there, the floor's soft contact (a spring of w_c = 2 pi contactHertz, capped at a quarter of the
// substep rate) holds the drag's spring k_d (2.5 m - overlap): the overlap is 2.5 k_d / (k_c + k_d) with
// k_d = m w_d^2 and k_c = m w_c^2 / 1.25 (each of the square box's two points a spring of its own:
// test::pointCompliance; 12.15 mm at 40 Hz, measured to 1e-5 m). 1 mm more is allowed for the settling.
TEST(Controls, DraggedBodyStopsOnTheFloor) {
    Runner runner = makeRunner();
    runner.restart();
    Simulation& sim = runner.simulation();
    runner.handleEvent(mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left, pixelOf(sim, Vec2::Zero())),
                       nullptr);
    runner.handleEvent(mouseMove(pixelOf(sim, {0.0, -5.0})), nullptr);  // 2 m inside the 1 m floor
    runFrames(runner, 120);
    // The floor's top is at y = -3; the box's half height 0.5.
    const WorldSettings& s = sim.world().settings();
    const double contactW = 2 * M_PI * std::min(s.contactHertz, s.substeps * sim.physicsRate() / 4.0);
    const double dragW = 2 * M_PI * Controls::dragHertz;
    const double contactK = contactW * contactW / test::pointCompliance(0.5, 0.5);  // per kg, the 1 m box
    const double overlap = 2.5 * dragW * dragW / (contactK + dragW * dragW);
    EXPECT_GT(scene(runner).box->getPosition().y(), -2.5 - overlap - 1e-3);
}

TEST(Controls, SingleStepAdvancesExactlyOneStep) {
    Runner runner = makeRunner();
    runner.restart();
    Simulation& sim = runner.simulation();
    runFrames(runner, 10);
    runner.handleEvent(keyPress(sf::Keyboard::P), nullptr);
    ASSERT_TRUE(sim.paused);
    EXPECT_EQ(runFrames(runner, 10), 0) << "paused: no steps";
    const std::uint64_t steps = sim.world().stepCount();
    const double t = sim.time;
    runner.handleEvent(keyPress(sf::Keyboard::O), nullptr);
    EXPECT_EQ(runner.frame(0.5, nullptr), 1) << "one step, however long the frame";
    EXPECT_EQ(sim.world().stepCount(), steps + 1);
    EXPECT_DOUBLE_EQ(sim.time, t + sim.fixedTimeStep());
    EXPECT_EQ(runFrames(runner, 10), 0) << "and only one";
    EXPECT_TRUE(sim.paused);

    runner.handleEvent(keyPress(sf::Keyboard::P), nullptr);  // running again: O pauses, then steps
    runFrames(runner, 3);
    runner.handleEvent(keyPress(sf::Keyboard::O), nullptr);
    EXPECT_TRUE(sim.paused);
    EXPECT_EQ(runner.frame(kFrame, nullptr), 1);
}

// 40 Hz physics on 60 Hz frames: one real second runs 40 steps at 1x; ] doubles, [ halves. A frame carries
// its remainder to the next, so each second's count is within one step of rate x scale.
TEST(Controls, TimeScaleChangesStepsPerRealSecond) {
    Runner runner = makeRunner();
    runner.restart();
    EXPECT_NEAR(runFrames(runner, 60), 40, 1);
    runner.handleEvent(keyPress(sf::Keyboard::LBracket), nullptr);
    EXPECT_EQ(runner.timeScale(), 0.5);
    EXPECT_NEAR(runFrames(runner, 60), 20, 1);
    runner.handleEvent(keyPress(sf::Keyboard::RBracket), nullptr);
    runner.handleEvent(keyPress(sf::Keyboard::RBracket), nullptr);
    EXPECT_EQ(runner.timeScale(), 2.0);
    EXPECT_NEAR(runFrames(runner, 60), 80, 1);
    for (int i = 0; i < 10; ++i) runner.handleEvent(keyPress(sf::Keyboard::RBracket), nullptr);
    EXPECT_EQ(runner.timeScale(), Runner::maxTimeScale) << "capped";
    EXPECT_THROW(runner.setTimeScale(0.0), std::invalid_argument);
    EXPECT_THROW(runner.setTimeScale(NAN), std::invalid_argument);
}

// 1000 Hz on 60 Hz frames needs 16.7 steps a frame; --max-steps-per-frame 8 holds the run at 8 x 60 / 1000 = 0.48
// of real time, and the pace meter (what the overlay reports) says so. At 40 Hz nothing is capped.
TEST(Controls, PaceMeterReportsTheCatchUpCap) {
    RunOptions options;
    options.headless = true;
    options.hz = 1000.0;
    options.maxStepsPerFrame = 8;
    Runner capped([] { return std::make_unique<Scene>(); }, options);
    capped.restart();
    runFrames(capped, 120);
    EXPECT_NEAR(RunnerAccess::pace(capped).pace(), 0.48, 1e-9);
    EXPECT_TRUE(RunnerAccess::pace(capped).cappedBelow(1.0));

    options.hz = 40.0;  // still with the cap: the pacing would catch the slow frame below up in full
    Runner free([] { return std::make_unique<Scene>(); }, options);
    free.restart();
    runFrames(free, 120);
    EXPECT_NEAR(RunnerAccess::pace(free).pace(), 1.0, 0.03);
    EXPECT_FALSE(RunnerAccess::pace(free).cappedBelow(1.0));
    // One slow frame (0.5 s: a window being moved) drops steps once; it is no sustained limit.
    free.frame(0.5, nullptr);
    runFrames(free, 30);
    EXPECT_LT(RunnerAccess::pace(free).pace(), 0.97) << "that second did run slow";
    EXPECT_FALSE(RunnerAccess::pace(free).cappedBelow(1.0)) << "but the cap is not what holds the run back";
}

TEST(Controls, WheelZoomsAboutTheCursor) {
    Runner runner = makeRunner();
    runner.restart();
    Simulation& sim = runner.simulation();
    const sf::Vector2i cursor(620, 130);
    const Vec2 under = sim.view.toWorld(cursor, kWindow);
    const double scale = sim.view.pixelsPerMetre;
    runner.handleEvent(wheel(2.0f, cursor), nullptr);
    EXPECT_NEAR(sim.view.pixelsPerMetre, scale * 1.1 * 1.1, 1e-9 * scale);
    EXPECT_LT((sim.view.toWorld(cursor, kWindow) - under).norm(), 1e-12) << "the point under the cursor stays";
    runner.handleEvent(wheel(-1.0f, cursor), nullptr);
    EXPECT_NEAR(sim.view.pixelsPerMetre, scale * 1.1, 1e-9 * scale);
}

TEST(Controls, RightDragPansWithTheCursorAndFRefits) {
    Runner runner = makeRunner();
    runner.restart();
    Simulation& sim = runner.simulation();
    const View fitted = sim.view;
    const sf::Vector2i from(300, 300), to(420, 250);
    const Vec2 grabbed = sim.view.toWorld(from, kWindow);
    runner.handleEvent(mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Right, from), nullptr);
    runner.handleEvent(mouseMove({350, 280}), nullptr);
    runner.handleEvent(mouseMove(to), nullptr);
    runner.handleEvent(mouseButton(sf::Event::MouseButtonReleased, sf::Mouse::Right, to), nullptr);
    EXPECT_LT((sim.view.toWorld(to, kWindow) - grabbed).norm(), 1e-12) << "the scene moved with the cursor";
    EXPECT_FALSE(RunnerAccess::controls(runner).dragJoint().has_value()) << "panning grabs no body";
    runner.handleEvent(mouseMove({0, 0}), nullptr);
    EXPECT_LT((sim.view.toWorld(to, kWindow) - grabbed).norm(), 1e-12) << "released: moving no longer pans";

    runner.handleEvent(keyPress(sf::Keyboard::F), nullptr);
    runner.frame(0.0, nullptr);
    EXPECT_EQ(sim.view, fitted) << "F fits the view again";
}

TEST(Controls, KeysToggleDebugDrawingAndStatistics) {
    Runner runner = makeRunner();
    runner.restart();
    Simulation& sim = runner.simulation();
    const std::pair<sf::Keyboard::Key, bool DebugDrawOptions::*> keys[] = {
        {sf::Keyboard::Num1, &DebugDrawOptions::contacts}, {sf::Keyboard::Num2, &DebugDrawOptions::boxes},
        {sf::Keyboard::Num3, &DebugDrawOptions::velocities}, {sf::Keyboard::Num4, &DebugDrawOptions::joints},
        {sf::Keyboard::Num5, &DebugDrawOptions::centres}, {sf::Keyboard::Num6, &DebugDrawOptions::sleep},
        {sf::Keyboard::Num7, &DebugDrawOptions::sensors}, {sf::Keyboard::Num8, &DebugDrawOptions::rays}};
    for (const auto& [code, option] : keys) {
        EXPECT_FALSE(sim.debugDraw.*option);
        runner.handleEvent(keyPress(code), nullptr);
        EXPECT_TRUE(sim.debugDraw.*option) << code;
    }
    EXPECT_FALSE(runner.statsShown());
    runner.handleEvent(keyPress(sf::Keyboard::Tab), nullptr);
    EXPECT_TRUE(runner.statsShown());
    runner.setStatsShown(false);  // the panel's way, as the gallery does
    EXPECT_FALSE(runner.statsShown());
}

// Space makes the simulation again with the user's parameter values and debug drawing; a new factory (the
// gallery switching scenes) starts from that scene's own.
TEST(Controls, RestartKeepsParametersAndDrawingANewSceneStartsFresh) {
    Runner runner = makeRunner();
    runner.restart();
    runner.simulation().parameters.set("width", 2.0);
    runner.simulation().debugDraw.boxes = true;
    runner.handleEvent(keyPress(sf::Keyboard::Space), nullptr);
    EXPECT_EQ(runner.simulation().parameters.get("width"), 2.0);
    EXPECT_TRUE(runner.simulation().debugDraw.boxes);
    EXPECT_NEAR(scene(runner).box->rb.mass(), 2.0, 1e-12) << "made with the kept width: 2 m x 1 m at 1 kg/m^2";

    runner.setFactory([] { return std::make_unique<Scene>(); });
    runner.restart();
    EXPECT_EQ(runner.simulation().parameters.get("width"), 1.0);
    EXPECT_FALSE(runner.simulation().debugDraw.boxes);
}

// A drag in progress when the simulation is made again belongs to the old world: it is dropped, not reused.
TEST(Controls, RestartDuringADragLetsGo) {
    Runner runner = makeRunner();
    runner.restart();
    runner.handleEvent(
        mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left, pixelOf(runner.simulation(), Vec2::Zero())),
        nullptr);
    ASSERT_TRUE(RunnerAccess::controls(runner).dragJoint().has_value());
    runner.handleEvent(keyPress(sf::Keyboard::Space), nullptr);
    EXPECT_FALSE(RunnerAccess::controls(runner).dragJoint().has_value());
    runner.handleEvent(mouseMove({10, 10}), nullptr);  // no stale joint to move
    runner.handleEvent(mouseButton(sf::Event::MouseButtonReleased, sf::Mouse::Left, {10, 10}), nullptr);
    EXPECT_EQ(runner.simulation().world().jointCount(), 0u);
}

}  // namespace
}  // namespace physim

namespace physim {
namespace {

// The README's scene: a 20 m ground and a box 5 m up, no view set. At the start every body is inside the
// scene area (the part of the window below the overlay); a simulation that sets its view keeps it.
class Drop : public Simulation {
public:
    void onCreate() override {
        auto& ground = spawn<Object>(Vec2(20.0, 1.0));
        ground.rb.setMass(0.0);
        ground.setPosition({0.0, -0.5});
        spawn<Object>(Vec2(1.0, 1.0)).setPosition({0.0, 5.0});
    }
};

class HandSetView : public Drop {
public:
    void onCreate() override {
        Drop::onCreate();
        view.center = {17.5, 7.0};
        view.pixelsPerMetre = 30.0;
    }
};

TEST(Controls, TheStartViewShowsEveryBodyUnlessTheSceneSetsIt) {
    for (const auto& size : {sf::Vector2u(1280, 720), sf::Vector2u(640, 360), sf::Vector2u(300, 900)}) {
        RunOptions options;
        options.headless = true;
        options.width = static_cast<int>(size.x);
        options.height = static_cast<int>(size.y);
        Runner runner([] { return std::make_unique<Drop>(); }, options);
        runner.restart();
        const Simulation& sim = runner.simulation();
        const sf::FloatRect area = runner.sceneArea();
        const sf::Transform toPixels = sim.view.worldToPixels(size);
        for (BodyId id : sim.world().bodies()) {
            const Aabb box = computeAabb(sim.world().shape(id), sim.world().transform(id));
            for (const Vec2& corner : {box.lower, box.upper}) {
                const sf::Vector2f p = toPixels.transformPoint(float(corner.x()), float(corner.y()));
                EXPECT_TRUE(area.contains(p)) << size.x << "x" << size.y << ": (" << p.x << ", " << p.y << ")";
            }
        }
    }
    Runner runner([] { return std::make_unique<HandSetView>(); }, RunOptions{});
    runner.restart();
    EXPECT_EQ(runner.simulation().view.center, Vec2(17.5, 7.0));
    EXPECT_EQ(runner.simulation().view.pixelsPerMetre, 30.0);
}

}  // namespace
}  // namespace physim
