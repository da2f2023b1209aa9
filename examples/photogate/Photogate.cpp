// photogate: a ball (radius r, 2 cm by default) dropped from rest falls through six thin sensor gates (World sensors,
// physim/core/Sensor.hpp) h = 0.25, 0.5, ..., 1.5 m below its release point. Each gate reports when the ball entered
// it and when it left, to a fraction of the step (Simulation::onSensor), as a real photogate times a ball's
// shadow: at 40 Hz the ball crosses a gate in 8 to 20 ms, less than one 25 ms step.
//
// What is compared with what (results, summary.json):
// - "v at h": the ball's mean speed through the gate, L / (t_out - t_in) with L = 2 r + the gate's thickness (from
//   the moment its bottom reaches the gate's top to the moment its top leaves the gate's bottom), beside the exact
//   free-fall value for that chord, L / (sqrt(2 (h + L / 2) / g) - sqrt(2 (h - L / 2) / g)). That mean is sqrt(2 g h)
//   less about L^2 / (16 h^2) of it (0.2% at the first gate, 0.01% at the last): the plot shows sqrt(2 g h).
// - "g fitted": g from the twelve entry and exit times by a straight-line fit of sqrt(2 d) against t, whose slope is
//   sqrt(g) for any start offset (sqrt(2 d) = sqrt(g) (t + t0)): the solver's semi-implicit Euler runs ahead of the
//   exact fall by half a substep (t0 = dt / 16, 1.6 ms at 40 Hz with 8 substeps), which the offset takes up. A fit
//   with t0 = 0 would read g about 0.5% high at the first gates; that is the integrator, not the gates.
// The figures hold at any rate: the sensors time the crossing on the ball's path through every substep, not at the
// steps' ends (a gate sampled once per step reads the speed to the step, the 2.0 or 4.0 m/s for 3.1).
// When the ball has passed the last gate it is dropped again. Keys: N drops it again.

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Window/Event.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace physim::examples {
namespace {

constexpr std::array<double, 6> kDepths = {0.25, 0.5, 0.75, 1.0, 1.25, 1.5};  // m below the release point
constexpr double kGateThickness = 0.001;  // m: a thin beam
constexpr double kGateWidth = 0.5;        // m

class Photogate : public physim::Simulation {
public:
    Photogate() { parameters.add("r", "ball radius (m)", 0.02, 0.005, 0.1); }

    std::string title() const override { return "photogate: a falling ball timed by sensor gates, v = sqrt(2 g h)"; }
    std::string keysHelp() const override { return "N: drop again"; }

    std::optional<Aabb> viewBounds() const override {
        return Aabb{{-0.6, -kDepths.back() - 0.2}, {0.6, 0.2}};
    }

    void onCreate() override {
        physim::WorldSettings settings = world().settings();
        settings.enableSleep = false;  // the ball is at rest for an instant at release
        world().setSettings(settings);
        radius_ = parameters.get("r");
        for (const double h : kDepths) {
            // Drawn as a beam 5 mm wide (the 1 mm gate would be a hairline), outlined by nothing.
            const double half = 0.5 * kGateWidth;
            auto& gate = spawn<physim::Object>(
                physim::Mesh::LineMesh({{-half, 0.0}, {half, 0.0}}, false, 0.005, sf::Color(230, 150, 0)),
                physim::RectangleShape({kGateWidth, kGateThickness}));
            gate.setPosition({0.0, -h});
            gate.rb.setMass(0.0);
            gate.rb.setSensor(true);
            gates_.push_back(&gate);
        }
        ball_ = &spawn<physim::Object>(physim::CircleShape(radius_), sf::Color(40, 110, 200));

        speed_ = graphsManager.addGraph("Speed at the gates;h (m);v (m/s)", "L / (t_{out} - t_{in})");
        root_ = graphsManager.addSeries(speed_, "#sqrt{2 g h}");
        drop_ = graphsManager.addGraph("Gate times;t (s);fallen d (m)", "entry and exit");
        fit_ = graphsManager.addSeries(drop_, "g_{fit} (t + t_{0})^{2} / 2");
        graphsManager.build();
        drop();
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) drop();
    }

    void onSensor(const physim::SensorEvent& event, bool began, double at) override {
        if (event.visitorBody != ball_->rb.bodyId()) return;
        for (std::size_t i = 0; i < gates_.size(); ++i)
            if (event.sensorBody == gates_[i]->rb.bodyId()) (began ? in_ : out_)[i] = at - releaseTime_;
        if (!began && event.sensorBody == gates_.back()->rb.bodyId()) passed_ = true;
    }

    void onDrawGraphs() override {
        if (!passed_) return;
        passed_ = false;
        report();
        drop();
    }

private:
    double gravity() const { return -world().settings().gravity.y(); }  // m/s^2
    double chord() const { return 2.0 * radius_ + kGateThickness; }     // m

    // The exact free fall from rest: the time to fall d.
    double fallTime(double d) const { return std::sqrt(2.0 * d / gravity()); }

    void drop() {
        ball_->setPosition({0.0, 0.0});
        ball_->setRotation(0.0);
        ball_->rb.setVelocity({0.0, 0.0});
        ball_->rb.setAngularVelocity(0.0);
        ball_->rb.wakeUp();
        releaseTime_ = time;
        in_.fill(-1.0);
        out_.fill(-1.0);
    }

    void report() {
        const double g = gravity(), half = 0.5 * chord();
        graphsManager.reset();
        for (double h = 0.2; h <= kDepths.back() + 0.05; h += 0.05) graphsManager.addPoint(root_, h, std::sqrt(2.0 * g * h));
        // sqrt(2 d) = sqrt(g) (t + t0) at every entry (d = h - L / 2) and exit (d = h + L / 2): least squares.
        double n = 0.0, st = 0.0, sy = 0.0, stt = 0.0, sty = 0.0;
        for (std::size_t i = 0; i < kDepths.size(); ++i) {
            if (in_[i] < 0.0 || out_[i] < 0.0) continue;  // a gate missed (none should be)
            const double h = kDepths[i];
            const double v = chord() / (out_[i] - in_[i]);
            const double predicted = chord() / (fallTime(h + half) - fallTime(h - half));
            graphsManager.addPoint(speed_, h, v);
            if (!measured_) setResult("v at " + number(h) + " m", v, predicted, "m/s");
            for (const auto& [t, d] : {std::pair{in_[i], h - half}, std::pair{out_[i], h + half}}) {
                const double y = std::sqrt(2.0 * d);
                n += 1.0;
                st += t;
                sy += y;
                stt += t * t;
                sty += t * y;
                graphsManager.addPoint(drop_, t, d);
            }
        }
        if (n >= 2.0) {
            const double slope = (n * sty - st * sy) / (n * stt - st * st);
            const double t0 = (sy - slope * st) / n / slope;
            const double fitted = slope * slope;
            for (double t = 0.0; t <= fallTime(kDepths.back() + half) + 0.02; t += 0.01)
                graphsManager.addPoint(fit_, t, 0.5 * fitted * (t + t0) * (t + t0));
            if (!measured_) setResult("g fitted", fitted, g, "m/s^2");
        }
        measured_ = true;
    }

    static std::string number(double x) {
        std::string s = std::to_string(x);
        while (s.size() > 1 && s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
        return s;
    }

    physim::Object* ball_ = nullptr;  // owned by the simulation
    std::vector<physim::Object*> gates_;
    std::array<double, kDepths.size()> in_{}, out_{};  // s since release; -1: not yet
    double radius_ = 0.0, releaseTime_ = 0.0;
    int speed_ = -1, root_ = -1, drop_ = -1, fit_ = -1;
    bool passed_ = false, measured_ = false;
};

}  // namespace

std::unique_ptr<Simulation> makePhotogate() { return std::make_unique<Photogate>(); }

}  // namespace physim::examples
