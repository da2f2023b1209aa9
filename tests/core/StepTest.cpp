// The one step (World::step): forces between steps, the step refusing changes made from inside it, contact events,
// contacts found once per step and kept, the broad phase left alone by bodies at rest, the local centre of mass,
// type changes checked at the boundary, and bit-identical results for any thread count.

#include "physim/core/ContinuousBatch.hpp"
#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;

WorldSettings settings(Vec2 gravity = {0.0, -9.81}) {
    WorldSettings s;
    s.gravity = gravity;
    return s;
}

BodyId addGround(World& world) {
    BodyDef g;
    g.type = BodyType::Static;
    g.shape = makeBox(20.0, 0.5);
    g.position = {0.0, -0.5};  // top face at y = 0
    return world.createBody(g);
}

BodyId addBox(World& world, Vec2 at, double half = 0.5) {
    BodyDef b;
    b.shape = makeBox(half, half);
    b.position = at;
    return world.createBody(b);
}

// A force applied between steps (the framework's checkCollisions or fixedUpdate) acts in the next step and is then
// cleared: F = 10 N on 1 kg in free space changes the velocity by exactly F dt / m, once.
TEST(Step, AForceAddedBetweenStepsActsInTheNextStepOnce) {
    World world(settings(Vec2::Zero()));
    BodyDef d;
    d.shape = makeBox(0.5, 0.5);  // 1 kg at density 1
    const BodyId id = world.createBody(d);
    world.step(kDt);
    world.applyForce(id, {10.0, 0.0});
    world.step(kDt);
    EXPECT_NEAR(world.velocity(id).x(), 10.0 * kDt, 1e-12);
    world.step(kDt);
    EXPECT_NEAR(world.velocity(id).x(), 10.0 * kDt, 1e-12) << "cleared after the step that used it";
}

// The only user code that runs inside the step is a continuous solver: changing the world from there is refused
// with a std::logic_error naming the call, and the world still steps afterwards.
class MeddlingSolver final : public ContinuousSolver {
public:
    explicit MeddlingSolver(World& world) : world_(world) {}
    void solve(const ContinuousBatch& batch, ContinuousBatchResult& result) override {
        try {
            world_.createBody(BodyDef{});
        } catch (const std::logic_error& e) {
            refusal = e.what();
        }
        solveOnCpu(batch, result, 1);
    }
    std::string name() const override { return "meddling"; }
    std::string refusal;

private:
    World& world_;
};

TEST(Step, ChangingTheWorldFromInsideItsStepIsRefused) {
    World world(settings(Vec2::Zero()));
    auto solver = std::make_shared<MeddlingSolver>(world);
    world.setContinuousSolver(solver);
    BodyDef wall;
    wall.type = BodyType::Static;
    wall.shape = makeBox(0.05, 2.0);
    wall.position = {2.0, 0.0};
    world.createBody(wall);
    BodyDef bullet;
    bullet.shape = makeCircle(0.05);
    bullet.velocity = {200.0, 0.0};
    bullet.collisionDetection = CollisionDetection::ContinuousExact;
    world.createBody(bullet);
    world.step(kDt);
    EXPECT_NE(solver->refusal.find("createBody"), std::string::npos) << solver->refusal;
    EXPECT_EQ(world.bodyCount(), 2u) << "nothing was added";
    EXPECT_NO_THROW(world.step(kDt));
    EXPECT_THROW(world.step(std::nan("")), std::invalid_argument);
}

// A box dropped 1 m onto the ground: one begin event and one impact event (approach sqrt(2 g h) = 4.43 m/s,
// within what one step of gravity adds, g dt = 0.16 m/s), no end event while it rests; lifted off, one end event.
TEST(Step, ContactEventsBeginEndAndImpact) {
    World world(settings());
    const BodyId ground = addGround(world);
    const BodyId box = addBox(world, {0.0, 1.5});
    int begins = 0, ends = 0, impacts = 0;
    double speed = 0.0;
    for (int i = 0; i < 120; ++i) {
        world.step(kDt);
        const ContactEvents& e = world.contactEvents();
        for (const ContactEvent& b : e.begin) {
            ++begins;
            EXPECT_TRUE((b.bodyA == ground && b.bodyB == box) || (b.bodyA == box && b.bodyB == ground));
        }
        ends += static_cast<int>(e.end.size());
        for (const ImpactEvent& hit : e.impacts) {
            ++impacts;
            speed = hit.approachSpeed;
            EXPECT_NEAR(std::abs(hit.normal.y()), 1.0, 1e-9);
        }
    }
    EXPECT_EQ(begins, 1);
    EXPECT_EQ(ends, 0);
    EXPECT_EQ(impacts, 1);
    EXPECT_NEAR(speed, std::sqrt(2.0 * 9.81 * 1.0), 9.81 * kDt);
    world.setTransform(box, {0.0, 5.0}, 0.0);
    world.step(kDt);
    EXPECT_EQ(world.contactEvents().end.size(), 1u);
}

// Contacts are found once per step and kept: a box resting on the ground keeps its contact (same feature ids) and
// its impulse, which over the step equals the weight's m g dt. Once it rests, its proxy stays in its enlarged box,
// so the broad phase does no work at all.
TEST(Step, RestingContactsPersistAndTheBroadPhaseRests) {
    WorldSettings awake = settings();
    awake.enableSleep = false;  // a sleeping body's contact is in sleepingContacts(), not here
    World world(awake);
    addGround(world);
    const BodyId box = addBox(world, {0.0, 0.5});
    for (int i = 0; i < 120; ++i) world.step(kDt);
    ASSERT_EQ(world.contacts().size(), 1u);
    const Manifold m = world.contacts()[0];
    ASSERT_EQ(m.pointCount, 2);
    EXPECT_NEAR(m.points[0].normalImpulse + m.points[1].normalImpulse, world.mass(box) * 9.81 * kDt, 1e-6);
    for (int i = 0; i < 60; ++i) {
        world.step(kDt);
        EXPECT_FALSE(world.profile().didRun(Stage::BroadPhase)) << "step " << i;
        EXPECT_TRUE(world.profile().didRun(Stage::NarrowPhase));
    }
    EXPECT_EQ(world.contacts()[0].points[0].id, m.points[0].id);
}

// The impulses are written back to the contacts by the last relax pass, or after the substeps when there is none
// (relaxIterations 0): either way a resting box's contact reports the weight's m g dt over the step (1e-6 N s, as
// above: the settled impulse is exact to rounding).
TEST(Step, ImpulsesAreStoredWithAndWithoutARelaxPass) {
    for (const int relax : {0, 1, 2}) {
        WorldSettings s = settings();
        s.enableSleep = false;
        s.relaxIterations = relax;
        World world(s);
        addGround(world);
        const BodyId box = addBox(world, {0.0, 0.5});
        for (int i = 0; i < 120; ++i) world.step(kDt);
        ASSERT_EQ(world.contacts().size(), 1u) << "relax passes " << relax;
        const Manifold& m = world.contacts()[0];
        EXPECT_NEAR(m.points[0].normalImpulse + m.points[1].normalImpulse, world.mass(box) * 9.81 * kDt, 1e-6)
            << "relax passes " << relax;
    }
}

// A body turns about its centre of mass, not its origin. A circle centred 1 m off its body's origin, spinning with
// no linear momentum: its centre of mass stays put (1e-12 m: rounding) while position() (the origin) circles it.
TEST(Step, BodiesTurnAboutTheirCentreOfMass) {
    World world(settings(Vec2::Zero()));
    BodyDef d;
    d.shape = makeCircle(0.1, {1.0, 0.0});
    d.angularVelocity = 5.0;
    const BodyId id = world.createBody(d);
    EXPECT_NEAR((world.centerOfMass(id) - Vec2(1.0, 0.0)).norm(), 0.0, 1e-15);
    EXPECT_NEAR(world.inertia(id), 0.5 * world.mass(id) * 0.01, 1e-12) << "about the centroid: m r^2 / 2";
    for (int i = 0; i < 30; ++i) world.step(kDt);
    EXPECT_NEAR((world.centerOfMass(id) - Vec2(1.0, 0.0)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((world.position(id) - Vec2(1.0, 0.0)).norm(), 1.0, 1e-12) << "the origin circles the centre";
    EXPECT_NEAR(world.angle(id), 5.0 * 30 * kDt, 1e-12);
}

// Two offset shapes colliding in free space (an off-centre polygon hitting an off-centre circle): every impulse
// comes in an equal and opposite pair, so linear momentum is kept to rounding (1e-9 relative). Angular momentum
// about the origin too, except that a bounce places the bodies as the discrete mirror of their approach, up to one
// substep's travel v h from where continuous time would put them without changing their momentum: the bound is
// that, sum of m |v|^2 h.
TEST(Step, OffsetShapesKeepMomentumInACollision) {
    World world(settings(Vec2::Zero()));
    BodyDef a;
    a.shape = makePolygon({{0.5, -0.3}, {1.3, -0.2}, {1.1, 0.4}, {0.4, 0.3}});
    a.position = {-2.0, 0.1};
    a.velocity = {3.0, 0.0};
    a.angularVelocity = 1.0;
    a.restitution = 0.5;
    BodyDef b;
    b.shape = makeCircle(0.3, {-0.4, 0.2});
    b.position = {1.0, 0.0};
    b.velocity = {-1.0, 0.0};
    const BodyId ia = world.createBody(a), ib = world.createBody(b);
    auto momentum = [&]() -> Vec2 { return world.mass(ia) * world.velocity(ia) + world.mass(ib) * world.velocity(ib); };
    auto angular = [&] {
        double l = 0.0;
        for (const BodyId id : {ia, ib})
            l += world.inertia(id) * world.angularVelocity(id) +
                 world.mass(id) * cross(world.centerOfMass(id), world.velocity(id));
        return l;
    };
    const Vec2 p0 = momentum();
    const double l0 = angular();
    const double h = kDt / world.settings().substeps;
    double bound = 0.0;
    for (const BodyId id : {ia, ib}) {
        const double v = world.velocity(id).norm() + world.angularVelocity(id) * 1.3;  // 1.3 m: farthest point
        bound += world.mass(id) * v * v * h;
    }
    int touching = 0;
    for (int i = 0; i < 90; ++i) {
        world.step(kDt);
        touching += static_cast<int>(world.contactEvents().begin.size());
    }
    ASSERT_GT(touching, 0) << "they met";
    EXPECT_LT((momentum() - p0).norm(), 1e-9 * p0.norm());
    EXPECT_NEAR(angular(), l0, bound);
}

// Type changes are checked: a body made with density 0 cannot become dynamic (no positive mass), and a BodyType
// outside the enum is refused by createBody and setType, each naming the value, with nothing changed.
TEST(Step, TypeChangesAreCheckedAtTheBoundary) {
    World world(settings());
    BodyDef k;
    k.type = BodyType::Kinematic;
    k.density = 0.0;
    const BodyId id = world.createBody(k);
    try {
        world.setType(id, BodyType::Dynamic);
        FAIL() << "a massless body became dynamic";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("mass"), std::string::npos) << e.what();
    }
    EXPECT_EQ(world.type(id), BodyType::Kinematic);
    const auto bad = static_cast<BodyType>(7);
    EXPECT_THROW(world.setType(id, bad), std::invalid_argument);
    BodyDef d;
    d.type = bad;
    EXPECT_THROW(world.createBody(d), std::invalid_argument);
    EXPECT_EQ(world.bodyCount(), 1u);
    world.step(kDt);
    EXPECT_TRUE(std::isfinite(world.position(id).x()));
}

// Results do not depend on the thread count: a tilted pyramid with balls dropped on it, 200 steps with 1, 2 and
// every hardware thread, and twice with 1, give the same bits (the solver's colours have no shared body, and every
// merge of per-worker results is in a fixed order).
std::vector<double> scene(int threads) {
    WorldSettings s = settings({0.0, -10.0});
    s.threads = threads;
    World world(s);
    addGround(world);
    std::vector<BodyId> ids;
    const int n = 15;
    for (int i = 0; i < n; ++i)
        for (int j = i; j < n; ++j) {
            BodyDef d;
            d.shape = makeBox(0.5, 0.5);
            d.position = {(i + 1) * 0.5 + (j - i) - 0.5 * n, 0.5 + i + 0.01 * j};
            d.angle = 0.01 * i;
            ids.push_back(world.createBody(d));
        }
    for (int k = 0; k < 8; ++k) {
        BodyDef d;
        d.shape = makeCircle(0.2);
        d.position = {k - 4.0, 30.0};
        d.velocity = {0.0, -20.0};
        d.restitution = 0.6;
        ids.push_back(world.createBody(d));
    }
    for (int i = 0; i < 200; ++i) world.step(kDt);
    std::vector<double> state;
    for (const BodyId id : ids)
        for (const double v : {world.position(id).x(), world.position(id).y(), world.angle(id),
                               world.velocity(id).x(), world.velocity(id).y(), world.angularVelocity(id)})
            state.push_back(v);
    return state;
}

TEST(Step, BitIdenticalForAnyThreadCount) {
    const std::vector<double> one = scene(1);
    for (const int threads : {1, 2, 0}) {
        const std::vector<double> other = scene(threads);
        ASSERT_EQ(other.size(), one.size());
        EXPECT_EQ(std::memcmp(one.data(), other.data(), one.size() * sizeof(double)), 0) << threads << " threads";
    }
}

}  // namespace
}  // namespace physim
