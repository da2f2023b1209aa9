// orbits: a sun and two planets held together by Newtonian gravitation alone (GravitationSettings, direct
// summation). Every substep is a symplectic Euler step, so the total energy stays within a small bounded band and
// the angular momentum is kept to rounding; the graphs show both against their start values (E / E(0) and
// L / L(0), the start value drawn at 1). The scene is scaled: G = 1 N m^2/kg^2 and a 1000 kg sun (with the real
// G the sun would weigh 1.5e13 kg). Keys: N nudges the outer planet (its orbit turns elliptic; the start values
// are taken again). Results (summary.json): the energy and angular momentum beside their start values.

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <SFML/Window/Event.hpp>

#include <array>
#include <cmath>
#include <deque>

namespace physim::examples {
namespace {

constexpr double kG = 1.0;  // N m^2 / kg^2, this scene's scaled constant

struct Planet {
    double mass, radius, distance;  // kg, m (drawn and colliding size), m from the sun
    sf::Color color;
};

constexpr std::size_t kCount = 3;
const std::array<Planet, kCount> kBodies{{  // sf::Color is not a literal type
    {1000.0, 0.4, 0.0, sf::Color(240, 180, 40)},  // the sun
    {1.0, 0.12, 4.0, sf::Color(60, 120, 220)},    // period 2 pi sqrt(r^3 / (G M)) = 1.6 s
    {5.0, 0.2, 8.0, sf::Color(200, 80, 60)},      // 4.5 s
}};

class Orbits : public physim::Simulation {
public:
    std::string title() const override { return "orbits: a sun and two planets, energy and angular momentum kept"; }
    std::string keysHelp() const override { return "N: nudge the outer planet"; }

    void onCreate() override {
        setPhysicsRate(60.0);
        physim::WorldSettings settings = world().settings();
        settings.gravity = physim::Vec2::Zero();
        world().setSettings(settings);
        physim::GravitationSettings gravitation;
        gravitation.G = kG;
        world().setGravitation(gravitation);
        physim::Vec2 momentum = physim::Vec2::Zero();
        for (std::size_t i = 0; i < kBodies.size(); ++i) {
            const Planet& p = kBodies[i];
            physim::Object& body = spawn<physim::Object>(physim::Mesh::CircleMesh(p.radius, p.color),
                                                         physim::CircleShape(p.radius));
            body.rb.setMass(p.mass);
            body.setPosition({p.distance, 0.0});
            world().setAttracting(body.rb.bodyId(), true);
            if (i > 0) {  // a circular orbit about the sun: v = sqrt(G M / r)
                const double v = std::sqrt(kG * kBodies[0].mass / p.distance);
                body.rb.setVelocity({0.0, v});
                momentum += p.mass * physim::Vec2(0.0, v);
            }
            bodies_[i] = &body;
        }
        bodies_[0]->rb.setVelocity(-momentum / kBodies[0].mass);  // the centre of mass at rest
        view.pixelsPerMetre = 38.0;

        energy_ = graphsManager.addGraph("Energy against its start value;time (s);E / E(0)", "simulated", {},
                                         physim::GraphMode::WITH_LINES);
        energyStart_ = graphsManager.addSeries(energy_, "start value");
        momentum_ = graphsManager.addGraph("Angular momentum against its start value;time (s);L / L(0)",
                                           "simulated", {}, physim::GraphMode::WITH_LINES);
        momentumStart_ = graphsManager.addSeries(momentum_, "start value");
        graphsManager.build();
        takeStartValues();
    }

    void onEvent(sf::Event event) override {
        if (event.type != sf::Event::KeyPressed || event.key.code != sf::Keyboard::N) return;
        physim::RigidBody& outer = bodies_[2]->rb;
        outer.setVelocity(1.15 * outer.velocity());
        takeStartValues();
    }

    void onDrawGraphs() override {
        setResult("total energy", energy(), e0_, "J");
        setResult("angular momentum", angularMomentum(), l0_, "kg m^2/s");
        graphsManager.addPoint(energy_, time, energy() / e0_);
        graphsManager.addPoint(energyStart_, time, 1.0);
        graphsManager.addPoint(momentum_, time, angularMomentum() / l0_);
        graphsManager.addPoint(momentumStart_, time, 1.0);
        for (std::size_t i = 0; i < trails_.size(); ++i) {
            trails_[i].push_back(bodies_[i]->getPosition());
            if (trails_[i].size() > 600) trails_[i].pop_front();  // the last 10 s at 60 frames per second
        }
    }

    void onRender(sf::RenderWindow* window) override {
        const sf::Transform toPixels = view.worldToPixels(window->getSize());
        for (std::size_t i = 0; i < trails_.size(); ++i) {
            sf::VertexArray path(sf::LineStrip, trails_[i].size());
            for (std::size_t k = 0; k < trails_[i].size(); ++k) {
                sf::Color c = kBodies[i].color;
                c.a = static_cast<sf::Uint8>(40 + 160 * k / trails_[i].size());
                path[k] = sf::Vertex({float(trails_[i][k].x()), float(trails_[i][k].y())}, c);
            }
            window->draw(path, toPixels);
        }
    }

private:
    // Kinetic plus the pairs' potential energy -G mA mB / r, J.
    double energy() const {
        double e = 0.0;
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            e += 0.5 * bodies_[i]->rb.mass() * bodies_[i]->rb.velocity().squaredNorm();
            for (std::size_t j = i + 1; j < bodies_.size(); ++j)
                e -= kG * bodies_[i]->rb.mass() * bodies_[j]->rb.mass() /
                     (bodies_[i]->getPosition() - bodies_[j]->getPosition()).norm();
        }
        return e;
    }

    // About the origin, kg m^2/s (the centre of mass is at rest, so any fixed point serves).
    double angularMomentum() const {
        double l = 0.0;
        for (const physim::Object* b : bodies_) l += b->rb.mass() * physim::cross(b->getPosition(), b->rb.velocity());
        return l;
    }

    void takeStartValues() {
        e0_ = energy();
        l0_ = angularMomentum();
    }

    std::array<physim::Object*, kCount> bodies_{};  // owned by the simulation
    std::array<std::deque<physim::Vec2>, kCount> trails_;
    double e0_ = 0.0, l0_ = 0.0;
    int energy_ = -1, energyStart_ = -1, momentum_ = -1, momentumStart_ = -1;
};

}  // namespace

std::unique_ptr<Simulation> makeOrbits() { return std::make_unique<Orbits>(); }

}  // namespace physim::examples
