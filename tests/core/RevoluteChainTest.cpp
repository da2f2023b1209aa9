// A chain of 20 revolute-jointed links holding a weight 100 times heavier than a link (the stiffness case):
// settled, it stretches by the soft pins' give and no more, which the 1% bar meets where the pins may be
// stiff enough (the substep rate).

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace physim {
namespace {

constexpr double kG = 9.81;
constexpr int kLinks = 20;
constexpr double kLinkLength = 0.5, kHalfThickness = 0.05, kWeightHalf = 0.25;  // m
constexpr double kWeightRatio = 100.0;

struct HeavyChain {
    World world;
    std::vector<BodyId> links;
    BodyId weight;
    double linkMass = 0.0;
};

// Boxes of 0.5 m x 0.1 m hanging straight down from a static point at the origin, pinned end to end, and a square
// weight pinned at its top edge's middle below the last link; nothing collides (the joints alone hold it).
void build(HeavyChain& c, const WorldSettings& settings) {
    c.world.setSettings(settings);
    BodyId above = test::addStaticPivot(c.world);
    for (int i = 0; i < kLinks; ++i) {
        BodyDef d;
        d.shape = makeBox(kHalfThickness, 0.5 * kLinkLength);
        d.collides = false;
        d.position = {0.0, -(i + 0.5) * kLinkLength};
        const BodyId link = c.world.createBody(d);
        RevoluteJointDef pin;
        pin.bodyA = above;
        pin.bodyB = link;
        pin.anchor = {0.0, -i * kLinkLength};
        c.world.createRevoluteJoint(pin);
        c.links.push_back(link);
        above = link;
    }
    c.linkMass = c.world.mass(c.links[0]);
    BodyDef d;
    d.shape = makeBox(kWeightHalf, kWeightHalf);
    d.density = kWeightRatio * c.linkMass / (4 * kWeightHalf * kWeightHalf);
    d.collides = false;
    d.position = {0.0, -kLinks * kLinkLength - kWeightHalf};
    c.weight = c.world.createBody(d);
    RevoluteJointDef pin;
    pin.bodyA = above;
    pin.bodyB = c.weight;
    pin.anchor = {0.0, -kLinks * kLinkLength};
    c.world.createRevoluteJoint(pin);
}

// The chain's stretch: the weight's pin's distance from the top over the links' length, minus 1.
double stretch(const HeavyChain& c) {
    return c.world.transform(c.weight).apply(Vec2(0.0, kWeightHalf)).norm() / (kLinks * kLinkLength) - 1.0;
}

// A soft pin carrying F settles F / (m_eff omega^2) apart (the impulse it keeps and the spring's pull-back balance),
// m_eff its row's effective mass along the chain, where the lever arms are parallel to the load and add nothing:
// 1 / m_eff = 1/m at the top (static above), 2/m between links, 1/m + 1/M at the weight. The pin below link i-1
// carries the weight and the links from i down.
double predictedStretch(const HeavyChain& c, double omega) {
    const double m = c.linkMass, M = c.world.mass(c.weight);
    double give = (M + kLinks * m) * kG / m;                                    // the top pin
    for (int i = 1; i < kLinks; ++i) give += (M + (kLinks - i) * m) * kG * 2.0 / m;
    give += M * kG * (1.0 / m + 1.0 / M);                                       // the weight's pin
    return give / (omega * omega) / (kLinks * kLinkLength);
}

// Averaged over the last 10 s of 20, when the weight's slow bounce on the chain (about 1.2 Hz) has nearly died out.
double settledStretch(HeavyChain& c, double hz) {
    double sum = 0.0;
    int count = 0;
    for (int i = 1; i <= static_cast<int>(20 * hz); ++i) {
        c.world.step(1.0 / hz);
        if (i > static_cast<int>(10 * hz)) {
            sum += stretch(c);
            ++count;
        }
    }
    return sum / count;
}

// At the defaults (40 Hz in the framework, 8 substeps) the pins are springs of a quarter of the 320 Hz substep rate,
// 80 Hz, whatever jointHertz asks above it: the settled stretch is their give, 1.7% for these 0.5 m links, over the
// issue's 1% bar. 1% relative covers the weight's bounce left after 20 s (its critically damped pins die out far
// sooner).
TEST(RevoluteJointChain, HeavyWeightStretchesTheChainByThePinsGive) {
    HeavyChain c;
    build(c, test::awakeSettings());
    ASSERT_NEAR(c.world.mass(c.weight) / c.linkMass, kWeightRatio, 1e-9);
    const double predicted = predictedStretch(c, 2 * M_PI * 80.0);
    EXPECT_NEAR(settledStretch(c, 40.0) / predicted, 1.0, 0.01) << predicted;
    for (const BodyId link : c.links) EXPECT_NEAR(c.world.position(link).x(), 0.0, 1e-6) << "the chain hangs straight";
}

// Twice the substeps (16 at 40 Hz; 8 at 60 Hz does the same: the substep rate sets the pins' cap) let the pins be
// the 120 Hz jointHertz asks for: (80/120)^2 of the give, within the 1% bar once settled.
TEST(RevoluteJointChain, StifferPinsHoldTheHeavyWeightWithinOnePercent) {
    WorldSettings s = test::awakeSettings();
    s.substeps = 16;
    HeavyChain c;
    build(c, s);
    const double predicted = predictedStretch(c, 2 * M_PI * 120.0);
    const double settled = settledStretch(c, 40.0);
    EXPECT_NEAR(settled / predicted, 1.0, 0.01);
    EXPECT_LT(settled, 0.01);
}

}  // namespace
}  // namespace physim
