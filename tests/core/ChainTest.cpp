// Chains in a World: smooth where pieces meet (a disc rolls down a curved chain as down the curve), one-sided,
// containers from loops, continuous detection against them, and what createChain refuses.

#include "physim/core/World.hpp"
#include "Manifolds.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace physim {
namespace {

constexpr double kG = 9.81;

BodyId addChainGround(World& world, const std::vector<Vec2>& points, bool loop = false, double friction = 0.6) {
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.withShape = false;
    const BodyId id = world.createBody(ground);
    ChainDef chain;
    chain.points = points;
    chain.loop = loop;
    chain.staticFriction = chain.dynamicFriction = friction;
    world.createChain(id, chain);
    return id;
}

// The lower half of a circle of radius R about the origin, as `pieces` pieces, listed left to right (solid below).
std::vector<Vec2> halfPipe(double R, int pieces) {
    std::vector<Vec2> points;
    for (int i = 0; i <= pieces; ++i) {
        const double a = M_PI + M_PI * i / pieces;  // from the left rim, down through the bottom, to the right rim
        points.emplace_back(R * std::cos(a), R * std::sin(a));
    }
    return points;
}

// The fastest speed (m/s) of the disc of the tests below, and its prediction.
std::pair<double, double> rollDownTheHalfPipe(CollisionDetection detection) {
    // The half-pipe: radius 3 m, a 0.2 m disc released 60 degrees up the side, default 40 Hz. A rolling disc
    // on a circular track reaches v = sqrt(4 g h / 3) at the bottom, h the fall of its centre. Tolerance 2%: the
    // chord of 120 pieces sits 0.3 mm inside the arc, the centre's path turns by 1.5 degrees at each (concave)
    // joint, which costs a little energy as on any polygonal track, and the contact's slop and the 40 Hz step a
    // little more.
    // Rolling without slipping at 60 degrees needs mu >= tan(60) / 3 = 0.58: the pair's is 1.
    World world;
    const double R = 3.0, r = 0.2;
    addChainGround(world, halfPipe(R, 120), false, 1.0);
    BodyDef disc;
    disc.shape = makeCircle(r);
    disc.staticFriction = disc.dynamicFriction = 1.0;
    disc.collisionDetection = detection;
    const double start = -M_PI / 2.0 + M_PI / 3.0;  // 60 degrees up the right side, from the bottom
    disc.position = (R - r) * Vec2(std::cos(start), std::sin(start));
    const BodyId id = world.createBody(disc);
    const double h = world.position(id).y() - (-(R - r));
    double fastest = 0.0;
    for (int i = 0; i < 80; ++i) {  // 2 s: past the bottom once (a quarter period is about 0.6 s)
        world.step(1.0 / 40.0);
        fastest = std::max(fastest, world.velocity(id).norm());
    }
    return {fastest, std::sqrt(4.0 * kG * h / 3.0)};
}

TEST(Chain, ADiscRollsDownACurvedChainAsDownTheCurve) {
    const auto [fastest, predicted] = rollDownTheHalfPipe(CollisionDetection::Discrete);
    EXPECT_NEAR(fastest, predicted, 0.02 * predicted);
}

TEST(Chain, AContinuousDiscRollsDownACurvedChainAsADiscreteOne) {
    // At 40 Hz the disc crosses more than a piece a step: its sweep enters the next piece's line at each concave
    // joint without striking it, which must cost no impact (tolerance as above).
    for (const CollisionDetection d : {CollisionDetection::ContinuousExact, CollisionDetection::ContinuousSampled}) {
        const auto [fastest, predicted] = rollDownTheHalfPipe(d);
        EXPECT_NEAR(fastest, predicted, 0.02 * predicted) << static_cast<int>(d);
    }
}

TEST(Chain, AFastDiscEnteringAConcaveJointKeepsItsStep) {
    // A discrete disc that moves more than half its radius in a step is swept against the ground. Here it slides
    // (frictionless) along a flat piece into a concave joint (the next piece rises 0.1 in 2) and ends the step
    // 1.3 cm into the rising piece's line, its centre still 0.19 m in front of it: it has not passed the piece,
    // the contacts answer the overlap, so the sweep must not put it back (an impact there keeps the speed and
    // drops the step's motion: energy gained). Without friction or a contact that step, x moves by v dt exactly;
    // 1e-9 m is rounding.
    World world;
    addChainGround(world, {{-2.0, 0.0}, {0.0, 0.0}, {2.0, 0.1}}, false, 0.0);
    BodyDef disc;
    disc.shape = makeCircle(0.2);
    disc.staticFriction = disc.dynamicFriction = 0.0;
    disc.position = {-0.05, 0.2};
    disc.velocity = {8.0, 0.0};
    const BodyId id = world.createBody(disc);
    world.step(1.0 / 40.0);
    EXPECT_NEAR(world.position(id).x(), -0.05 + 8.0 / 40.0, 1e-9);
}

TEST(Chain, AFastDiscFallingOntoAChainStaysInFront) {
    // The other side of the rule above: a discrete disc falling at 30 m/s (0.75 m a step at 40 Hz, past the chain in
    // one step) onto a flat chain ends each step in front of it.
    World world;
    addChainGround(world, {{-5.0, 0.0}, {0.0, 0.0}, {5.0, 0.0}});
    BodyDef disc;
    disc.shape = makeCircle(0.2);
    disc.position = {0.3, 1.0};
    disc.velocity = {0.0, -30.0};
    const BodyId id = world.createBody(disc);
    for (int i = 0; i < 20; ++i) {
        world.step(1.0 / 40.0);
        EXPECT_GT(world.position(id).y(), 0.0) << "step " << i;
    }
}

TEST(Chain, ABoxSlidingDownACurvedChainGainsNoEnergy) {
    // Frictionless, 40 Hz, the half-pipe of the disc test: a sliding box may lose energy at the concave joints (its
    // path turns there) but never gain. Tolerance 0.5% of the drop: what the soft contacts' push-out of an
    // overlap within the slop can give back.
    World world;
    const double R = 3.0, half = 0.1;
    addChainGround(world, halfPipe(R, 120), false, 0.0);
    BodyDef box;
    box.shape = makeBox(0.2, half);
    box.staticFriction = box.dynamicFriction = 0.0;
    const double start = -M_PI / 2.0 + M_PI / 3.0;
    box.position = (R - half) * Vec2(std::cos(start), std::sin(start));
    box.angle = start + M_PI / 2.0;
    const BodyId id = world.createBody(box);
    const double m = world.mass(id), inertia = world.inertia(id);
    auto energy = [&] {
        return 0.5 * m * world.velocity(id).squaredNorm() +
               0.5 * inertia * world.angularVelocity(id) * world.angularVelocity(id) + m * kG * world.position(id).y();
    };
    const double e0 = energy(), drop = m * kG * (world.position(id).y() + (R - half));
    for (int i = 0; i < 160; ++i) {  // 4 s: past the bottom three times
        world.step(1.0 / 40.0);
        EXPECT_LT(energy() - e0, 0.005 * drop) << "step " << i;
    }
}

// A frictionless 1 m box turned by `angle` (rad), sliding at 4 m/s for 10 s (40 m: 160 joints) over a flat chain
// of 0.25 m pieces: its lowest horizontal speed and highest centre over the run.
struct Slide {
    double lowest = 4.0, highest = 0.0;
    BodyId box;
};
Slide slideOverFlatChain(World& world, double angle) {
    std::vector<Vec2> points;
    for (int i = 0; i <= 400; ++i) points.emplace_back(-50.0 + 0.25 * i, 0.0);
    addChainGround(world, points, false, 0.0);
    BodyDef box;
    box.shape = makeBox(0.5, 0.5);
    box.position = {-45.0, 0.5};
    box.angle = angle;
    box.velocity = {4.0, 0.0};
    box.staticFriction = box.dynamicFriction = 0.0;
    Slide slide;
    slide.box = world.createBody(box);
    for (int i = 0; i < 600; ++i) {
        world.step(1.0 / 60.0);
        slide.lowest = std::min(slide.lowest, world.velocity(slide.box).x());
        slide.highest = std::max(slide.highest, world.position(slide.box).y());
    }
    return slide;
}

TEST(Chain, ABoxSlidesAcrossManyJointsWithoutABump) {
    // The box's horizontal speed stays what it was (a joint that caught its corner would take some), and it never
    // leaves the ground.
    World world(test::awakeSettings());
    const Slide slide = slideOverFlatChain(world, 0.0);
    // Relative 1e-9: only rounding may change a free slide's speed; a bump is a change of order 1e-2 or more.
    EXPECT_NEAR(slide.lowest, 4.0, 4e-9);
    EXPECT_LT(slide.highest, 0.5 + 1e-3);
    EXPECT_NEAR(world.angle(slide.box), 0.0, 1e-5) << "a caught corner tips the box by 1e-2 rad or more";
}

TEST(Chain, ABoxTurnedByAHairSlidesAcrossJointsWithoutLosingSpeed) {
    // Turned by 2e-5 rad, the box's face meets each joint's vertex just before its corner does, with the face's own
    // normal, leaning 2e-5 off the ground's. Taken as it is, that push along the ground cost 5e-7 m/s over the run;
    // at a flat joint the piece answers along its face normal instead, and nothing is lost.
    World world(test::awakeSettings());
    EXPECT_NEAR(slideOverFlatChain(world, 2e-5).lowest, 4.0, 4e-9);  // as above: rounding only
}

TEST(Chain, IsOneSided) {
    // Ground listed left to right is solid below: a ball thrown up from below passes through, one dropped from
    // above lands on it.
    World world(test::awakeSettings());
    addChainGround(world, {{-5.0, 0.0}, {0.0, 0.0}, {5.0, 0.0}});
    BodyDef ball;
    ball.shape = makeCircle(0.25);
    ball.position = {-1.0, -1.0};
    ball.velocity = {0.0, 8.0};
    const BodyId up = world.createBody(ball);
    ball.position = {1.0, 2.0};
    ball.velocity = Vec2::Zero();
    const BodyId down = world.createBody(ball);
    double highest = -1.0;
    for (int i = 0; i < 90; ++i) {
        world.step(1.0 / 60.0);
        highest = std::max(highest, world.position(up).y());
    }
    EXPECT_GT(highest, 1.0) << "from behind, the chain is not there";
    EXPECT_NEAR(world.position(down).y(), 0.25, 5e-3) << "from the front, it is ground";
}

TEST(Chain, ACounterClockwiseLoopHoldsBodiesInside) {
    World world;
    addChainGround(world, {{-2.0, 0.0}, {2.0, 0.0}, {2.0, 4.0}, {-2.0, 4.0}}, true);
    std::vector<BodyId> balls;
    for (int i = 0; i < 12; ++i) {
        BodyDef d;
        d.shape = i % 2 == 0 ? Geometry(makeCircle(0.2)) : Geometry(makeCapsule({-0.2, 0.0}, {0.2, 0.0}, 0.1));
        d.position = {-1.5 + 0.27 * i, 1.0 + 0.2 * i};
        d.velocity = {i % 3 == 0 ? 6.0 : -6.0, 3.0};
        d.restitution = 0.5;
        balls.push_back(world.createBody(d));
    }
    for (int i = 0; i < 600; ++i) world.step(1.0 / 60.0);
    for (const BodyId id : balls) {
        const Vec2 p = world.position(id);
        EXPECT_TRUE(p.x() > -2.0 && p.x() < 2.0 && p.y() > 0.0 && p.y() < 4.0) << p.transpose();
    }
}

TEST(Chain, AnExactBulletStopsAtTheFrontAndPassesFromBehind) {
    WorldSettings s = test::awakeSettings({0.0, 0.0});
    World world(s);
    addChainGround(world, {{-5.0, 0.0}, {0.0, 0.0}, {5.0, 0.0}});
    BodyDef bullet;
    bullet.shape = makeCircle(0.05);
    bullet.collisionDetection = CollisionDetection::ContinuousExact;
    bullet.position = {0.3, 2.0};
    bullet.velocity = {0.0, -300.0};  // 5 m a step at 60 Hz: far more than its size
    const BodyId front = world.createBody(bullet);
    bullet.position = {-0.3, -2.0};
    bullet.velocity = {0.0, 300.0};
    const BodyId back = world.createBody(bullet);
    for (int i = 0; i < 3; ++i) world.step(1.0 / 60.0);
    EXPECT_GT(world.position(front).y(), 0.0) << "exact detection never tunnels through the solid side";
    EXPECT_GT(world.position(back).y(), 5.0) << "from behind it flies on";
}

// A discrete disc (r = 0.1 m) resting on a flat chain, struck from above by a 1 m box falling at 10 to 40 m/s, 300 to
// 30 000 times its mass: the box drives the disc past half its radius in one step, so the Continuous stage sees it
// as fast but touching the chain from the start. Its centre must stay in front of the chain (y > 0, no tolerance):
// behind the piece's line the one-sided narrow phase gives no contact and the disc falls away. Without the stage's
// check of the centroid's path it ends metres below. (A slower press, where the disc moves less than half its radius
// a step, is the contacts' business: a box 3 000 times the disc's mass at 5 m/s still squeezes it through.)
TEST(Chain, ADiscPressedIntoAChainByAHeavyBoxStaysInFront) {
    for (const double speed : {10.0, 20.0, 40.0})
        for (const double density : {10.0, 1000.0}) {
            World world;
            addChainGround(world, {{-5.0, 0.0}, {0.0, 0.0}, {5.0, 0.0}});
            EXPECT_GT(test::lowestDiscUnderAFallingBox(world, speed, density), 0.0)
                << speed << " m/s, density " << density;
        }
}

// A small copy of peer_bench's spinner: a loop of 90 pieces on a circle of 10 m, a rounded bar pinned 5 m below its
// centre reaching its bottom, turned at 20 rad/s (100 m/s at the tip) by an unbounded motor, and 150 capsules,
// discs and squares inside. The bar flings the crowd around the loop, which presses its outer bodies into the chain
// at tens of g, fast and already touching. Over 5 s every centre stays within the loop's circle (a centre that
// crossed a piece falls away, metres out; the 6 mm between a piece and the circle is far less than any escape).
// Without the Continuous stage's check of a touching body's centroid, 80 of the 150 are outside at the end.
TEST(Chain, ASpinnerKeepsItsCrowdInsideTheLoop) {
    const double R = 10.0;
    World world;
    std::vector<Vec2> points;
    for (int i = 0; i < 90; ++i) points.push_back(R * Vec2(std::cos(2.0 * M_PI * i / 90), std::sin(2.0 * M_PI * i / 90)));
    const BodyId ground = addChainGround(world, points, true, 0.1);
    BodyDef bar;
    bar.shape = makeRoundedBox(0.4, 0.5 * R - 0.2, 0.2);
    bar.position = {0.0, -0.5 * R};
    bar.allowSleep = false;
    bar.staticFriction = bar.dynamicFriction = 0.0;
    RevoluteJointDef pin;
    pin.bodyA = ground;
    pin.bodyB = world.createBody(bar);
    pin.anchor = bar.position;
    pin.enableMotor = true;
    pin.motorSpeed = 20.0;
    pin.maxMotorTorque = 1e30;
    world.createRevoluteJoint(pin);
    std::vector<BodyId> crowd;
    for (int row = 0; row < 6; ++row)
        for (int column = 0; column < 25; ++column) {
            BodyDef b;
            b.position = {-6.0 + 0.5 * column, -3.0 + 0.5 * row};
            b.density = 0.25;
            b.staticFriction = b.dynamicFriction = 0.1;
            b.restitution = 0.1;
            const int kind = static_cast<int>(crowd.size()) % 3;
            if (kind == 0) b.shape = makeCapsule({-0.25, 0.0}, {0.25, 0.0}, 0.25);
            else if (kind == 1) b.shape = makeCircle(0.35);
            else b.shape = makeBox(0.35, 0.35);
            crowd.push_back(world.createBody(b));
        }
    for (int i = 0; i < 300; ++i) {
        world.step(1.0 / 60.0);
        for (std::size_t k = 0; k < crowd.size(); ++k)
            ASSERT_LT(world.position(crowd[k]).norm(), R) << "body " << k << " left the loop in step " << i;
    }
}

// The narrow phase skips a chain piece's routine while an empty answer's promise holds (StaysEmpty), and reuses an
// empty answer while the pair moves less than the reuse tolerance unless the answer was fragile (a rule on
// directions dropped the point): no pair it skips may touch. Discs and boxes roll, slide, bounce and come to rest
// over 300 pieces of rolling ground at 40 Hz (wheels left to a piece's neighbour, pieces out of reach, bodies
// behind pieces as they jump, boxes across joints). Each step, every body is collided afresh with every piece near
// it at the poses the step started from: each point closer than half the speculative distance (the narrow phase
// keeps any point closer than the whole) must be in the world's contacts of that step with its feature id. A
// promise that held too long would drop such a point (three times too long: hundreds missed), and so did the reuse of a
// fragile empty answer for a box resting across a joint (292 missed, corner points 45 micrometres deep).
TEST(Chain, NoPieceThatTouchesIsSkipped) {
    WorldSettings settings;
    settings.enableSleep = false;  // contacts() lists the awake ones
    World world(settings);
    std::vector<Vec2> ground;
    for (int i = 0; i <= 300; ++i) {
        const double x = -37.5 + 0.25 * i;
        ground.emplace_back(x, 0.4 * std::sin(x / 2.3) + 0.1 * std::sin(x / 0.7));
    }
    const BodyId chain = addChainGround(world, ground);
    const std::vector<ShapeId> pieces = world.shapes(chain);
    std::vector<BodyId> bodies;
    for (int k = 0; k < 16; ++k) {
        BodyDef d;
        d.shape = k % 4 == 3 ? Geometry{makeBox(0.3, 0.2)} : Geometry{makeCircle(0.2 + 0.05 * (k % 5))};
        d.position = {-30.0 + 3.7 * k, 1.5 + 0.3 * (k % 3)};
        d.velocity = {k % 2 == 0 ? 2.0 + 0.5 * k : -3.0, 0.0};
        d.angularVelocity = k % 3 == 0 ? -8.0 : 0.0;
        bodies.push_back(world.createBody(d));
    }
    const double speculative = 4.0 * world.settings().linearSlop;
    int checked = 0;
    for (int step = 0; step < 300; ++step) {
        std::vector<Transform> before;
        for (const BodyId b : bodies) before.push_back(world.transform(b));
        world.step(1.0 / 40.0);
        for (std::size_t i = 0; i < bodies.size(); ++i) {
            for (const ShapeId piece : pieces) {
                const Geometry& pieceShape = world.geometry(piece);
                const Vec2 mid = 0.5 * (std::get<ChainSegment>(pieceShape).segment.point1 +
                                        std::get<ChainSegment>(pieceShape).segment.point2);
                if ((mid - before[i].p).norm() > 1.5) continue;
                const Manifold fresh = collideGeometries(pieceShape, Transform{}, world.shape(bodies[i]), before[i],
                                                         0.5 * speculative)
                                           .manifold;
                for (int p = 0; p < fresh.pointCount; ++p) {
                    bool found = false;
                    for (const Manifold& m : world.contacts())
                        if ((m.shapeA == piece && m.bodyB == bodies[i]) || (m.shapeB == piece && m.bodyA == bodies[i]))
                            for (int q = 0; q < m.pointCount; ++q) found = found || m.points[q].id == fresh.points[p].id;
                    EXPECT_TRUE(found) << "step " << step << ", body " << i << ", piece " << piece.index;
                    ++checked;
                }
            }
        }
    }
    EXPECT_GT(checked, 2000);
}

TEST(Chain, BadInputIsNamedAndLeavesTheWorldUnchanged) {
    World world;
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.withShape = false;
    const BodyId id = world.createBody(ground);
    auto refuse = [&](const ChainDef& def, const std::string& words) {
        try {
            world.createChain(id, def);
            ADD_FAILURE() << "accepted: " << words;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
        EXPECT_EQ(world.shapeCount(), 0u);
    };
    ChainDef def;
    def.points = {{0.0, 0.0}};
    refuse(def, "at least 2 points");
    def.points = {{0.0, 0.0}, {1.0, 0.0}};
    def.loop = true;
    refuse(def, "at least 3 points");
    def.loop = false;
    def.points = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}};
    refuse(def, "point 1 and point 2");
    def.points = {{0.0, 0.0}, {1.0, std::nan("")}, {2.0, 0.0}};
    refuse(def, "point");
    def.points = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 0.0}};
    def.loop = true;
    refuse(def, "point 3 and point 0");
    def.loop = false;
    def.points = {{0.0, 0.0}, {1.0, 0.0}};
    def.restitution = 2.0;
    refuse(def, "restitution");
    def.restitution = 0.0;
    EXPECT_EQ(world.createChain(id, def).size(), 1u);
    EXPECT_EQ(world.shapeCount(), 1u);
}

TEST(Chain, PiecesKnowTheirNeighbours) {
    const std::vector<Vec2> p = {{0.0, 0.0}, {1.0, 0.0}, {2.0, 1.0}, {3.0, 1.0}};
    const std::vector<ChainSegment> open = makeChain(p);
    ASSERT_EQ(open.size(), 3u);
    EXPECT_EQ(open[0].ghost1, p[0]) << "an open end is a real corner";
    EXPECT_EQ(open[0].ghost2, p[2]);
    EXPECT_EQ(open[1].ghost1, p[0]);
    EXPECT_EQ(open[2].ghost2, p[3]);
    const std::vector<ChainSegment> loop = makeChain(p, true);
    ASSERT_EQ(loop.size(), 4u);
    EXPECT_EQ(loop[0].ghost1, p[3]);
    EXPECT_EQ(loop[3].segment.point2, p[0]);
    EXPECT_EQ(loop[3].ghost2, p[1]);
}

}  // namespace
}  // namespace physim
