// double_pendulum: chaos made visible with a branch (Simulation::startBranch). Two 1 m links hang from a pivot on
// revolute joints, released at rest from a large angle (a parameter, 150 degrees by default). At release the
// simulation takes a snapshot and starts a branch from it whose lower link is turned 1e-9 rad more: the window draws
// the branch's links as blue ghosts, at first exactly over the first run's. Their distance (Simulation::
// branchDistance, m) grows as exp(lambda t), lambda the largest Lyapunov exponent, until it is as large as the
// pendulum; then the two futures have nothing in common. Graph: log10 of the distance against time, with the fitted
// line. Result
// (summary.json): lambda fitted by least squares to ln(distance) over the stretch where it grows from 100 times the
// first separation to 1 mm (no closed form: predicted null). Keys: N releases both again.

#include <SFML/Window/Event.hpp>
#include <cmath>
#include <optional>
#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <string>
#include <utility>
#include <vector>

#include "Scenes.hpp"

namespace physim::examples {
namespace {

constexpr double kLength = 1.0;  // m, each link
constexpr double kWidth = 0.06;  // m
constexpr double kNudge = 1e-9;  // rad: how much more the branch's lower link is turned at release
constexpr double kFitTo = 1e-3;  // m: the fit ends where the distance reaches this (well before it saturates)

class DoublePendulum : public physim::Simulation {
public:
    DoublePendulum() {
        parameters.add("angle", "release angle of both links from the vertical (degrees)", 150, 10, 179);
    }

    std::string title() const override { return "double_pendulum: two futures 1e-9 rad apart, chaos"; }
    std::string keysHelp() const override { return "N: release again"; }

    std::optional<Aabb> viewBounds() const override {
        const double r = 2.0 * kLength + 0.2;
        return Aabb{{-r, -r}, {r, r}};
    }

    void onCreate() override {
        physim::WorldSettings settings = world().settings();
        settings.enableSleep = false;  // at rest for an instant at release
        world().setSettings(settings);
        auto& pivot = spawn<physim::Object>(physim::CircleShape(0.04), sf::Color(60, 60, 60));
        pivot.rb.setMass(0.0);
        world().setCollides(pivot.rb.bodyId(), false);  // the lower link swings past it
        upper_ = &spawn<physim::Object>(physim::RectangleShape({kWidth, kLength}), sf::Color(200, 80, 40));
        lower_ = &spawn<physim::Object>(physim::RectangleShape({kWidth, kLength}), sf::Color(200, 140, 40));
        place();
        physim::RevoluteJointDef top, middle;
        top.anchor = {0.0, 0.0};
        pivot.join(*upper_, top);
        middle.anchor = elbow();
        upper_->join(*lower_, middle);

        distance_ = graphsManager.addGraph("Distance between the two futures;t (s);log_{10} distance (m)", "branch", {},
                                           physim::GraphMode::WITH_LINES);
        fit_ = graphsManager.addSeries(distance_, "fit: distance ~ exp(#lambda t)");
        graphsManager.build();
        release();
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) {
            graphsManager.reset();
            place();
            release();
        }
    }

    void onDrawGraphs() override {
        const double t = time - releaseTime_, d = branchDistance();
        if (t <= lastT_ || !(d > 0.0)) return;
        lastT_ = t;
        graphsManager.addPoint(distance_, t, std::log10(d));
        if (fitted_) return;
        if (d >= 100.0 * first_ && d <= kFitTo) samples_.push_back({t, std::log(d)});
        if (d > kFitTo && samples_.size() >= 10) {
            const auto [lambda, lnD0] = fit();
            setResult("lyapunov exponent", lambda, std::nullopt, "1/s");
            for (const double at : {samples_.front().t, samples_.back().t})
                graphsManager.addPoint(fit_, at, (lnD0 + lambda * at) / std::log(10.0));
            fitted_ = true;
        }
    }

    std::any saveState() const override { return State{releaseTime_, lastT_, first_, fitted_, samples_}; }
    void restoreState(const std::any& state) override {
        const State& s = std::any_cast<const State&>(state);
        releaseTime_ = s.releaseTime, lastT_ = s.lastT, first_ = s.first, fitted_ = s.fitted, samples_ = s.samples;
    }
    // The same members in a snapshot file (--snapshot-every, --from).
    void writeState(physim::StateWriter& out) const override {
        for (const double v : {releaseTime_, lastT_, first_}) out.putDouble(v);
        out.putBool(fitted_);
        std::vector<double> samples;
        for (const Sample& s : samples_) samples.insert(samples.end(), {s.t, s.lnD});
        out.putDoubles(samples);
    }
    void readState(physim::StateReader& in) override {
        releaseTime_ = in.getDouble(), lastT_ = in.getDouble(), first_ = in.getDouble();
        fitted_ = in.getBool();
        const std::vector<double> samples = in.getDoubles();
        samples_.clear();
        for (std::size_t i = 0; i + 1 < samples.size(); i += 2) samples_.push_back({samples[i], samples[i + 1]});
    }

private:
    struct Sample {
        double t, lnD;
    };
    struct State {
        double releaseTime, lastT, first;
        bool fitted;
        std::vector<Sample> samples;
    };

    double angle() const { return parameters.get("angle") * M_PI / 180.0; }
    // The elbow: the upper link's lower end, at release.
    Vec2 elbow() const { return kLength * Vec2(std::sin(angle()), -std::cos(angle())); }

    // Both links straight out at `angle` from the hanging position, at rest.
    void place() {
        const Vec2 u(std::sin(angle()), -std::cos(angle()));
        upper_->setPosition(0.5 * kLength * u);
        lower_->setPosition(elbow() + 0.5 * kLength * u);
        for (physim::Object* link : {upper_, lower_}) {
            link->setRotation(angle());
            link->rb.setVelocity({0.0, 0.0});
            link->rb.setAngularVelocity(0.0);
        }
    }

    // A snapshot now and a branch from it whose lower link is turned kNudge more about the elbow.
    void release() {
        releaseTime_ = time;
        lastT_ = 0.0;
        fitted_ = false;
        samples_.clear();
        const BodyId lower = lower_->rb.bodyId();
        startBranch(snapshot(), [&](World& branch) {
            const Vec2 pin = elbow(), arm = branch.position(lower) - pin;
            const double c = std::cos(kNudge), s = std::sin(kNudge);
            branch.setTransform(lower, pin + Vec2(c * arm.x() - s * arm.y(), s * arm.x() + c * arm.y()),
                                branch.angle(lower) + kNudge);
        });
        first_ = 0.5 * kLength * kNudge;  // the lower link's centre moved this far
    }

    // Least-squares line through ln(distance) against t: its slope (the exponent, 1/s) and its value at t = 0.
    std::pair<double, double> fit() const {
        double st = 0.0, sy = 0.0, stt = 0.0, sty = 0.0;
        for (const Sample& p : samples_) st += p.t, sy += p.lnD, stt += p.t * p.t, sty += p.t * p.lnD;
        const double n = static_cast<double>(samples_.size());
        const double slope = (n * sty - st * sy) / (n * stt - st * st);
        return {slope, (sy - slope * st) / n};
    }

    physim::Object* upper_ = nullptr;  // owned by the simulation
    physim::Object* lower_ = nullptr;
    int distance_ = -1, fit_ = -1;
    double releaseTime_ = 0.0, lastT_ = 0.0, first_ = 0.0;
    bool fitted_ = false;
    std::vector<Sample> samples_;
};

}  // namespace

std::unique_ptr<Simulation> makeDoublePendulum() { return std::make_unique<DoublePendulum>(); }

}  // namespace physim::examples
