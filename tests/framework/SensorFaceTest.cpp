// The paper's face of sensors: RigidBody::setSensor and CollisionShape::setSensor, Simulation::onSensor with each
// event's simulated time, and debug drawing's resting contacts, which a sensor has none of.

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/DebugDraw.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace physim {
namespace {

struct Heard {
    BodyId sensor, visitor;
    bool began = false;
    double at = 0.0;
};

class Gate : public Simulation {
public:
    std::vector<Heard> heard;
    void onSensor(const SensorEvent& e, bool began, double at) override {
        heard.push_back({e.sensorBody, e.visitorBody, began, at});
    }
};

TEST(SensorFace, ABallFallingThroughAGateIsHeardWithTheTimesOfItsPath) {
    Gate sim;  // 40 Hz, 8 substeps, g = 9.81
    RectangleShape beam({1.0, 0.01});
    beam.setSensor(true);
    Object& gate = sim.spawn<Object>(beam, sf::Color::Black);
    gate.setPosition({0.0, -0.5});
    gate.rb.setMass(0.0);
    Object& ball = sim.spawn<Object>(CircleShape(0.05), sf::Color::Black);
    EXPECT_TRUE(gate.rb.isSensor());
    EXPECT_FALSE(ball.rb.isSensor());
    EXPECT_EQ(sim.world().sensorCount(), 1u);
    for (int i = 0; i < 20; ++i) sim.fixedStep();
    ASSERT_EQ(sim.heard.size(), 2u);
    EXPECT_TRUE(sim.heard[0].began);
    EXPECT_FALSE(sim.heard[1].began);
    EXPECT_EQ(sim.heard[0].sensor, gate.rb.bodyId());
    EXPECT_EQ(sim.heard[0].visitor, ball.rb.bodyId());
    // Free fall from rest by d = 0.5 -+ (0.005 + 0.05): the solver's substeps run ahead of the exact fall by half a
    // substep (1.6 ms at 40 Hz), so the exact times hold to within one substep (3.1 ms); a gate read at the steps'
    // ends would be off by up to a whole step (25 ms).
    const double g = 9.81, h = sim.fixedTimeStep() / 8.0;
    EXPECT_NEAR(sim.heard[0].at, std::sqrt(2.0 * (0.5 - 0.055) / g), h);
    EXPECT_NEAR(sim.heard[1].at, std::sqrt(2.0 * (0.5 + 0.055) / g), h);
    // Nothing pushed: the ball fell freely through.
    EXPECT_LT(ball.getPosition().y(), -0.6);
}

TEST(SensorFace, RigidBodySetSensorBeforeAndAfterTheBodyJoinsAWorld) {
    Gate sim;
    Object& a = sim.spawn<Object>(RectangleShape({1.0, 1.0}), sf::Color::Black);  // dynamic, made a sensor after
    Object b(CircleShape(0.1), sf::Color::Black);
    b.rb.setSensor(true);
    EXPECT_TRUE(b.rb.isSensor());
    Object& c = sim.spawn<Object>(CircleShape(0.1), sf::Color::Black);
    c.rb.setSensor(true);  // after: every shape of the body
    EXPECT_TRUE(c.rb.isSensor());
    EXPECT_EQ(sim.world().sensorCount(), 1u);
    a.rb.setSensor(true);
    EXPECT_EQ(sim.world().sensorCount(), 2u);
    a.rb.setSensor(false);
    EXPECT_FALSE(a.rb.isSensor());
    EXPECT_EQ(sim.world().sensorCount(), 1u);
}

TEST(SensorFace, RestingContactsLeaveSensorsOut) {
    Gate sim;
    WorldSettings s = sim.world().settings();
    s.gravity = Vec2::Zero();
    sim.world().setSettings(s);
    RectangleShape zone({2.0, 2.0});
    zone.setSensor(true);
    Object& sensor = sim.spawn<Object>(zone, sf::Color::Black);
    sensor.rb.setMass(0.0);
    Object& ball = sim.spawn<Object>(CircleShape(0.1), sf::Color::Black);
    for (int i = 0; i < 60; ++i) sim.fixedStep();  // at rest inside the sensor: asleep after half a second
    ASSERT_FALSE(ball.rb.isAwake());
    EXPECT_TRUE(restingContacts(sim.world()).empty());
    EXPECT_EQ(sim.world().sensorOverlaps(sensor.rb.shapeIds().front()).size(), 1u);
}

}  // namespace
}  // namespace physim
