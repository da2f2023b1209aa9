// collisions: two head-on collisions of discs in zero gravity with no friction (the textbook formulas assume
// neither). The upper pair is elastic (restitution 1), the lower perfectly inelastic (restitution 0); in both
// a 1 kg/m^2 disc at 3 m/s meets one three times as dense (coming at 0.5 m/s in the elastic pair, at rest in
// the inelastic one, which then keeps 1/4 of its energy and moves on at 3/4 m/s). Momentum is conserved in
// both; kinetic energy is conserved in the elastic one, while the inelastic pair ends moving together at
// v = (m1 u1 + m2 u2) / (m1 + m2), keeping only (m1 u1 + m2 u2)^2 / (2 (m1 + m2)). Graphs: each pair's
// momentum and kinetic energy against time, over the analytic values. Keys: N launches both pairs again.

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <SFML/Window/Event.hpp>

#include <cmath>

namespace {

constexpr double kRadius = 0.5;             // m
constexpr double kDensityA = 1.0, kDensityB = 3.0;  // kg/m^2
constexpr double kStartA = -2.0, kStartB = 0.0;     // m, centres along x: 1 m of gap between the surfaces
constexpr double kSpeedA = 3.0;             // m/s, both pairs
constexpr double kSpeedBElastic = -0.5, kSpeedBInelastic = 0.0;  // m/s; approach speeds 3.5 and 3 m/s, both
                                                                 // above the 1 m/s restitution threshold
constexpr double kLaneY = 2.0;              // m: elastic pair at +kLaneY, inelastic at -kLaneY

struct Pair {
    physim::Object* a = nullptr;  // owned by the simulation
    physim::Object* b = nullptr;
    double uB = 0.0;              // m/s, b's launch velocity

    double momentum() const { return a->rb.mass() * a->rb.velocity().x() + b->rb.mass() * b->rb.velocity().x(); }
    double kinetic() const {
        const auto k = [](const physim::Object* o) {
            return 0.5 * o->rb.mass() * o->rb.velocity().squaredNorm() +
                   0.5 * o->rb.inertia() * o->rb.angularVelocity() * o->rb.angularVelocity();
        };
        return k(a) + k(b);
    }
    double initialMomentum() const { return a->rb.mass() * kSpeedA + b->rb.mass() * uB; }
    double initialKinetic() const { return 0.5 * a->rb.mass() * kSpeedA * kSpeedA + 0.5 * b->rb.mass() * uB * uB; }
    double contactTime() const { return (kStartB - kStartA - 2 * kRadius) / (kSpeedA - uB); }  // s
};

class Collisions : public physim::Simulation {
public:
    std::string title() const override { return "collisions: elastic (top) and perfectly inelastic (bottom)"; }

    void onCreate() override {
        physim::WorldSettings settings = world().settings();
        settings.gravity = {0.0, 0.0};
        world().setSettings(settings);
        elastic_ = makePair(kLaneY, 1.0, kSpeedBElastic);
        inelastic_ = makePair(-kLaneY, 0.0, kSpeedBInelastic);
        launch();
        view.center = {0.0, 0.0};
        view.pixelsPerMetre = 60.0;
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
    }

private:
    Pair makePair(double y, double restitution, double uB) {
        Pair pair;
        pair.uB = uB;
        pair.a = &spawn<physim::Object>(physim::Mesh::CircleMesh(kRadius, sf::Color(200, 60, 60)),
                                        physim::CircleShape(kRadius));
        pair.b = &spawn<physim::Object>(physim::Mesh::CircleMesh(kRadius, sf::Color(60, 60, 200)),
                                        physim::CircleShape(kRadius));
        pair.a->rb.setDensity(kDensityA);
        pair.b->rb.setDensity(kDensityB);
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
            pair->a->rb.setVelocity({kSpeedA, 0.0});
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

int main(int argc, char** argv) { return physim::runMain<Collisions>(argc, argv); }
