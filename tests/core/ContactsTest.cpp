// Persistent contacts (src/core/Contacts.cpp): a pair that has hardly moved relative to itself keeps its last
// collision and rebuilds the manifold from it at the present poses. Checked against a fresh collision of the same
// shapes at the same poses, step after step, in scenes where pairs rest, creep, slide, tip and roll.

#include "BodyData.hpp"
#include "ContactData.hpp"
#include "Contacts.hpp"
#include "Manifolds.hpp"
#include "physim/core/World.hpp"
#include "support/Pyramid.hpp"
#include "support/WideCodes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;

BodyId add(World& world, BodyType type, Geometry shape, Vec2 at, double angle = 0.0, Vec2 velocity = Vec2::Zero(),
           double spin = 0.0) {
    BodyDef d;
    d.type = type;
    d.shape = shape;
    d.position = at;
    d.angle = angle;
    d.velocity = velocity;
    d.angularVelocity = spin;
    return world.createBody(d);
}

// A settling base-6 pyramid, a box sliding to a stop, a box tipping over a ledge, a ball rolling to the side and a
// box tumbling onto the ground: pairs that rest (kept manifolds), creep (kept, then collided again) and move
// fast (collided every step).
std::vector<BodyId> buildScene(World& world) {
    std::vector<BodyId> ids;
    ids.push_back(add(world, BodyType::Static, makeBox(30.0, 0.5), {0.0, -0.5}));
    scenes::forEachPyramidBox(6, 1.0, 0.0, 0.0, [&](double x, double y) {
        ids.push_back(add(world, BodyType::Dynamic, makeBox(0.5, 0.5), {x, y}));
    });
    ids.push_back(add(world, BodyType::Dynamic, makeBox(0.4, 0.2), {8.0, 0.2}, 0.0, {1.5, 0.0}));
    ids.push_back(add(world, BodyType::Static, makeBox(1.0, 1.0), {-12.0, 1.0}));
    ids.push_back(add(world, BodyType::Dynamic, makeBox(0.5, 0.5), {-11.2, 2.5}));
    ids.push_back(add(world, BodyType::Dynamic, makeCircle(0.3), {14.0, 0.3}, 0.0, {-0.5, 0.0}, 0.5 / 0.3));
    ids.push_back(add(world, BodyType::Dynamic, makeBox(0.6, 0.3), {20.0, 2.0}, 0.7, Vec2::Zero(), 3.0));
    return ids;
}

// Every point the world reports (touching, or speculative up to the speculative distance apart) is where a fresh
// collision of the two shapes, at the poses the step started from and with the point's separation as its margin,
// puts the point with the same feature id: within the reuse tolerance (a tenth of the linear slop) along the
// surfaces, and within 1e-5 m in separation. A kept manifold's separation is
// measured at the present poses from points that lag by at most the tolerance along faces that have turned
// by at most the tolerance over the body's size, so its error is of order tolerance^2 / size (~1e-6 m here).
TEST(Contacts, AKeptManifoldMatchesAFreshCollisionAtThePresentPoses) {
    WorldSettings settings;
    settings.enableSleep = false;
    World world(settings);
    const std::vector<BodyId> ids = buildScene(world);
    const double tolerance = 0.1 * settings.linearSlop;
    auto slot = [&](BodyId id) { return std::find(ids.begin(), ids.end(), id) - ids.begin(); };

    double worstPoint = 0.0, worstSeparation = 0.0;
    int checked = 0;
    for (int step = 0; step < 240; ++step) {
        std::vector<Transform> before;
        for (const BodyId id : ids) before.push_back(world.transform(id));
        world.step(kDt);
        for (const Manifold& m : world.contacts()) {
            for (int p = 0; p < m.pointCount; ++p) {
                const ContactPoint& kept = m.points[p];
                const Manifold fresh =
                    collideGeometries(world.shape(m.bodyA), before[static_cast<std::size_t>(slot(m.bodyA))],
                                      world.shape(m.bodyB), before[static_cast<std::size_t>(slot(m.bodyB))],
                                      std::max(kept.separation, 0.0) + tolerance)
                        .manifold;
                const ContactPoint* match = nullptr;
                for (int q = 0; q < fresh.pointCount; ++q)
                    if (fresh.points[q].id == kept.id) match = &fresh.points[q];
                ASSERT_NE(match, nullptr) << "step " << step << ": point " << kept.id << " of bodies "
                                          << m.bodyA.index << ", " << m.bodyB.index << " has no fresh twin";
                worstPoint = std::max(worstPoint, (kept.point - match->point).norm());
                worstSeparation = std::max(worstSeparation, std::abs(kept.separation - match->separation));
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 10000);
    EXPECT_LE(worstPoint, tolerance + 1e-9);
    EXPECT_LE(worstSeparation, 1e-5);
}

// A ball rolling without slip on flat ground, with no rolling resistance, keeps its speed: nothing does work on
// it. A kept manifold's point on the ball turns with the ball, so it slips back along the surface as the ball rolls;
// the load on a point left behind the centre is a lever that drives the roll. Before the cache accounted for that, a
// ball nudged to 0.1 mm/s sped up to about 1 cm/s. Both orders of the pair (the ball as the contact's first body
// too, whose frame the cached normal rides in). 1%: the ground's soft contact barely moves the centre (the ball
// sinks 0.04 mm and stays there).
TEST(Contacts, ABallRollingSlowlyKeepsItsSpeed) {
    for (const double speed : {1e-4, 1e-3, 5e-3})
        for (const bool ballFirst : {false, true}) {
            WorldSettings settings;
            settings.enableSleep = false;
            World world(settings);
            const double r = 0.2;
            auto addBall = [&] {
                return add(world, BodyType::Dynamic, makeCircle(r), {0.0, r}, 0.0, {speed, 0.0}, -speed / r);
            };
            BodyId ball;
            if (ballFirst) ball = addBall();
            add(world, BodyType::Static, makeBox(30.0, 0.5), {0.0, -0.5});
            if (!ballFirst) ball = addBall();
            const int steps = 600;  // 10 s
            for (int i = 0; i < steps; ++i) world.step(kDt);
            const std::string where =
                "speed " + std::to_string(speed) + (ballFirst ? ", ball first" : ", ground first");
            EXPECT_NEAR(world.velocity(ball).x(), speed, 0.01 * speed) << where;
            EXPECT_NEAR(world.angularVelocity(ball), -speed / r, 0.01 * speed / r) << where;
            EXPECT_NEAR(world.position(ball).x(), speed * steps * kDt, 0.01 * speed * steps * kDt) << where;
        }
}

// A contact lives while its bodies' proxies overlap. After a step in which nothing moved, the narrow phase takes
// the overlap as known; a ball that then leaves slowly (its proxy moved by the step, not by a call) must still lose
// its contact once its proxy no longer overlaps the ground's.
TEST(Contacts, AContactEndsWhenItsProxiesPartAfterRestingSteps) {
    WorldSettings settings;
    settings.gravity = {0.0, 0.0};  // the ball stays where it is put, at rest, then drifts off at a set speed
    settings.enableSleep = false;
    World world(settings);
    add(world, BodyType::Static, makeBox(5.0, 0.5), {0.0, -0.5});
    const BodyId ball = add(world, BodyType::Dynamic, makeCircle(0.25), {0.0, 0.25});
    for (int i = 0; i < 30; ++i) world.step(kDt);
    ASSERT_EQ(world.profile().candidatePairs, 1u) << "the resting ball's contact";
    world.setVelocity(ball, {0.0, 1.0});  // 1 m/s up: the proxy (a 0.1 m margin) is outgrown within a few steps
    int parted = -1;
    for (int i = 0; i < 120 && parted < 0; ++i) {
        world.step(kDt);
        if (world.profile().candidatePairs == 0) parted = i;
    }
    EXPECT_GE(parted, 0) << "the contact ended";
    EXPECT_LT(world.position(ball).y(), 2.5) << "within two metres of leaving";
}

// A body's turn moves its outline only as far as its shapes' cores reach from its centre of mass: a wheel spinning
// about its centre keeps its outline where it is, so its box does not grow with the spin and it pairs with nothing
// 0.3 m below it (the box's margin is 0.1 m); a dumbbell of two such circles, whose circles do swing round, sweeps
// down to the ground within the step and must pair with it.
TEST(Contacts, ASpinningWheelPairsOnlyWithWhatItsOutlineCanReach) {
    WorldSettings settings;
    settings.gravity = {0.0, 0.0};
    World world(settings);
    add(world, BodyType::Static, makeBox(20.0, 0.5), {0.0, -0.5});
    constexpr double kSpin = 200.0;  // rad/s: 3.3 rad a step
    add(world, BodyType::Dynamic, makeCircle(0.5), {-5.0, 0.8}, 0.0, Vec2::Zero(), kSpin);
    world.step(kDt);
    EXPECT_EQ(world.profile().candidatePairs, 0u) << "the wheel's outline stays 0.3 m above the ground";

    BodyDef d;
    d.shape = makeCircle(0.25, {-0.5, 0.0});
    d.position = {5.0, 0.55};  // the circles' lowest points 0.3 m above the ground, their sweep 0.2 m into it
    const BodyId dumbbell = world.createBody(d);
    ShapeDef other;
    other.geometry = makeCircle(0.25, {0.5, 0.0});
    world.createShape(dumbbell, other);  // the centre of mass midway between the circles
    world.setAngularVelocity(dumbbell, kSpin);
    world.step(kDt);
    EXPECT_EQ(world.profile().candidatePairs, 2u) << "each circle of the dumbbell meets the ground";
}

// A moving body's proxy box exceeds its shape's by 0.1 m, or by a quarter of its extent where that is less, so a
// crowd of small bodies pairs only with near neighbours; the ground's static proxy exceeds its box by the
// speculative distance (2 cm). Balls at rest, no gravity (no travel widens the boxes): a pair is made exactly
// when the gap is under the ball's margin plus 2 cm. A ball of radius 0.1 m (margin 2.5 cm) 6 cm above the
// ground makes none, with 0.1 m it would; 3 cm above, one. A ball of radius 0.5 m (margin 0.1 m) 6 cm above, one.
TEST(Contacts, AProxysMarginIsAQuarterOfItsBodysExtentAtMostATenthOfAMetre) {
    WorldSettings settings;
    settings.gravity = {0.0, 0.0};
    settings.enableSleep = false;
    const auto pairsFor = [&](double radius, double gap) {
        World world(settings);
        add(world, BodyType::Static, makeBox(5.0, 0.5), {0.0, -0.5});
        add(world, BodyType::Dynamic, makeCircle(radius), {0.0, radius + gap});
        world.step(kDt);
        return world.profile().candidatePairs;
    };
    EXPECT_EQ(pairsFor(0.1, 0.06), 0u) << "gap 6 cm, reach 2.5 + 2 cm";
    EXPECT_EQ(pairsFor(0.1, 0.03), 1u) << "gap 3 cm, reach 2.5 + 2 cm";
    EXPECT_EQ(pairsFor(0.5, 0.06), 1u) << "gap 6 cm, reach 10 + 2 cm";
    EXPECT_EQ(pairsFor(0.5, 0.13), 0u) << "gap 13 cm, reach 10 + 2 cm";
}

// A contact that slept while its boxes parted is tested when it wakes. A static platform moved away from a
// sleeping ball (the move wakes only what the platform's new place touches) leaves the pair's boxes apart, and
// narrow phases run meanwhile for another pair: the first narrow phase after the ball wakes must end the contact.
TEST(Contacts, AContactThatSleptWhileItsBoxesPartedEndsWhenItWakes) {
    World world;  // sleep on
    const BodyId platform = add(world, BodyType::Static, makeBox(1.0, 0.1), {0.0, -0.1});
    const BodyId ball = add(world, BodyType::Dynamic, makeCircle(0.25), {0.0, 0.25});
    // Far off, a ball that never sleeps keeps a contact awake, so the narrow phase runs while the first one sleeps.
    add(world, BodyType::Static, makeBox(1.0, 0.1), {-20.0, -0.1});
    BodyDef awake;
    awake.shape = makeCircle(0.25);
    awake.position = {-20.0, 0.25};
    awake.allowSleep = false;
    world.createBody(awake);
    for (int i = 0; i < 600 && world.isAwake(ball); ++i) world.step(kDt);
    ASSERT_FALSE(world.isAwake(ball));
    world.setTransform(platform, {50.0, -0.1}, 0.0);
    for (int i = 0; i < 3; ++i) world.step(kDt);  // narrow phases while the ball sleeps
    ASSERT_FALSE(world.isAwake(ball));
    world.setAwake(ball, true);
    world.step(kDt);
    ASSERT_EQ(world.profile().candidatePairs, 2u) << "with the woken contact, counted before the narrow phase";
    world.step(kDt);
    EXPECT_EQ(world.profile().candidatePairs, 1u) << "ended by the first narrow phase after the ball woke";
}

// The narrow phase's loop is built for baseline x86-64 and for AVX2 (without FMA), and works out four kept
// manifolds at once where it can; each build, and the scalar rule one contact at a time, must give the same bits.
// Random boxes and circles, some static, moving and spinning, close enough that most pairs touch or nearly do,
// are refreshed, nudged (some pairs then keep their manifolds, some are collided again) and refreshed again, by
// every build from the same records. Every field the loop writes is compared bit for bit.
bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectSameContact(const ContactData& x, const ContactData& y, std::size_t i, int round) {
    const Manifold &m = x.manifold, &n = y.manifold;
    ASSERT_EQ(m.pointCount, n.pointCount) << "contact " << i << ", round " << round;
    EXPECT_TRUE(sameBits(m.normal.x(), n.normal.x()) && sameBits(m.normal.y(), n.normal.y())) << "contact " << i;
    for (int p = 0; p < m.pointCount; ++p) {
        const ContactPoint &a = m.points[p], &b = n.points[p];
        EXPECT_TRUE(sameBits(a.point.x(), b.point.x()) && sameBits(a.point.y(), b.point.y()) &&
                    sameBits(a.separation, b.separation) && sameBits(a.normalImpulse, b.normalImpulse) &&
                    sameBits(a.tangentImpulse, b.tangentImpulse) && a.id == b.id)
            << "contact " << i << ", point " << p << ", round " << round;
    }
    EXPECT_EQ(x.touching, y.touching) << "contact " << i;
    const ManifoldCache &k = x.cache, &l = y.cache;
    EXPECT_TRUE(sameBits(k.margin, l.margin) && sameBits(k.offset.x(), l.offset.x()) &&
                sameBits(k.offset.y(), l.offset.y()) && sameBits(k.angle, l.angle) &&
                sameBits(k.normal.x(), l.normal.x()) && sameBits(k.normal.y(), l.normal.y()) &&
                k.pointCount == l.pointCount)
        << "contact " << i << ", round " << round;
    for (int p = 0; p < k.pointCount; ++p)
        EXPECT_TRUE(sameBits(k.points[p].onA.x(), l.points[p].onA.x()) &&
                    sameBits(k.points[p].onA.y(), l.points[p].onA.y()) &&
                    sameBits(k.points[p].onB.x(), l.points[p].onB.x()) &&
                    sameBits(k.points[p].onB.y(), l.points[p].onB.y()) && k.points[p].id == l.points[p].id &&
                    k.points[p].rounding == l.points[p].rounding)
            << "contact " << i << ", cached point " << p << ", round " << round;
}

TEST(Contacts, EveryBuildOfTheNarrowPhaseGivesTheSameBits) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<BodyData> bodies(60);
    std::vector<ShapeData> shapes(bodies.size());  // body i's one shape is shape i
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        BodyData& b = bodies[i];
        const bool circle = i % 3 == 0;
        const double hx = 0.3 + 0.2 * std::abs(u(rng)), hy = 0.2 + 0.2 * std::abs(u(rng));
        shapes[i].geometry = circle ? Geometry(makeCircle(hx)) : Geometry(makeBox(hx, hy));
        shapes[i].body = static_cast<std::uint32_t>(i);
        b.extent = circle ? hx : std::hypot(hx, hy);
        b.type = i % 7 == 0 ? BodyType::Static : BodyType::Dynamic;
        b.awakeIndex = b.type == BodyType::Dynamic ? static_cast<std::int32_t>(i) : kNullIndex;
        b.angle = u(rng);
        b.xf = {Vec2(3.0 * u(rng), 3.0 * u(rng)), Rotation::fromAngle(b.angle)};
        b.center = b.xf.p;  // the local centre of mass is the origin
        if (b.type == BodyType::Dynamic) {
            b.v = Vec2(2.0 * u(rng), 2.0 * u(rng));
            b.w = 3.0 * u(rng);
        }
    }
    std::vector<ContactData> contacts;
    for (std::uint32_t a = 0; a < bodies.size(); ++a)
        for (std::uint32_t b = a + 1; b < bodies.size(); ++b)
            if (bodies[a].type == BodyType::Dynamic || bodies[b].type == BodyType::Dynamic) {
                ContactData c;
                c.manifold.bodyA.index = c.manifold.shapeA.index = a;
                c.manifold.bodyB.index = c.manifold.shapeB.index = b;
                contacts.push_back(c);
            }
    std::vector<std::uint32_t> awake(contacts.size());
    for (std::uint32_t i = 0; i < awake.size(); ++i) awake[i] = i;
    // Each build refreshes its own copy of the contacts, from the same bodies; the last copy is refreshed one
    // contact at a time, which takes the scalar rule where the others take four contacts at once.
    const std::vector<WideCode> codes = test::runnableWideCodes();
    const std::size_t copyCount = codes.size() + 1;
    std::vector<std::vector<ContactData>> copies(copyCount, contacts);
    int touched = 0, kept = 0, collided = 0;
    for (int round = 0; round < 3; ++round) {
        const std::vector<ContactData> before = copies[0];
        std::vector<std::vector<std::uint8_t>> flags(copyCount, std::vector<std::uint8_t>(contacts.size(), kNone));
        for (std::size_t c = 0; c < copyCount; ++c) {
            std::atomic<bool> pointsChanged{false};
            // Every other build also asks for records ahead, which must change nothing.
            const RefreshPass pass{copies[c].data(), awake.data(), bodies.data(), shapes.data(), nullptr,
                                   flags[c].data(), nullptr,
                                   0.02, 5e-4, 1.0 / 60.0, true, c % 2 == 1, &pointsChanged};
            if (c < codes.size())
                refreshContacts(pass, 0, contacts.size(), codes[c]);
            else
                for (std::size_t i = 0; i < contacts.size(); ++i) refreshContacts(pass, i, i + 1);
        }
        for (std::size_t c = 1; c < copyCount; ++c)
            for (std::size_t i = 0; i < contacts.size(); ++i) {
                EXPECT_EQ(flags[c][i], flags[0][i]) << "contact " << i << ", round " << round;
                expectSameContact(copies[c][i], copies[0][i], i, round);
            }
        for (std::size_t i = 0; i < contacts.size(); ++i) {
            const ContactData &now = copies[0][i], &was = before[i];
            touched += now.touching ? 1 : 0;
            // A kept manifold leaves the cache as it was; a new collision writes it (its offset is the present one).
            if (was.cache.margin < 0.0 || now.manifold.pointCount == 0) continue;
            const bool same = sameBits(now.cache.margin, was.cache.margin) &&
                              sameBits(now.cache.offset.x(), was.cache.offset.x()) &&
                              sameBits(now.cache.offset.y(), was.cache.offset.y());
            (same ? kept : collided) += 1;
        }
        // A nudge that keeps some manifolds (well under the reuse tolerance, and turning a round surface less
        // than its own) and not others.
        for (BodyData& b : bodies) {
            if (b.type != BodyType::Dynamic) continue;
            const bool small = (&b - bodies.data()) % 2 == 0;
            const double step = small ? 1e-5 : 1e-2, turn = small ? 1e-9 : 1e-2;
            b.angle += turn * u(rng);
            b.xf = {b.xf.p + Vec2(step * u(rng), step * u(rng)), Rotation::fromAngle(b.angle)};
            b.center = b.xf.p;
        }
        if (::testing::Test::HasFailure()) break;
    }
    // The scene reached the paths that matter: touching pairs, manifolds kept and pairs collided again.
    EXPECT_GT(touched, 50);
    EXPECT_GT(kept, 50);
    EXPECT_GT(collided, 50);
}

}  // namespace
}  // namespace physim
