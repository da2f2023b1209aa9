// projectile: a ball launched at 20 m/s, 60 degrees above the horizontal, with no air resistance.
// Graphs: the trajectory and the speed against time (the paper's), each with the analytic answer drawn over
// the simulated points: y(x) = x tan(a) - g x^2 / (2 v0^2 cos^2 a), |v(t)| = sqrt(vx^2 + (vy0 - g t)^2).
// The ball is recorded until it comes back to launch height. Keys: N launches it again.

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <SFML/Window/Event.hpp>

#include <cmath>

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
        trajectoryTheory_ = graphsManager.addSeries(trajectory_, "analytic");
        speed_ = graphsManager.addGraph("Speed;time (s);speed (m/s)");
        speedTheory_ = graphsManager.addSeries(speed_, "analytic");
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
        graphsManager.addPoint(trajectory_, p.x(), p.y());
        graphsManager.addPoint(trajectoryTheory_, p.x(), p.x() * std::tan(kAngle) - g * p.x() * p.x() / (2 * vx * vx));
        graphsManager.addPoint(speed_, t, ball_->rb.velocity().norm());
        graphsManager.addPoint(speedTheory_, t, std::hypot(vx, vy - g * t));
    }

private:
    void launch() {
        ball_->setPosition({0.0, 0.0});
        ball_->rb.setVelocity({kSpeed * std::cos(kAngle), kSpeed * std::sin(kAngle)});
        launchTime_ = time;
    }

    physim::Object* ball_ = nullptr;  // owned by the simulation
    int trajectory_ = -1, speed_ = -1;  // graph indices
    int trajectoryTheory_ = -1;
    int speedTheory_ = -1;
    double launchTime_ = 0.0;
};

}  // namespace

int main(int argc, char** argv) { return physim::runMain<Projectile>(argc, argv); }
