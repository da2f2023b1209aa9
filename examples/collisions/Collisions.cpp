// collisions: two head-on collisions of discs in zero gravity with no friction (the textbook formulas assume
// neither). The upper pair is elastic (restitution 1), the lower perfectly inelastic (restitution 0); in both
// a 1 kg/m^2 disc at 3 m/s meets one three times as dense (coming at 0.5 m/s in the elastic pair, at rest in
// the inelastic one, which then keeps 1/4 of its energy and moves on at 3/4 m/s). Momentum is conserved in
// both; kinetic energy is conserved in the elastic one, while the inelastic pair ends moving together at
// v = (m1 u1 + m2 u2) / (m1 + m2), keeping only (m1 u1 + m2 u2)^2 / (2 (m1 + m2)). Graphs: each pair's
// momentum and kinetic energy against time, over the analytic values. When a disc leaves the lanes (6 m from
// the middle), both pairs are launched again, so the discs stay in view. Keys: N launches both pairs again.
// Parameters: disc a's speed and the density ratio of b to a (b's speeds keep their ratio to a's). Results
// (summary.json): both pairs' momentum, and their velocities and kinetic energy after the contact, beside the
// textbook's.

#include "Scenes.hpp"

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>

#include <SFML/Window/Event.hpp>

#include <cmath>

namespace physim::examples {
namespace {

constexpr double kRadius = 0.5;             // m
constexpr double kDensityA = 1.0;           // kg/m^2; b's is the "density_ratio" parameter times this
constexpr double kStartA = -2.0, kStartB = 0.0;     // m, centres along x: 1 m of gap between the surfaces
// b's launch velocity as a fraction of a's: -1/6 (3 m/s against -0.5) in the elastic pair, at rest in the
// inelastic one; approach speeds 3.5 and 3 m/s at the default 3 m/s, above the 1 m/s restitution threshold.
constexpr double kElasticBShare = -1.0 / 6.0;
constexpr double kLaneY = 2.0;              // m: elastic pair at +kLaneY, inelastic at -kLaneY
constexpr double kLaneEnd = 6.0;            // m from the middle: past it, both pairs are launched again

struct Pair {
    physim::Object* a = nullptr;  // owned by the simulation
    physim::Object* b = nullptr;
    double uA = 0.0;              // m/s, a's launch velocity
    double uB = 0.0;              // m/s, b's launch velocity

    double momentum() const { return a->rb.mass() * a->rb.velocity().x() + b->rb.mass() * b->rb.velocity().x(); }
    double kinetic() const {
        const auto k = [](const physim::Object* o) {
            return 0.5 * o->rb.mass() * o->rb.velocity().squaredNorm() +
                   0.5 * o->rb.inertia() * o->rb.angularVelocity() * o->rb.angularVelocity();
        };
        return k(a) + k(b);
    }
    double initialMomentum() const { return a->rb.mass() * uA + b->rb.mass() * uB; }
    double initialKinetic() const { return 0.5 * a->rb.mass() * uA * uA + 0.5 * b->rb.mass() * uB * uB; }
    double contactTime() const { return (kStartB - kStartA - 2 * kRadius) / (uA - uB); }  // s
    bool outOfLane() const {
        return std::abs(a->getPosition().x()) > kLaneEnd || std::abs(b->getPosition().x()) > kLaneEnd;
    }
};

class Collisions : public physim::Simulation {
public:
    Collisions() {
        parameters.add("speed", "disc a's launch speed (m/s)", 3.0, 1.5, 10.0);
        parameters.add("density_ratio", "b's density over a's (their mass ratio)", 3.0, 0.2, 10.0);
    }

    std::string title() const override { return "collisions: elastic (top) and perfectly inelastic (bottom)"; }

    void onCreate() override {
        physim::WorldSettings settings = world().settings();
        settings.gravity = {0.0, 0.0};
        world().setSettings(settings);
        const double speed = parameters.get("speed");
        elastic_ = makePair(kLaneY, 1.0, speed, kElasticBShare * speed);
        inelastic_ = makePair(-kLaneY, 0.0, speed, 0.0);
        launch();
        elasticP_ = graphsManager.addGraph("Elastic pair: momentum;time (s);p (kg m/s)");
        graphsManager.addSeries(elasticP_, "conserved");
        elasticK_ = graphsManager.addGraph("Elastic pair: kinetic energy;time (s);K (J)");
        graphsManager.addSeries(elasticK_, "conserved");
        inelasticP_ = graphsManager.addGraph("Perfectly inelastic pair: momentum;time (s);p (kg m/s)");
        graphsManager.addSeries(inelasticP_, "conserved");
        inelasticK_ = graphsManager.addGraph("Perfectly inelastic pair: kinetic energy;time (s);K (J)");
        graphsManager.addSeries(inelasticK_, "K0, then p^2 / (2 (m1 + m2))");
        graphsManager.build();
    }

    std::string keysHelp() const override { return "N: launch again"; }

    // Both lanes to where the pairs are launched again.
    std::optional<Aabb> viewBounds() const override {
        return Aabb{{-kLaneEnd - kRadius, -kLaneY - 1.0}, {kLaneEnd + kRadius, kLaneY + 1.0}};
    }

    void onUpdate() override {
        if (elastic_.outOfLane() || inelastic_.outOfLane()) {
            graphsManager.reset();
            launch();
        }
    }

    void onEvent(sf::Event event) override {
        if (event.type == sf::Event::KeyPressed && event.key.code == sf::Keyboard::N) {
            graphsManager.reset();
            launch();
        }
    }

    // Each analytic series is graph index + 1 (added right after its graph).
    void onDrawGraphs() override {
        const double t = time - launchTime_;
        const double mTotal = inelastic_.a->rb.mass() + inelastic_.b->rb.mass();
        const double pIn = inelastic_.initialMomentum();
        const double kInelastic =
            t < inelastic_.contactTime() ? inelastic_.initialKinetic() : pIn * pIn / (2 * mTotal);
        graphsManager.addPoint(elasticP_, t, elastic_.momentum());
        graphsManager.addPoint(elasticP_ + 1, t, elastic_.initialMomentum());
        graphsManager.addPoint(elasticK_, t, elastic_.kinetic());
        graphsManager.addPoint(elasticK_ + 1, t, elastic_.initialKinetic());
        graphsManager.addPoint(inelasticP_, t, inelastic_.momentum());
        graphsManager.addPoint(inelasticP_ + 1, t, pIn);
        graphsManager.addPoint(inelasticK_, t, inelastic_.kinetic());
        graphsManager.addPoint(inelasticK_ + 1, t, kInelastic);
        reportResults(t);
    }

private:
    // Momentum at every frame; the velocities and energies once a frame has passed since the contact.
    void reportResults(double t) {
        setResult("elastic: momentum", elastic_.momentum(), elastic_.initialMomentum(), "kg m/s");
        setResult("inelastic: momentum", inelastic_.momentum(), inelastic_.initialMomentum(), "kg m/s");
        if (t > elastic_.contactTime() + fixedTimeStep()) {
            const double mA = elastic_.a->rb.mass(), mB = elastic_.b->rb.mass(), uA = elastic_.uA, uB = elastic_.uB;
            setResult("elastic: a's velocity after", elastic_.a->rb.velocity().x(),
                      ((mA - mB) * uA + 2 * mB * uB) / (mA + mB), "m/s");
            setResult("elastic: b's velocity after", elastic_.b->rb.velocity().x(),
                      (2 * mA * uA + (mB - mA) * uB) / (mA + mB), "m/s");
            setResult("elastic: kinetic energy after", elastic_.kinetic(), elastic_.initialKinetic(), "J");
        }
        if (t > inelastic_.contactTime() + fixedTimeStep()) {
            const double mTotal = inelastic_.a->rb.mass() + inelastic_.b->rb.mass(), p = inelastic_.initialMomentum();
            setResult("inelastic: common velocity after", inelastic_.b->rb.velocity().x(), p / mTotal, "m/s");
            setResult("inelastic: kinetic energy after", inelastic_.kinetic(), p * p / (2 * mTotal), "J");
        }
    }

    Pair makePair(double y, double restitution, double uA, double uB) {
        Pair pair;
        pair.uA = uA;
        pair.uB = uB;
        pair.a = &spawn<physim::Object>(physim::Mesh::CircleMesh(kRadius, sf::Color(200, 60, 60)),
                                        physim::CircleShape(kRadius));
        pair.b = &spawn<physim::Object>(physim::Mesh::CircleMesh(kRadius, sf::Color(60, 60, 200)),
                                        physim::CircleShape(kRadius));
        pair.a->rb.setDensity(kDensityA);
        pair.b->rb.setDensity(kDensityA * parameters.get("density_ratio"));
        for (physim::Object* o : {pair.a, pair.b}) {
            o->rb.setRestitution(restitution);
            o->rb.setStaticFriction(0.0);
            o->rb.setDynamicFriction(0.0);
            o->setPosition({0.0, y});
        }
        return pair;
    }

    void launch() {
        for (Pair* pair : {&elastic_, &inelastic_}) {
            const double y = pair->a->getPosition().y();
            pair->a->setPosition({kStartA, y});
            pair->b->setPosition({kStartB, y});
            pair->a->rb.setVelocity({pair->uA, 0.0});
            pair->b->rb.setVelocity({pair->uB, 0.0});
            for (physim::Object* o : {pair->a, pair->b}) {
                o->setRotation(0.0);
                o->rb.setAngularVelocity(0.0);
            }
        }
        launchTime_ = time;
    }

    Pair elastic_, inelastic_;
    int elasticP_ = -1, elasticK_ = -1, inelasticP_ = -1, inelasticK_ = -1;  // graph indices
    double launchTime_ = 0.0;  // s
};

}  // namespace

std::unique_ptr<Simulation> makeCollisions() { return std::make_unique<Collisions>(); }

}  // namespace physim::examples
