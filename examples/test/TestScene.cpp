// test: the paper's first simulation. A box tilted by 30 degrees falls on the ground, lands on a corner,
// tips over and comes to rest on a face. The contact points and normals of every contact are drawn over the
// scene (red points, blue normals). Graph: the box's angle against time. Keys: N drops it again.

#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/Vertex.hpp>
#include <SFML/Window/Event.hpp>

#include <cmath>

namespace {

constexpr double kTilt = 30.0 * M_PI / 180.0;  // rad

class TestScene : public physim::Simulation {
public:
    std::string title() const override { return "test: a tilted box falls on the ground (contacts drawn)"; }

    void onCreate() override {
        auto& ground = spawn<physim::Object>(physim::Mesh::RectangleMesh({16.0, 1.0}, sf::Color(90, 90, 90)),
                                             physim::RectangleShape({16.0, 1.0}));
        ground.rb.setMass(0.0);
        ground.setPosition({0.0, -0.5});
        box_ = &spawn<physim::Object>(physim::Vec2(1.5, 1.0));
        drop();
        view.center = {0.0, 2.0};
        angleGraph_ = graphsManager.addGraph("Box angle;time (s);angle (rad)", {}, physim::GraphMode::WITH_LINES);
        graphsManager.build();
    }

    std::string keysHelp() const override { return "N: drop again"; }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) drop();
    }

    void onDrawGraphs() override { graphsManager.addPoint(angleGraph_, time, box_->getRotation()); }

    // Debug overlay: each contact point (m) as a dot, and its normal as a 0.5 m line from A towards B.
    void onRender(sf::RenderWindow* window) override {
        const sf::Transform toPixels = view.worldToPixels(window->getSize());
        for (const physim::Manifold& m : world().contacts()) {
            for (int i = 0; i < m.pointCount; ++i) {
                const physim::Vec2 p = m.points[i].point;
                const physim::Vec2 tip = p + 0.5 * m.normal;
                const sf::Vertex normal[] = {
                    sf::Vertex(sf::Vector2f(float(p.x()), float(p.y())), sf::Color::Blue),
                    sf::Vertex(sf::Vector2f(float(tip.x()), float(tip.y())), sf::Color::Blue)};
                window->draw(normal, 2, sf::Lines, toPixels);
                sf::CircleShape dot(0.06f);
                dot.setOrigin(0.06f, 0.06f);
                dot.setPosition(float(p.x()), float(p.y()));
                dot.setFillColor(sf::Color::Red);
                window->draw(dot, toPixels);
            }
        }
    }

private:
    void drop() {
        box_->setPosition({0.0, 3.0});
        box_->setRotation(kTilt);
        box_->rb.setVelocity({0.0, 0.0});
        box_->rb.setAngularVelocity(0.0);
    }

    physim::Object* box_ = nullptr;  // owned by the simulation
    int angleGraph_ = -1;
};

}  // namespace

int main(int argc, char** argv) { return physim::runMain<TestScene>(argc, argv); }
