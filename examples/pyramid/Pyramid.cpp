// pyramid: 210 boxes of 1 m (half-size 0.5 m, 1 kg) stacked 20, 19, ..., 1 on static ground whose top is at
// y = 0, each placed at its resting height, row r's centres at 0.5 + r m. A stack that holds keeps its total
// energy at the potential energy it was built with, sum of m g (0.5 + r), and the top box at 19.5 m; the
// solver only lets each contact keep up to its slop (5 mm) of overlap, so the stack may settle by at most
// 20 slops at the top. Sleeping is off (as in the core stacking test) so the graphs show the solver holding
// the stack, not sleep freezing it. Graphs: total energy (kinetic + potential) and the top box's height
// against time, each over its analytic rest value. Keys: N knocks the top box sideways at 3 m/s.
// Parameter: the number of boxes in the bottom row (20 above).

#include "Scenes.hpp"

#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Window/Event.hpp>

#include <string>
#include <vector>

namespace physim::examples {
namespace {

constexpr double kSize = 1.0;    // m, box side (half-size 0.5 m)
constexpr double kDensity = 1.0; // kg/m^2: 1 kg boxes

class Pyramid : public physim::Simulation {
public:
    Pyramid() { parameters.add("base", "boxes in the bottom row", 20, 1, 30, true); }

    std::string title() const override {
        const int base = parameters.getInt("base");
        return "pyramid: " + std::to_string(base * (base + 1) / 2) + " boxes on a " + std::to_string(base) +
               "-box base";
    }

    void onCreate() override {
        physim::WorldSettings settings = world().settings();
        settings.enableSleep = false;
        world().setSettings(settings);
        auto& ground = spawn<physim::Object>(physim::Mesh::RectangleMesh({100.0, 1.0}, sf::Color(90, 90, 90)),
                                             physim::RectangleShape({100.0, 1.0}));
        ground.rb.setMass(0.0);
        ground.setPosition({0.0, -0.5});  // top face at y = 0
        const int base = parameters.getInt("base");
        for (int row = 0; row < base; ++row) {
            for (int i = 0; i < base - row; ++i) {
                auto& box = spawn<physim::Object>(physim::Vec2(kSize, kSize));
                box.rb.setDensity(kDensity);
                box.setPosition({-0.5 * kSize * (base - row - 1) + kSize * i, kSize * (0.5 + row)});
                boxes_.push_back(&box);
            }
        }
        energy_ = graphsManager.addGraph("Total energy;time (s);kinetic + potential (J)");
        energyTheory_ = graphsManager.addSeries(energy_, "sum of m g (0.5 + row)");
        top_ = graphsManager.addGraph("Top box;time (s);height of the centre (m)");
        topTheory_ = graphsManager.addSeries(top_, "rest height, (base - 0.5) m");
        graphsManager.build();
    }

    std::string keysHelp() const override { return "N: knock the top box"; }

    // The stack, not the whole 100 m of ground.
    std::optional<Aabb> viewBounds() const override {
        const double half = 0.5 * kSize * parameters.getInt("base") + 1.0;
        return Aabb{{-half, -1.0}, {half, 2 * half - 1.0}};
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N)
            boxes_.back()->rb.setVelocity({3.0, 0.0});
    }

    void onDrawGraphs() override {
        const double g = -world().settings().gravity.y();
        double energy = 0.0, rest = 0.0;  // J
        const int base = parameters.getInt("base");
        for (int row = 0, k = 0; row < base; ++row) {
            for (int i = 0; i < base - row; ++i, ++k) {
                const physim::RigidBody& rb = boxes_[k]->rb;
                energy += 0.5 * rb.mass() * rb.velocity().squaredNorm() +
                          0.5 * rb.inertia() * rb.angularVelocity() * rb.angularVelocity() +
                          rb.mass() * g * rb.position().y();
                rest += rb.mass() * g * kSize * (0.5 + row);
            }
        }
        graphsManager.addPoint(energy_, time, energy);
        graphsManager.addPoint(energyTheory_, time, rest);
        graphsManager.addPoint(top_, time, boxes_.back()->getPosition().y());
        graphsManager.addPoint(topTheory_, time, kSize * (base - 0.5));
    }

private:
    std::vector<physim::Object*> boxes_;  // owned by the simulation; row by row, the top box last
    int energy_ = -1, energyTheory_ = -1, top_ = -1, topTheory_ = -1;  // graph indices
};

}  // namespace

std::unique_ptr<Simulation> makePyramid() { return std::make_unique<Pyramid>(); }

}  // namespace physim::examples
