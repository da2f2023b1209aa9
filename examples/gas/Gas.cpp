// gas: 300 discs in a closed 20 m box, no gravity, perfectly elastic and frictionless. They all start at the
// same speed in random directions; collisions share the energy out until the speeds follow the 2D
// Maxwell-Boltzmann distribution f(v) = (v / s^2) exp(-v^2 / (2 s^2)), with s^2 = <v^2> / 2 fixed by the
// (conserved) kinetic energy. Graphs: the speed histogram against f(v) (N x bin width x f at each bin centre),
// and the total kinetic energy against its initial value. Keys: N gives every disc its initial speed again.
// Parameters: the number of discs, their initial speed. Results (summary.json): the kinetic energy, the mean
// speed and the distance of the speeds' distribution to Maxwell-Boltzmann's.

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Window/Event.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

namespace physim::examples {
namespace {

constexpr double kRadius = 0.2;   // m
constexpr double kHalfBox = 10.0; // m, inside half-width
constexpr int kPerRow = 20;       // discs start on a grid of 20 per row
constexpr int kBins = 20;         // histogram bins over [0, 3 v0)

class Gas : public physim::Simulation {
public:
    Gas() {
        parameters.add("discs", "number of discs", 300, 2, kPerRow * kPerRow, true);
        parameters.add("speed", "every disc's initial speed (m/s)", 5.0, 0.5, 20.0);
    }

    std::string title() const override { return "gas: discs relax to the Maxwell-Boltzmann distribution"; }
    std::string keysHelp() const override { return "N: all at the same speed again"; }

    void onCreate() override {
        physim::WorldSettings settings = world().settings();
        settings.gravity = physim::Vec2::Zero();
        settings.restitutionThreshold = 0.0;  // every collision elastic, however slow
        settings.enableSleep = false;         // a slow disc must not freeze
        world().setSettings(settings);
        setPhysicsRate(60.0);

        // Four static walls; their restitution 1 and no friction, like the discs'.
        const double t = 1.0;  // wall thickness, m
        const double len = 2 * kHalfBox + 2 * t;
        for (const auto& [size, pos] : {std::pair{physim::Vec2(len, t), physim::Vec2(0, -kHalfBox - t / 2)},
                                        std::pair{physim::Vec2(len, t), physim::Vec2(0, kHalfBox + t / 2)},
                                        std::pair{physim::Vec2(t, len), physim::Vec2(-kHalfBox - t / 2, 0)},
                                        std::pair{physim::Vec2(t, len), physim::Vec2(kHalfBox + t / 2, 0)}}) {
            auto& wall = spawn<physim::Object>(physim::Mesh::RectangleMesh(size, sf::Color(90, 90, 90)),
                                               physim::RectangleShape(size));
            makeElastic(wall);
            wall.rb.setMass(0.0);
            wall.setPosition(pos);
        }
        // Discs on a grid (no overlaps at the start).
        const double spacing = 2 * kHalfBox / kPerRow;
        for (int i = 0; i < parameters.getInt("discs"); ++i) {
            auto& disc = spawn<physim::Object>(physim::Mesh::CircleMesh(kRadius, sf::Color(60, 110, 200)),
                                               physim::CircleShape(kRadius));
            makeElastic(disc);
            disc.setPosition({-kHalfBox + spacing * (i % kPerRow + 0.5), -kHalfBox + spacing * (i / kPerRow + 0.5)});
            discs_.push_back(&disc);
        }
        randomizeDirections();

        histogram_ = graphsManager.addGraph("Speeds;speed (m/s);discs per bin");
        boltzmann_ = graphsManager.addSeries(histogram_, "Maxwell-Boltzmann");
        energy_ = graphsManager.addGraph("Kinetic energy;time (s);energy (J)", {}, physim::GraphMode::WITH_LINES);
        energy0_ = graphsManager.addSeries(energy_, "initial");
        graphsManager.build();
        initialEnergy_ = kineticEnergy();
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) randomizeDirections();
    }

    void onDrawGraphs() override {
        const double binWidth = 3 * parameters.get("speed") / kBins;
        std::vector<int> counts(kBins, 0);
        double sumV2 = 0.0;
        for (const physim::Object* d : discs_) {
            const double v = d->rb.velocity().norm();
            sumV2 += v * v;
            const int bin = static_cast<int>(v / binWidth);
            if (bin < kBins) ++counts[static_cast<std::size_t>(bin)];
        }
        const double n = static_cast<double>(discs_.size());
        const double s2 = sumV2 / n / 2.0;  // s^2 = <v^2> / 2 in two dimensions
        std::vector<std::pair<double, double>> measured, theory;
        for (int b = 0; b < kBins; ++b) {
            const double v = (b + 0.5) * binWidth;
            measured.emplace_back(v, counts[static_cast<std::size_t>(b)]);
            theory.emplace_back(v, n * binWidth * v / s2 * std::exp(-v * v / (2 * s2)));
        }
        graphsManager.setPoints(histogram_, measured);
        graphsManager.setPoints(boltzmann_, theory);
        graphsManager.addPoint(energy_, time, kineticEnergy());
        graphsManager.addPoint(energy0_, time, initialEnergy_);
        reportResults(s2);
    }

private:
    // The energy against its start; the mean speed against Maxwell-Boltzmann's s sqrt(pi / 2); and the
    // Kolmogorov-Smirnov distance between the speeds and F(v) = 1 - exp(-v^2 / (2 s^2)), which has no
    // predicted value (300 samples from the distribution itself would stay below 0.113 in 999 runs of 1000).
    void reportResults(double s2) {
        setResult("kinetic energy", kineticEnergy(), initialEnergy_, "J");
        std::vector<double> speeds;
        for (const physim::Object* d : discs_) speeds.push_back(d->rb.velocity().norm());
        std::sort(speeds.begin(), speeds.end());
        double sum = 0.0, distance = 0.0;
        const double n = static_cast<double>(speeds.size());
        for (std::size_t i = 0; i < speeds.size(); ++i) {
            sum += speeds[i];
            const double cdf = 1.0 - std::exp(-speeds[i] * speeds[i] / (2 * s2));
            distance = std::max({distance, std::abs(cdf - i / n), std::abs(cdf - (i + 1) / n)});
        }
        setResult("mean speed", sum / n, std::sqrt(M_PI / 2 * s2), "m/s");
        setResult("Kolmogorov-Smirnov distance to Maxwell-Boltzmann", distance, std::nullopt, "");
    }

    static void makeElastic(physim::Object& o) {
        o.rb.setRestitution(1.0);
        o.rb.setStaticFriction(0.0);
        o.rb.setDynamicFriction(0.0);
    }

    void randomizeDirections() {
        std::mt19937 rng(7);  // this simulation's own generator: every run starts the same
        std::uniform_real_distribution<double> angle(0.0, 2 * M_PI);
        for (physim::Object* d : discs_) {
            const double a = angle(rng);
            d->rb.setVelocity(parameters.get("speed") * physim::Vec2(std::cos(a), std::sin(a)));
        }
    }

    double kineticEnergy() const {
        double e = 0.0;
        for (const physim::Object* d : discs_) e += 0.5 * d->rb.mass() * d->rb.velocity().squaredNorm();
        return e;
    }

    std::vector<physim::Object*> discs_;  // owned by the simulation
    int histogram_ = -1, boltzmann_ = -1, energy_ = -1, energy0_ = -1;
    double initialEnergy_ = 0.0;
};

}  // namespace

std::unique_ptr<Simulation> makeGas() { return std::make_unique<Gas>(); }

}  // namespace physim::examples
