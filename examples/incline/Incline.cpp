// incline: seven blocks on seven static inclines at 10 to 45 degrees, each pair with mu_s = 0.6 and
// mu_d = 0.4 (the pair averages its two bodies' coefficients, so these are the pair's too). Coulomb's law says
// a block sticks while tan(theta) <= mu_s (below the angle of repose, atan 0.6 = 31 degrees) and otherwise
// slides with a(theta) = g (sin theta - mu_d cos theta). Each block's acceleration along its slope is measured
// from its velocity at 0.25 s and 1.25 s after release (once the contact is established) and plotted against
// the angle, over that analytic curve. 30 degrees is left out: within 4% of the static limit, the block's
// first contact substep (no normal impulse built up yet) lets it slip, and as tan 30 > mu_d it then keeps
// sliding, which is Coulomb's hysteresis rather than the sticking the curve shows. The slopes stand in two
// rows, and a stop at each slope's foot catches its block. Keys: N puts the blocks back at the top and
// measures again. Parameters: the two friction coefficients. Results (summary.json): each block's measured
// acceleration beside Coulomb's. A second graph (Simulation::addEnergyPlot) shows where the energy went.

#include "Scenes.hpp"

#include <physim/core/RectangleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Window/Event.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <string>

namespace physim::examples {
namespace {

constexpr int kCount = 7;
constexpr std::array<double, kCount> kAnglesDeg{10.0, 15.0, 20.0, 25.0, 35.0, 40.0, 45.0};
constexpr int kPerRow = 4;              // the four gentle slopes above, the three steep ones below
constexpr double kHalfLength = 5.5;     // m, half the incline's length along the slope
constexpr double kThickness = 1.0;      // m, of the incline slab
constexpr double kBlock = 1.0;          // m, block side
constexpr double kStop = 0.4;           // m, thickness of the stop at the slope's foot (1.2 m tall)
constexpr double kStartUpSlope = 4.5;   // m up the slope from the incline's centre: 9 m to slide
constexpr double kSpacing = 10.0;       // m between incline centres in a row (they never overlap)
constexpr double kRowGap = 9.0;         // m between the rows' centres
constexpr double kMeasureFrom = 0.25, kMeasureTo = 1.25;  // s after release

double radians(double degrees) { return degrees * M_PI / 180.0; }

class Incline : public physim::Simulation {
public:
    Incline() {
        parameters.add("mu_s", "static friction coefficient", 0.6, 0.0, 1.5);
        parameters.add("mu_d", "dynamic friction coefficient", 0.4, 0.0, 1.5);
    }

    std::string title() const override { return "incline: blocks on 10 to 45 degree slopes (Coulomb friction)"; }

    void onCreate() override {
        const double muStatic = parameters.get("mu_s"), muDynamic = parameters.get("mu_d");
        for (int k = 0; k < kCount; ++k) {
            Lane& lane = lanes_[k];
            lane.theta = radians(kAnglesDeg[k]);
            lane.centre = {(k % kPerRow) * kSpacing, -(k / kPerRow) * kRowGap};
            auto& slope = spawn<physim::Object>(
                physim::Mesh::RectangleMesh({2 * kHalfLength, kThickness}, sf::Color(90, 90, 90)),
                physim::RectangleShape({2 * kHalfLength, kThickness}));
            slope.rb.setMass(0.0);  // static
            slope.rb.setStaticFriction(muStatic);
            slope.rb.setDynamicFriction(muDynamic);
            slope.setPosition(lane.centre);
            slope.setRotation(lane.theta);
            // The stop stands on the slope's top face at its foot.
            auto& stop = spawn<physim::Object>(
                physim::Mesh::RectangleMesh({kStop, 1.2}, sf::Color(90, 90, 90)), physim::RectangleShape({kStop, 1.2}));
            stop.rb.setMass(0.0);
            stop.setPosition(lane.centre + (kHalfLength - 0.5 * kStop) * lane.down() +
                             (0.5 * kThickness + 0.6) * lane.normal());
            stop.setRotation(lane.theta);
            lane.block = &spawn<physim::Object>(physim::Vec2(kBlock, kBlock));
            lane.block->rb.setStaticFriction(muStatic);
            lane.block->rb.setDynamicFriction(muDynamic);
        }
        release();
        acceleration_ = graphsManager.addGraph("Acceleration along the slope;incline angle (deg);a (m/s^2)");
        analytic_ = graphsManager.addSeries(acceleration_, "g (sin - mu_d cos), 0 below the angle of repose");
        addEnergyPlot();  // where the blocks' potential energy went: friction, and the stops at the slopes' feet
        graphsManager.build();
        drawAnalytic();
    }

    std::string keysHelp() const override { return "N: blocks back to the top"; }

    // Both rows of slopes, their blocks at the top.
    std::optional<Aabb> viewBounds() const override {
        const double reach = kHalfLength * std::cos(radians(kAnglesDeg.front())) + kThickness;
        return Aabb{{-reach, -kRowGap - kHalfLength}, {(kPerRow - 1) * kSpacing + reach, 4.0}};
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) {
            graphsManager.reset();
            drawAnalytic();
            release();
        }
    }

    // The velocities are sampled at the first frame past each instant; the acceleration uses the times of
    // those samples, so it does not depend on how many fixed steps a frame ran.
    void onDrawGraphs() override {
        const double t = time - releaseTime_;
        for (Lane& lane : lanes_) {
            const double v = lane.block->rb.velocity().dot(lane.down());
            if (!lane.first && t >= kMeasureFrom) lane.first = Sample{t, v};
            if (lane.first && !lane.measured && t >= kMeasureTo) {
                lane.measured = true;
                const double a = (v - lane.first->v) / (t - lane.first->t);
                const double degrees = lane.theta * 180.0 / M_PI;
                graphsManager.addPoint(acceleration_, degrees, a);
                setResult("acceleration at " + std::to_string(std::lround(degrees)) + " degrees", a,
                          coulomb(lane.theta), "m/s^2");
            }
        }
    }

private:
    struct Sample {
        double t, v;  // s since release, m/s down the slope
    };
    struct Lane {
        double theta = 0.0;  // rad
        physim::Vec2 centre;
        physim::Object* block = nullptr;  // owned by the simulation
        std::optional<Sample> first;
        bool measured = false;
        physim::Vec2 down() const { return {-std::cos(theta), -std::sin(theta)}; }
        physim::Vec2 normal() const { return {-std::sin(theta), std::cos(theta)}; }
    };

    // Each block resting on its slope's top face, kStartUpSlope up from the centre, at rest.
    void release() {
        for (Lane& lane : lanes_) {
            lane.block->setPosition(lane.centre + 0.5 * (kThickness + kBlock) * lane.normal() -
                                    kStartUpSlope * lane.down());
            lane.block->setRotation(lane.theta);
            lane.block->rb.setVelocity({0.0, 0.0});
            lane.block->rb.setAngularVelocity(0.0);
            lane.block->rb.wakeUp();
            lane.first.reset();
            lane.measured = false;
        }
        releaseTime_ = time;
    }

    // Coulomb's acceleration down a slope of theta rad, m/s^2: 0 while the block sticks.
    double coulomb(double th) const {
        const double g = -world().settings().gravity.y();
        const double muStatic = parameters.get("mu_s"), muDynamic = parameters.get("mu_d");
        return std::tan(th) > muStatic ? g * (std::sin(th) - muDynamic * std::cos(th)) : 0.0;
    }

    void drawAnalytic() {
        for (double deg = 0.0; deg <= 50.0; deg += 0.25) graphsManager.addPoint(analytic_, deg, coulomb(radians(deg)));
    }

    std::array<Lane, kCount> lanes_;
    int acceleration_ = -1, analytic_ = -1;  // graph indices
    double releaseTime_ = 0.0;               // s
};

}  // namespace

std::unique_ptr<Simulation> makeIncline() { return std::make_unique<Incline>(); }

}  // namespace physim::examples
