// The frame loop with a real SFML window (run under Xvfb by tests/support/with-display.sh): the render
// phase comes after the fixed steps and onDrawGraphs, entities first, then onRender.

#include "support/Recorder.hpp"
#include "support/SfmlEvents.hpp"

#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <SFML/Graphics/RenderTexture.hpp>
#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Window/Event.hpp>

#include <gtest/gtest.h>

namespace physim {
namespace {

using test::CallLog;

TEST(WindowLifecycle, RenderPhaseFollowsTheGraphs) {
    CallLog log;
    RunOptions options;
    options.hz = 40.0;
    Runner runner([&log] { return std::make_unique<test::RecordingSimulation>(log); }, options);
    sf::RenderWindow window(sf::VideoMode(320, 240), "physim test");
    runner.restart();
    log.clear();
    EXPECT_EQ(runner.frame(0.025, &window), 1);
    const CallLog expected{"onUpdate",          "update 1",          "update 2",
                           "beforeFixedUpdate 1", "beforeFixedUpdate 2", "checkCollisions 1",
                           "checkCollisions 2", "fixedUpdate 1",     "fixedUpdate 2",
                           "onDrawGraphs",      "render 1",          "render 2",
                           "onRender"};
    EXPECT_EQ(log, expected);
}

using test::keyPress;

TEST(WindowLifecycle, KeysReachOnEventThenPauseRestartQuit) {
    CallLog log;
    Runner runner([&log] { return std::make_unique<test::RecordingSimulation>(log); }, RunOptions{});
    runner.restart();
    runner.frame(0.1, nullptr);
    log.clear();

    runner.handleEvent(keyPress(sf::Keyboard::P), nullptr);
    EXPECT_TRUE(runner.simulation().paused);
    runner.handleEvent(keyPress(sf::Keyboard::Space), nullptr);  // restart: a fresh, running simulation
    EXPECT_FALSE(runner.simulation().paused);
    EXPECT_EQ(runner.simulation().time, 0.0);
    EXPECT_FALSE(runner.quitRequested());
    runner.handleEvent(keyPress(sf::Keyboard::Escape), nullptr);
    EXPECT_TRUE(runner.quitRequested());
    EXPECT_EQ(log, (CallLog{"onEvent", "onEvent", "onCreate", "onEvent"}));
}

// A box drawn at the origin lands in the window's centre; y up in the world is up on screen.
TEST(WindowLifecycle, ViewMapsMetresToPixelsWithYUp) {
    View view;
    const sf::Transform t = view.worldToPixels({800, 600});
    const sf::Vector2f centre = t.transformPoint(0.f, 0.f);
    const sf::Vector2f up = t.transformPoint(0.f, 1.f);
    EXPECT_FLOAT_EQ(centre.x, 400.f);
    EXPECT_FLOAT_EQ(centre.y, 300.f);
    EXPECT_FLOAT_EQ(up.y, 200.f) << "1 m up is 100 px higher on screen";
    const Vec2 back = view.toWorld({500, 200}, {800, 600});
    EXPECT_NEAR(back.x(), 1.0, 1e-12);
    EXPECT_NEAR(back.y(), 1.0, 1e-12);

    sf::RenderTexture target;
    ASSERT_TRUE(target.create(800, 600));
    target.clear(sf::Color::White);
    Object box(Vec2(1.0, 1.0));
    box.mesh.draw(target, t, Vec2(1.0, 1.0), 0.0);  // a 1 m box centred 1 m right and 1 m up
    target.display();
    const sf::Image img = target.getTexture().copyToImage();
    EXPECT_NE(img.getPixel(500, 200), sf::Color::White) << "box centre at (500, 200) px";
    EXPECT_EQ(img.getPixel(400, 300), sf::Color::White) << "nothing at the origin";
    EXPECT_EQ(img.getPixel(500, 400), sf::Color::White) << "nothing mirrored below the axis";
}

}  // namespace
}  // namespace physim
