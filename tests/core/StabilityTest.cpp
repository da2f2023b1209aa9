// The hard cases (docs/stability.md): scenes that break solvers, each at the default settings (60 Hz, 8 substeps),
// sleep off so the solver, not sleeping, holds them. Each test states its criterion and why; measured values are
// recorded as test properties (ctest --output-junit shows them) and listed in docs/stability.md.
// Tests named for a known limit keep a scene that misses its criterion today, guarded so it gets no worse;
// docs/stability.md gives the criterion, the numbers and the diagnosis.

#include "support/Scenes.hpp"

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace physim {
namespace {

using test::addBox;
using test::addGround;
using test::awakeSettings;
using test::PyramidRun;
using test::runPyramid;

constexpr double kDt = 1.0 / 60.0;
constexpr double kG = 9.81;

// --- stacks ---------------------------------------------------------------------------------------------------

// The criterion: after 1 s the top box drifts under 5 cm, and no box moves sideways more than 25 cm over
// 500 steps. A pyramid of touching boxes has a static solution with no sideways force at all, so any sideways
// motion is the solver's error; 25 cm is a quarter box, where a pyramid visibly starts to come apart.
// (The 100-box base is in StabilityLongTest.cpp: 5050 boxes take minutes.)
TEST(Stability, PyramidsWith20And40BoxBasesStand) {
    for (const int base : {20, 40}) {
        const PyramidRun r = runPyramid(base, 500);
        RecordProperty("base" + std::to_string(base) + "_top_drift_m", std::to_string(r.topDrift));
        RecordProperty("base" + std::to_string(base) + "_sideways_m", std::to_string(r.sideways));
        EXPECT_LT(r.topDrift, 0.05) << "base " << base;
        EXPECT_LT(r.sideways, 0.25) << "base " << base;
    }
}

// 20 boxes in a column for 30 s. A column has no sideways force either: the top stays within 1 mm of x = 0 and
// upright, does not move after the first second (1 cm, the existing 10-box test's bound), and sinks by the soft
// contacts' static compression: N^2 g / (2 pi f)^2 for boxes sunk as bare masses (WorldSettings::contactHertz;
// f = 120 Hz: 6.9 mm), times the point compliance (8.6 mm). Measured equal to 1e-4; 2% either way.
TEST(Stability, TwentyBoxColumnStandsThirtySeconds) {
    World world(awakeSettings());
    addGround(world);
    const int n = 20;
    BodyId top;
    for (int i = 0; i < n; ++i) top = addBox(world, {0.0, 0.5 + i}, 0.5, 0.5);
    Vec2 settled = Vec2::Zero();
    double drift = 0.0, sideways = 0.0, tilt = 0.0;
    for (int s = 0; s < 30 * 60; ++s) {
        world.step(kDt);
        if (s + 1 == 60) settled = world.position(top);
        if (s + 1 > 60) drift = std::max(drift, (world.position(top) - settled).norm());
        sideways = std::max(sideways, std::abs(world.position(top).x()));
        tilt = std::max(tilt, std::abs(world.angle(top)));
    }
    const double omega = 2.0 * M_PI * world.settings().contactHertz;
    const double predictedSink = test::pointCompliance(0.5, 0.5) * n * n * kG / (omega * omega);
    const double sink = n - 0.5 - world.position(top).y();
    RecordProperty("top_drift_m", std::to_string(drift));
    RecordProperty("sink_m", std::to_string(sink));
    EXPECT_LT(drift, 0.01);
    EXPECT_LT(sideways, 1e-3);
    EXPECT_LT(tilt, 1e-3);
    EXPECT_NEAR(sink, predictedSink, 0.02 * predictedSink);
}

// A heavy box (density `ratio`) resting on a light 1 m box (density 1) on the ground, placed touching, 10 s.
// The heavy box's height loss against its exact resting height (1.5 m) is its sinking.
double heavyOnLightSink(double ratio) {
    World world(awakeSettings());
    addGround(world);
    const BodyId light = addBox(world, {0.0, 0.5}, 0.5, 0.5, 1.0);
    const BodyId heavy = addBox(world, {0.0, 1.5}, 0.5, 0.5, ratio);
    double lowest = 1.5, sideways = 0.0;
    for (int s = 0; s < 10 * 60; ++s) {
        world.step(kDt);
        lowest = std::min(lowest, world.position(heavy).y());
        sideways = std::max({sideways, std::abs(world.position(heavy).x()), std::abs(world.position(light).x())});
    }
    EXPECT_LT(sideways, 1e-3) << "ratio " << ratio;
    return 1.5 - lowest;
}

// Heavy-on-light stacks: the heavy box sinks less than 1 cm (the resting-contact bound) at mass ratios 10 and 100.
// A soft contact's static compression is its load over its effective mass times g / (2 pi f)^2: the ground
// contact carries (1 + ratio) kg on a 1 kg box, the upper one ratio kg on a reduced mass of about 1 kg, so the sink
// grows with the ratio: about 0.35 mm at 10, 3.5 mm at 100 (measured 0.4 and 4.5 mm with the landing transient).
TEST(Stability, HeavyOnLightStacksHoldAtMassRatios10And100) {
    for (const double ratio : {10.0, 100.0}) {
        const double sink = heavyOnLightSink(ratio);
        RecordProperty("ratio" + std::to_string(static_cast<int>(ratio)) + "_sink_m", std::to_string(sink));
        EXPECT_LT(sink, 0.01) << "mass ratio " << ratio;
    }
}

// A known limit (docs/stability.md): the 1 cm criterion is not met at mass ratio 1000. The soft contacts hold the
// heavy box's load 1.25 x 2 x 1000 x g / (2 pi 120 Hz)^2 = 4.3 cm deep at rest (1.25: pointCompliance), and the
// landing adds to it (7.0 cm measured). Guarded at 8.6 cm, twice the static prediction: deeper means the contacts
// got softer.
TEST(Stability, HeavyOnLightStackAtMassRatio1000SinksNoDeeperThanTwiceTheSoftContactPrediction) {
    const double sink = heavyOnLightSink(1000.0);
    RecordProperty("ratio1000_sink_m", std::to_string(sink));
    const double w = 2 * M_PI * 120.0;
    EXPECT_LT(sink, 2.0 * test::pointCompliance(0.5, 0.5) * (2 * 1000.0 * kG / (w * w)));
}

struct DropRun {
    double rise = 0.0;      // m: highest any small box's centre gets above its resting height after the landing
    double sideways = 0.0;  // m: farthest any box gets from its starting x
    double restError = 0.0; // m: |big box height - its resting height| after 10 s
    double tilt = 0.0;      // rad: big box's angle after 10 s
};

// A 4 m x 2 m box of density `density` dropped from `gap` m onto two 0.5 m boxes (density 1) 2 m apart, all with
// restitution 0 (the default).
DropRun dropBigBox(double gap, double density) {
    World world(awakeSettings());
    addGround(world);
    const BodyId left = addBox(world, {-1.0, 0.25}, 0.25, 0.25);
    const BodyId right = addBox(world, {1.0, 0.25}, 0.25, 0.25);
    const BodyId big = addBox(world, {0.0, 1.5 + gap}, 2.0, 1.0, density);
    DropRun r;
    for (int s = 0; s < 10 * 60; ++s) {
        world.step(kDt);
        r.rise = std::max({r.rise, world.position(left).y() - 0.25, world.position(right).y() - 0.25});
        r.sideways = std::max({r.sideways, std::abs(world.position(big).x()), std::abs(world.position(left).x() + 1.0),
                               std::abs(world.position(right).x() - 1.0)});
    }
    r.restError = std::abs(world.position(big).y() - 1.5);
    r.tilt = std::abs(world.angle(big));
    return r;
}

// A big box dropped on two small ones, restitution 0: nothing bounces (no small box rises 1 cm above the ground),
// the small ones are not squeezed out (5 cm), and the big box comes to rest level (1 mrad) at its resting height
// (1 cm). The big box here is 3.2 times the mass of each small one, dropped 1 m (4.4 m/s).
TEST(Stability, BigBoxDroppedOnTwoSmallOnesComesToRest) {
    const DropRun r = dropBigBox(1.0, 0.1);
    RecordProperty("rise_m", std::to_string(r.rise));
    RecordProperty("sideways_m", std::to_string(r.sideways));
    EXPECT_LT(r.rise, 0.01);
    EXPECT_LT(r.sideways, 0.05);
    EXPECT_LT(r.restError, 0.01);
    EXPECT_LT(r.tilt, 1e-3);
}

// A known limit (docs/stability.md, "Heavy box dropped on light ones"): with the big box 32 times each small one's
// mass (all density 1) the 1 cm criterion is not met; a 1 m drop throws the small boxes 0.25 m up, restitution 0.
// They also slide 18 cm sideways (criterion 5 cm). Guarded at half the fall height (0.5 m up) and 0.5 m sideways,
// half the way out from under the big box: more means the landing pumps more energy into them than today.
TEST(Stability, HeavyBigBoxDroppedOnTwoSmallOnesThrowsThemLessThanHalfTheDrop) {
    const DropRun r = dropBigBox(1.0, 1.0);
    RecordProperty("rise_m", std::to_string(r.rise));
    RecordProperty("sideways_m", std::to_string(r.sideways));
    EXPECT_LT(r.rise, 0.5);
    EXPECT_LT(r.sideways, 0.5);
}

// --- held by friction -----------------------------------------------------------------------------------------

// A semicircular arch of `blocks` voussoirs (radial joints), inner radius `inner`, outer `outer` (m), standing on
// the ground with friction mu everywhere. Returns the largest distance any block moves in 10 s.
double archMotion(int blocks, double inner, double outer, double mu) {
    World world(awakeSettings());
    world.setMaterial(addGround(world, 50.0), 0.0, mu, mu);
    std::vector<BodyId> ids;
    for (int k = 0; k < blocks; ++k) {
        const double a0 = M_PI * k / blocks, a1 = M_PI * (k + 1) / blocks;
        std::vector<Vec2> corners{{inner * std::cos(a0), inner * std::sin(a0)},
                                  {outer * std::cos(a0), outer * std::sin(a0)},
                                  {outer * std::cos(a1), outer * std::sin(a1)},
                                  {inner * std::cos(a1), inner * std::sin(a1)}};
        if (k == 0) corners[0].y() = corners[1].y() = 0.0;  // springings flat on the ground (sin(pi) is not 0)
        if (k == blocks - 1) corners[2].y() = corners[3].y() = 0.0;
        const Vec2 centroid = computeMassProperties(makePolygon(corners)).centroid;
        for (Vec2& c : corners) c -= centroid;
        BodyDef d;
        d.shape = makePolygon(corners);
        d.position = centroid;
        d.staticFriction = d.dynamicFriction = mu;
        ids.push_back(world.createBody(d));
    }
    return test::farthestMove(world, ids, 10 * 60);
}

// An arch held by friction. Heyman's limit analysis: a semicircular arch stands (hinges cannot form) when its
// thickness is at least 0.1075 of its mean radius. Eleven blocks, mu = 0.6: at t/R = 0.22 it stands (no block
// moves 1 cm in 10 s); the same arch without friction slides apart, and one of t/R = 0.08 (below the limit)
// collapses (blocks move over 1 m): the engine agrees with the mechanics on both sides.
TEST(Stability, ArchHeldByFrictionStandsAboveHeymansThickness) {
    const double stands = archMotion(11, 4.0, 5.0, 0.6);
    RecordProperty("arch_motion_m", std::to_string(stands));
    EXPECT_LT(stands, 0.01);
    EXPECT_GT(archMotion(11, 4.0, 5.0, 0.0), 1.0) << "without friction the radial joints slide";
    EXPECT_GT(archMotion(11, 4.8, 5.2, 0.6), 1.0) << "t/R = 0.08 is below Heyman's minimum thickness";
}

// A card (1 m x 2 cm) leaning `alpha` from the vertical against the apex at x = cx from the side `side` (-1: it
// stands to the left), its lowest corner on the line y = base.
BodyId addCard(World& world, double cx, double base, double alpha, int side, double mu) {
    BodyDef d;
    d.shape = makeBox(0.01, 0.5);
    d.angle = side < 0 ? -alpha : alpha;
    d.staticFriction = d.dynamicFriction = mu;
    const Transform turn{Vec2::Zero(), Rotation::fromAngle(d.angle)};
    const Polygon& p = std::get<Polygon>(d.shape);
    double lowest = 1e9, apex = side < 0 ? -1e9 : 1e9;
    for (int i = 0; i < p.count; ++i) {
        const Vec2 v = turn.apply(p.vertices[i]);
        lowest = std::min(lowest, v.y());
        apex = side < 0 ? std::max(apex, v.x()) : std::min(apex, v.x());
    }
    d.position = {cx - apex, base - lowest};
    return world.createBody(d);
}

// A two-storey card house: two A-frames of cards leaning 15 degrees, a flat card across their apexes, an A-frame
// on it; friction mu everywhere. Returns the largest distance any card moves in 10 s.
double cardHouseMotion(double mu) {
    World world(awakeSettings());
    world.setMaterial(addGround(world, 50.0), 0.0, mu, mu);
    const double alpha = 15.0 * M_PI / 180.0;
    const double spacing = 2.0 * (std::sin(alpha) + 0.02 * std::cos(alpha)) + 0.02;  // frames 2 cm apart at the feet
    std::vector<BodyId> cards;
    for (const double cx : {-0.5 * spacing, 0.5 * spacing})
        for (const int side : {-1, 1}) cards.push_back(addCard(world, cx, 0.0, alpha, side, mu));
    double top = 0.0;
    for (const BodyId c : cards) top = std::max(top, world.bounds(c).upper.y());
    BodyDef floor;
    floor.shape = makeBox(0.5 * spacing + 0.3, 0.01);
    floor.position = {0.0, top + 0.01};
    floor.staticFriction = floor.dynamicFriction = mu;
    cards.push_back(world.createBody(floor));
    for (const int side : {-1, 1}) cards.push_back(addCard(world, 0.0, top + 0.02, alpha, side, mu));
    return test::farthestMove(world, cards, 10 * 60);
}

// A card house held by friction: with mu = 0.6 no card moves 1 cm in 10 s. A leaning card needs at least
// tan(15 deg) / 2 = 0.13 of friction at its foot (more under load); with mu = 0.05 the house falls (cards move
// over 0.5 m), so it is friction, not the solver's error, that holds it.
TEST(Stability, CardHouseHeldByFrictionStands) {
    const double stands = cardHouseMotion(0.6);
    RecordProperty("card_house_motion_m", std::to_string(stands));
    EXPECT_LT(stands, 0.01);
    EXPECT_GT(cardHouseMotion(0.05), 0.5);
}

// --- joints ---------------------------------------------------------------------------------------------------

struct ChainRun {
    double sag = 0.0;         // m: weight's distance from the anchor beyond the chain's length, after 20 s
    double worstStretch = 0.0;// m: largest |link length - 0.25 m| over the run
    double energyRise = 0.0;  // J: largest rise of kinetic + potential energy above its start
    double energyScale = 0.0; // J: m_total g L, for the tolerance
};

// A chain of 20 links (5 cm discs, 0.25 m apart, distance joints) from a static anchor at the origin, carrying a
// weight `ratio` times a link's mass at its end; hanging at rest, or released horizontal (`swing`). 20 s.
ChainRun runChain(double ratio, bool swing) {
    World world(awakeSettings());
    BodyDef anchor;
    anchor.type = BodyType::Static;
    anchor.shape = makeCircle(0.05);
    BodyId previous = world.createBody(anchor);
    const int links = 20;
    const double length = 0.25;
    std::vector<BodyId> ids;
    for (int i = 0; i < links; ++i) {
        BodyDef d;
        d.shape = makeCircle(0.05);
        d.density = i == links - 1 ? ratio : 1.0;
        d.position = swing ? Vec2(length * (i + 1), 0.0) : Vec2(0.0, -length * (i + 1));
        ids.push_back(world.createBody(d));
        DistanceJointDef j;
        j.bodyA = previous;
        j.bodyB = ids.back();
        world.createDistanceJoint(j);
        previous = ids.back();
    }
    ChainRun r;
    double mass = 0.0;
    for (const BodyId id : ids) mass += world.mass(id);
    r.energyScale = mass * kG * links * length;
    const double e0 = test::mechanicalEnergy(world, ids);
    for (int s = 0; s < 20 * 60; ++s) {
        world.step(kDt);
        Vec2 above = Vec2::Zero();
        for (const BodyId id : ids) {
            r.worstStretch = std::max(r.worstStretch, std::abs((world.position(id) - above).norm() - length));
            above = world.position(id);
        }
        r.energyRise = std::max(r.energyRise, test::mechanicalEnergy(world, ids) - e0);
    }
    r.sag = world.position(ids.back()).norm() - links * length;
    return r;
}

// A chain of 20 links carrying a weight 100 times a link's mass. Hanging: the weight settles within 2% of the
// chain's length of where an inextensible chain holds it (the soft joints' static stretch, load over effective
// mass times g / (2 pi f)^2 summed over the links, is 1.4%). Released horizontal: no link stretches by more than
// 10% of its length at any time, and the chain never gains energy (1e-3 of m g L: the joints' push-out is bounded
// by their damping).
TEST(Stability, ChainCarriesAHundredTimesHeavierWeight) {
    const ChainRun hang = runChain(100.0, false);
    RecordProperty("hanging_sag_m", std::to_string(hang.sag));
    EXPECT_LT(std::abs(hang.sag), 0.02 * 5.0);
    const ChainRun swing = runChain(100.0, true);
    RecordProperty("swing_worst_stretch_m", std::to_string(swing.worstStretch));
    RecordProperty("swing_energy_rise_J", std::to_string(swing.energyRise));
    EXPECT_LT(swing.worstStretch, 0.1 * 0.25);
    EXPECT_LT(swing.energyRise, 1e-3 * swing.energyScale);
}

// --- overlap recovery -----------------------------------------------------------------------------------------

struct OverlapRun {
    double fastest = 0.0;  // m/s: largest speed of any body over the run
    double deepest = 0.0;  // m: deepest contact overlap after the run (negative separation)
    double restSpeed = 0.0;// m/s: largest speed at the end
};

OverlapRun recover(World& world, const std::vector<BodyId>& ids, int steps) {
    OverlapRun r;
    for (int s = 0; s < steps; ++s) {
        world.step(kDt);
        for (const BodyId id : ids) r.fastest = std::max(r.fastest, world.velocity(id).norm());
    }
    for (const Manifold& m : world.contacts())
        for (int p = 0; p < m.pointCount; ++p) r.deepest = std::max(r.deepest, -m.points[p].separation);
    for (const BodyId id : ids) r.restSpeed = std::max(r.restSpeed, world.velocity(id).norm());
    return r;
}

// Bodies spawned deeply overlapping separate without exploding. The push-out is capped per contact at
// contactPushMaxVelocity (3 m/s): a body pushed out through k overlapping layers (the ground counts) can reach k
// times that, and no more. Two boxes spawned 1 cm apart on the ground (k = 2), two discs likewise, and a pyramid
// of four rows spawned 25% into each other (k = 4): each separates (overlap under the linear slop after 10 s),
// never exceeds k x 3 m/s, and the boxes come to rest (1 cm/s; discs pushed apart roll on, having no rolling
// resistance).
TEST(Stability, DeeplyOverlappingBodiesSeparateWithBoundedSpeed) {
    const double cap = WorldSettings{}.contactPushMaxVelocity;
    for (const bool discs : {false, true}) {
        World world(awakeSettings());
        addGround(world);
        std::vector<BodyId> ids;
        for (int i = 0; i < 2; ++i) {
            BodyDef d;
            d.shape = discs ? Geometry(makeCircle(0.5)) : Geometry(makeBox(0.5, 0.5));
            d.position = {0.01 * i, 0.5 + 0.01 * i};
            ids.push_back(world.createBody(d));
        }
        const OverlapRun r = recover(world, ids, 10 * 60);
        RecordProperty(std::string(discs ? "discs" : "boxes") + "_fastest_mps", std::to_string(r.fastest));
        EXPECT_LT(r.fastest, 2 * cap) << (discs ? "discs" : "boxes");
        EXPECT_LT(r.deepest, world.settings().linearSlop);
        if (!discs) {
            EXPECT_LT(r.restSpeed, 0.01);
        }
    }
    World world(awakeSettings());
    addGround(world);
    std::vector<BodyId> ids;
    const int rows = 4;
    const double spacing = 0.75;  // 1 m boxes 0.75 m apart: each overlaps its neighbours by a quarter
    for (int row = 0; row < rows; ++row)
        for (int i = 0; i < rows - row; ++i)
            ids.push_back(addBox(world, {spacing * (i - 0.5 * (rows - row - 1)), 0.5 + spacing * row}, 0.5, 0.5));
    const OverlapRun r = recover(world, ids, 10 * 60);
    RecordProperty("pyramid_fastest_mps", std::to_string(r.fastest));
    EXPECT_LT(r.fastest, rows * cap);
    EXPECT_LT(r.deepest, world.settings().linearSlop);
    EXPECT_LT(r.restSpeed, 0.01);
}

// A known limit (docs/stability.md, "Tall overlapping spawn"): a ten-row pyramid spawned 10% into itself launches
// its top box at 17 m/s in the first step, although 3 m/s would separate every pair (criterion 2 x 3 m/s, not
// met). Guarded at 10 row push speeds (30 m/s): the pushes of the rows below add up, and no more than that.
TEST(Stability, TallOverlappingPyramidLaunchesNoFasterThanItsRowsPushesAddUp) {
    World world(awakeSettings());
    addGround(world);
    std::vector<BodyId> ids;
    const int rows = 10;
    for (int row = 0; row < rows; ++row)
        for (int i = 0; i < rows - row; ++i)
            ids.push_back(addBox(world, {0.9 * (i - 0.5 * (rows - row - 1)), 0.5 + 0.9 * row}, 0.5, 0.5));
    world.step(kDt);
    double fastest = 0.0;
    for (const BodyId id : ids) fastest = std::max(fastest, world.velocity(id).norm());
    RecordProperty("first_step_fastest_mps", std::to_string(fastest));
    EXPECT_LT(fastest, rows * world.settings().contactPushMaxVelocity);
}

// --- scales ---------------------------------------------------------------------------------------------------

// 1 cm and 100 m bodies in one scene: a 100 m plank (dynamic) on the ground with ten 1 cm boxes resting on it,
// five 1 cm discs on the ground beside it, 1 cm boxes dropped 1 m onto the plank, and a 100 m box landing on the
// ground far off. The resting small bodies stay within 1 mm of where they were put (a tenth of their size), the
// dropped ones come to rest on the plank's top (within 1 mm of resting height, no tunnelling), and the plank and
// the big box rest level at their heights (1 mm).
TEST(Stability, CentimetreAndHundredMetreBodiesShareAScene) {
    World world(awakeSettings());
    addGround(world, 1000.0);
    const BodyId plank = addBox(world, {0.0, 0.5}, 50.0, 0.5);
    std::vector<BodyId> resting, dropped;
    std::vector<Vec2> start;
    for (int i = 0; i < 10; ++i) {
        resting.push_back(addBox(world, {-5.0 + i, 1.005}, 0.005, 0.005));
        start.push_back(world.position(resting.back()));
    }
    for (int i = 0; i < 5; ++i) {
        BodyDef d;
        d.shape = makeCircle(0.005);
        d.position = {60.0 + i, 0.005};
        resting.push_back(world.createBody(d));
        start.push_back(d.position);
    }
    for (int i = 0; i < 5; ++i) dropped.push_back(addBox(world, {10.0 + i, 2.0}, 0.005, 0.005));
    const BodyId big = addBox(world, {-200.0, 60.0}, 50.0, 50.0);
    double worstMove = 0.0;
    for (int s = 0; s < 10 * 60; ++s) {
        world.step(kDt);
        for (std::size_t k = 0; k < resting.size(); ++k)
            worstMove = std::max(worstMove, (world.position(resting[k]) - start[k]).norm());
    }
    RecordProperty("small_worst_move_m", std::to_string(worstMove));
    EXPECT_LT(worstMove, 1e-3);
    for (const BodyId id : dropped) {
        EXPECT_NEAR(world.position(id).y(), 1.005, 1e-3);
        EXPECT_LT(world.velocity(id).norm(), 0.01);
    }
    EXPECT_NEAR(world.position(plank).y(), 0.5, 1e-3);
    EXPECT_LT(std::abs(world.angle(plank)), 1e-4);
    EXPECT_NEAR(world.position(big).y(), 50.0, 1e-3);
    EXPECT_LT(std::abs(world.angle(big)), 1e-4);
}

}  // namespace
}  // namespace physim

namespace physim {
namespace {

// --- the shapes of issue 52 -------------------------------------------------------------------------------------

// Ten rounded boxes and ten capsules lying flat, alternating, in one column for 10 s. As for the box column, no
// sideways force exists: the top stays within 1 cm of x = 0 and upright (0.01 rad), and stops moving after the first
// second (1 cm): rounded corners must not roll the column apart.
TEST(Stability, ColumnOfRoundedBoxesAndCapsulesStands) {
    World world(test::awakeSettings());
    test::addGround(world);
    BodyId top;
    double y = 0.0;
    for (int i = 0; i < 20; ++i) {
        BodyDef d;
        const bool capsule = i % 2 == 1;
        d.shape = capsule ? Geometry(makeCapsule({-0.4, 0.0}, {0.4, 0.0}, 0.25))
                          : Geometry(makeRoundedBox(0.45, 0.2, 0.05));
        const double half = 0.25;
        d.position = {0.0, y + half};
        y += 2.0 * half;
        top = world.createBody(d);
    }
    Vec2 settled = Vec2::Zero();
    double drift = 0.0;
    for (int s = 0; s < 10 * 60; ++s) {
        world.step(kDt);
        if (s + 1 == 60) settled = world.position(top);
        if (s + 1 > 60) drift = std::max(drift, (world.position(top) - settled).norm());
    }
    RecordProperty("top_drift_m", std::to_string(drift));
    EXPECT_LT(std::abs(world.position(top).x()), 0.01);
    EXPECT_LT(std::abs(world.angle(top)), 0.01);
    EXPECT_LT(drift, 0.01);
}

// 300 circles, capsules and rounded boxes dropped on a chain terrain of 2,000 pieces (a sum of sines, walled at
// both ends) for 20 s:
// the long run the chain_terrain bench times. None may end below the terrain under it (a body through the ground
// has tunnelled), none may leave the scene, the state stays finite, and the pile settles (kinetic energy at the end
// below a thousandth of the potential energy it fell through).
TEST(Stability, MixedPileOnAChainTerrainStaysOnIt) {
    World world;
    auto terrain = [](double x) { return 0.6 * std::sin(0.5 * x) + 0.25 * std::sin(1.7 * x + 1.0); };
    BodyDef groundDef;
    groundDef.type = BodyType::Static;
    groundDef.withShape = false;
    const BodyId ground = world.createBody(groundDef);
    ChainDef chain;  // walls at both ends keep the pile on the terrain
    chain.points.emplace_back(-50.0, 10.0);
    for (int i = 0; i <= 2000; ++i) {
        const double x = -50.0 + 0.05 * i;
        chain.points.emplace_back(x, terrain(x));
    }
    chain.points.emplace_back(50.0, 10.0);
    world.createChain(ground, chain);
    std::vector<BodyId> bodies;
    double fall = 0.0;
    for (int i = 0; i < 300; ++i) {
        BodyDef d;
        switch (i % 3) {
        case 0: d.shape = makeCircle(0.2); break;
        case 1: d.shape = makeCapsule({-0.2, 0.0}, {0.2, 0.0}, 0.12); break;
        default: d.shape = makeRoundedBox(0.15, 0.1, 0.04); break;
        }
        d.position = {-45.0 + 0.3 * i, 3.0 + 0.5 * (i % 7)};
        d.angle = 0.3 * i;
        const BodyId id = world.createBody(d);
        fall += world.mass(id) * kG * (d.position.y() - terrain(d.position.x()));
        bodies.push_back(id);
    }
    for (int s = 0; s < 20 * 60; ++s) world.step(kDt);
    double kinetic = 0.0, deepest = INFINITY;  // the least height of a centre above the terrain under it
    for (const BodyId id : bodies) {
        const Vec2 p = world.position(id);
        ASSERT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y()));
        ASSERT_GT(p.x(), -50.0);
        ASSERT_LT(p.x(), 50.0);
        deepest = std::min(deepest, p.y() - terrain(p.x()));
        kinetic += 0.5 * world.mass(id) * world.velocity(id).squaredNorm() +
                   0.5 * world.inertia(id) * world.angularVelocity(id) * world.angularVelocity(id);
    }
    RecordProperty("lowest_centre_above_terrain_m", std::to_string(deepest));
    // A centre may sit below the curve where a body rests in a dip narrower than itself: never by its size.
    EXPECT_GT(deepest, -0.1);
    EXPECT_LT(kinetic, 1e-3 * fall);
}

}  // namespace
}  // namespace physim
