// ramp: a disc (radius 0.2 m) released at rest on a curved ramp, a half-pipe of radius 3 m made of one chain of
// straight pieces (ChainShape: smooth where the pieces meet), `angle` degrees up its side (40 by default). A disc
// that rolls without slipping loses no energy, so when its centre has dropped h it has v = sqrt(4 g h / 3): a third
// of the energy turns it (I = m r^2 / 2), two thirds move it. It rolls without slipping while the friction needed,
// m g sin(theta) / 3, is within mu_s times the normal force, which on this concave track is at least m g cos(theta):
// mu_s >= tan(theta) / 3, 0.28 at 40 degrees and 0.58 at 60; the pair's mu_s (the two bodies' average) is 0.8.
// What the simulation loses is the step's: the contact holds its normal for a step while the track turns under the
// disc, about 1.7% of the energy by the far side at 40 Hz from 40 degrees, 4.1% from 60 degrees, and it shrinks
// with the step (1.1% at 120 Hz from 60 degrees). The joints themselves cost little with 320 pieces (the `pieces`
// parameter shows it: 160 loses a little more). Graphs: the centre's height, its speed beside the prediction
// sqrt(4 g (h0 - h) / 3) at the same height, and the total energy (gravity, motion, turning) beside the starting
// energy. Results (summary.json): the speed at the bottom on the first pass and the total energy when the disc
// stops on the far side (the end of the first pass), each beside its prediction. Keys: N releases the disc again.
// Parameters: the release angle, mu_s, the number of pieces.

#include "Scenes.hpp"

#include <physim/core/ChainShape.hpp>
#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Window/Event.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace physim::examples {
namespace {

constexpr double kPipeRadius = 3.0;    // m, the half-pipe's; its lowest point is the origin
constexpr double kDiscRadius = 0.2;    // m
constexpr double kDensity = 1.0;       // kg/m^2
constexpr double kArcDegrees = 80.0;   // the pipe rises to 80 degrees on each side

double radians(double degrees) { return degrees * M_PI / 180.0; }

class Ramp : public physim::Simulation {
public:
    Ramp() {
        parameters.add("angle", "release angle up the side (degrees)", 40.0, 10.0, 75.0);
        parameters.add("mu_s", "static friction coefficient of disc and ramp", 0.8, 0.0, 1.5);
        parameters.add("pieces", "straight pieces of the chain over the pipe's arc", 320.0, 20.0, 1000.0);
    }

    std::string title() const override { return "ramp: a disc rolling on a curved chain, v = sqrt(4 g h / 3)"; }
    std::string keysHelp() const override { return "N: release again"; }

    // The whole pipe.
    std::optional<Aabb> viewBounds() const override {
        const double half = kPipeRadius * std::sin(radians(kArcDegrees)) + 0.3;
        return Aabb{{-half, -0.3}, {half, kPipeRadius * (1.0 - std::cos(radians(kArcDegrees))) + 0.3}};
    }

    void onCreate() override {
        physim::WorldSettings settings = world().settings();
        settings.enableSleep = false;  // the disc is still for an instant only, at each end of its swing
        world().setSettings(settings);
        const double muStatic = parameters.get("mu_s");
        // The pipe's arc listed left to right: a chain is solid on its right, so this is ground with the disc on top.
        std::vector<physim::Vec2> arc;
        const int pieces = static_cast<int>(std::lround(parameters.get("pieces")));
        for (int i = 0; i <= pieces; ++i) {
            const double phi = radians(-kArcDegrees + 2.0 * kArcDegrees * i / pieces);
            arc.push_back({kPipeRadius * std::sin(phi), kPipeRadius * (1.0 - std::cos(phi))});
        }
        auto& ramp = spawn<physim::Object>(physim::ChainShape(arc), sf::Color(90, 90, 90));
        ramp.rb.setStaticFriction(muStatic);
        disc_ = &spawn<physim::Object>(physim::CircleShape(kDiscRadius), sf::Color(200, 80, 40));
        disc_->rb.setDensity(kDensity);
        disc_->rb.setStaticFriction(muStatic);
        release();

        height_ = graphsManager.addGraph("Height of the centre;t (s);h (m)", "disc",
                                         {}, physim::GraphMode::WITH_LINES);
        speed_ = graphsManager.addGraph("Speed;t (s);v (m/s)", "disc", {}, physim::GraphMode::WITH_LINES);
        predicted_ = graphsManager.addSeries(speed_, "rolling: sqrt(4 g (h_{0} - h) / 3)");
        energy_ = graphsManager.addGraph("Total energy;t (s);E (J)", "gravity + motion + turning", {},
                                         physim::GraphMode::WITH_LINES);
        start_ = graphsManager.addSeries(energy_, "at release");
        graphsManager.build();
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) {
            graphsManager.reset();
            release();
        }
    }

    void onDrawGraphs() override {
        const double t = time - releaseTime_;
        const double h = centreHeight();
        const double v = disc_->rb.velocity().norm();
        const double e = energy();
        graphsManager.addPoint(height_, t, h);
        graphsManager.addPoint(speed_, t, v);
        graphsManager.addPoint(predicted_, t, rollingSpeed(h));
        graphsManager.addPoint(energy_, t, e);
        graphsManager.addPoint(start_, t, startEnergy_);

        // The first pass: the crossing of the bottom (x = 0, interpolated within the frame), then the stop on the
        // far side (the velocity along x turns).
        const double x = disc_->rb.centerOfMass().x(), vx = disc_->rb.velocity().x();
        if (!crossed_ && (x > 0.0) != (lastX_ > 0.0)) {
            crossed_ = true;
            const double f = lastX_ / (lastX_ - x);  // fraction of the frame before the crossing
            const double atBottom = lastV_ + f * (v - lastV_);
            setResult("speed at the bottom, first pass", atBottom, rollingSpeed(0.0), "m/s");
        } else if (crossed_ && !stopped_ && vx * lastVx_ < 0.0) {
            stopped_ = true;
            setResult("total energy after the first pass", e, startEnergy_, "J");
        }
        lastX_ = x;
        lastV_ = v;
        lastVx_ = vx;
    }

private:
    double gravity() const { return -world().settings().gravity.y(); }  // m/s^2
    // The centre's height above its lowest possible place (the disc at the bottom of the pipe), m.
    double centreHeight() const { return disc_->rb.centerOfMass().y() - kDiscRadius; }
    // sqrt(4 g (h0 - h) / 3), m/s: a disc rolling without slipping from rest at h0.
    double rollingSpeed(double h) const { return std::sqrt(std::max(0.0, 4.0 * gravity() * (h0_ - h) / 3.0)); }
    // J: gravity's potential (zero at the bottom), the motion's and the turning's kinetic energy.
    double energy() const {
        const double m = disc_->rb.mass(), w = disc_->rb.angularVelocity();
        return m * gravity() * centreHeight() + 0.5 * m * disc_->rb.velocity().squaredNorm() +
               0.5 * disc_->rb.inertia() * w * w;
    }

    // At rest, touching the pipe `angle` degrees up its left side: the centre on the circle of radius R - r.
    void release() {
        const double a = radians(parameters.get("angle"));
        const double reach = kPipeRadius - kDiscRadius;
        disc_->setPosition({-reach * std::sin(a), kPipeRadius - reach * std::cos(a)});
        disc_->setRotation(0.0);
        disc_->rb.setVelocity({0.0, 0.0});
        disc_->rb.setAngularVelocity(0.0);
        disc_->rb.wakeUp();
        h0_ = centreHeight();
        startEnergy_ = energy();
        lastX_ = disc_->rb.centerOfMass().x();
        lastV_ = 0.0;
        lastVx_ = 0.0;
        crossed_ = stopped_ = false;
        releaseTime_ = time;
    }

    physim::Object* disc_ = nullptr;  // owned by the simulation
    int height_ = -1, speed_ = -1, predicted_ = -1, energy_ = -1, start_ = -1;  // graph indices
    double h0_ = 0.0, startEnergy_ = 0.0, releaseTime_ = 0.0;
    double lastX_ = 0.0, lastV_ = 0.0, lastVx_ = 0.0;
    bool crossed_ = false, stopped_ = false;
};

}  // namespace

std::unique_ptr<Simulation> makeRamp() { return std::make_unique<Ramp>(); }

}  // namespace physim::examples
