// pendulum: six 1 m pendulums (the length is a parameter) released at rest from 10 to 150 degrees. The
// small-angle period 2 pi sqrt(L/g) holds only for small swings; the exact period is
// T = 4 sqrt(L / g) K(sin(theta0 / 2)), K the complete elliptic integral of the first kind. Graph: each pendulum's measured period (from successive crossings of the
// vertical) against the exact curve and the small-angle line. Keys: N releases them all again. Results
// (summary.json): each measured period beside the exact one.

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <SFML/Window/Event.hpp>

#include <array>
#include <cmath>
#include <string>

namespace physim::examples {
namespace {

constexpr std::array<double, 6> kAmplitudes{10, 30, 60, 90, 120, 150};  // degrees
constexpr double kSpacing = 2.2;  // m between pivots

class Pendulums : public physim::Simulation {
public:
    // Up to 1 m: with pivots 2.2 m apart, the 150 degree swing of a longer one would reach its neighbour's.
    Pendulums() { parameters.add("length", "length of each pendulum (m)", 1.0, 0.2, 1.0); }

    std::string title() const override { return "pendulum: period against amplitude"; }
    std::string keysHelp() const override { return "N: release again"; }

    // Every pivot and the full circle each bob can reach.
    std::optional<Aabb> viewBounds() const override {
        const double reach = length() + 0.1, outer = 2.5 * kSpacing + reach;
        return Aabb{{-outer, -reach}, {outer, reach}};
    }

    void onCreate() override {
        setPhysicsRate(60.0);
        physim::WorldSettings settings = world().settings();
        settings.enableSleep = false;  // a pendulum at the top of its swing is still for an instant only
        world().setSettings(settings);
        for (std::size_t i = 0; i < kAmplitudes.size(); ++i) {
            Swing& s = swings_[i];
            s.pivotX = (static_cast<double>(i) - 2.5) * kSpacing;
            auto& pivot = spawn<physim::Object>(physim::Mesh::CircleMesh(0.03, sf::Color(60, 60, 60)),
                                                physim::CircleShape(0.03));
            pivot.rb.setMass(0.0);
            pivot.setPosition({s.pivotX, 0.0});
            s.bob = &spawn<physim::Object>(physim::Mesh::CircleMesh(0.08, sf::Color(200, 80, 40)),
                                           physim::CircleShape(0.08));
            physim::DistanceJointDef rod;
            rod.bodyA = pivot.rb.bodyId();
            rod.bodyB = s.bob->rb.bodyId();
            rod.length = length();
            release(s, kAmplitudes[i]);
            world().createDistanceJoint(rod);
        }

        // The measured periods as markers over the two formulas' curves.
        measured_ = graphsManager.addGraph("Period against amplitude;amplitude (degrees);period (s)", "measured");
        exact_ = graphsManager.addSeries(measured_, "exact: 4 sqrt(L/g) K(sin(#theta_{0}/2))");
        smallAngle_ = graphsManager.addSeries(measured_, "small angle: 2#pi sqrt(L/g)");
        graphsManager.build();
        const double g = -world().settings().gravity.y();
        for (int deg = 0; deg <= 160; deg += 5) {
            graphsManager.addPoint(exact_, deg, exactPeriod(deg));
            graphsManager.addPoint(smallAngle_, deg, 2 * M_PI * std::sqrt(length() / g));
        }
    }

    void onEvent(sf::Event event) override {
        if (event.type != sf::Event::KeyPressed || event.key.code != sf::Keyboard::N) return;
        for (std::size_t i = 0; i < swings_.size(); ++i) release(swings_[i], kAmplitudes[i]);
    }

    // A crossing of the vertical while moving right starts a period; the next one ends it. One graph point per
    // pendulum: its first full period.
    void onDrawGraphs() override {
        for (std::size_t i = 0; i < swings_.size(); ++i) {
            Swing& s = swings_[i];
            const double x = s.bob->getPosition().x() - s.pivotX;
            if (s.lastX < 0.0 && x >= 0.0) {
                const double crossing = time - fixedTimeStep() * x / (x - s.lastX);  // interpolated, s
                if (s.lastCrossing >= 0.0 && !s.reported) {
                    graphsManager.addPoint(measured_, kAmplitudes[i], crossing - s.lastCrossing);
                    setResult("period at " + std::to_string(static_cast<int>(kAmplitudes[i])) + " degrees",
                              crossing - s.lastCrossing, exactPeriod(kAmplitudes[i]), "s");
                    s.reported = true;
                }
                s.lastCrossing = crossing;
            }
            s.lastX = x;
        }
    }

    void onRender(sf::RenderWindow* window) override {
        const sf::Transform toPixels = view.worldToPixels(window->getSize());
        sf::VertexArray rods(sf::Lines, 2 * swings_.size());
        for (std::size_t i = 0; i < swings_.size(); ++i) {
            const physim::Vec2 p = swings_[i].bob->getPosition();
            rods[2 * i] = sf::Vertex({float(swings_[i].pivotX), 0.f}, sf::Color(60, 60, 60));
            rods[2 * i + 1] = sf::Vertex({float(p.x()), float(p.y())}, sf::Color(60, 60, 60));
        }
        window->draw(rods, toPixels);
    }

private:
    struct Swing {
        physim::Object* bob = nullptr;  // owned by the simulation
        double pivotX = 0.0;            // m
        double lastX = 0.0;             // bob's x from its pivot at the last frame, m
        double lastCrossing = -1.0;     // s
        bool reported = false;
    };

    double length() const { return parameters.get("length"); }  // m

    // s: 4 sqrt(L / g) K(sin(theta0 / 2)) for an amplitude theta0 in degrees.
    double exactPeriod(double degrees) const {
        const double g = -world().settings().gravity.y();
        const double a = degrees * M_PI / 180.0;
        return 4.0 * std::sqrt(length() / g) * std::comp_ellint_1(std::sin(a / 2));
    }

    void release(Swing& s, double degrees) {
        const double a = degrees * M_PI / 180.0;
        s.bob->setPosition({s.pivotX - length() * std::sin(a), -length() * std::cos(a)});  // starts on the left
        s.bob->rb.setVelocity({0.0, 0.0});
        s.lastX = -length() * std::sin(a);
        s.lastCrossing = -1.0;
        s.reported = false;
    }

    std::array<Swing, kAmplitudes.size()> swings_{};
    int measured_ = -1, exact_ = -1, smallAngle_ = -1;
};

}  // namespace

std::unique_ptr<Simulation> makePendulum() { return std::make_unique<Pendulums>(); }

}  // namespace physim::examples
