// circles: the paper's circles. Forty discs of random sizes drop into an open box, bounce (restitution 0.4),
// roll and settle into a heap. Graph: the total mechanical energy (kinetic + potential, J) against time,
// under the line of the energy they started with: contacts only take energy away. Keys: N drops them again.
// Parameters: the number of discs, their restitution.

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Window/Event.hpp>

#include <random>
#include <vector>

namespace physim::examples {
namespace {

constexpr double kHalfWidth = 2.0;  // m, inside half-width of the box

class Circles : public physim::Simulation {
public:
    Circles() {
        parameters.add("discs", "number of discs", 40, 1, 80, true);
        parameters.add("restitution", "restitution of discs and box", 0.4, 0.0, 1.0);
    }

    std::string title() const override { return "circles: discs drop into a box"; }
    std::string keysHelp() const override { return "N: drop them again"; }

    void onCreate() override {
        setPhysicsRate(60.0);
        const double t = 0.4;  // wall thickness, m
        for (const auto& [size, pos] :
             {std::pair{physim::Vec2(2 * kHalfWidth + 2 * t, t), physim::Vec2(0, -t / 2)},
              std::pair{physim::Vec2(t, 4.0), physim::Vec2(-kHalfWidth - t / 2, 2.0)},
              std::pair{physim::Vec2(t, 4.0), physim::Vec2(kHalfWidth + t / 2, 2.0)}}) {
            auto& wall = spawn<physim::Object>(physim::Mesh::RectangleMesh(size, sf::Color(90, 90, 90)),
                                               physim::RectangleShape(size));
            wall.rb.setMass(0.0);
            wall.rb.setRestitution(parameters.get("restitution"));
            wall.setPosition(pos);
        }
        std::mt19937 rng(11);  // this simulation's own generator: every run drops the same discs
        std::uniform_real_distribution<double> radius(0.1, 0.3);
        const int n = parameters.getInt("discs");
        for (int i = 0; i < n; ++i) {
            const double r = radius(rng);
            const int shade = 200 * i / n;  // blue to purple along the drop order
            const sf::Color color(static_cast<sf::Uint8>(40 + shade), 120, static_cast<sf::Uint8>(220 - shade * 4 / 5));
            auto& c = spawn<physim::Object>(physim::Mesh::CircleMesh(r, color), physim::CircleShape(r));
            c.rb.setRestitution(parameters.get("restitution"));
            circles_.push_back(&c);
        }
        drop();
        initialEnergy_ = mechanicalEnergy();
        energy_ = graphsManager.addGraph("Mechanical energy;time (s);kinetic + potential (J)", {},
                                         physim::GraphMode::WITH_LINES);
        initial_ = graphsManager.addSeries(energy_, "initial");
        graphsManager.build();
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) drop();
    }

    void onDrawGraphs() override {
        graphsManager.addPoint(energy_, time, mechanicalEnergy());
        graphsManager.addPoint(initial_, time, initialEnergy_);
    }

private:
    // Two staggered columns of discs above the box, 0.7 m apart: no overlaps at the start.
    void drop() {
        for (int i = 0; i < static_cast<int>(circles_.size()); ++i) {
            const double x = -1.4 + 0.7 * (i % 5) + (i / 5 % 2 ? 0.2 : 0.0);
            circles_[static_cast<std::size_t>(i)]->setPosition({x, 1.0 + 0.7 * (i / 5)});
            circles_[static_cast<std::size_t>(i)]->rb.setVelocity({0.0, 0.0});
            circles_[static_cast<std::size_t>(i)]->rb.setAngularVelocity(0.0);
        }
    }

    double mechanicalEnergy() const {
        const double g = -world().settings().gravity.y();
        double e = 0.0;
        for (const physim::Object* c : circles_) {
            const double m = c->rb.mass();
            e += 0.5 * m * c->rb.velocity().squaredNorm() + 0.5 * c->rb.inertia() * c->rb.angularVelocity() *
                 c->rb.angularVelocity() + m * g * c->getPosition().y();
        }
        return e;
    }

    std::vector<physim::Object*> circles_;  // owned by the simulation
    double initialEnergy_ = 0.0;
    int energy_ = -1, initial_ = -1;
};

}  // namespace

std::unique_ptr<Simulation> makeCircles() { return std::make_unique<Circles>(); }

}  // namespace physim::examples
