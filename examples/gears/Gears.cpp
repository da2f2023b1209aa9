// gears: a gear train and a crank-slider piston.
// The train: three discs on revolute joints to a static frame, each pair meshed by a gear joint (GearJointDef:
// angle1 + ratio angle2 stays constant, the discs turning opposite ways as meshed teeth do; the discs' radii are in
// the same ratio, so their rims roll on each other). A motor turns the first disc. The measured ratio is
// -angle1 / angle2 since the start, against the set one: a gear joint holds its ratio exactly but for the solver's
// residual.
// The piston: a crank (radius r = 0.5 m, its own motor) on a revolute joint, a connecting rod (l = 1.5 m) pinned to
// the crank and to a piston that slides on a prismatic joint along the line through the crank's axle. Geometry
// alone puts the piston at x = r cos(theta) + sqrt(l^2 - r^2 sin^2(theta)) from the axle, theta the crank's angle,
// so its worst deviation from that formula is predicted 0: what is measured is how far the joints give.
// Graphs: the discs' and the crank's angles, the measured ratios beside the set ones, the piston's position beside
// the formula. Results (summary.json): both measured ratios and the piston's worst deviation. Parameters: the two
// ratios, the motors' speeds. Nothing here touches anything else: the bodies do not collide.

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Graphics/RenderWindow.hpp>
#include <SFML/Graphics/VertexArray.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

namespace physim::examples {
namespace {

constexpr double kFirstRadius = 0.5;        // m, the driven disc's
constexpr double kDiscDensity = 1.0;        // kg/m^2
constexpr double kMotorTorque = 200.0;      // N m, ample for either motor
constexpr double kCrankRadius = 0.5;        // m, r: axle to crank pin
constexpr double kRodLength = 1.5;          // m, l: crank pin to piston pin
const physim::Vec2 kCrankAxle{-1.2, -2.2};  // m

class Gears : public physim::Simulation {
public:
    Gears() {
        parameters.add("ratio12", "gear ratio of disc 1 to disc 2 (their radii's ratio r2 / r1)", 2.0, 0.25, 4.0);
        parameters.add("ratio23", "gear ratio of disc 2 to disc 3 (r3 / r2)", 0.5, 0.25, 4.0);
        parameters.add("speed", "motor speed of disc 1 (rad/s)", 2.0, -10.0, 10.0);
        parameters.add("crank", "motor speed of the crank (rad/s)", 3.0, -10.0, 10.0);
    }

    std::string title() const override {
        return "gears: a gear train (angle1 + ratio angle2 = const) and a crank-slider piston";
    }

    std::optional<Aabb> viewBounds() const override {
        const double right = std::max(discX_[2] + radius_[2], kCrankAxle.x() + kCrankRadius + kRodLength + 0.4);
        const double top = std::max({radius_[0], radius_[1], radius_[2]});
        return Aabb{{-kFirstRadius - 0.4, kCrankAxle.y() - kCrankRadius - 0.4}, {right + 0.3, top + 0.3}};
    }

    void onCreate() override {
        physim::WorldSettings settings = world().settings();
        settings.enableSleep = false;
        world().setSettings(settings);
        ratio_ = {parameters.get("ratio12"), parameters.get("ratio23")};
        radius_[0] = kFirstRadius;
        radius_[1] = radius_[0] * ratio_[0];
        radius_[2] = radius_[1] * ratio_[1];
        discX_[0] = 0.0;
        discX_[1] = discX_[0] + radius_[0] + radius_[1];
        discX_[2] = discX_[1] + radius_[1] + radius_[2];

        auto& frame = spawn<physim::Object>(physim::RectangleShape({0.1, 0.1}), sf::Color(90, 90, 90));
        frame.rb.setMass(0.0);
        const std::array<sf::Color, 3> colors{sf::Color(200, 80, 40), sf::Color(40, 110, 200), sf::Color(60, 160, 80)};
        for (int i = 0; i < 3; ++i) {
            disc_[i] = &spawn<physim::Object>(physim::CircleShape(radius_[i]), colors[i]);
            disc_[i]->setPosition({discX_[i], 0.0});
            disc_[i]->rb.setDensity(kDiscDensity);
            physim::RevoluteJointDef axle;
            axle.anchor = {discX_[i], 0.0};
            if (i == 0) {
                axle.enableMotor = true;
                axle.motorSpeed = parameters.get("speed");
                axle.maxMotorTorque = kMotorTorque;
            }
            axle_[i] = frame.join(*disc_[i], axle);
        }
        for (int i = 0; i < 2; ++i) {
            physim::GearJointDef gear;
            gear.joint1 = axle_[i];
            gear.joint2 = axle_[i + 1];
            gear.ratio = ratio_[i];
            world().createGearJoint(gear);
        }

        // The crank-slider, theta = 0 at the start: crank pin at (r, 0) from the axle, piston at r + l.
        crank_ = &spawn<physim::Object>(physim::CircleShape(kCrankRadius + 0.1), sf::Color(150, 150, 150));
        crank_->setPosition(kCrankAxle);
        rod_ = &spawn<physim::Object>(physim::RectangleShape({kRodLength, 0.08}), sf::Color(200, 160, 40));
        rod_->setPosition(kCrankAxle + physim::Vec2(kCrankRadius + 0.5 * kRodLength, 0.0));
        piston_ = &spawn<physim::Object>(physim::RectangleShape({0.4, 0.3}), sf::Color(40, 110, 200));
        piston_->setPosition(kCrankAxle + physim::Vec2(kCrankRadius + kRodLength, 0.0));
        for (physim::Object* o : {static_cast<physim::Object*>(&frame), crank_, rod_, piston_, disc_[0], disc_[1],
                                  disc_[2]})
            world().setCollides(o->rb.bodyId(), false);
        physim::RevoluteJointDef crankAxle;
        crankAxle.anchor = kCrankAxle;
        crankAxle.enableMotor = true;
        crankAxle.motorSpeed = parameters.get("crank");
        crankAxle.maxMotorTorque = kMotorTorque;
        frame.join(*crank_, crankAxle);
        physim::RevoluteJointDef crankPin;
        crankPin.anchor = kCrankAxle + physim::Vec2(kCrankRadius, 0.0);
        crank_->join(*rod_, crankPin);
        physim::RevoluteJointDef pistonPin;
        pistonPin.anchor = piston_->getPosition();
        rod_->join(*piston_, pistonPin);
        physim::PrismaticJointDef slide;
        slide.anchor = piston_->getPosition();
        slide.axis = {1.0, 0.0};
        frame.join(*piston_, slide);

        angles_ = graphsManager.addGraph("Angles;t (s);#theta (rad)", "disc 1", {}, physim::GraphMode::WITH_LINES);
        angle2_ = graphsManager.addSeries(angles_, "disc 2");
        angle3_ = graphsManager.addSeries(angles_, "disc 3");
        crankAngle_ = graphsManager.addSeries(angles_, "crank");
        ratios_ = graphsManager.addGraph("Gear ratios;t (s);-#Delta#theta_{i} / #Delta#theta_{i+1}", "1:2 measured",
                                         {}, physim::GraphMode::WITH_LINES);
        set12_ = graphsManager.addSeries(ratios_, "1:2 set");
        ratio23_ = graphsManager.addSeries(ratios_, "2:3 measured");
        set23_ = graphsManager.addSeries(ratios_, "2:3 set");
        pistonX_ = graphsManager.addGraph("Piston;t (s);x (m)", "measured", {}, physim::GraphMode::WITH_LINES);
        formula_ = graphsManager.addSeries(pistonX_, "r cos#theta + #sqrt{l^{2} - r^{2} sin^{2}#theta}");
        graphsManager.build();
    }

    void onDrawGraphs() override {
        std::array<double, 3> a{};
        for (int i = 0; i < 3; ++i) a[i] = world().jointAngle(axle_[i]);
        graphsManager.addPoint(angles_, time, a[0]);
        graphsManager.addPoint(angle2_, time, a[1]);
        graphsManager.addPoint(angle3_, time, a[2]);
        const double theta = crank_->getRotation();
        graphsManager.addPoint(crankAngle_, time, theta);
        // The ratios once the discs have turned enough for the quotient to mean something (0.1 rad).
        if (std::abs(a[1]) > 0.1 && std::abs(a[2]) > 0.1) {
            const double r12 = -a[0] / a[1], r23 = -a[1] / a[2];
            graphsManager.addPoint(ratios_, time, r12);
            graphsManager.addPoint(set12_, time, ratio_[0]);
            graphsManager.addPoint(ratio23_, time, r23);
            graphsManager.addPoint(set23_, time, ratio_[1]);
            setResult("gear ratio 1:2", r12, ratio_[0], "");
            setResult("gear ratio 2:3", r23, ratio_[1], "");
        }
        const double x = piston_->getPosition().x() - kCrankAxle.x();
        const double s = kCrankRadius * std::sin(theta);
        const double formula = kCrankRadius * std::cos(theta) + std::sqrt(kRodLength * kRodLength - s * s);
        graphsManager.addPoint(pistonX_, time, x);
        graphsManager.addPoint(formula_, time, formula);
        worst_ = std::max(worst_, std::abs(x - formula));
        setResult("piston's worst deviation from the crank-slider formula", worst_, 0.0, "m");
    }

    void onRender(sf::RenderWindow* window) override {
        // A spoke on each disc and on the crank (to its pin), so their turning shows.
        const sf::Transform toPixels = view.worldToPixels(window->getSize());
        sf::VertexArray spokes(sf::Lines);
        const sf::Color ink(30, 30, 30);
        auto spoke = [&](const physim::Object& o, double length) {
            const physim::Vec2 c = o.getPosition();
            const double t = o.getRotation();
            spokes.append(sf::Vertex({float(c.x()), float(c.y())}, ink));
            spokes.append(sf::Vertex({float(c.x() + length * std::cos(t)), float(c.y() + length * std::sin(t))}, ink));
        };
        for (int i = 0; i < 3; ++i) spoke(*disc_[i], radius_[i]);
        spoke(*crank_, kCrankRadius);
        window->draw(spokes, toPixels);
    }

private:
    std::array<physim::Object*, 3> disc_{};  // owned by the simulation
    physim::Object* crank_ = nullptr;
    physim::Object* rod_ = nullptr;
    physim::Object* piston_ = nullptr;
    std::array<physim::JointId, 3> axle_{};
    std::array<double, 2> ratio_{};
    std::array<double, 3> radius_{}, discX_{};  // m
    int angles_ = -1, angle2_ = -1, angle3_ = -1, crankAngle_ = -1, ratios_ = -1, set12_ = -1, ratio23_ = -1,
        set23_ = -1, pistonX_ = -1, formula_ = -1;
    double worst_ = 0.0;  // m
};

}  // namespace

std::unique_ptr<Simulation> makeGears() { return std::make_unique<Gears>(); }

}  // namespace physim::examples
