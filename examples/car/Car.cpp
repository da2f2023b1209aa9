// car: a chassis (120 kg by default) on two wheels (10 kg discs of radius 0.3 m), each on a wheel joint (WheelJointDef:
// a suspension spring along the chassis' vertical, the wheel turning freely), the rear one driven by a motor of at most
// `torque` N m, up to 5 rad/s (1.5 m/s rolling). The terrain is one chain (ChainShape): a flat run-in, an incline of
// `slope` degrees 8 m long, a flat top, a way down and a wall. The car starts at rest at the foot of the incline, held
// by the motor as a brake for half a second while its springs settle, then climbs it torque-limited. Rolling without
// slipping, the motor's work T omega feeds the motion, the wheels' turning and the climb: T v / r = M_eff v a + M g v
// sin(theta), so
//     a = (T / r - M g sin(theta)) / M_eff,   M = chassis + wheels,  M_eff = M + 2 I_wheel / r^2
// (0.41 m/s^2 at the defaults). Results (summary.json): the mean acceleration along the incline from 1 s (the
// suspension settled) until 3 s, the car's leaving the incline or 1.4 m/s (below the motor's speed), beside that
// formula (none when that window is under 0.5 s: a strong motor at its top speed); and the driven wheel's worst slip
// |omega r / v - 1| on the incline once it moves at 0.3 m/s or more, predicted 0. Graphs: the travel speed along the
// chassis beside the driven wheel's omega r, the chassis' height. Parameters: the motor torque, the springs' frequency,
// the slope, the chassis' mass.

#include "Scenes.hpp"

#include <physim/core/ChainShape.hpp>
#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace physim::examples {
namespace {

constexpr double kWheelRadius = 0.3;   // m
constexpr double kWheelMass = 10.0;    // kg
constexpr double kWheelBase = 1.6;     // m, rear axle to front axle
constexpr double kAxleDrop = 0.35;     // m, the axles below the chassis' centre line
constexpr double kInclineLength = 8.0; // m, along the slope
constexpr double kStartOnSlope = 0.5;  // m, the rear wheel's contact from the incline's foot at the start
constexpr double kMotorSpeed = 5.0;    // rad/s, the motor's top speed (1.5 m/s rolling)
constexpr double kRelease = 0.5;       // s: the motor holds the rear wheel still (a brake) while the springs settle
constexpr double kMeasureFrom = 1.0, kMeasureTo = 3.0;  // s, the acceleration's window
constexpr double kMeasureTopSpeed = 1.4;                // m/s, the window ends there too (below the motor's speed)
constexpr double kSlipFromSpeed = 0.3;                  // m/s, the slip counts from there (a ratio of small speeds)

double radians(double degrees) { return degrees * M_PI / 180.0; }

class Car : public physim::Simulation {
public:
    Car() {
        parameters.add("torque", "rear motor's maximum torque (N m)", 90.0, 0.0, 400.0);
        parameters.add("hertz", "suspension springs' frequency (Hz)", 4.0, 0.5, 10.0);
        parameters.add("slope", "incline (degrees)", 10.0, 0.0, 20.0);
        parameters.add("mass", "chassis mass (kg)", 120.0, 20.0, 500.0);
    }

    std::string title() const override {
        return "car: wheel joints climbing a chain terrain, a = (T / r - M g sin(theta)) / M_eff";
    }

    std::optional<Aabb> viewBounds() const override {
        return Aabb{{-3.0, -0.5}, {terrain_.back().x() + 0.5, top_ + 2.0}};
    }

    void onCreate() override {
        physim::WorldSettings settings = world().settings();
        settings.enableSleep = false;
        world().setSettings(settings);
        const double theta = radians(parameters.get("slope"));
        const physim::Vec2 u(std::cos(theta), std::sin(theta)), n(-std::sin(theta), std::cos(theta));
        // The terrain left to right (a chain is solid on its right: ground below).
        const physim::Vec2 foot(0.0, 0.0), crest = foot + kInclineLength * u;
        top_ = crest.y();
        terrain_ = {{-4.0, 0.0}, foot, crest, crest + physim::Vec2(4.0, 0.0),
                    crest + physim::Vec2(4.0 + 4.0 * std::cos(theta), -4.0 * std::sin(theta)),
                    crest + physim::Vec2(12.0 + 4.0 * std::cos(theta), -4.0 * std::sin(theta)),
                    crest + physim::Vec2(12.0 + 4.0 * std::cos(theta), 1.0 - 4.0 * std::sin(theta))};  // a wall
        crestX_ = crest.x();
        auto& ground = spawn<physim::Object>(physim::ChainShape(terrain_), sf::Color(90, 90, 90));
        ground.rb.setStaticFriction(0.9);
        ground.rb.setDynamicFriction(0.8);

        // On the slope: wheels touching it, the chassis parallel to it.
        const physim::Vec2 rearCentre = foot + kStartOnSlope * u + kWheelRadius * n;
        const physim::Vec2 frontCentre = rearCentre + kWheelBase * u;
        chassis_ = &spawn<physim::Object>(physim::RectangleShape({2.2, 0.3}), sf::Color(200, 80, 40));
        chassis_->setPosition(rearCentre + 0.5 * kWheelBase * u + kAxleDrop * n);
        chassis_->setRotation(theta);
        chassis_->rb.setMass(parameters.get("mass"));
        rear_ = &spawn<physim::Object>(physim::CircleShape(kWheelRadius), sf::Color(40, 40, 40));
        front_ = &spawn<physim::Object>(physim::CircleShape(kWheelRadius), sf::Color(40, 40, 40));
        rear_->setPosition(rearCentre);
        front_->setPosition(frontCentre);
        for (physim::Object* wheel : {rear_, front_}) {
            wheel->rb.setMass(kWheelMass);
            wheel->rb.setStaticFriction(0.9);
            wheel->rb.setDynamicFriction(0.8);
            physim::WheelJointDef axle;
            axle.anchor = wheel->getPosition();
            axle.axis = n;
            axle.hertz = parameters.get("hertz");
            axle.dampingRatio = 0.7;
            if (wheel == rear_) {
                axle.enableMotor = true;
                axle.motorSpeed = 0.0;  // the brake until kRelease
                axle.maxMotorTorque = parameters.get("torque");
            }
            const physim::JointId joint = chassis_->join(*wheel, axle);
            if (wheel == rear_) motor_ = joint;
        }
        // a = (T / r - M g sin(theta)) / M_eff: the energy balance of a car rolling without slipping.
        const double mass = chassis_->rb.mass() + rear_->rb.mass() + front_->rb.mass();
        const double massEff = mass + (rear_->rb.inertia() + front_->rb.inertia()) / (kWheelRadius * kWheelRadius);
        const double g = -world().settings().gravity.y();
        predicted_ = (parameters.get("torque") / kWheelRadius - mass * g * std::sin(theta)) / massEff;
        slope_ = u;

        speed_ = graphsManager.addGraph("Speed;t (s);v (m/s)", "travel speed (along the chassis)", {},
                                        physim::GraphMode::WITH_LINES);
        rolling_ = graphsManager.addSeries(speed_, "driven wheel's #omega r");
        height_ = graphsManager.addGraph("Height of the chassis;t (s);y (m)", "chassis", {},
                                         physim::GraphMode::WITH_LINES);
        graphsManager.build();
    }

    void onUpdate() override {
        if (!released_ && time >= kRelease) {
            released_ = true;
            // Clockwise: forward, up the slope.
            world().setWheelMotor(motor_, true, -kMotorSpeed, parameters.get("torque"));
        }
    }

    void onDrawGraphs() override {
        // The travel speed along the chassis (its bounce on the springs across it left out).
        const double phi = chassis_->getRotation();
        const double v = chassis_->rb.velocity().dot(physim::Vec2(std::cos(phi), std::sin(phi)));
        const double omegaR = -rear_->rb.angularVelocity() * kWheelRadius;
        graphsManager.addPoint(speed_, time, v);
        graphsManager.addPoint(rolling_, time, omegaR);
        graphsManager.addPoint(height_, time, chassis_->getPosition().y());

        const bool onIncline = front_->getPosition().x() < crestX_ - kWheelRadius;
        const double along = chassis_->rb.velocity().dot(slope_);  // m/s, up the slope
        if (!windowOpen_ && !windowDone_ && time >= kMeasureFrom) {
            windowOpen_ = true;
            t0_ = time;
            v0_ = along;
        } else if (windowOpen_ && (time >= kMeasureTo || !onIncline || along >= kMeasureTopSpeed)) {
            windowOpen_ = false;
            windowDone_ = true;
            // A window under half a second (a strong motor at its top speed by then) measures nothing worth saying.
            if (time - t0_ >= 0.5)
                setResult("acceleration on the incline", (along - v0_) / (time - t0_), predicted_, "m/s^2");
        }
        // The driven wheel's slip: its centre's speed against omega r (the rolling speed).
        const double vWheel = rear_->rb.velocity().dot(slope_);
        if (onIncline && vWheel >= kSlipFromSpeed) {
            worstSlip_ = std::max(worstSlip_, std::abs(omegaR / vWheel - 1.0));
            setResult("driven wheel's worst slip |omega r / v - 1| on the incline", worstSlip_, 0.0, "");
        }
    }

private:
    physim::Object* chassis_ = nullptr;  // owned by the simulation
    physim::Object* rear_ = nullptr;
    physim::Object* front_ = nullptr;
    std::vector<physim::Vec2> terrain_;
    physim::Vec2 slope_ = physim::Vec2(1.0, 0.0);
    double top_ = 0.0, crestX_ = 0.0;  // m
    double predicted_ = 0.0;           // m/s^2
    int speed_ = -1, rolling_ = -1, height_ = -1;
    physim::JointId motor_;
    bool released_ = false, windowOpen_ = false, windowDone_ = false;
    double t0_ = 0.0, v0_ = 0.0, worstSlip_ = 0.0;
};

}  // namespace

std::unique_ptr<Simulation> makeCar() { return std::make_unique<Car>(); }

}  // namespace physim::examples
