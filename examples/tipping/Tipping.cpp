// tipping: twenty cups, each one body of three shapes (Object::addShape): a heavy base 0.6 m x 0.1 m and two light
// walls 0.08 m x 0.8 m, a compound body whose centre of mass (drawn as a marker, with a plumb line) lies on its
// axis, low because the base is denser. Each cup is released at rest balanced on the right edge of its base, tilted
// by 22.5 to 70 degrees. A cup tips over when its centre of mass has passed beyond that edge, at the tilt
// theta_c = atan(d / h), d the centre's distance from the edge across the cup (half the base, 0.3 m) and h its
// height above the base's underside; below that tilt gravity turns it back onto its base. Graph: each cup's final
// angle against its starting tilt, beside theta_c. Result (summary.json): the tipping angle measured as the midway
// point between the largest tilt that fell back and the smallest that tipped (within 1.25 degrees of the truth by
// construction), beside atan(d / h). Keys: N releases the cups again. Parameter: the base's density.

#include "Scenes.hpp"

#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Graphics/CircleShape.hpp>
#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <SFML/Window/Event.hpp>

#include <algorithm>
#include <array>
#include <memory>
#include <cmath>
#include <optional>
#include <string>

namespace physim::examples {
namespace {

constexpr int kCups = 20;
constexpr int kPerRow = 10;
constexpr double kFirstTilt = 22.5, kTiltStep = 2.5;  // degrees
constexpr double kBaseWidth = 0.6, kBaseHeight = 0.1;  // m
constexpr double kWallWidth = 0.08, kWallHeight = 0.8;  // m
constexpr double kWallDensity = 1.0;                    // kg/m^2
constexpr double kSpacing = 1.8;                        // m between the cups' pivots in a row
constexpr double kRowGap = 2.2;                         // m between the rows' floors
constexpr double kFloorThickness = 0.2;                 // m

double radians(double degrees) { return degrees * M_PI / 180.0; }
double degrees(double radians) { return radians * 180.0 / M_PI; }

class Tipping : public physim::Simulation {
public:
    Tipping() { parameters.add("base_density", "density of each cup's base (kg/m^2)", 2.0, 1.0, 4.0); }

    std::string title() const override { return "tipping: cups tip over once the centre of mass passes the edge"; }
    std::string keysHelp() const override { return "N: release again"; }

    std::optional<Aabb> viewBounds() const override {
        return Aabb{{-1.0, -kRowGap - 0.3}, {(kPerRow - 1) * kSpacing + 1.2, 1.2}};
    }

    void onCreate() override {
        for (int row = 0; row < 2; ++row) {
            auto& floor = spawn<physim::Object>(physim::Vec2(kPerRow * kSpacing + 1.5, kFloorThickness));
            floor.rb.setMass(0.0);
            floor.setPosition({0.5 * (kPerRow - 1) * kSpacing, floorTop(row) - 0.5 * kFloorThickness});
        }
        const physim::Material wall{kWallDensity, 0.0, 0.8, 0.6};
        for (int i = 0; i < kCups; ++i) {
            Cup& cup = cups_[static_cast<std::size_t>(i)];
            cup.tilt = kFirstTilt + kTiltStep * i;
            cup.pivot = {(i % kPerRow) * kSpacing, floorTop(i / kPerRow)};
            // The base is the body's first shape, its centre the body origin; the walls stand on it. The cup is
            // put together before it joins the simulation, so its mass comes from the three shapes' own densities.
            auto made = std::make_unique<physim::Object>(physim::RectangleShape({kBaseWidth, kBaseHeight}),
                                                         sf::Color(60, 90, 160));
            physim::Object& body = *made;
            body.rb.setDensity(parameters.get("base_density"));
            body.rb.setStaticFriction(0.8);
            body.rb.setDynamicFriction(0.6);
            const double wallX = 0.5 * (kBaseWidth - kWallWidth), wallY = 0.5 * (kBaseHeight + kWallHeight);
            for (double side : {-1.0, 1.0})
                body.addShape(physim::RectangleShape({kWallWidth, kWallHeight}), wall, {side * wallX, wallY}, 0.0,
                              physim::Mesh::RectangleMesh({kWallWidth, kWallHeight}, sf::Color(150, 190, 230)));
            cup.body = &addEntity(std::move(made));
        }
        release();
        outcome_ = graphsManager.addGraph("Final angle against starting tilt;tilt (degrees);final turn (degrees)",
                                          "cups");
        critical_ = graphsManager.addSeries(outcome_, "tipping angle atan(d / h)");
        graphsManager.build();
        drawCritical();
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) {
            graphsManager.reset();
            drawCritical();
            release();
        }
    }

    // A cup has tipped once turned past 80 degrees clockwise (it lies on its side), and fell back once upright
    // and nearly still, at least 0.5 s after release. The result comes once every cup is known, or at 8 s from
    // those known then (a cup within a hair of the tipping angle balances for long).
    void onDrawGraphs() override {
        const double t = time - releaseTime_;
        bool all = true;
        for (Cup& cup : cups_) {
            if (!cup.outcome) {
                const double turn = -degrees(cup.body->getRotation());
                if (turn > 80.0) cup.outcome = true;
                else if (t > 0.5 && std::abs(turn) < 1.0 && std::abs(cup.body->rb.angularVelocity()) < 0.05)
                    cup.outcome = false;
                if (cup.outcome) graphsManager.addPoint(outcome_, cup.tilt, *cup.outcome ? 90.0 : 0.0);
            }
            all = all && cup.outcome.has_value();
        }
        if ((!all && t < 8.0) || reported_) return;
        reported_ = true;
        double fellBack = -1.0, tipped = 1e9;  // degrees: the bracket around the tipping angle
        for (const Cup& cup : cups_) {
            if (!cup.outcome) continue;
            if (*cup.outcome) tipped = std::min(tipped, cup.tilt);
            else fellBack = std::max(fellBack, cup.tilt);
        }
        if (fellBack >= 0.0 && tipped < 1e9 && fellBack < tipped)
            setResult("tipping angle", 0.5 * (fellBack + tipped), criticalAngle(), "degrees");
    }

    // Each cup's centre of mass: a marker and a plumb line to the floor, so one sees it pass over the edge.
    void onRender(sf::RenderWindow* window) override {
        const sf::Transform toPixels = view.worldToPixels(window->getSize());
        const float r = 0.045f;
        sf::CircleShape marker(r, 24);
        marker.setOrigin(r, r);
        marker.setFillColor(sf::Color(250, 210, 40));
        marker.setOutlineColor(sf::Color(20, 20, 20));
        marker.setOutlineThickness(-0.012f);
        sf::VertexArray lines(sf::Lines);
        for (std::size_t i = 0; i < cups_.size(); ++i) {
            const physim::Vec2 c = cups_[i].body->getCenterOfMass();
            const sf::Vector2f p(static_cast<float>(c.x()), static_cast<float>(c.y()));
            lines.append(sf::Vertex(p, sf::Color(200, 40, 40)));
            lines.append(sf::Vertex({p.x, static_cast<float>(floorTop(static_cast<int>(i) / kPerRow))},
                                    sf::Color(200, 40, 40)));
            marker.setPosition(p);
            window->draw(marker, toPixels);
        }
        window->draw(lines, toPixels);
    }

private:
    struct Cup {
        double tilt = 0.0;  // degrees, clockwise, at release
        physim::Vec2 pivot;  // m, where the base's right edge touches the floor
        physim::Object* body = nullptr;  // owned by the simulation
        std::optional<bool> outcome;     // tipped (true) or fell back (false), once known
    };

    static double floorTop(int row) { return -row * kRowGap; }

    // atan(d / h) in degrees, from the parts' masses and centres (base centre at the origin).
    double criticalAngle() const {
        const double base = parameters.get("base_density") * kBaseWidth * kBaseHeight;
        const double walls = 2.0 * kWallDensity * kWallWidth * kWallHeight;
        const double centreY = walls * 0.5 * (kBaseHeight + kWallHeight) / (base + walls);
        return degrees(std::atan(0.5 * kBaseWidth / (centreY + 0.5 * kBaseHeight)));
    }

    void drawCritical() {
        graphsManager.addPoint(critical_, criticalAngle(), 0.0);
        graphsManager.addPoint(critical_, criticalAngle(), 90.0);
    }

    // Each cup turned clockwise by its tilt about the right edge of its base, that edge on the floor, at rest.
    void release() {
        for (Cup& cup : cups_) {
            const double a = -radians(cup.tilt);
            const physim::Vec2 fromEdge(-0.5 * kBaseWidth, 0.5 * kBaseHeight);  // base centre from the edge, upright
            const physim::Vec2 turned(std::cos(a) * fromEdge.x() - std::sin(a) * fromEdge.y(),
                                      std::sin(a) * fromEdge.x() + std::cos(a) * fromEdge.y());
            cup.body->setPosition(cup.pivot + turned);
            cup.body->setRotation(a);
            cup.body->rb.setVelocity({0.0, 0.0});
            cup.body->rb.setAngularVelocity(0.0);
            cup.body->rb.wakeUp();
            cup.outcome.reset();
        }
        reported_ = false;
        releaseTime_ = time;
    }

    std::array<Cup, kCups> cups_{};
    int outcome_ = -1, critical_ = -1;  // graph indices
    double releaseTime_ = 0.0;          // s
    bool reported_ = false;
};

}  // namespace

std::unique_ptr<Simulation> makeTipping() { return std::make_unique<Tipping>(); }

}  // namespace physim::examples
