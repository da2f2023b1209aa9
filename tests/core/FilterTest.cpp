// Collision filtering (Filter.hpp, World::setFilter, World::setPairFilter): categories and masks, groups, the pair
// filter, a filter changed while the world runs, and a brute-force reference: over random filters, the touching
// contacts are exactly the overlapping pairs of shapes the filters allow.
// Tolerances: a box resting on a face sinks by about the linear slop (5 mm) under the soft contacts; 0.02 m is a
// few slops, far from the 0.5 m or more by which a box that fell through (or did not) is elsewhere.

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kRest = 0.02;  // m: how far a resting box may sit from where its faces meet (see above)

Filter filterOf(std::uint64_t category, std::uint64_t mask, std::int32_t group = 0) {
    Filter f;
    f.categoryBits = category;
    f.maskBits = mask;
    f.groupIndex = group;
    return f;
}

// Ground with its top face at y = 0, 20 m wide.
BodyId addGround(World& world, const Filter& filter = {}) {
    BodyDef g;
    g.type = BodyType::Static;
    g.shape = makeBox(10.0, 0.5);
    g.position = {0.0, -0.5};
    g.filter = filter;
    return world.createBody(g);
}

// A 1 m box with its centre at (x, y).
BodyId addBox(World& world, double x, double y, const Filter& filter = {}) {
    BodyDef b;
    b.shape = makeBox(0.5, 0.5);
    b.position = {x, y};
    b.filter = filter;
    return world.createBody(b);
}

void run(World& world, int steps) {
    for (int i = 0; i < steps; ++i) world.step(kDt);
}

bool touching(const World& world, BodyId a, BodyId b) {
    for (const Manifold& m : world.contacts())
        if ((m.bodyA == a && m.bodyB == b) || (m.bodyA == b && m.bodyB == a)) return true;
    return false;
}

template <class Events>
bool hasEvent(const Events& events, BodyId a, BodyId b) {
    return std::any_of(events.begin(), events.end(), [&](const ContactEvent& e) {
        return (e.bodyA == a && e.bodyB == b) || (e.bodyA == b && e.bodyB == a);
    });
}

TEST(Filter, CategoriesAndMasksLetOneCategoryFallThroughAnother) {
    World world;
    constexpr std::uint64_t kGround = 1, kLow = 2, kGhost = 4, kSolid = 8;
    addGround(world, filterOf(kGround, ~std::uint64_t{0}));
    // Left: a ghost dropped on a low box whose mask leaves ghosts out falls through it onto the ground.
    const BodyId low = addBox(world, -3.0, 0.5, filterOf(kLow, ~kGhost));
    const BodyId ghost = addBox(world, -3.0, 2.0, filterOf(kGhost, ~std::uint64_t{0}));
    // Right: the same low box under a solid box holds it: one refusing side is enough, and here neither refuses.
    const BodyId lowRight = addBox(world, 3.0, 0.5, filterOf(kLow, ~kGhost));
    const BodyId solid = addBox(world, 3.0, 2.0, filterOf(kSolid, ~std::uint64_t{0}));
    for (int i = 0; i < 180; ++i) {
        world.step(kDt);
        ASSERT_FALSE(touching(world, low, ghost)) << "step " << i;
    }
    EXPECT_NEAR(world.position(low).y(), 0.5, kRest);
    EXPECT_NEAR(world.position(ghost).y(), 0.5, kRest);  // on the ground, inside the low box
    EXPECT_NEAR(world.position(lowRight).y(), 0.5, kRest);
    EXPECT_NEAR(world.position(solid).y(), 1.5, kRest);  // stacked
}

TEST(Filter, GroupsOverrideTheBits) {
    World world;
    addGround(world);
    // Masks that refuse each other, in one positive group: they collide (the box stacks).
    const Filter refusesA = filterOf(2, ~std::uint64_t{4}, 7), refusesB = filterOf(4, ~std::uint64_t{2}, 7);
    addBox(world, -4.0, 0.5, refusesA);
    const BodyId stacked = addBox(world, -4.0, 2.0, refusesB);
    // Bits that accept each other, in one negative group: they never collide (the box falls through).
    const BodyId under = addBox(world, 0.0, 0.5, filterOf(1, ~std::uint64_t{0}, -3));
    const BodyId through = addBox(world, 0.0, 2.0, filterOf(1, ~std::uint64_t{0}, -3));
    // Different groups: the bits decide (here they refuse).
    addBox(world, 4.0, 0.5, filterOf(2, ~std::uint64_t{4}, 5));
    const BodyId otherGroup = addBox(world, 4.0, 2.0, filterOf(4, ~std::uint64_t{2}, -5));
    run(world, 180);
    EXPECT_NEAR(world.position(stacked).y(), 1.5, kRest);
    EXPECT_NEAR(world.position(through).y(), 0.5, kRest);
    EXPECT_FALSE(touching(world, under, through));
    EXPECT_NEAR(world.position(otherGroup).y(), 0.5, kRest);
    // shouldCollide itself, on the rule's cases.
    EXPECT_TRUE(shouldCollide(refusesA, refusesB));
    EXPECT_FALSE(shouldCollide(filterOf(1, ~std::uint64_t{0}, -3), filterOf(1, ~std::uint64_t{0}, -3)));
    EXPECT_FALSE(shouldCollide(filterOf(2, ~std::uint64_t{4}, 5), filterOf(4, ~std::uint64_t{2}, -5)));
    EXPECT_TRUE(shouldCollide(Filter{}, Filter{}));
}

TEST(Filter, PairCallbackRefusesPairsAndIsAskedOncePerPair) {
    WorldSettings settings;
    settings.enableSleep = false;  // the resting pair stays awake: a callback asked per step would show
    World world(settings);
    const BodyId ground = addGround(world);
    const BodyId kept = addBox(world, -2.0, 0.5);
    const BodyId dropped = addBox(world, 2.0, 0.5);
    const ShapeId droppedShape = world.shapes(dropped)[0];
    int keptCalls = 0, droppedCalls = 0;
    world.setPairFilter([&](ShapeId a, ShapeId b) {
        const bool refused = a == droppedShape || b == droppedShape;
        ++(refused ? droppedCalls : keptCalls);
        return !refused;
    });
    run(world, 120);
    EXPECT_NEAR(world.position(kept).y(), 0.5, kRest);
    EXPECT_TRUE(touching(world, ground, kept));
    EXPECT_LT(world.position(dropped).y(), -5.0);  // 2 s of free fall: about 19 m
    // The kept pair was asked once, when its contact was made, though it stayed awake 120 steps. The refused pair
    // was asked again each time the falling box's proxy moved while overlapping the ground's (it has no contact to
    // keep), and no more once it fell clear.
    EXPECT_EQ(keptCalls, 1);
    EXPECT_GT(droppedCalls, 0);
    const int droppedBefore = droppedCalls;
    run(world, 60);
    EXPECT_EQ(keptCalls, 1);
    EXPECT_EQ(droppedCalls, droppedBefore);
    // Clearing the callback asks every pair again at the next step; the kept contact stays.
    world.setPairFilter(nullptr);
    run(world, 1);
    EXPECT_TRUE(touching(world, ground, kept));
}

TEST(Filter, ChangeMidRunEndsContactsWakesAndCollidesAgainWhenChangedBack) {
    World world;  // sleep on: the resting box must be woken by the change
    const BodyId ground = addGround(world, filterOf(1, ~std::uint64_t{0}));
    const BodyId box = addBox(world, 0.0, 0.5, filterOf(2, ~std::uint64_t{0}));
    run(world, 240);
    ASSERT_FALSE(world.isAwake(box)) << "the resting box should sleep within 4 s";
    const ShapeId shape = world.shapes(box)[0];
    world.setFilter(shape, filterOf(2, ~std::uint64_t{1}));  // no longer collides with the ground
    EXPECT_EQ(world.filter(shape).maskBits, ~std::uint64_t{1});
    EXPECT_EQ(world.filter(box).maskBits, ~std::uint64_t{1});
    world.step(kDt);
    EXPECT_TRUE(hasEvent(world.contactEvents().end, ground, box));
    EXPECT_TRUE(world.isAwake(box));
    EXPECT_FALSE(touching(world, ground, box));
    run(world, 3);
    EXPECT_LT(world.velocity(box).y(), -0.3);  // falling: g t = 9.81 * 4 / 60 = 0.65 m/s
    EXPECT_LT(world.position(box).y(), 0.5 - 0.01);
    // Back: the pair is found again, touches (a begin event) and the contact pushes the box out onto the ground.
    world.setFilter(box, filterOf(2, ~std::uint64_t{0}));
    world.step(kDt);
    EXPECT_TRUE(hasEvent(world.contactEvents().begin, ground, box));
    run(world, 120);
    EXPECT_TRUE(touching(world, ground, box) || !world.isAwake(box));
    EXPECT_NEAR(world.position(box).y(), 0.5, kRest);
}

TEST(Filter, ContinuousStageObeysFilters) {
    // A continuous box at 60 m/s onto a thin static plate: the Continuous stage stops it at the plate unless the
    // filters refuse the pair, when it passes as the discrete contacts let it.
    for (const bool refused : {false, true}) {
        World world;
        BodyDef plate;
        plate.type = BodyType::Static;
        plate.shape = makeBox(5.0, 0.05);
        plate.filter = filterOf(1, ~std::uint64_t{0});
        world.createBody(plate);
        BodyDef b;
        b.shape = makeBox(0.2, 0.2);
        b.position = {0.0, 3.0};
        b.velocity = {0.0, -60.0};
        b.collisionDetection = CollisionDetection::ContinuousExact;
        b.filter = filterOf(2, refused ? ~std::uint64_t{1} : ~std::uint64_t{0});
        const BodyId box = world.createBody(b);
        run(world, 30);
        if (refused) EXPECT_LT(world.position(box).y(), -10.0) << "passed through";
        else EXPECT_NEAR(world.position(box).y(), 0.05 + 0.2, kRest) << "stopped on the plate";
    }
}

// The rule of Filter.hpp, written out again: the brute force shares no code with the world's.
bool referenceAllows(const Filter& a, const Filter& b) {
    if (a.groupIndex != 0 && a.groupIndex == b.groupIndex) return a.groupIndex > 0;
    const bool aTakesB = (a.maskBits & b.categoryBits) != 0;
    const bool bTakesA = (b.maskBits & a.categoryBits) != 0;
    return aTakesB && bTakesA;
}

Filter randomFilter(std::mt19937& rng) {
    std::uniform_int_distribution<std::uint64_t> bits(0, 7);
    std::uniform_int_distribution<int> group(-2, 2);
    return filterOf(std::uint64_t{1} << (bits(rng) % 3), bits(rng), group(rng));
}

TEST(Filter, ContactsEqualBruteForceOverRandomFilters) {
    // Circles at rest without gravity, overlapping at random: after a step the touching contacts must be exactly the
    // pairs (of different bodies) that overlap and whose filters allow each other. Overlap is decided from the
    // centres and radii alone, and configurations within 0.02 m of touching are drawn again, so the speculative
    // margin (4 slops = 0.02 m) cannot blur the answer. Some bodies have two circles: their own pair never counts.
    WorldSettings settings;
    settings.gravity = {0.0, 0.0};
    settings.enableSleep = false;
    for (unsigned seed = 1; seed <= 6; ++seed) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> coordinate(0.0, 6.0), radius(0.2, 0.6);
        struct Piece {
            Vec2 centre;
            double r;
        };
        std::vector<Piece> pieces;
        std::vector<std::vector<Vec2>> bodyOffsets;  // per body, its circles' centres relative to its origin
        auto clear = [&](const Vec2& c, double r) {
            for (const Piece& p : pieces)
                if (std::abs((p.centre - c).norm() - (p.r + r)) < 0.02) return false;
            return true;
        };
        World world(settings);
        std::vector<ShapeId> shapes;
        std::vector<BodyId> owners;
        for (int body = 0; body < 40; ++body) {
            const int count = body % 5 == 0 ? 2 : 1;
            std::vector<Piece> mine;
            for (int k = 0; k < count; ++k) {
                Piece p{{coordinate(rng), coordinate(rng)}, radius(rng)};
                while (!clear(p.centre, p.r)) p = {{coordinate(rng), coordinate(rng)}, radius(rng)};
                pieces.push_back(p);
                mine.push_back(p);
            }
            BodyDef d;
            d.position = mine[0].centre;
            d.shape = Circle{Vec2::Zero(), mine[0].r};
            d.filter = randomFilter(rng);
            const BodyId id = world.createBody(d);
            shapes.push_back(world.shapes(id)[0]);
            owners.push_back(id);
            for (std::size_t k = 1; k < mine.size(); ++k) {
                ShapeDef s;
                s.geometry = Circle{mine[k].centre - mine[0].centre, mine[k].r};
                s.filter = randomFilter(rng);
                shapes.push_back(world.createShape(id, s));
                owners.push_back(id);
            }
        }
        auto check = [&](const char* when) {
            std::set<std::pair<std::uint32_t, std::uint32_t>> expected, found;
            for (std::size_t i = 0; i < pieces.size(); ++i)
                for (std::size_t j = i + 1; j < pieces.size(); ++j) {
                    if (owners[i] == owners[j]) continue;
                    const bool overlap = (pieces[i].centre - pieces[j].centre).norm() < pieces[i].r + pieces[j].r;
                    if (overlap && referenceAllows(world.filter(shapes[i]), world.filter(shapes[j])))
                        expected.emplace(std::min(shapes[i].index, shapes[j].index),
                                         std::max(shapes[i].index, shapes[j].index));
                }
            for (const Manifold& m : world.contacts())
                found.emplace(std::min(m.shapeA.index, m.shapeB.index), std::max(m.shapeA.index, m.shapeB.index));
            EXPECT_EQ(found, expected) << "seed " << seed << ", " << when;
            EXPECT_FALSE(expected.empty()) << "seed " << seed << ": the scene should have some allowed overlaps";
        };
        world.step(kDt);
        check("first step");
        // New random filters on every shape: the contacts follow at the next step. The first step's push-out
        // moved the circles by at most contactPushMaxVelocity * dt = 0.05 m, so the drawn pieces are moved back.
        for (std::size_t i = 0; i < shapes.size(); ++i) world.setFilter(shapes[i], randomFilter(rng));
        for (std::size_t i = 0; i < shapes.size(); ++i) {
            if (world.shapes(owners[i])[0] != shapes[i]) continue;  // a body's first circle places it
            world.setTransform(owners[i], pieces[i].centre, 0.0);
            world.setVelocity(owners[i], Vec2::Zero());
            world.setAngularVelocity(owners[i], 0.0);
        }
        world.step(kDt);
        check("after setFilter");
    }
}

TEST(Filter, BadIdsAreRefusedAndLeaveTheWorldUnchanged) {
    World world;
    addGround(world);
    const BodyId box = addBox(world, 0.0, 0.5);
    const ShapeId shape = world.shapes(box)[0];
    world.destroyBody(box);
    try {
        world.setFilter(shape, filterOf(2, 1));
        FAIL() << "a destroyed shape's filter was set";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("index " + std::to_string(shape.index)), std::string::npos) << e.what();
    }
    EXPECT_THROW(world.filter(shape), std::invalid_argument);
    // A new body takes the freed slot: the old id is stale, and the new shape keeps its own filter.
    const BodyId again = addBox(world, 0.0, 0.5, filterOf(4, 4));
    const ShapeId fresh = world.shapes(again)[0];
    ASSERT_EQ(fresh.index, shape.index);
    EXPECT_THROW(world.setFilter(shape, filterOf(2, 1)), std::invalid_argument);
    EXPECT_EQ(world.filter(fresh), filterOf(4, 4));
    EXPECT_THROW(world.setFilter(BodyId{}, Filter{}), std::invalid_argument);
    EXPECT_THROW(world.setFilter(ShapeId{}, Filter{}), std::invalid_argument);
}

}  // namespace
}  // namespace physim
