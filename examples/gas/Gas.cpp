// gas: 300 discs in a closed 20 m box, no gravity, perfectly elastic and frictionless. They all start at the
// same speed in random directions; collisions share the energy out until the speeds follow the 2D
// Maxwell-Boltzmann distribution f(v) = (v / s^2) exp(-v^2 / (2 s^2)), with s^2 = <v^2> / 2 fixed by the
// (conserved) kinetic energy. Graphs: the speed histogram against f(v) (N x bin width x f at each bin centre),
// and the total kinetic energy against its initial value. Keys: N gives every disc its initial speed again.

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <SFML/Window/Event.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace {

constexpr int kDiscs = 300;
constexpr double kRadius = 0.2;   // m
constexpr double kSpeed = 5.0;    // m/s, every disc's initial speed
constexpr double kHalfBox = 10.0; // m, inside half-width
constexpr int kBins = 20;         // histogram bins over [0, 3 kSpeed)

class Gas : public physim::Simulation {
public:
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
        const int perRow = 20;
        const double spacing = 2 * kHalfBox / perRow;
        for (int i = 0; i < kDiscs; ++i) {
            auto& disc = spawn<physim::Object>(physim::Mesh::CircleMesh(kRadius, sf::Color(60, 110, 200)),
                                               physim::CircleShape(kRadius));
            makeElastic(disc);
            disc.setPosition({-kHalfBox + spacing * (i % perRow + 0.5), -kHalfBox + spacing * (i / perRow + 0.5)});
            discs_.push_back(&disc);
        }
        randomizeDirections();
        view.pixelsPerMetre = 30.0;

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
        const double binWidth = 3 * kSpeed / kBins;
        std::vector<int> counts(kBins, 0);
        double sumV2 = 0.0;
        for (const physim::Object* d : discs_) {
            const double v = d->rb.velocity().norm();
            sumV2 += v * v;
            const int bin = static_cast<int>(v / binWidth);
            if (bin < kBins) ++counts[static_cast<std::size_t>(bin)];
        }
        const double s2 = sumV2 / kDiscs / 2.0;  // s^2 = <v^2> / 2 in two dimensions
        std::vector<std::pair<double, double>> measured, theory;
        for (int b = 0; b < kBins; ++b) {
            const double v = (b + 0.5) * binWidth;
            measured.emplace_back(v, counts[static_cast<std::size_t>(b)]);
            theory.emplace_back(v, kDiscs * binWidth * v / s2 * std::exp(-v * v / (2 * s2)));
        }
        graphsManager.setPoints(histogram_, measured);
        graphsManager.setPoints(boltzmann_, theory);
        graphsManager.addPoint(energy_, time, kineticEnergy());
        graphsManager.addPoint(energy0_, time, initialEnergy_);
    }

private:
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
            d->rb.setVelocity({kSpeed * std::cos(a), kSpeed * std::sin(a)});
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

int main(int argc, char** argv) { return physim::runMain<Gas>(argc, argv); }
