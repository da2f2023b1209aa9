// atwood: two blocks (m1 = 2 kg and m2 = 1 kg by default, parameters) hang from one rope over two fixed pulleys, a
// pulley joint (PulleyJointDef: lengthA + lengthB stays the rope's length). Released at rest, the heavier block
// falls and the lighter rises with a = (m1 - m2) g / (m1 + m2), the rope pulling each with T = 2 m1 m2 g /
// (m1 + m2) (Newton's second law for each block, one rope of one length). Graphs: the heavy block's acceleration
// (between frames) beside the formula, the rope's pull on the light block (World::jointReactionForce) beside T,
// and the blocks' heights. Results (summary.json): the mean acceleration since release and the tension, each beside
// its formula. When the light block nears its pulley the blocks are released again. Keys: N releases them again.

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/VertexArray.hpp>
#include <SFML/Window/Event.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace physim::examples {
namespace {

constexpr double kPulleyRadius = 0.25;  // m
constexpr double kPulleyX = 0.8;        // m, each pulley's centre at (+-kPulleyX, 0)
constexpr double kBlockSize = 0.4;      // m, a square block; the rope holds it at the middle of its top
constexpr double kHeavyStart = 1.0;     // m, the heavy block's side of the rope at release
constexpr double kLightStart = 8.0;     // m, the light block's
constexpr double kLightStop = 0.8;      // m: the light block is released again when its side is this short

class Atwood : public physim::Simulation {
public:
    Atwood() {
        parameters.add("m1", "mass of the left block (kg)", 2.0, 0.1, 20.0);
        parameters.add("m2", "mass of the right block (kg)", 1.0, 0.1, 20.0);
    }

    std::string title() const override {
        return "atwood: a pulley joint, a = (m1 - m2) g / (m1 + m2), T = 2 m1 m2 g / (m1 + m2)";
    }
    std::string keysHelp() const override { return "N: release again"; }

    // The pulleys and both blocks' whole travel.
    std::optional<Aabb> viewBounds() const override {
        return Aabb{{-kPulleyX - 1.5, -kLightStart - kBlockSize - 0.3}, {kPulleyX + 1.5, kPulleyRadius + 0.4}};
    }

    void onCreate() override {
        physim::WorldSettings settings = world().settings();
        settings.enableSleep = false;  // the blocks are at rest for an instant at release
        world().setSettings(settings);
        m1_ = parameters.get("m1");
        m2_ = parameters.get("m2");
        // The pulleys: static discs; the rope leaves each at its outer side, straight down to its block.
        for (const double x : {-kPulleyX, kPulleyX}) {
            auto& pulley = spawn<physim::Object>(physim::CircleShape(kPulleyRadius), sf::Color(120, 120, 120));
            pulley.setPosition({x, 0.0});
            pulley.rb.setMass(0.0);
        }
        heavy_ = &spawn<physim::Object>(physim::RectangleShape({kBlockSize, kBlockSize}), sf::Color(200, 80, 40));
        light_ = &spawn<physim::Object>(physim::RectangleShape({kBlockSize, kBlockSize}), sf::Color(40, 110, 200));
        heavy_->rb.setMass(m1_);
        light_->rb.setMass(m2_);
        place();
        physim::PulleyJointDef rope;
        rope.groundAnchorA = {-kPulleyX - kPulleyRadius, 0.0};
        rope.groundAnchorB = {kPulleyX + kPulleyRadius, 0.0};
        rope.localAnchorA = rope.localAnchorB = {0.0, 0.5 * kBlockSize};
        rope_ = heavy_->join(*light_, rope);
        release();

        acceleration_ = graphsManager.addGraph("Acceleration of the left block (down);t (s);a (m/s^{2})", "measured",
                                               {}, physim::GraphMode::WITH_LINES);
        predictedA_ = graphsManager.addSeries(acceleration_, "(m_{1} - m_{2}) g / (m_{1} + m_{2})");
        tension_ = graphsManager.addGraph("Rope tension;t (s);T (N)", "pull on the right block", {},
                                          physim::GraphMode::WITH_LINES);
        predictedT_ = graphsManager.addSeries(tension_, "2 m_{1} m_{2} g / (m_{1} + m_{2})");
        heights_ = graphsManager.addGraph("Heights;t (s);y (m)", "left block", {}, physim::GraphMode::WITH_LINES);
        lightHeight_ = graphsManager.addSeries(heights_, "right block");
        graphsManager.build();
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) restart();
    }

    void onDrawGraphs() override {
        const double t = time - releaseTime_;
        const double v = -heavy_->rb.velocity().y();  // m/s, down
        const double tension = world().jointReactionForce(rope_).norm();
        if (t > lastT_) {
            graphsManager.addPoint(acceleration_, t, (v - lastV_) / (t - lastT_));
            graphsManager.addPoint(predictedA_, t, predictedAcceleration());
            graphsManager.addPoint(tension_, t, tension);
            graphsManager.addPoint(predictedT_, t, predictedTension());
            graphsManager.addPoint(heights_, t, heavy_->getPosition().y());
            graphsManager.addPoint(lightHeight_, t, light_->getPosition().y());
            // The mean acceleration since release (v / t from rest) and the rope's pull now; the first pass only
            // (a relaunch measures the same again).
            if (!measured_) {
                setResult("acceleration", v / t, predictedAcceleration(), "m/s^2");
                setResult("tension", tension, predictedTension(), "N");
            }
            lastT_ = t;
            lastV_ = v;
        }
        // Near the top (or bottom, when m2 is the heavier) the blocks start again.
        const auto [lengthA, lengthB] = world().jointPulleyLengths(rope_);
        if (std::min(lengthA, lengthB) < kLightStop) {
            measured_ = true;
            restart();
        }
    }

    void onRender(sf::RenderWindow* window) override {
        // The rope: down from each pulley's outer side to its block, and over both pulleys' tops.
        const sf::Transform toPixels = view.worldToPixels(window->getSize());
        const sf::Color rope(60, 60, 60);
        constexpr int kArc = 12;  // segments over each pulley's outer quarter and top
        sf::VertexArray line(sf::LineStrip);
        const auto [a, b] = world().jointAnchors(rope_);
        line.append(sf::Vertex({float(a.x()), float(a.y())}, rope));
        for (int i = 0; i <= kArc; ++i) {  // left pulley: from its left side (pi) over the top (pi / 2)
            const double phi = M_PI - 0.5 * M_PI * i / kArc;
            line.append(sf::Vertex(
                {float(-kPulleyX + kPulleyRadius * std::cos(phi)), float(kPulleyRadius * std::sin(phi))}, rope));
        }
        for (int i = 0; i <= kArc; ++i) {  // right pulley: from its top to its right side (0)
            const double phi = 0.5 * M_PI - 0.5 * M_PI * i / kArc;
            line.append(sf::Vertex(
                {float(kPulleyX + kPulleyRadius * std::cos(phi)), float(kPulleyRadius * std::sin(phi))}, rope));
        }
        line.append(sf::Vertex({float(b.x()), float(b.y())}, rope));
        window->draw(line, toPixels);
    }

private:
    double gravity() const { return -world().settings().gravity.y(); }  // m/s^2
    double predictedAcceleration() const { return (m1_ - m2_) * gravity() / (m1_ + m2_); }  // m/s^2, m1 down
    double predictedTension() const { return 2.0 * m1_ * m2_ * gravity() / (m1_ + m2_); }    // N

    // Each block hangs straight below its pulley's outer side: the rope's sides kHeavyStart and kLightStart long.
    void place() {
        const double half = 0.5 * kBlockSize;
        heavy_->setPosition({-kPulleyX - kPulleyRadius, -kHeavyStart - half});
        light_->setPosition({kPulleyX + kPulleyRadius, -kLightStart - half});
        for (physim::Object* block : {heavy_, light_}) {
            block->setRotation(0.0);
            block->rb.setVelocity({0.0, 0.0});
            block->rb.setAngularVelocity(0.0);
            block->rb.wakeUp();
        }
    }

    void release() {
        releaseTime_ = time;
        lastT_ = 0.0;
        lastV_ = 0.0;
    }

    void restart() {
        graphsManager.reset();
        place();
        release();
    }

    physim::Object* heavy_ = nullptr;  // owned by the simulation
    physim::Object* light_ = nullptr;
    physim::JointId rope_;
    double m1_ = 0.0, m2_ = 0.0;  // kg
    int acceleration_ = -1, predictedA_ = -1, tension_ = -1, predictedT_ = -1, heights_ = -1, lightHeight_ = -1;
    double releaseTime_ = 0.0, lastT_ = 0.0, lastV_ = 0.0;
    bool measured_ = false;
};

}  // namespace

std::unique_ptr<Simulation> makeAtwood() { return std::make_unique<Atwood>(); }

}  // namespace physim::examples
