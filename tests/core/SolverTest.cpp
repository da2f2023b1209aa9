// The solve island by island: a scene of many islands is solved in groups of whole islands, each group through
// all of its substeps before the next. Islands never share a dynamic body, so a pile must move exactly as it would
// alone in its world, and the grouping must not depend on the thread count.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kPileSpacing = 5.0;  // m between the piles' centres: no pile reaches the next

WorldSettings crowdSettings(int threads = 1) {
    WorldSettings s;
    s.gravity = {0.0, -10.0};
    s.enableSleep = false;  // every pile stays awake: the solver sees every island in every step
    s.threads = threads;
    return s;
}

/// A slightly tilted pyramid of 28 boxes centred at x with a bouncing ball dropped on it: 29 bodies whose contacts
/// keep changing (the ball bounces, the tilted rows settle). Returns the bodies in creation order.
std::vector<BodyId> addPile(World& world, double x, int seed) {
    std::vector<BodyId> ids;
    const int base = 7;
    const double half = 0.25;
    for (int row = 0; row < base; ++row)
        for (int i = 0; i < base - row; ++i) {
            BodyDef d;
            d.shape = makeBox(half, half);
            d.position = {x + 2 * half * (i + 0.5 * row - 0.5 * (base - 1)) + 0.01 * row, half + 2 * half * row};
            d.angle = 0.02 * row * ((seed % 3) - 1);
            d.staticFriction = d.dynamicFriction = 0.6;
            ids.push_back(world.createBody(d));
        }
    BodyDef ball;
    ball.shape = makeCircle(0.2);
    ball.position = {x + 0.1 * (seed % 5) - 0.2, 6.0};
    ball.velocity = {0.3 * (seed % 4) - 0.45, -2.0};
    ball.restitution = 0.8;
    ids.push_back(world.createBody(ball));
    return ids;
}

std::vector<double> poses(const World& world, const std::vector<BodyId>& ids) {
    std::vector<double> out;
    for (const BodyId id : ids)
        for (const double v : {world.position(id).x(), world.position(id).y(), world.angle(id),
                               world.velocity(id).x(), world.velocity(id).y(), world.angularVelocity(id)})
            out.push_back(v);
    return out;
}

bool sameBits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// 16 piles of 29 bodies (464: more than one group) on one ground. Each of three piles, built alone in a world of
// its own (one island, one group), must end with the same bits as in the crowd: nothing of another island, and
// nothing of how islands were grouped, may reach a pile.
TEST(Solver, EachIslandMovesAsIfItWereAlone) {
    const int piles = 16, steps = 150;
    World crowd(crowdSettings());
    test::addGround(crowd, 60.0);
    std::vector<std::vector<BodyId>> crowdIds;
    for (int p = 0; p < piles; ++p) crowdIds.push_back(addPile(crowd, kPileSpacing * (p - piles / 2), p));
    for (int i = 0; i < steps; ++i) crowd.step(kDt);

    for (const int p : {0, 9, 15}) {
        World alone(crowdSettings());
        test::addGround(alone, 60.0);
        const std::vector<BodyId> ids = addPile(alone, kPileSpacing * (p - piles / 2), p);
        for (int i = 0; i < steps; ++i) alone.step(kDt);
        const std::vector<double> expected = poses(alone, ids), got = poses(crowd, crowdIds[p]);
        EXPECT_TRUE(sameBits(expected, got)) << "pile " << p;
        // The pile did something worth comparing: the ball bounced and came to the pile.
        EXPECT_LT(alone.position(ids.back()).y(), 5.0) << "pile " << p;
    }
}

// After a step's first substep an island warm-starts on its bodies, unless it has a joint or an exact-continuous
// bullet (those keep the pass over the rows, the same to rounding only). A small world is one group; a pile beside a
// pinned pair of piles and a bullet in the same world must still end with the bits it has alone.
TEST(Solver, AnIslandKeepsItsBitsBesideAJointAndABullet) {
    const int steps = 150;
    World crowd(crowdSettings());
    test::addGround(crowd, 60.0);
    const std::vector<BodyId> pile = addPile(crowd, 0.0, 4);
    const std::vector<BodyId> left = addPile(crowd, -2.0 * kPileSpacing, 1), right = addPile(crowd, -kPileSpacing, 2);
    RevoluteJointDef pin;
    pin.bodyA = left[27];
    pin.bodyB = right[27];
    pin.anchor = {-1.5 * kPileSpacing, 3.5};
    crowd.createRevoluteJoint(pin);
    BodyDef bullet;
    bullet.shape = makeCircle(0.05);
    bullet.position = {2.0 * kPileSpacing, 3.0};
    bullet.velocity = {0.0, -150.0};
    bullet.restitution = 1.0;
    bullet.collisionDetection = CollisionDetection::ContinuousExact;
    const BodyId shot = crowd.createBody(bullet);
    for (int i = 0; i < steps; ++i) crowd.step(kDt);
    ASSERT_EQ(crowd.bodyCount(), 1u + 3u * 29u + 1u) << "one group: under 256 bodies";

    World alone(crowdSettings());
    test::addGround(alone, 60.0);
    const std::vector<BodyId> ids = addPile(alone, 0.0, 4);
    for (int i = 0; i < steps; ++i) alone.step(kDt);
    EXPECT_TRUE(sameBits(poses(alone, ids), poses(crowd, pile)));
    EXPECT_LT(alone.position(ids.back()).y(), 5.0) << "the ball came to the pile";
    EXPECT_GT(crowd.position(shot).y(), 0.0) << "the bullet bounced off the ground";
}

// A crowd with a large island (a base-46 pyramid, 1081 boxes: a group that spreads its loops over the threads),
// small piles (groups that go to the threads whole), two piles joined by a joint and two touched by one kinematic
// paddle (each pair one island): the same bits on 1, 2 and every hardware thread.
std::vector<double> crowdScene(int threads) {
    World world(crowdSettings(threads));
    test::addGround(world, 120.0);
    std::vector<BodyId> ids = test::addPyramid(world, 46, -47.5);
    std::vector<std::vector<BodyId>> piles;
    for (int p = 0; p < 12; ++p) {
        piles.push_back(addPile(world, kPileSpacing * p, p));
        ids.insert(ids.end(), piles.back().begin(), piles.back().end());
    }
    RevoluteJointDef pin;
    pin.bodyA = piles[0][27];  // the tops of piles 0 and 1, pinned halfway between them
    pin.bodyB = piles[1][27];
    pin.anchor = {0.5 * kPileSpacing, 3.5};
    world.createRevoluteJoint(pin);
    BodyDef paddle;
    paddle.type = BodyType::Kinematic;
    paddle.shape = makeBox(3.0, 0.1);
    paddle.position = {7.5 * kPileSpacing, 3.6};  // over piles 7 and 8, coming down on them
    paddle.velocity = {0.0, -0.15};
    ids.push_back(world.createBody(paddle));
    // The impact events too (each group's store pass finds its rows' impacts, on whichever worker solves it):
    // bodies, point and speed, step by step.
    constexpr std::size_t kImpactFields = 8;  // per event, as below
    std::vector<double> impacts;
    for (int i = 0; i < 90; ++i) {
        world.step(kDt);
        for (const ImpactEvent& e : world.contactEvents().impacts)
            for (const double v : {double(e.bodyA.index), double(e.bodyB.index), e.point.x(), e.point.y(),
                                   e.normal.x(), e.normal.y(), e.approachSpeed, double(i)})
                impacts.push_back(v);
    }
    std::vector<double> out = poses(world, ids);
    out.push_back(static_cast<double>(impacts.size() / kImpactFields));
    out.insert(out.end(), impacts.begin(), impacts.end());
    return out;
}

TEST(Solver, ManyIslandsGiveTheSameBitsOnAnyThreadCount) {
    const std::vector<double> one = crowdScene(1);
    const std::size_t bodies = 1081 + 12 * 29 + 1;
    ASSERT_GT(one.size(), 6 * bodies);
    EXPECT_GE(one[6 * bodies], 12.0) << "impacts: at least each pile's ball landing";
    for (const int threads : {2, 0}) EXPECT_TRUE(sameBits(one, crowdScene(threads))) << threads << " threads";
}

// A step keeps the last step's row layout (colours, groups, blocks) while nothing that decides it changed. Two
// worlds run the same script of changes, with sleep on; before each step one of them changes the static ground's
// detection to what it already is, which changes nothing physical but makes the step lay its rows out again. Both
// must end with the same bits, and each with a mix of laid-out and kept steps, or the comparison proves nothing.
struct LayoutRun {
    std::vector<double> poses;
    int laidOut = 0, kept = 0;  // steps with rows that laid them out again, and that kept the last layout
};

LayoutRun layoutScript(bool layOutEveryStep) {
    WorldSettings settings = crowdSettings();
    settings.enableSleep = true;
    World world(settings);
    BodyDef g;
    g.type = BodyType::Static;
    g.shape = makeBox(60.0, 0.5);
    g.position = {0.0, -0.5};
    const BodyId ground = world.createBody(g);
    std::vector<BodyId> ids = addPile(world, 0.0, 4);
    const std::vector<BodyId> other = addPile(world, kPileSpacing, 2);
    ids.insert(ids.end(), other.begin(), other.end());
    LayoutRun run;
    JointId mouse;
    for (int i = 0; i < 400; ++i) {
        if (i == 60) {  // the first pile's top box pinned to one below it: a joint row in a kept layout
            RevoluteJointDef pin;
            pin.bodyA = ids[25];
            pin.bodyB = ids[27];
            pin.anchor = world.position(ids[27]);
            world.createRevoluteJoint(pin);
        }
        if (i == 80) {
            MouseJointDef grab;
            grab.body = ids[29 + 27];  // the second pile's top box, pulled up and sideways
            grab.target = world.position(grab.body);
            grab.maxForce = 50.0;
            mouse = world.createMouseJoint(grab);
        }
        if (i > 80 && i < 110)
            world.setMouseJointTarget(mouse, {kPileSpacing + 0.01 * (i - 80), 3.0 + 0.02 * (i - 80)});
        if (i == 110) world.destroyJoint(mouse);
        if (i == 120) world.setCollisionDetection(ids[20], CollisionDetection::ContinuousExact);
        if (i == 160) world.setCollisionDetection(ids[20], CollisionDetection::Discrete);
        if (i == 200) world.setType(ids[27], BodyType::Kinematic);  // the pile's top box
        if (i == 240) world.setType(ids[27], BodyType::Dynamic);
        if (i == 260) world.destroyBody(ids[30]);  // in the second pile's bottom row
        if (i == 300) {
            BodyDef ball;
            ball.shape = makeCircle(0.2);
            ball.position = {0.3, 5.0};
            ids.push_back(world.createBody(ball));
        }
        if (layOutEveryStep) world.setCollisionDetection(ground, CollisionDetection::Discrete);
        world.step(kDt);
        if (world.profile().manifolds == 0) continue;  // nothing to solve (everything asleep)
        ++(world.profile().rowsLaidOut ? run.laidOut : run.kept);
    }
    ids.erase(ids.begin() + 30);
    run.poses = poses(world, ids);
    return run;
}

TEST(Solver, AKeptRowLayoutGivesTheBitsOfOneLaidOutAgain) {
    const LayoutRun kept = layoutScript(false), again = layoutScript(true);
    EXPECT_TRUE(sameBits(kept.poses, again.poses));
    EXPECT_EQ(again.kept, 0) << "the forcing change lays the rows out every step";
    EXPECT_GE(again.laidOut, 200);
    EXPECT_GE(kept.kept, 100) << "settled piles keep their layout";
    EXPECT_GE(kept.laidOut, 20) << "bounces, the changes, sleeping and waking lay the rows out again";
}

// Balls rolling down a chain meet the pieces ahead and leave those behind: contacts without points join and leave
// the awake list nearly every step. They decide no row, so the layout is kept through them, with the bits of one
// laid out every step.
struct ChainRun {
    std::vector<double> poses;
    int kept = 0;  // steps that kept the last step's layout
};
ChainRun ballsDownAChain(bool layOutEveryStep) {
    World world(crowdSettings());
    BodyDef g;
    g.type = BodyType::Static;
    g.withShape = false;
    const BodyId ground = world.createBody(g);
    ChainDef chain;
    for (int i = 0; i <= 160; ++i) chain.points.emplace_back(0.25 * i, -0.1 * 0.25 * i);  // 0.1 down a metre
    world.createChain(ground, chain);
    std::vector<BodyId> ids;
    for (int k = 0; k < 4; ++k) {
        BodyDef ball;
        ball.shape = makeCircle(0.3);
        ball.position = {1.0 + 8.0 * k, 0.31 - 0.1 * (1.0 + 8.0 * k)};
        ids.push_back(world.createBody(ball));
    }
    ChainRun run;
    for (int i = 0; i < 240; ++i) {
        if (layOutEveryStep) world.setCollisionDetection(ground, CollisionDetection::Discrete);
        world.step(kDt);
        if (!world.profile().rowsLaidOut) ++run.kept;
    }
    run.poses = poses(world, ids);
    return run;
}

TEST(Solver, ContactsWithoutPointsComingAndGoingKeepTheRowLayoutAndItsBits) {
    const ChainRun kept = ballsDownAChain(false), again = ballsDownAChain(true);
    EXPECT_TRUE(sameBits(kept.poses, again.poses));
    EXPECT_EQ(again.kept, 0);
    // 217 of 240 steps keep it; 185 did when any contact joining or leaving laid the rows out again.
    EXPECT_GE(kept.kept, 205) << "chain pieces ahead join and those behind leave without points";
}

// Each change that decides the layout lays the rows out again in the next step, and the step after keeps it.
TEST(Solver, ChangesThatDecideTheRowLayoutLayItOutAgain) {
    World world(crowdSettings());
    test::addGround(world, 60.0);
    const std::vector<BodyId> ids = addPile(world, 0.0, 4);
    for (int i = 0; i < 240; ++i) world.step(kDt);  // the ball has bounced off and the pile settled
    world.step(kDt);
    ASSERT_GT(world.profile().manifolds, 0u);
    ASSERT_FALSE(world.profile().rowsLaidOut) << "a settled pile keeps its layout";
    auto next = [&](const char* change) {
        world.step(kDt);
        EXPECT_TRUE(world.profile().rowsLaidOut) << change;
        world.step(kDt);
        EXPECT_FALSE(world.profile().rowsLaidOut) << change << ", the step after";
    };
    world.setType(ids[0], BodyType::Kinematic);
    next("setType");
    world.setType(ids[0], BodyType::Dynamic);
    next("setType back");
    world.setCollisionDetection(ids[3], CollisionDetection::ContinuousExact);
    next("setCollisionDetection");
    WorldSettings settings = world.settings();
    settings.threads = 2;
    world.setSettings(settings);
    next("setSettings");
    DistanceJointDef rod;
    rod.bodyA = ids[0];
    rod.bodyB = ids[1];
    const JointId joint = world.createDistanceJoint(rod);
    next("createDistanceJoint");
    world.destroyJoint(joint);
    next("destroyJoint");
    BodyDef far;
    far.position = {40.0, 10.0};
    const BodyId farBody = world.createBody(far);
    next("createBody");
    world.destroyBody(farBody);
    next("destroyBody");
}


// On two threads a spread group runs its colours, and its substeps with the bodies' loops between, as one ordered
// sequence (Team::forLoopsInOrder); the sequence's loops are decoded from the pass counts. A pyramid of 210 boxes
// (one group, its halves meeting in few blocks) with an elastic ball bouncing on it must give one thread's bits
// for every count of solve and relax passes and of substeps.
std::vector<double> pyramidWithBall(int threads, int substeps, int solves, int relaxes) {
    WorldSettings settings = crowdSettings(threads);
    settings.substeps = substeps;
    settings.velocityIterations = solves;
    settings.relaxIterations = relaxes;
    World world(settings);
    test::addGround(world, 30.0);
    std::vector<BodyId> ids = test::addPyramid(world, 20);
    BodyDef ball;
    ball.shape = makeCircle(0.3);
    ball.position = {0.2, 22.0};
    ball.restitution = 0.9;  // a bounce: the warm start the bodies' loops keep (bounces) is read in the sequence
    ids.push_back(world.createBody(ball));
    for (int i = 0; i < 90; ++i) world.step(kDt);
    return poses(world, ids);
}

TEST(Solver, TwoThreadsInOrderGiveOneThreadsBitsForAnyPassCounts) {
    for (const auto& [substeps, solves, relaxes] :
         {std::array<int, 3>{8, 1, 1}, {3, 2, 0}, {5, 1, 2}, {1, 3, 1}, {4, 1, 0}}) {
        const std::vector<double> one = pyramidWithBall(1, substeps, solves, relaxes);
        EXPECT_TRUE(sameBits(one, pyramidWithBall(2, substeps, solves, relaxes)))
            << substeps << " substeps, " << solves << " solve and " << relaxes << " relax passes";
    }
}

// Circles made row by row from the floor up and dropped into a box: their contacts begin in the order the pile
// forms as it falls, not in the bodies' order. Each colour's rows are laid out in their bodies' order, so on two
// threads the halves of each colour are the lower and the upper part of the pile, and they meet only in a band
// across it: few head blocks. Laid out in the order the contacts began, the halves met in nearly every block, and
// the group went colour by colour (counting in neither). Either way, one thread's bits. How many blocks the band
// takes depends on how the pile happens to settle, which a nanometre in where the circles start changes (from about
// a fifth to a half of the blocks): three piles lifted by 0, 1 and 2 nm are counted together.
std::vector<double> circlePile(int threads, StepProfile& profile, double lift = 0.0) {
    World world(crowdSettings(threads));
    auto wall = [&](double x, double y, double hx, double hy) {
        BodyDef d;
        d.type = BodyType::Static;
        d.shape = makeBox(hx, hy);
        d.position = {x, y};
        world.createBody(d);
    };
    wall(0.0, -0.5, 7.0, 0.5);
    wall(-6.5, 8.0, 0.5, 8.0);
    wall(6.5, 8.0, 0.5, 8.0);
    std::vector<BodyId> ids;
    for (int k = 0; k < 360; ++k) {
        const int row = k / 18;
        BodyDef d;
        d.shape = makeCircle(0.25);
        d.position = {-5.4 + 0.6 * (k % 18) + 0.3 * (row % 2), 0.5 + 0.6 * row + lift};
        ids.push_back(world.createBody(d));
    }
    for (int i = 0; i < 240; ++i) world.step(kDt);
    profile = world.profile();
    return poses(world, ids);
}

TEST(Solver, APileSplitsIntoHalvesThatMeetInFewBlocksHoweverItsContactsBegan) {
    StepProfile one, two;
    const std::vector<double> onePoses = circlePile(1, one);
    EXPECT_TRUE(sameBits(onePoses, circlePile(2, two)));
    EXPECT_EQ(one.halvedBlocks, 0u);
    std::size_t heads = two.headBlocks, halved = two.halvedBlocks;
    for (const double lift : {1e-9, 2e-9}) {
        circlePile(2, two, lift);
        heads += two.headBlocks;
        halved += two.halvedBlocks;
    }
    ASSERT_GT(halved, 0u) << "the piles are halved, their heads under half their blocks";
    // The halves laid out in the contacts' order met in nearly every block; a band is well under half of them.
    EXPECT_LT(5 * heads, 2 * halved) << heads << " head blocks of " << halved;
}

// Joint rows are coloured and each colour is solved on the team's threads: plain pins four at a time in lanes, other
// rows (a pin with a motor or limits, a weld, a distance joint) one by one within their colour. A hanging net of
// discs pinned to their neighbours (Box2D's joint_grid, smaller), with all of those kinds in it and a pile of boxes
// beside it, must give the same bits on 1, 2 and every hardware thread, step after step, and set motors and limits
// that change which rows go in lanes must too.
std::vector<double> jointNet(int threads) {
    World world(crowdSettings(threads));
    test::addGround(world, 60.0);
    std::vector<BodyId> ids = addPile(world, 40.0, 3);
    constexpr int kSide = 24;
    std::vector<BodyId> net(kSide * kSide);
    for (int k = 0; k < kSide; ++k)
        for (int i = 0; i < kSide; ++i) {
            BodyDef d;
            d.type = i == 0 && (k == 0 || k == kSide / 2 || k == kSide - 1) ? BodyType::Static : BodyType::Dynamic;
            d.shape = makeCircle(0.4);
            d.position = {k, 60.0 - i};
            d.collides = false;
            net[k * kSide + i] = world.createBody(d);
            ids.push_back(net[k * kSide + i]);
        }
    std::vector<JointId> pins;
    for (int k = 0; k < kSide; ++k)
        for (int i = 0; i < kSide; ++i) {
            const BodyId body = net[k * kSide + i];
            if (i > 0 && (k + i) % 7 == 3) {  // some welds and distance joints among the pins
                WeldJointDef weld;
                weld.bodyA = net[k * kSide + i - 1];
                weld.bodyB = body;
                weld.anchor = {k, 60.5 - i};
                world.createWeldJoint(weld);
            } else if (i > 0 && (k + i) % 7 == 5) {
                DistanceJointDef rod;
                rod.bodyA = net[k * kSide + i - 1];
                rod.bodyB = body;
                world.createDistanceJoint(rod);
            } else if (i > 0) {
                RevoluteJointDef pin;
                pin.bodyA = net[k * kSide + i - 1];
                pin.bodyB = body;
                pin.anchor = {k, 60.5 - i};
                pin.enableLimit = (k * i) % 11 == 1;
                pin.lowerAngle = -0.2;
                pin.upperAngle = 0.3;
                pins.push_back(world.createRevoluteJoint(pin));
            }
            if (k > 0 && !(i == 0 && (k == kSide / 2 || k == kSide - 1))) {
                RevoluteJointDef pin;
                pin.bodyA = net[(k - 1) * kSide + i];
                pin.bodyB = body;
                pin.anchor = {k - 0.5, 60.0 - i};
                pin.enableMotor = (k * i) % 13 == 2;
                pin.motorSpeed = 1.0;
                pin.maxMotorTorque = 5.0;
                pins.push_back(world.createRevoluteJoint(pin));
            }
        }
    std::vector<double> out;
    for (int step = 0; step < 60; ++step) {
        if (step == 30)  // motors and limits on and off: rows move between the lanes and the scalar path
            for (std::size_t p = 0; p < pins.size(); p += 5) {
                world.setJointMotor(pins[p], p % 2 == 0, -0.5, 3.0);
                world.setJointLimits(pins[p], p % 3 == 0, -0.1, 0.1);
            }
        world.step(kDt);
        const std::vector<double> now = poses(world, ids);
        out.insert(out.end(), now.begin(), now.end());
    }
    return out;
}

TEST(Solver, JointNetOfRevoluteWeldAndDistanceJointsGivesTheSameBitsOnAnyThreadCount) {
    const std::vector<double> one = jointNet(1);
    for (const double v : one) ASSERT_TRUE(std::isfinite(v));
    for (const int threads : {2, 0}) EXPECT_TRUE(sameBits(one, jointNet(threads))) << threads << " threads";
}

}  // namespace
}  // namespace physim
