// test: the paper's first simulation. A box tilted by 30 degrees falls on the ground, lands on a corner,
// tips over and comes to rest on a face. The contact points and normals of every contact are drawn over the
// scene (debug drawing's contacts, on from the start: red points, blue normals; dimmed once the box sleeps).
// Graph: the box's angle against time. Keys: N drops it again. Parameter: the tilt.

#include "Scenes.hpp"

#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Window/Event.hpp>

#include <cmath>

namespace physim::examples {
namespace {

class TestScene : public Simulation {
public:
    TestScene() { parameters.add("tilt", "the box's tilt at the drop (degrees)", 30.0, 0.0, 90.0); }

    std::string title() const override { return "test: a tilted box falls on the ground (contacts drawn)"; }

    void onCreate() override {
        auto& ground = spawn<Object>(Mesh::RectangleMesh({16.0, 1.0}, sf::Color(90, 90, 90)),
                                     RectangleShape({16.0, 1.0}));
        ground.rb.setMass(0.0);
        ground.setPosition({0.0, -0.5});
        box_ = &spawn<Object>(Vec2(1.5, 1.0));
        drop();
        debugDraw.contacts = true;
        angleGraph_ = graphsManager.addGraph("Box angle;time (s);angle (rad)", {}, GraphMode::WITH_LINES);
        graphsManager.build();
    }

    std::optional<Aabb> viewBounds() const override { return Aabb{{-4.0, -1.0}, {4.0, 4.0}}; }

    std::string keysHelp() const override { return "N: drop again"; }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) drop();
    }

    void onDrawGraphs() override { graphsManager.addPoint(angleGraph_, time, box_->getRotation()); }

private:
    void drop() {
        box_->setPosition({0.0, 3.0});
        box_->setRotation(parameters.get("tilt") * M_PI / 180.0);
        box_->rb.setVelocity({0.0, 0.0});
        box_->rb.setAngularVelocity(0.0);
    }

    Object* box_ = nullptr;  // owned by the simulation
    int angleGraph_ = -1;
};

}  // namespace

std::unique_ptr<Simulation> makeTestScene() { return std::make_unique<TestScene>(); }

}  // namespace physim::examples
