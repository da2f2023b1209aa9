// rope: the paper's rope, 20 small discs linked by distance joints (rigid links of 12 cm), hanging from a
// fixed pivot. It starts horizontal and swings down, whipping as it folds. Graph: the distance from the pivot
// to the rope's free end against time, with the rope's length, which it can never exceed. Keys: N lays the
// rope horizontal again. Parameter: the number of links.

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <SFML/Window/Event.hpp>

#include <vector>

namespace physim::examples {
namespace {

constexpr double kLinkLength = 0.12;  // m between neighbouring disc centres
constexpr double kRadius = 0.05;      // m

class Rope : public physim::Simulation {
public:
    Rope() { parameters.add("links", "number of links", 20, 2, 60, true); }

    std::string title() const override { return "rope: linked discs swing from a pivot"; }
    std::string keysHelp() const override { return "N: lay it horizontal again"; }

    void onCreate() override {
        setPhysicsRate(60.0);
        pivot_ = &spawn<physim::Object>(physim::Mesh::CircleMesh(0.04, sf::Color(60, 60, 60)),
                                        physim::CircleShape(0.04));
        pivot_->rb.setMass(0.0);
        physim::Object* previous = pivot_;
        for (int i = 1; i <= parameters.getInt("links"); ++i) {
            auto& link = spawn<physim::Object>(physim::Mesh::CircleMesh(kRadius, sf::Color(150, 100, 50)),
                                               physim::CircleShape(kRadius));
            physim::DistanceJointDef joint;
            joint.bodyA = previous->rb.bodyId();
            joint.bodyB = link.rb.bodyId();
            joint.length = kLinkLength;
            world().createDistanceJoint(joint);
            links_.push_back(&link);
            previous = &link;
        }
        layHorizontal();
        distance_ = graphsManager.addGraph("Rope end;time (s);distance from the pivot (m)", {},
                                           physim::GraphMode::WITH_LINES);
        length_ = graphsManager.addSeries(distance_, "rope length");
        graphsManager.build();
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) layHorizontal();
    }

    void onDrawGraphs() override {
        graphsManager.addPoint(distance_, time, (links_.back()->getPosition() - pivot_->getPosition()).norm());
        graphsManager.addPoint(length_, time, length());
    }

    // The circle the rope's end can reach, above the pivot too (it whips up).
    std::optional<Aabb> viewBounds() const override {
        const double r = length() + 0.05;
        return Aabb{{-r, -r}, {r, 0.3 * r}};
    }

    void onRender(sf::RenderWindow* window) override {
        sf::VertexArray line(sf::LineStrip, links_.size() + 1);
        line[0] = sf::Vertex({0.f, 0.f}, sf::Color(60, 60, 60));
        for (std::size_t i = 0; i < links_.size(); ++i) {
            const physim::Vec2 p = links_[i]->getPosition();
            line[i + 1] = sf::Vertex({float(p.x()), float(p.y())}, sf::Color(60, 60, 60));
        }
        window->draw(line, view.worldToPixels(window->getSize()));
    }

private:
    double length() const { return static_cast<double>(links_.size()) * kLinkLength; }  // m

    void layHorizontal() {
        for (int i = 0; i < static_cast<int>(links_.size()); ++i) {
            links_[static_cast<std::size_t>(i)]->setPosition({(i + 1) * kLinkLength, 0.0});
            links_[static_cast<std::size_t>(i)]->rb.setVelocity({0.0, 0.0});
        }
    }

    physim::Object* pivot_ = nullptr;      // owned by the simulation
    std::vector<physim::Object*> links_;  // owned by the simulation
    int distance_ = -1, length_ = -1;
};

}  // namespace

std::unique_ptr<Simulation> makeRope() { return std::make_unique<Rope>(); }

}  // namespace physim::examples
