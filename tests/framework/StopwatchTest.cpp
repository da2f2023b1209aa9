// The window's stopwatch (W): simulated seconds between its start and stop, whatever the time scale and pauses.
// Checked against the number of fixed steps the runner reports it ran, times the step.

#include "RunnerAccess.hpp"
#include "Stopwatch.hpp"
#include "support/SfmlEvents.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace physim {
namespace {

TEST(Stopwatch, StartsStopsAndStartsAnew) {
    Stopwatch watch;
    EXPECT_EQ(watch.state(), Stopwatch::State::Idle);
    EXPECT_EQ(watch.reading(5.0), 0.0);
    watch.press(1.25);
    EXPECT_EQ(watch.state(), Stopwatch::State::Running);
    EXPECT_EQ(watch.reading(3.75), 2.5);  // exact in binary: a tolerance of 0
    watch.press(4.0);
    EXPECT_EQ(watch.state(), Stopwatch::State::Stopped);
    EXPECT_EQ(watch.reading(10.0), 2.75) << "held after the stop";
    watch.press(10.0);
    EXPECT_EQ(watch.state(), Stopwatch::State::Running);
    EXPECT_EQ(watch.reading(10.5), 0.5) << "a new reading from the new start";
    EXPECT_EQ(watch.reading(9.0), 0.0) << "scrubbed back before the start";
}

TEST(Stopwatch, RejectsANonFiniteTime) {
    Stopwatch watch;
    EXPECT_THROW(watch.press(std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
    EXPECT_THROW(watch.press(INFINITY), std::invalid_argument);
    EXPECT_EQ(watch.state(), Stopwatch::State::Idle);
}

// A box falling in a window-less runner.
class Falling : public Simulation {
public:
    void onCreate() override { spawn<Object>(Vec2(1.0, 1.0)); }
};

// W through the runner: the reading is the simulated time of the steps run between the presses, at 4x, with a
// pause in between (no steps, no time), and a restart sets it back to idle. Tolerance: sim.time is a sum of steps,
// a few ulps of 10 s.
TEST(Stopwatch, TimesSimulatedSecondsInTheRunner) {
    RunOptions options;
    options.headless = true;
    options.hz = 40.0;
    Runner runner([] { return std::make_unique<Falling>(); }, options);
    runner.restart();
    Simulation& sim = runner.simulation();
    for (int i = 0; i < 10; ++i) runner.frame(1.0 / 60.0, nullptr);
    runner.setTimeScale(4.0);
    runner.handleEvent(test::keyPress(sf::Keyboard::W), nullptr);
    const Stopwatch& watch = RunnerAccess::controls(runner).stopwatch();
    ASSERT_EQ(watch.state(), Stopwatch::State::Running);
    int steps = 0;
    for (int i = 0; i < 60; ++i) steps += runner.frame(1.0 / 60.0, nullptr);
    runner.handleEvent(test::keyPress(sf::Keyboard::P), nullptr);
    for (int i = 0; i < 60; ++i) steps += runner.frame(1.0 / 60.0, nullptr);
    runner.handleEvent(test::keyPress(sf::Keyboard::P), nullptr);
    for (int i = 0; i < 30; ++i) steps += runner.frame(1.0 / 60.0, nullptr);
    EXPECT_EQ(steps, 240) << "4x for 1.5 real seconds of running at 40 Hz";
    EXPECT_NEAR(watch.reading(sim.time), steps * sim.fixedTimeStep(), 1e-12);
    runner.handleEvent(test::keyPress(sf::Keyboard::W), nullptr);
    ASSERT_EQ(watch.state(), Stopwatch::State::Stopped);
    const double held = watch.reading(sim.time);
    for (int i = 0; i < 30; ++i) runner.frame(1.0 / 60.0, nullptr);
    EXPECT_EQ(watch.reading(sim.time), held) << "stopped: the reading holds while time runs on";
    runner.handleEvent(test::keyPress(sf::Keyboard::Space), nullptr);
    EXPECT_EQ(RunnerAccess::controls(runner).stopwatch().state(), Stopwatch::State::Idle) << "a restart clears it";
}

// Armed (Shift+W), sensors press it: the first entry starts it, the next stops it and disarms it.
TEST(Stopwatch, SensorEntriesStartAndStopItWhenArmed) {
    Stopwatch watch;
    watch.sensorEntered(1.0);
    EXPECT_EQ(watch.state(), Stopwatch::State::Idle) << "not armed: sensors do nothing";
    watch.arm();
    watch.sensorEntered(1.25);
    EXPECT_EQ(watch.state(), Stopwatch::State::Running);
    watch.sensorEntered(2.0);
    EXPECT_EQ(watch.state(), Stopwatch::State::Stopped);
    EXPECT_EQ(watch.reading(5.0), 0.75);
    EXPECT_FALSE(watch.armed());
    watch.sensorEntered(3.0);
    EXPECT_EQ(watch.state(), Stopwatch::State::Stopped) << "disarmed after its stop";
}

// A ball dropped through two thin sensor gates, the stopwatch armed: it reads the time between the ball's entries
// into the gates, sqrt(2 d2 / g) - sqrt(2 d1 / g), d the fall before the ball's lowest point reaches each gate.
// Tolerance 1e-5 s (found 1.9e-6): the gates time each entry within its step, on the path the substeps take, and
// semi-implicit Euler's lead over the exact fall (g h t / 2) moves both entries by nearly the same time.
class Gates : public Simulation {
public:
    void onCreate() override {
        for (const double y : {-0.5, -1.5}) {
            auto& gate = spawn<Object>(RectangleShape({1.0, 0.001}), sf::Color::Yellow);
            gate.setPosition({0.0, y});
            gate.rb.setMass(0.0);
            gate.rb.setSensor(true);
        }
        spawn<Object>(CircleShape(0.05), sf::Color::Blue);
    }
};

TEST(Stopwatch, SensorsTimeABallBetweenTwoGates) {
    RunOptions options;
    options.headless = true;
    options.hz = 40.0;
    Runner runner([] { return std::make_unique<Gates>(); }, options);
    runner.restart();
    runner.handleEvent(test::keyPress(sf::Keyboard::W, /*shift=*/true), nullptr);
    const Stopwatch& watch = RunnerAccess::controls(runner).stopwatch();
    ASSERT_TRUE(watch.armed());
    for (int i = 0; i < 80; ++i) runner.frame(1.0 / 40.0, nullptr);
    ASSERT_EQ(watch.state(), Stopwatch::State::Stopped);
    const double g = 9.81, d1 = 0.5 - 0.0005 - 0.05, d2 = 1.5 - 0.0005 - 0.05;
    EXPECT_NEAR(watch.reading(0.0), std::sqrt(2.0 * d2 / g) - std::sqrt(2.0 * d1 / g), 1e-5);
}

}  // namespace
}  // namespace physim
