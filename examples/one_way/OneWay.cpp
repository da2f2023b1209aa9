// one_way: a one-way platform built with the pre-solve hook (World::setPreSolve). Boxes on the ground under a thin
// platform are thrown straight up, fast and slow in turn. The platform's contacts act only on what lies above it
// (the normal from the platform to the other shape points up) and has not sunk into it by more than 4 linear slops:
// a box rising from below passes through, and one that stops partly inside falls back. A box whose bottom climbs
// past the top, v^2 / (2 g) > h (h the top's height above the ground), lands on it and rests there. Graphs: the
// bottoms of a fast and a slow box beside the top's height. Results (summary.json): the boxes that passed up, rest
// on the top and fell back, each beside the count the energy rule gives, and the largest gap between a resting
// box's bottom and the top (within the linear slop). Keys: N throws them again.

#include "Scenes.hpp"

#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Window/Event.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace physim::examples {
namespace {

constexpr int kBoxes = 8;
constexpr double kBox = 0.5;          // m, a square box's side
constexpr double kTop = 2.1;          // m, the platform's top face above the ground
constexpr double kThickness = 0.2;    // m
constexpr double kWidth = 5.0;        // m
constexpr double kMeasureAfter = 3.5; // s after the throw: every box has landed and settled
constexpr double kRethrowAfter = 5.0; // s: the boxes are thrown again (a window keeps showing it)

class OneWay : public physim::Simulation {
public:
    OneWay() {
        parameters.add("fast", "launch speed of the odd boxes (m/s)", 7.0, 1.0, 12.0);
        parameters.add("slow", "launch speed of the even boxes (m/s)", 6.0, 1.0, 12.0);
    }

    std::string title() const override {
        return "one_way: a platform boxes pass up through and land on (a pre-solve hook)";
    }
    std::string keysHelp() const override { return "N: throw again"; }

    std::optional<Aabb> viewBounds() const override {
        const double apex = std::max(fast_, slow_) * std::max(fast_, slow_) / (2.0 * gravity()) + kBox;
        return Aabb{{-0.5 * kWidth - 1.0, -0.5}, {0.5 * kWidth + 1.0, std::max(kTop + 1.0, apex + 0.3)}};
    }

    void onCreate() override {
        fast_ = parameters.get("fast");
        slow_ = parameters.get("slow");
        auto& ground = spawn<physim::Object>(physim::RectangleShape({kWidth + 4.0, 1.0}), sf::Color(90, 90, 90));
        ground.setPosition({0.0, -0.5});
        ground.rb.setMass(0.0);
        auto& platform =
            spawn<physim::Object>(physim::RectangleShape({kWidth, kThickness}), sf::Color(200, 150, 40));
        platform.setPosition({0.0, kTop - 0.5 * kThickness});
        platform.rb.setMass(0.0);
        platform_ = platform.rb.shapeIds().front();
        for (int i = 0; i < kBoxes; ++i) {
            auto& box = spawn<physim::Object>(physim::RectangleShape({kBox, kBox}),
                                              fastBox(i) ? sf::Color(200, 70, 50) : sf::Color(50, 110, 200));
            boxes_.push_back(&box);
        }
        through_ = 4.0 * world().settings().linearSlop;
        world().setPreSolve([this](const physim::Manifold& m) { return oneWay(m); });
        throwBoxes();

        heights_ = graphsManager.addGraph("Bottoms of two boxes;t (s);y (m)", "fast box", {},
                                          physim::GraphMode::WITH_LINES);
        slowHeight_ = graphsManager.addSeries(heights_, "slow box");
        topLine_ = graphsManager.addSeries(heights_, "platform top");
        graphsManager.build();
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) rethrow();
    }

    void onDrawGraphs() override {
        const double t = time - throwTime_;
        for (int i = 0; i < kBoxes; ++i)
            if (bottom(i) > kTop) passed_[static_cast<std::size_t>(i)] = true;
        graphsManager.addPoint(heights_, t, bottom(1));
        graphsManager.addPoint(slowHeight_, t, bottom(0));
        graphsManager.addPoint(topLine_, t, kTop);
        if (!measured_ && t >= kMeasureAfter) {
            measure();
            measured_ = true;
        }
        if (t >= kRethrowAfter) rethrow();
    }

private:
    double gravity() const { return -world().settings().gravity.y(); }  // m/s^2
    static bool fastBox(int i) { return i % 2 == 1; }
    double speed(int i) const { return fastBox(i) ? fast_ : slow_; }
    double bottom(int i) const { return boxes_[static_cast<std::size_t>(i)]->getPosition().y() - 0.5 * kBox; }
    // The energy rule: the bottom, thrown up from the ground at v, climbs v^2 / (2 g).
    bool clears(int i) const { return speed(i) * speed(i) / (2.0 * gravity()) > kTop; }

    // The platform's contact acts only on a shape above it that has not sunk into it (the hook's whole rule).
    bool oneWay(const physim::Manifold& m) const {
        double up = 0.0;  // the normal from the platform to the other shape, its upward part
        if (m.shapeA == platform_) up = m.normal.y();  // the normal points from A to B
        else if (m.shapeB == platform_) up = -m.normal.y();
        else return true;
        if (up < 0.7) return false;  // below or beside: passing up through it
        double deepest = std::numeric_limits<double>::infinity();
        for (int p = 0; p < m.pointCount; ++p) deepest = std::min(deepest, m.points[p].separation);
        return deepest > -through_;  // sunk deeper: partly through, it passes on
    }

    void throwBoxes() {
        const double spacing = kWidth / kBoxes;
        for (int i = 0; i < kBoxes; ++i) {
            physim::Object& box = *boxes_[static_cast<std::size_t>(i)];
            box.setPosition({-0.5 * kWidth + spacing * (i + 0.5), 0.5 * kBox});
            box.setRotation(0.0);
            box.rb.setAngularVelocity(0.0);
            box.rb.setVelocity({0.0, speed(i)});
            box.rb.wakeUp();
        }
        passed_.assign(kBoxes, false);
        throwTime_ = time;
    }

    void rethrow() {
        graphsManager.reset();
        throwBoxes();
    }

    // The counts against the energy rule, and how close the resting boxes sit to the top.
    void measure() {
        const double slop = world().settings().linearSlop;
        int passed = 0, resting = 0, fellBack = 0, predictedUp = 0;
        double gap = 0.0;
        for (int i = 0; i < kBoxes; ++i) {
            const bool still = boxes_[static_cast<std::size_t>(i)]->rb.velocity().norm() < 0.05;
            if (passed_[static_cast<std::size_t>(i)]) ++passed;
            if (clears(i)) ++predictedUp;
            if (still && std::abs(bottom(i) - kTop) <= 2.0 * slop) {
                ++resting;
                gap = std::max(gap, std::abs(bottom(i) - kTop));
            } else if (still && std::abs(bottom(i)) <= 2.0 * slop) {
                ++fellBack;
            }
        }
        setResult("passed up", passed, predictedUp, "boxes");
        setResult("resting on top", resting, predictedUp, "boxes");
        setResult("fell back", fellBack, kBoxes - predictedUp, "boxes");
        setResult("resting gap to the top", gap, 0.0, "m");
    }

    physim::ShapeId platform_;
    std::vector<physim::Object*> boxes_;  // owned by the simulation
    std::vector<bool> passed_;            // per box: its bottom rose past the top since the throw
    double fast_ = 0.0, slow_ = 0.0;      // m/s
    double through_ = 0.0;                // m: deeper than this into the platform, a box passes on
    double throwTime_ = 0.0;
    bool measured_ = false;
    int heights_ = -1, slowHeight_ = -1, topLine_ = -1;
};

}  // namespace

std::unique_ptr<Simulation> makeOneWay() { return std::make_unique<OneWay>(); }

}  // namespace physim::examples
