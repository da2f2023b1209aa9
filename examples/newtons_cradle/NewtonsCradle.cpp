// newtons_cradle: five equal elastic balls in a row, 1 mm apart; the first is sent into the others at 2 m/s.
// One ball in, one ball out: momentum and kinetic energy conservation together leave the last ball leaving
// at 2 m/s and the other four at rest, with the kinetic energy constant throughout. The strings are not
// modelled (nor is gravity): they only matter over the swing, while the shock crosses the row in a few
// milliseconds. The 1 mm gaps let the striker reach each next ball alone, one pair per substep, which is how
// a real cradle's shock travels; touching balls would need the shock's order, which no contact solver has.
// Graphs: each ball's velocity against time, and the total kinetic energy against the constant m v0^2 / 2.
// Once the last ball is 2 m past the row, the striker strikes again, so the balls stay in view. Keys: N
// strikes again. Parameter: the number of balls. Results (summary.json): the kinetic energy, and after the
// shock the last ball's velocity and the others' largest speed, beside conservation's answer.

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Window/Event.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace physim::examples {
namespace {

constexpr double kRadius = 0.5;     // m
constexpr double kGap = 0.001;      // m between neighbours at rest
constexpr double kStrikerX = -2.0;  // m: 1 m short of the first ball at rest
constexpr double kSpeed = 2.0;      // m/s, the striker's
constexpr double kRunOut = 2.0;     // m the last ball travels past the row before the next strike

class NewtonsCradle : public physim::Simulation {
public:
    NewtonsCradle() { parameters.add("balls", "number of balls, the striker included", 5, 2, 10, true); }

    std::string title() const override { return "newtons_cradle: one ball in, one ball out"; }

    void onCreate() override {
        physim::WorldSettings settings = world().settings();
        settings.gravity = {0.0, 0.0};
        world().setSettings(settings);
        balls_.resize(static_cast<std::size_t>(parameters.getInt("balls")));
        for (std::size_t i = 0; i < balls_.size(); ++i) {
            physim::Object*& ball = balls_[i];
            ball = &spawn<physim::Object>(
                physim::Mesh::CircleMesh(kRadius, i == 0 ? sf::Color(200, 60, 60) : sf::Color(170, 170, 190)),
                physim::CircleShape(kRadius));
            ball->rb.setRestitution(1.0);
            ball->rb.setStaticFriction(0.0);  // head-on: friction would do nothing but is left out, as in the
            ball->rb.setDynamicFriction(0.0); // textbook
        }
        strike();
        velocity_.assign(balls_.size(), -1);
        velocity_[0] = graphsManager.addGraph("Ball velocities;time (s);v_x (m/s)", "ball 1");
        for (std::size_t i = 1; i < balls_.size(); ++i)  // simulated too: markers, as ball 1's
            velocity_[i] = graphsManager.addSeries(velocity_[0], "ball " + std::to_string(i + 1), {},
                                                   physim::GraphMode::DEFAULT);
        kinetic_ = graphsManager.addGraph("Kinetic energy;time (s);K (J)");
        kineticTheory_ = graphsManager.addSeries(kinetic_, "m v0^2 / 2");
        graphsManager.build();
    }

    std::string keysHelp() const override { return "N: strike again"; }

    // From the striker's start to the last ball's run-out.
    std::optional<Aabb> viewBounds() const override {
        return Aabb{{kStrikerX - kRadius - 0.3, -1.5}, {rowEnd() + kRunOut + kRadius + 0.3, 1.5}};
    }

    void onUpdate() override {
        if (balls_.back()->getPosition().x() > rowEnd() + kRunOut) {
            graphsManager.reset();
            strike();
        }
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) {
            graphsManager.reset();
            strike();
        }
    }

    void onDrawGraphs() override {
        const double t = time - strikeTime_;
        double k = 0.0;  // J
        for (std::size_t i = 0; i < balls_.size(); ++i) {
            const physim::RigidBody& rb = balls_[i]->rb;
            graphsManager.addPoint(velocity_[i], t, rb.velocity().x());
            k += 0.5 * rb.mass() * rb.velocity().squaredNorm() +
                 0.5 * rb.inertia() * rb.angularVelocity() * rb.angularVelocity();
        }
        graphsManager.addPoint(kinetic_, t, k);
        graphsManager.addPoint(kineticTheory_, t, 0.5 * balls_[0]->rb.mass() * kSpeed * kSpeed);
        setResult("kinetic energy", k, 0.5 * balls_[0]->rb.mass() * kSpeed * kSpeed, "J");
        // Once the striker has crossed its gap and a frame more has passed (the shock crosses the row in a
        // few substeps): the last ball's speed and the fastest of the others.
        const double arrival = (-kStrikerX - 2 * kRadius) / kSpeed;  // s, from the strike to the first contact
        if (t > arrival + fixedTimeStep()) {
            setResult("last ball's velocity", balls_.back()->rb.velocity().x(), kSpeed, "m/s");
            double others = 0.0;
            for (std::size_t i = 0; i + 1 < balls_.size(); ++i)
                others = std::max(others, balls_[i]->rb.velocity().norm());
            setResult("fastest other ball's speed", others, 0.0, "m/s");
        }
    }

private:
    // Centre of the last ball at rest, m.
    double rowEnd() const { return static_cast<double>(balls_.size() - 2) * (2 * kRadius + kGap); }

    void strike() {
        for (std::size_t i = 0; i < balls_.size(); ++i) {
            physim::Object* ball = balls_[i];
            ball->setPosition({i == 0 ? kStrikerX : static_cast<double>(i - 1) * (2 * kRadius + kGap), 0.0});
            ball->setRotation(0.0);
            ball->rb.setVelocity({i == 0 ? kSpeed : 0.0, 0.0});
            ball->rb.setAngularVelocity(0.0);
            ball->rb.wakeUp();
        }
        strikeTime_ = time;
    }

    std::vector<physim::Object*> balls_;  // owned by the simulation; balls_[0] is the striker
    std::vector<int> velocity_;           // graph indices
    int kinetic_ = -1, kineticTheory_ = -1;
    double strikeTime_ = 0.0;  // s
};

}  // namespace

std::unique_ptr<Simulation> makeNewtonsCradle() { return std::make_unique<NewtonsCradle>(); }

}  // namespace physim::examples
