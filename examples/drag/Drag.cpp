// drag: a 1.57 kg ball dropped from 60 m through air (quadratic drag, C_d 1.2, 1.2 kg/m^2), beside the same
// ball in a vacuum. Under F = -1/2 rho C_d w |v| v its speed follows v(t) = v_t tanh(g t / v_t) towards the
// terminal velocity v_t = sqrt(m g / (1/2 rho C_d w)) = 10.3 m/s; the vacuum ball keeps accelerating (g t).
// Graph: the air ball's speed against time over the tanh curve, the terminal velocity and free fall, until it
// lands. Keys: N drops both again. Results (summary.json): the speed after one time constant v_t / g and just
// before landing, beside the curve's.

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <SFML/Window/Event.hpp>

#include <algorithm>
#include <cmath>

namespace physim::examples {
namespace {

constexpr double kRadius = 0.1;      // m
constexpr double kDensity = 50.0;    // kg/m^2: 1.57 kg
constexpr double kHeight = 60.0;     // m, the balls' centres at release
constexpr double kCd = 1.2;          // a long cylinder across the flow
constexpr double kAir = 1.2;         // kg/m^2: air, the world a slab 1 m deep

class Drag : public physim::Simulation {
public:
    std::string title() const override { return "drag: a ball falling through air reaches its terminal velocity"; }
    std::string keysHelp() const override { return "N: drop again"; }

    void onCreate() override {
        setPhysicsRate(60.0);
        auto& ground = spawn<physim::Object>(physim::Mesh::RectangleMesh({12.0, 1.0}, sf::Color(120, 120, 120)),
                                             physim::RectangleShape({12.0, 1.0}));
        ground.rb.setMass(0.0);
        ground.setPosition({0.0, -0.5});
        air_ = &spawn<physim::Object>(physim::Mesh::CircleMesh(kRadius, sf::Color(40, 110, 200)),
                                      physim::CircleShape(kRadius));
        vacuum_ = &spawn<physim::Object>(physim::Mesh::CircleMesh(kRadius, sf::Color(200, 80, 40)),
                                         physim::CircleShape(kRadius));
        air_->rb.setDensity(kDensity);
        vacuum_->rb.setDensity(kDensity);
        physim::DragDef drag;
        drag.dragCoefficient = kCd;
        drag.fluidDensity = kAir;  // width: the ball's diameter (the default)
        world().setDrag(air_->rb.bodyId(), drag);
        drop();

        const double m = air_->rb.mass(), g = -world().settings().gravity.y();
        terminal_ = std::sqrt(m * g / (0.5 * kAir * kCd * 2 * kRadius));
        speed_ = graphsManager.addGraph("Falling through air;time (s);speed (m/s)", "simulated");
        theory_ = graphsManager.addSeries(speed_, "v_{t} tanh(g t / v_{t})");
        terminalLine_ = graphsManager.addSeries(speed_, "terminal velocity v_{t}");
        freeFall_ = graphsManager.addSeries(speed_, "in a vacuum: g t");
        graphsManager.build();
        view.pixelsPerMetre = 40.0;
    }

    void onEvent(sf::Event event) override {
        if (event.type != sf::Event::KeyPressed || event.key.code != sf::Keyboard::N) return;
        graphsManager.reset();
        drop();
    }

    // One point per frame while the air ball is falling (until it is about to land).
    void onDrawGraphs() override {
        if (landed_ || air_->getPosition().y() < 2 * kRadius) {
            if (!landed_) setResult("speed before landing (terminal velocity)", lastSpeed_, terminal_, "m/s");
            landed_ = true;
            return;
        }
        const double t = time - dropTime_, g = -world().settings().gravity.y();
        const double v = air_->rb.velocity().norm();
        // The speed at the first frame past one time constant v_t / g (where the curve bends most); the last
        // frame's before landing is reported against v_t above.
        if (!timeConstantReported_ && g * t >= terminal_) {
            setResult("speed at one time constant", v, terminal_ * std::tanh(g * t / terminal_), "m/s");
            timeConstantReported_ = true;
        }
        lastSpeed_ = v;
        graphsManager.addPoint(speed_, t, v);
        graphsManager.addPoint(theory_, t, terminal_ * std::tanh(g * t / terminal_));
        graphsManager.addPoint(terminalLine_, t, terminal_);
        if (g * t < 1.5 * terminal_) graphsManager.addPoint(freeFall_, t, g * t);
    }

    // Follow the air ball; marks every 10 m of height.
    void onRender(sf::RenderWindow* window) override {
        view.center = {0.0, std::max(air_->getPosition().y(), 6.0)};
        const sf::Transform toPixels = view.worldToPixels(window->getSize());
        sf::VertexArray marks(sf::Lines, 14);
        for (int i = 0; i < 7; ++i) {
            marks[2 * i] = sf::Vertex({-4.f, float(10 * i)}, sf::Color(170, 170, 170));
            marks[2 * i + 1] = sf::Vertex({4.f, float(10 * i)}, sf::Color(170, 170, 170));
        }
        window->draw(marks, toPixels);
    }

private:
    void drop() {
        air_->setPosition({-1.0, kHeight});
        vacuum_->setPosition({1.0, kHeight});
        for (physim::Object* ball : {air_, vacuum_}) {
            ball->rb.setVelocity({0.0, 0.0});
            ball->rb.setAngularVelocity(0.0);
        }
        dropTime_ = time;
        landed_ = false;
        timeConstantReported_ = false;
    }

    physim::Object* air_ = nullptr;     // owned by the simulation
    physim::Object* vacuum_ = nullptr;
    double terminal_ = 0.0;             // m/s
    double dropTime_ = 0.0;             // s
    bool landed_ = false;
    bool timeConstantReported_ = false;
    double lastSpeed_ = 0.0;            // m/s, the air ball's at the last frame while falling
    int speed_ = -1, theory_ = -1, terminalLine_ = -1, freeFall_ = -1;
};

}  // namespace

std::unique_ptr<Simulation> makeDrag() { return std::make_unique<Drag>(); }

}  // namespace physim::examples
