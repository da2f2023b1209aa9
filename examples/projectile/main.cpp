// projectile: a ball launched at 20 m/s, 60 degrees above the horizontal, with no air resistance.
// Graphs: the trajectory and the speed against time (the paper's), each with the analytic answer drawn over
// the simulated points: y(x) = x tan(a) - g x^2 / (2 v0^2 cos^2 a), |v(t)| = sqrt(vx^2 + (vy0 - g t)^2).
// The ball is recorded until it comes back to launch height. Keys: N launches it again.

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <SFML/Window/Event.hpp>

#include <cmath>
#include <vector>

namespace {

constexpr double kSpeed = 20.0;                 // m/s
constexpr double kAngle = 60.0 * M_PI / 180.0;  // rad
constexpr double kRadius = 0.2;                 // m

class Projectile : public physim::Simulation {
public:
    std::string title() const override { return "projectile: launch at 20 m/s, 60 degrees"; }

    void onCreate() override {
        ball_ = &spawn<physim::Object>(physim::Mesh::CircleMesh(kRadius, sf::Color(200, 60, 60)),
                                       physim::CircleShape(kRadius));
        launch();
        view.center = {17.5, 7.0};
        view.pixelsPerMetre = 30.0;
        trajectory_ = graphsManager.addGraph("Trajectory;x (m);y (m)");
        trajectoryTheory_ = graphsManager.addSeries(trajectory_, "analytic (no air)");
        speed_ = graphsManager.addGraph("Speed;time (s);speed (m/s)");
        speedTheory_ = graphsManager.addSeries(speed_, "analytic (no air)");
        graphsManager.build();
    }

    std::string keysHelp() const override { return "N: launch again"; }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) {
            graphsManager.reset();
            launch();
        }
    }

    void onDrawGraphs() override {
        const physim::Vec2 p = ball_->getPosition();
        if (p.y() < 0.0) return;  // back below launch height: this flight is over
        const double t = time - launchTime_;
        const double g = -world().settings().gravity.y();
        const double vx = kSpeed * std::cos(kAngle), vy = kSpeed * std::sin(kAngle);
        trail_.push_back(p);
        graphsManager.addPoint(trajectory_, p.x(), p.y());
        graphsManager.addPoint(trajectoryTheory_, p.x(), p.x() * std::tan(kAngle) - g * p.x() * p.x() / (2 * vx * vx));
        graphsManager.addPoint(speed_, t, ball_->rb.velocity().norm());
        graphsManager.addPoint(speedTheory_, t, std::hypot(vx, vy - g * t));
    }

    // The launch height line, the analytic parabola (grey) and the path flown so far (red), in metres.
    void onRender(sf::RenderWindow* window) override {
        const sf::Transform toPixels = view.worldToPixels(window->getSize());
        const double g = -world().settings().gravity.y();
        const double vx = kSpeed * std::cos(kAngle), range = kSpeed * kSpeed * std::sin(2 * kAngle) / g;
        sf::VertexArray ground(sf::Lines, 2);
        ground[0] = sf::Vertex({-2.f, 0.f}, sf::Color(90, 90, 90));
        ground[1] = sf::Vertex({float(range + 2.0), 0.f}, sf::Color(90, 90, 90));
        window->draw(ground, toPixels);
        sf::VertexArray parabola(sf::LineStrip, 101);
        for (int i = 0; i <= 100; ++i) {
            const double x = range * i / 100.0;
            parabola[i] = sf::Vertex({float(x), float(x * std::tan(kAngle) - g * x * x / (2 * vx * vx))},
                                     sf::Color(150, 150, 150));
        }
        window->draw(parabola, toPixels);
        sf::VertexArray path(sf::LineStrip, trail_.size());
        for (std::size_t i = 0; i < trail_.size(); ++i)
            path[i] = sf::Vertex({float(trail_[i].x()), float(trail_[i].y())}, sf::Color(200, 60, 60));
        window->draw(path, toPixels);
    }

private:
    void launch() {
        trail_.clear();
        ball_->setPosition({0.0, 0.0});
        ball_->rb.setVelocity({kSpeed * std::cos(kAngle), kSpeed * std::sin(kAngle)});
        launchTime_ = time;
    }

    physim::Object* ball_ = nullptr;  // owned by the simulation
    int trajectory_ = -1, speed_ = -1;  // graph indices
    int trajectoryTheory_ = -1;
    int speedTheory_ = -1;
    double launchTime_ = 0.0;
    std::vector<physim::Vec2> trail_;  // m, one point per frame of the current flight
};

}  // namespace

int main(int argc, char** argv) { return physim::runMain<Projectile>(argc, argv); }
