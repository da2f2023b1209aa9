// conveyor: surface materials. Above, a box put down at rest on a conveyor belt (a static box whose surface runs at
// u = 2 m/s, RigidBody::setTangentSpeed) slides under kinetic friction, a = mu_d g, until it moves with the belt at
// t* = u / (mu_d g), and then rides along at u. Below, a ball (a disc, I = m r^2 / 2) rolling without slip at v0 on
// flat ground with rolling resistance C_rr (RigidBody::setRollingResistance: a torque of at most C_rr N r) slows at
// (2/3) C_rr g and stops after d = 3 v0^2 / (4 C_rr g). Graph: both bodies' speeds against time, beside the
// predicted lines. Results (summary.json): the box's final speed against u, its time to reach the belt's speed
// against u / (mu_d g), and the ball's stopping distance against d. Keys: N starts both again.

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <SFML/Window/Event.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace physim::examples {
namespace {

constexpr double kBeltHalfLength = 6.0;  // m
constexpr double kBeltHalfHeight = 0.2;  // m, the belt's top face at y = 0
constexpr double kBoxSize = 0.5;         // m
constexpr double kBoxStart = -5.5;       // m, the box's centre at release
constexpr double kFloorY = -3.0;         // m, the ball's floor's top face
constexpr double kBallRadius = 0.3;      // m
constexpr double kBallStart = -5.5;      // m

class Conveyor : public physim::Simulation {
public:
    Conveyor() {
        parameters.add("u", "belt speed (m/s)", 2.0, 0.1, 5.0);
        parameters.add("mu", "friction coefficient of both surfaces", 0.4, 0.05, 1.0);
        parameters.add("v0", "ball's launch speed (m/s)", 2.0, 0.1, 4.0);
        parameters.add("crr", "rolling resistance coefficient", 0.1, 0.01, 0.5);
    }

    std::string title() const override {
        return "conveyor: a belt carries a box to u after u / (mu g); rolling resistance stops a ball at 3 v0^2 / "
               "(4 C_rr g)";
    }
    std::string keysHelp() const override { return "N: start again"; }

    std::optional<Aabb> viewBounds() const override {
        return Aabb{{-kBeltHalfLength - 0.5, kFloorY - 1.0}, {kBeltHalfLength + 0.5, 1.5}};
    }

    void onCreate() override {
        physim::WorldSettings settings = world().settings();
        settings.enableSleep = false;  // the ball comes to rest and is watched there
        world().setSettings(settings);
        u_ = parameters.get("u");
        mu_ = parameters.get("mu");
        v0_ = parameters.get("v0");
        crr_ = parameters.get("crr");
        // The belt: a static box whose top face runs towards +x at u; both surfaces' friction mu (mixed: mu).
        auto& belt = spawn<physim::Object>(physim::RectangleShape({2.0 * kBeltHalfLength, 2.0 * kBeltHalfHeight}),
                                           sf::Color(90, 90, 100));
        belt.setPosition({0.0, -kBeltHalfHeight});
        belt.rb.setMass(0.0);
        belt.rb.setStaticFriction(mu_);
        belt.rb.setDynamicFriction(mu_);
        belt.rb.setTangentSpeed(u_);
        box_ = &spawn<physim::Object>(physim::RectangleShape({kBoxSize, kBoxSize}), sf::Color(200, 120, 40));
        box_->rb.setStaticFriction(mu_);
        box_->rb.setDynamicFriction(mu_);
        // The floor and the ball; only the ball resists rolling (the pair takes the larger coefficient).
        auto& floor = spawn<physim::Object>(physim::RectangleShape({2.0 * kBeltHalfLength, 0.4}),
                                            sf::Color(120, 120, 120));
        floor.setPosition({0.0, kFloorY - 0.2});
        floor.rb.setMass(0.0);
        ball_ = &spawn<physim::Object>(physim::CircleShape(kBallRadius), sf::Color(40, 110, 200));
        ball_->rb.setRollingResistance(crr_);
        place();

        speeds_ = graphsManager.addGraph("Speeds;t (s);v (m/s)", "box", {}, physim::GraphMode::WITH_LINES);
        boxPredicted_ = graphsManager.addSeries(speeds_, "box: min(#mu g t, u)");
        ballSpeed_ = graphsManager.addSeries(speeds_, "ball", {}, physim::GraphMode::WITH_LINES);  // markers: measured
        ballPredicted_ = graphsManager.addSeries(speeds_, "ball: v_{0} - (2/3) C_{rr} g t");
        graphsManager.build();
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) restart();
    }

    void onDrawGraphs() override {
        const double t = time - startTime_;
        if (!(t > lastT_)) return;
        const double v = box_->rb.velocity().x();
        const double w = ball_->rb.velocity().x();
        graphsManager.addPoint(speeds_, t, v);
        graphsManager.addPoint(boxPredicted_, t, std::min(mu_ * gravity() * t, u_));
        graphsManager.addPoint(ballSpeed_, t, w);
        graphsManager.addPoint(ballPredicted_, t, std::max(v0_ - 2.0 / 3.0 * crr_ * gravity() * t, 0.0));
        if (!measured_) {
            // The time the box reaches the belt: from the last frame it still slid, on at that frame's
            // acceleration (the speed grows linearly while it slides), so the frame rate does not round it.
            if (reachedAt_ < 0.0 && v >= u_ - 1e-3 && lastV_ < u_ - 1e-3 && slideAcceleration_ > 0.0)
                reachedAt_ = lastT_ + (u_ - lastV_) / slideAcceleration_;
            if (v < u_ - 1e-3 && t > lastT_) slideAcceleration_ = (v - lastV_) / (t - lastT_);
            if (reachedAt_ >= 0.0) setResult("box_time_to_belt_speed", reachedAt_, timeToBelt(), "s");
            if (t > 2.0 * timeToBelt()) setResult("box_final_speed", v, u_, "m/s");
            // The ball's distance once it has stopped (and stays so: resistance never reverses it).
            if (std::abs(w) < 1e-6 && t > 0.5)
                setResult("ball_stopping_distance", ball_->getPosition().x() - kBallStart, stoppingDistance(), "m");
        }
        lastT_ = t;
        lastV_ = v;
        // The box off the belt's end: both start again (the figures are the first run's).
        if (box_->getPosition().x() > kBeltHalfLength - kBoxSize) {
            measured_ = true;
            restart();
        }
    }

    // The belt's surface: marks on its face moving at u (the body itself stays put).
    void onRender(sf::RenderWindow* window) override {
        const sf::Transform toPixels = view.worldToPixels(window->getSize());
        constexpr double kSpacing = 0.5;  // m between marks
        const double shift = std::fmod(u_ * time, kSpacing);
        sf::VertexArray marks(sf::Lines);
        const sf::Color color(200, 200, 210);
        for (double x = -kBeltHalfLength + 0.1 + shift; x < kBeltHalfLength; x += kSpacing) {
            marks.append(sf::Vertex({float(x), -0.05f}, color));
            marks.append(sf::Vertex({float(x - 0.1), float(-2.0 * kBeltHalfHeight + 0.05)}, color));
        }
        window->draw(marks, toPixels);
    }

private:
    double gravity() const { return -world().settings().gravity.y(); }  // m/s^2
    double timeToBelt() const { return u_ / (mu_ * gravity()); }       // s
    double stoppingDistance() const { return 3.0 * v0_ * v0_ / (4.0 * crr_ * gravity()); }  // m

    void place() {
        box_->setPosition({kBoxStart, 0.5 * kBoxSize});
        box_->setRotation(0.0);
        box_->rb.setVelocity({0.0, 0.0});
        box_->rb.setAngularVelocity(0.0);
        ball_->setPosition({kBallStart, kFloorY + kBallRadius});
        ball_->setRotation(0.0);
        ball_->rb.setVelocity({v0_, 0.0});
        ball_->rb.setAngularVelocity(-v0_ / kBallRadius);  // rolling without slip
        startTime_ = time;
        lastT_ = 0.0;
        lastV_ = 0.0;
    }

    void restart() {
        graphsManager.reset();
        place();
    }

    physim::Object* box_ = nullptr;  // owned by the simulation
    physim::Object* ball_ = nullptr;
    double u_ = 0.0, mu_ = 0.0, v0_ = 0.0, crr_ = 0.0;
    int speeds_ = -1, boxPredicted_ = -1, ballSpeed_ = -1, ballPredicted_ = -1;
    double startTime_ = 0.0, lastT_ = 0.0, lastV_ = 0.0, slideAcceleration_ = 0.0, reachedAt_ = -1.0;
    bool measured_ = false;
};

}  // namespace

std::unique_ptr<Simulation> makeConveyor() { return std::make_unique<Conveyor>(); }

}  // namespace physim::examples
