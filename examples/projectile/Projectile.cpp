// projectile: a ball launched at 20 m/s, 60 degrees above the horizontal, with no air resistance.
// Graphs: the trajectory and the speed against time (the paper's), each with the analytic answer drawn over
// the simulated points: y(x) = x tan(a) - g x^2 / (2 v0^2 cos^2 a), |v(t)| = sqrt(vx^2 + (vy0 - g t)^2).
// The ball is recorded until it comes back to launch height; then it lands on the ground 0.5 m below and rolls
// into a wall past the landing point. Keys: N launches it again. Parameters: launch speed and angle. Results
// (summary.json): the range, time of flight and highest point beside v0^2 sin 2a / g, 2 v0 sin a / g and
// (v0 sin a)^2 / (2 g).

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <SFML/Window/Event.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace physim::examples {
namespace {

constexpr double kRadius = 0.2;   // m
constexpr double kGround = -0.5;  // m, the ground's top: below the launch height, so the recorded flight is whole

class Projectile : public Simulation {
public:
    Projectile() {
        parameters.add("speed", "launch speed (m/s)", 20.0, 1.0, 40.0);
        parameters.add("angle", "launch angle above the horizontal (degrees)", 60.0, 5.0, 85.0);
    }

    std::string title() const override { return "projectile: a launch without air resistance"; }

    void onCreate() override {
        ball_ = &spawn<Object>(Mesh::CircleMesh(kRadius, sf::Color(200, 60, 60)), CircleShape(kRadius));
        // Ground from behind the launch to a wall 4 m past the landing point.
        const double end = range() + 4.0, length = end + 3.0;
        auto& ground = spawn<Object>(Mesh::RectangleMesh({length, 1.0}, sf::Color(90, 90, 90)),
                                     RectangleShape({length, 1.0}));
        ground.rb.setMass(0.0);
        ground.setPosition({end - 0.5 * length, kGround - 0.5});
        auto& wall = spawn<Object>(Mesh::RectangleMesh({0.5, 1.5}, sf::Color(90, 90, 90)), RectangleShape({0.5, 1.5}));
        wall.rb.setMass(0.0);
        wall.setPosition({end + 0.25, kGround + 0.75});
        launch();
        trajectory_ = graphsManager.addGraph("Trajectory;x (m);y (m)");
        trajectoryTheory_ = graphsManager.addSeries(trajectory_, "analytic (no air)");
        speed_ = graphsManager.addGraph("Speed;time (s);speed (m/s)");
        speedTheory_ = graphsManager.addSeries(speed_, "analytic (no air)");
        graphsManager.build();
    }

    // The whole flight, the landing and the wall.
    std::optional<Aabb> viewBounds() const override {
        const double vy = speed() * std::sin(angle());
        return Aabb{{-2.0, kGround - 1.0}, {range() + 5.0, std::max(vy * vy / (2 * g()), 1.0) + 1.0}};
    }

    std::string keysHelp() const override { return "N: launch again"; }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) {
            graphsManager.reset();
            launch();
        }
    }

    void onDrawGraphs() override {
        const Vec2 p = ball_->getPosition();
        const double t = time - launchTime_;
        const double vx = speed() * std::cos(angle()), vy = speed() * std::sin(angle());
        if (p.y() < 0.0) {  // back below launch height: this flight is over
            if (!landed_ && !trail_.empty()) reportFlight(p, t, vy);
            landed_ = true;
            return;
        }
        peak_ = std::max(peak_, p.y());
        lastT_ = t;
        trail_.push_back(p);
        graphsManager.addPoint(trajectory_, p.x(), p.y());
        graphsManager.addPoint(trajectoryTheory_, p.x(),
                               p.x() * std::tan(angle()) - g() * p.x() * p.x() / (2 * vx * vx));
        graphsManager.addPoint(speed_, t, ball_->rb.velocity().norm());
        graphsManager.addPoint(speedTheory_, t, std::hypot(vx, vy - g() * t));
    }

    // The launch height line, the analytic parabola (grey) and the path flown so far (red), in metres.
    void onRender(sf::RenderWindow* window) override {
        const sf::Transform toPixels = view.worldToPixels(window->getSize());
        const double vx = speed() * std::cos(angle());
        sf::VertexArray launchHeight(sf::Lines, 2);
        launchHeight[0] = sf::Vertex({-2.f, 0.f}, sf::Color(150, 150, 150));
        launchHeight[1] = sf::Vertex({float(range() + 2.0), 0.f}, sf::Color(150, 150, 150));
        window->draw(launchHeight, toPixels);
        sf::VertexArray parabola(sf::LineStrip, 101);
        for (int i = 0; i <= 100; ++i) {
            const double x = range() * i / 100.0;
            parabola[i] = sf::Vertex({float(x), float(x * std::tan(angle()) - g() * x * x / (2 * vx * vx))},
                                     sf::Color(150, 150, 150));
        }
        window->draw(parabola, toPixels);
        sf::VertexArray path(sf::LineStrip, trail_.size());
        for (std::size_t i = 0; i < trail_.size(); ++i)
            path[i] = sf::Vertex({float(trail_[i].x()), float(trail_[i].y())}, sf::Color(200, 60, 60));
        window->draw(path, toPixels);
    }

private:
    double speed() const { return parameters.get("speed"); }                  // m/s
    double angle() const { return parameters.get("angle") * M_PI / 180.0; }  // rad
    double g() const { return -world().settings().gravity.y(); }              // m/s^2
    double range() const { return speed() * speed() * std::sin(2 * angle()) / g(); }  // m, back at launch height

    // The crossing of launch height, interpolated between the last frame above it and the first below.
    void reportFlight(const Vec2& below, double t, double vy) {
        const Vec2 above = trail_.back();
        const double f = above.y() / (above.y() - below.y());
        setResult("range at launch height", above.x() + f * (below.x() - above.x()), range(), "m");
        setResult("time of flight", lastT_ + f * (t - lastT_), 2 * vy / g(), "s");
        setResult("highest point", peak_, vy * vy / (2 * g()), "m");
    }

    void launch() {
        trail_.clear();
        landed_ = false;
        peak_ = 0.0;
        lastT_ = 0.0;
        ball_->setPosition({0.0, 0.0});
        ball_->setRotation(0.0);
        ball_->rb.setVelocity(speed() * Vec2(std::cos(angle()), std::sin(angle())));
        ball_->rb.setAngularVelocity(0.0);
        launchTime_ = time;
    }

    Object* ball_ = nullptr;  // owned by the simulation
    int trajectory_ = -1, speed_ = -1;  // graph indices
    int trajectoryTheory_ = -1;
    int speedTheory_ = -1;
    double launchTime_ = 0.0;
    double lastT_ = 0.0;   // s since launch of the last frame above launch height
    double peak_ = 0.0;    // m, highest frame of this flight
    bool landed_ = false;  // back below launch height: the flight's results are reported
    std::vector<Vec2> trail_;  // m, one point per frame of the current flight
};

}  // namespace

std::unique_ptr<Simulation> makeProjectile() { return std::make_unique<Projectile>(); }

}  // namespace physim::examples
