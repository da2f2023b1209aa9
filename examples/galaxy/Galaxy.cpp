// galaxy: 3000 stars and a heavy core pulling on each other (Newtonian gravitation with softening), summed with a
// Barnes-Hut quadtree: O(n log n) per evaluation instead of the 4.5 million pairs of a direct sum. The stars start
// on circular orbits about the core and the disc inside them; differential rotation winds the disc and its own
// pull clumps it. The stars touch nothing (BodyDef::collides false), so no contact stage ever runs. The overlay
// shows what the gravitation costs per step. Graphs: the step's cost (gravitation and the whole step) and the
// total energy against its start value. Scaled units: G = 1 N m^2/kg^2. Keys: T switches between the tree and the
// direct sum, to compare their cost.

#include "Scenes.hpp"

#include <physim/framework/Runner.hpp>

#include <SFML/Graphics/Font.hpp>
#include <SFML/Graphics/RectangleShape.hpp>
#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/Text.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <SFML/Window/Event.hpp>

#include <cmath>
#include <cstdio>
#include <optional>
#include <random>
#include <vector>

namespace physim::examples {
namespace {

constexpr int kStars = 3000;
constexpr double kCoreMass = 2000.0;  // kg
constexpr double kStarMass = 0.2;     // kg each: the disc weighs 600 kg
constexpr double kRadius = 12.0;      // m, the disc's edge
constexpr double kInner = 1.5;        // m, no stars closer to the core
constexpr double kSoftening = 0.15;   // m
constexpr double kG = 1.0;            // N m^2 / kg^2, this scene's scaled constant

class Galaxy : public physim::Simulation {
public:
    std::string title() const override { return "galaxy: 3000 stars, Barnes-Hut gravitation"; }
    std::string keysHelp() const override { return "T: tree / direct sum"; }

    void onCreate() override {
        setPhysicsRate(60.0);
        physim::WorldSettings settings = world().settings();
        settings.gravity = physim::Vec2::Zero();
        settings.substeps = 4;  // nothing touches: the substeps only refine the orbits (the innermost: 60 per turn)
        world().setSettings(settings);
        gravitation_.G = kG;
        gravitation_.softening = kSoftening;
        world().setGravitation(gravitation_);

        physim::BodyDef core;
        core.shape = physim::makeCircle(0.3);
        core.density = kCoreMass / (M_PI * 0.3 * 0.3);
        core.collides = false;
        core.attracting = true;
        stars_.push_back(world().createBody(core));
        // Stars uniform in area between kInner and kRadius, each on the circular orbit the mass inside it allows
        // (the core and the stars closer in, as if the disc were rings).
        std::mt19937 rng(2024);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (int i = 0; i < kStars; ++i) {
            const double r = std::sqrt(kInner * kInner + u(rng) * (kRadius * kRadius - kInner * kInner));
            const double a = 2 * M_PI * u(rng);
            const double inside = kCoreMass + kStars * kStarMass * (r * r - kInner * kInner) /
                                                  (kRadius * kRadius - kInner * kInner);
            const double v = std::sqrt(kG * inside / r);
            physim::BodyDef star;
            star.shape = physim::makeCircle(0.03);
            star.density = kStarMass / (M_PI * 0.03 * 0.03);
            star.collides = false;
            star.attracting = true;
            star.position = {r * std::cos(a), r * std::sin(a)};
            star.velocity = {-v * std::sin(a), v * std::cos(a)};
            stars_.push_back(world().createBody(star));
        }
        view.pixelsPerMetre = 26.0;
        font_.emplace();
        if (!font_->loadFromFile("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf")) font_.reset();

        cost_ = graphsManager.addGraph("Cost of a step;time (s);ms per step", "gravitation", {},
                                       physim::GraphMode::WITH_LINES);
        stepCost_ = graphsManager.addSeries(cost_, "whole step");
        energy_ = graphsManager.addGraph("Energy against its start value;time (s);E / E(0)", "simulated", {},
                                         physim::GraphMode::WITH_LINES);
        energyStart_ = graphsManager.addSeries(energy_, "start value");
        graphsManager.build();
        e0_ = energy();
    }

    void onEvent(sf::Event event) override {
        if (event.type != sf::Event::KeyPressed || event.key.code != sf::Keyboard::T) return;
        gravitation_.directBelow = gravitation_.directBelow > kStars ? physim::GravitationSettings{}.directBelow
                                                                      : 2 * kStars;
        world().setGravitation(gravitation_);
    }

    // Every frame: the last step's cost (averaged over the last half second for the overlay). Four times a
    // second: the energy (a direct O(n^2) sum, so not every frame).
    void onDrawGraphs() override {
        const physim::StepProfile& p = world().profile();
        const double gravitation = 1e3 * p.secondsOf(physim::Effect::Gravitation), step = 1e3 * p.total();
        graphsManager.addPoint(cost_, time, gravitation);
        graphsManager.addPoint(stepCost_, time, step);
        average_ = average_ == 0.0 ? gravitation : 0.97 * average_ + 0.03 * gravitation;
        averageStep_ = averageStep_ == 0.0 ? step : 0.97 * averageStep_ + 0.03 * step;
        if (time >= nextEnergy_) {
            graphsManager.addPoint(energy_, time, energy() / e0_);
            graphsManager.addPoint(energyStart_, time, 1.0);
            nextEnergy_ = time + 0.25;
        }
    }

    void onRender(sf::RenderWindow* window) override {
        window->clear(sf::Color(10, 10, 25));
        const sf::Transform toPixels = view.worldToPixels(window->getSize());
        sf::VertexArray dots(sf::Quads, 4 * stars_.size());
        const float s = 0.04f;  // m, half a dot
        for (std::size_t i = 0; i < stars_.size(); ++i) {
            const physim::Vec2 p = world().position(stars_[i]);
            const float x = float(p.x()), y = float(p.y()), k = i == 0 ? 4.f : 1.f;
            const sf::Color c = i == 0 ? sf::Color(255, 230, 150) : sf::Color(200, 210, 255);
            dots[4 * i] = sf::Vertex({x - k * s, y - k * s}, c);
            dots[4 * i + 1] = sf::Vertex({x + k * s, y - k * s}, c);
            dots[4 * i + 2] = sf::Vertex({x + k * s, y + k * s}, c);
            dots[4 * i + 3] = sf::Vertex({x - k * s, y + k * s}, c);
        }
        window->draw(dots, toPixels);
        if (!font_) return;
        const bool tree = stars_.size() >= gravitation_.directBelow;
        char line[200];
        std::snprintf(line, sizeof line, "%zu bodies, %s: gravitation %.1f ms of a %.1f ms step (%d substeps)",
                      stars_.size(), tree ? "Barnes-Hut tree, theta 0.5" : "direct sum", average_, averageStep_,
                      world().settings().substeps);
        sf::Text text(line, *font_, 15);
        text.setFillColor(sf::Color(30, 30, 30));
        const float y = static_cast<float>(window->getSize().y) - 30.f;
        text.setPosition(10.f, y);
        sf::RectangleShape backing({text.getLocalBounds().width + 16.f, 26.f});
        backing.setFillColor(sf::Color(255, 255, 255, 200));
        backing.setPosition(2.f, y - 2.f);
        window->draw(backing);
        window->draw(text);
    }

private:
    // Kinetic energy plus the softened pairs' -G mA mB / sqrt(r^2 + eps^2), the potential of the force the world
    // applies, J.
    double energy() const {
        const std::size_t n = stars_.size();
        std::vector<physim::Vec2> p(n);
        std::vector<double> m(n);
        double e = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            p[i] = world().position(stars_[i]);
            m[i] = world().mass(stars_[i]);
            e += 0.5 * m[i] * world().velocity(stars_[i]).squaredNorm();
        }
        const double eps2 = kSoftening * kSoftening;
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = i + 1; j < n; ++j) e -= kG * m[i] * m[j] / std::sqrt((p[i] - p[j]).squaredNorm() + eps2);
        return e;
    }

    std::vector<physim::BodyId> stars_;  // the core first
    physim::GravitationSettings gravitation_;
    std::optional<sf::Font> font_;       // none when the font file is missing: no cost line then
    double average_ = 0.0, averageStep_ = 0.0;  // ms
    double e0_ = 0.0, nextEnergy_ = 0.0;
    int cost_ = -1, stepCost_ = -1, energy_ = -1, energyStart_ = -1;
};

}  // namespace

std::unique_ptr<Simulation> makeGalaxy() { return std::make_unique<Galaxy>(); }

}  // namespace physim::examples
