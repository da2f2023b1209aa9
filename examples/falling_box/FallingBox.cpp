// falling_box: a 1 m box falls from 5 m onto static ground and comes to rest.
// Graph: the height of the box's centre against time.
// Keys: N gives the box an upward impulse (the paper's N action), plus the runner's Space / P / Esc.

#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>
#include <physim/framework/Simulation.hpp>

#include <SFML/Window/Event.hpp>

namespace {

constexpr double kDropHeight = 5.0;  // m, centre of the box at the start
constexpr double kBoxSize = 1.0;     // m

class FallingBox : public physim::Simulation {
public:
    std::string title() const override { return "falling_box: a box falls onto the ground"; }

    void onCreate() override {
        using physim::Vec2;
        // Static ground: 20 m wide, its top at y = 0.
        auto& ground = spawn<physim::Object>(physim::Mesh::RectangleMesh({20.0, 1.0}, sf::Color(90, 90, 90)),
                                             physim::RectangleShape({20.0, 1.0}));
        ground.rb.setMass(0.0);
        ground.rb.setRestitution(0.5);  // a pair bounces with the smaller restitution: the box's 0.3
        ground.setPosition({0.0, -0.5});

        box_ = &spawn<physim::Object>(Vec2(kBoxSize, kBoxSize));
        box_->rb.setDensity(1.0);
        box_->rb.setRestitution(0.3);
        box_->setPosition({0.0, kDropHeight});

        view.center = {0.0, 2.5};
        graphsManager.addGraph("Box height;time (s);height of the centre (m)", {}, physim::GraphMode::WITH_LINES);
        graphsManager.build();
    }

    std::string keysHelp() const override { return "N: kick the box up"; }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N)
            box_->rb.addForce({0.0, 6.0 * box_->rb.mass()}, physim::ForceMode::IMPULSE);
    }

    void onDrawGraphs() override { graphsManager.addPoint(0, time, box_->getPosition().y()); }

private:
    physim::Object* box_ = nullptr;  // owned by the simulation
};

}  // namespace

int main(int argc, char** argv) { return physim::runMain<FallingBox>(argc, argv); }
