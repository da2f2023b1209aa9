// The window's tape measure (M + drag) and protractor (A + drag, then a click): readings in metres and degrees of
// the world, checked against distances and angles laid out by hand, through the view's pixels at two zooms.

#include "Measure.hpp"
#include "RunnerAccess.hpp"
#include "support/SfmlEvents.hpp"

#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace physim {
namespace {

TEST(Protractor, AngleBetweenTwoRays) {
    const Vec2 v(1.0, -2.0);
    // Exact or within a few ulps of the angle (atan2 of exact cross and dot products): 1e-12 degrees.
    EXPECT_NEAR(protractorAngle(v, v + Vec2(3.0, 0.0), v + Vec2(0.0, 0.5)), 90.0, 1e-12);
    EXPECT_NEAR(protractorAngle(v, v + Vec2(0.0, 0.5), v + Vec2(3.0, 0.0)), 90.0, 1e-12) << "either order";
    EXPECT_NEAR(protractorAngle(v, v + Vec2(2.0, 2.0), v + Vec2(1.0, 0.0)), 45.0, 1e-12);
    EXPECT_NEAR(protractorAngle(v, v + Vec2(1.0, 0.0), v + Vec2(-1.0, std::sqrt(3.0))), 120.0, 1e-12);
    EXPECT_NEAR(protractorAngle(v, v + Vec2(1.0, 0.0), v + Vec2(-4.0, 0.0)), 180.0, 1e-12);
    EXPECT_EQ(protractorAngle(v, v + Vec2(1.0, 1.0), v + Vec2(3.0, 3.0)), 0.0) << "one ray";
    // Near 0: 1e-9 rad is 5.7e-8 degrees, which acos of the normalised dot product would lose entirely.
    // (At the origin: v + 1e-9 would round the ray.) 1e-20 degrees is some 1500 ulps of the answer.
    EXPECT_NEAR(protractorAngle(Vec2::Zero(), {1.0, 0.0}, {1.0, 1e-9}), 1e-9 * 180.0 / M_PI, 1e-20);
}

TEST(Protractor, RejectsAnArmWithNoDirection) {
    EXPECT_THROW(protractorAngle({0.0, 0.0}, {0.0, 0.0}, {1.0, 0.0}), std::invalid_argument);
    EXPECT_THROW(protractorAngle({0.0, 0.0}, {1.0, 0.0}, {NAN, 0.0}), std::invalid_argument);
}

TEST(TapeMeasure, FollowsTheDragAndClears) {
    Measurement m;
    EXPECT_TRUE(m.press(Measurement::Kind::Tape, {1.0, 2.0}));
    m.move({4.0, 2.0});
    EXPECT_EQ(*m.length(), 3.0);
    m.release({4.0, 6.0});
    EXPECT_EQ(*m.length(), 5.0);  // a 3-4-5 triangle: exact
    m.move({100.0, 100.0});
    EXPECT_EQ(*m.length(), 5.0) << "laid: the cursor no longer moves it";
    EXPECT_FALSE(m.angle().has_value());
    EXPECT_FALSE(m.press(Measurement::Kind::None, {0.0, 0.0})) << "a plain click is not the tape's";
    EXPECT_EQ(m.kind(), Measurement::Kind::None);
    EXPECT_FALSE(m.length().has_value());
}

TEST(Protractor, DragOneArmThenClickTheOther) {
    Measurement m;
    m.press(Measurement::Kind::Protractor, {0.0, 0.0});
    m.move({2.0, 0.0});
    EXPECT_FALSE(m.angle().has_value()) << "one arm so far";
    m.release({2.0, 0.0});
    EXPECT_TRUE(m.awaitingClick());
    EXPECT_EQ(*m.angle(), 0.0) << "the second arm starts at the cursor, on the first";
    m.move({0.0, 3.0});
    EXPECT_NEAR(*m.angle(), 90.0, 1e-12) << "the second arm follows the cursor";
    EXPECT_TRUE(m.press(Measurement::Kind::None, {-1.0, 1.0})) << "any click ends the second arm";
    EXPECT_FALSE(m.awaitingClick());
    m.move({5.0, 5.0});
    EXPECT_NEAR(*m.angle(), 135.0, 1e-12);
}

class Empty : public Simulation {
public:
    void onCreate() override { spawn<Object>(Vec2(1.0, 1.0)).setPosition({-20.0, -20.0}); }  // out of the way
};

sf::Vector2i pixelOf(const Simulation& sim, const Vec2& p, sf::Vector2u window) {
    return test::pixelOf(sim.view, p, window);
}

sf::Event keyRelease(sf::Keyboard::Key code) {
    sf::Event e = test::keyPress(code);
    e.type = sf::Event::KeyReleased;
    return e;
}

// Through the runner's events: M held, a drag from (1, 2) m to (4, 6) m reads 5 m at two zooms; the cursor lands
// on whole pixels, so each end may be off by half a pixel in x and y: a tolerance of sqrt(2) pixels in metres.
TEST(TapeMeasure, ReadsMetresThroughTheViewAtAnyZoom) {
    RunOptions options;
    options.headless = true;
    options.width = 800;
    options.height = 600;
    Runner runner([] { return std::make_unique<Empty>(); }, options);
    runner.restart();
    Simulation& sim = runner.simulation();
    const sf::Vector2u window(800, 600);
    const Measurement& m = RunnerAccess::controls(runner).measurement();
    for (double ppm : {37.0, 90.0}) {
        sim.view.pixelsPerMetre = ppm;
        runner.handleEvent(test::keyPress(sf::Keyboard::M), nullptr);
        runner.handleEvent(test::mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left,
                                             pixelOf(sim, {1.0, 2.0}, window)), nullptr);
        runner.handleEvent(test::mouseMove(pixelOf(sim, {4.0, 6.0}, window)), nullptr);
        runner.handleEvent(test::mouseButton(sf::Event::MouseButtonReleased, sf::Mouse::Left,
                                             pixelOf(sim, {4.0, 6.0}, window)), nullptr);
        runner.handleEvent(keyRelease(sf::Keyboard::M), nullptr);
        ASSERT_TRUE(m.length().has_value());
        EXPECT_NEAR(*m.length(), 5.0, std::sqrt(2.0) / ppm) << ppm << " px/m";
        EXPECT_FALSE(RunnerAccess::controls(runner).dragJoint().has_value());
    }
    // M released: a plain click clears the tape (and would grab a body there).
    runner.handleEvent(test::mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left, {10, 10}), nullptr);
    EXPECT_EQ(m.kind(), Measurement::Kind::None);
}

// A held: a drag along the +x axis from (0, 0), then a click at (-2, 2): 135 degrees, within the half-pixel
// rounding of each end (at 50 px/m and arms of 2 m or more: atan(0.5 * sqrt(2) / 100) per arm, 0.81 degrees in
// all is generous).
TEST(Protractor, ReadsDegreesThroughTheRunner) {
    RunOptions options;
    options.headless = true;
    options.width = 800;
    options.height = 600;
    Runner runner([] { return std::make_unique<Empty>(); }, options);
    runner.restart();
    Simulation& sim = runner.simulation();
    sim.view.pixelsPerMetre = 50.0;
    const sf::Vector2u window(800, 600);
    runner.handleEvent(test::keyPress(sf::Keyboard::A), nullptr);
    runner.handleEvent(test::mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left, pixelOf(sim, {0, 0}, window)),
                       nullptr);
    runner.handleEvent(test::mouseMove(pixelOf(sim, {3.0, 0.0}, window)), nullptr);
    runner.handleEvent(test::mouseButton(sf::Event::MouseButtonReleased, sf::Mouse::Left, pixelOf(sim, {3, 0}, window)),
                       nullptr);
    runner.handleEvent(keyRelease(sf::Keyboard::A), nullptr);
    runner.handleEvent(test::mouseMove(pixelOf(sim, {-2.0, 2.0}, window)), nullptr);
    runner.handleEvent(test::mouseButton(sf::Event::MouseButtonPressed, sf::Mouse::Left, pixelOf(sim, {-2, 2}, window)),
                       nullptr);
    const Measurement& m = RunnerAccess::controls(runner).measurement();
    ASSERT_TRUE(m.angle().has_value());
    EXPECT_NEAR(*m.angle(), 135.0, 0.81);
}

}  // namespace
}  // namespace physim
