// falling_box: a 1 m box falls from 5 m onto static ground and comes to rest.
// Graph: the height of the box's centre against time.
// Keys: N gives the box an upward impulse (the paper's N action), plus the runner's Space / P / Esc.
// Parameters: drop height, the box's restitution.

#include "Scenes.hpp"

#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>

#include <SFML/Window/Event.hpp>

namespace physim::examples {
namespace {

constexpr double kBoxSize = 1.0;  // m

class FallingBox : public Simulation {
public:
    FallingBox() {
        parameters.add("height", "drop height of the centre (m)", 5.0, 1.0, 20.0);
        parameters.add("restitution", "the box's restitution", 0.3, 0.0, 1.0);
    }

    std::string title() const override { return "falling_box: a box falls onto the ground"; }

    void onCreate() override {
        // Static ground: 20 m wide, its top at y = 0.
        auto& ground = spawn<Object>(Mesh::RectangleMesh({20.0, 1.0}, sf::Color(90, 90, 90)),
                                     RectangleShape({20.0, 1.0}));
        ground.rb.setMass(0.0);
        ground.rb.setRestitution(0.5);  // a pair bounces with the smaller restitution: the box's 0.3
        ground.setPosition({0.0, -0.5});

        box_ = &spawn<Object>(Vec2(kBoxSize, kBoxSize));
        box_->rb.setDensity(1.0);
        box_->rb.setRestitution(parameters.get("restitution"));
        box_->setPosition({0.0, parameters.get("height")});

        graphsManager.addGraph("Box height;time (s);height of the centre (m)", {}, GraphMode::WITH_LINES);
        graphsManager.build();
    }

    // The box's fall, not the whole ground.
    std::optional<Aabb> viewBounds() const override {
        return Aabb{{-6.0, -1.0}, {6.0, parameters.get("height") + 1.0}};
    }

    std::string keysHelp() const override { return "N: kick the box up"; }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N)
            box_->rb.addForce({0.0, 6.0 * box_->rb.mass()}, ForceMode::IMPULSE);
    }

    void onDrawGraphs() override { graphsManager.addPoint(0, time, box_->getPosition().y()); }

private:
    Object* box_ = nullptr;  // owned by the simulation
};

}  // namespace

std::unique_ptr<Simulation> makeFallingBox() { return std::make_unique<FallingBox>(); }

}  // namespace physim::examples
