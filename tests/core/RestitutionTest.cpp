// Restitution (issue #4), default settings at 60 Hz, no friction needed (straight drops).
// A ball dropped from H rebounds to e^2 H within 2%: contact is found once per substep, so the bounce happens
// up to one substep's travel v h (h = dt / substeps) below the surface, which moves the apex by at most
// v h (1 - e^2); with H = 10 m that bound is 1.7% of e^2 H for e = 0.5 and 0.5% for e = 0.8.
// With e = 1 a ball bouncing 20 times never rises above its drop height (no energy gain).

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace physim {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kRadius = 0.25;

struct Drop {
    World world;
    BodyId ball;
};

// Ground top at y = 0; the ball's lowest point starts `height` above it.
void build(Drop& s, double height, double e) {
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.shape = makeBox(5.0, 0.5);
    ground.position = {0.0, -0.5};
    ground.restitution = 1.0;  // the pair uses min(e_ground, e_ball) = e_ball
    s.world.createBody(ground);
    BodyDef ball;
    ball.shape = makeCircle(kRadius);
    ball.position = {0.0, kRadius + height};
    ball.restitution = e;
    s.ball = s.world.createBody(ball);
}

// Heights (of the ball's lowest point) at the apex of each of the next `bounces` rebounds.
std::vector<double> apexes(Drop& s, int bounces) {
    std::vector<double> out;
    double best = -1.0;
    bool rising = false;
    for (int i = 0; i < 100000 && static_cast<int>(out.size()) < bounces; ++i) {
        s.world.step(kDt);
        const double vy = s.world.velocity(s.ball).y();
        const double y = s.world.position(s.ball).y() - kRadius;
        if (vy > 0.0) {
            rising = true;
            best = std::max(best, y);
        } else if (rising) {
            out.push_back(std::max(best, y));
            rising = false;
            best = -1.0;
        }
    }
    return out;
}

TEST(Restitution, ReboundHeightIsESquaredTimesDropHeight) {
    for (const double e : {0.5, 0.8}) {
        Drop s;
        const double height = 10.0;
        build(s, height, e);
        const std::vector<double> apex = apexes(s, 1);
        ASSERT_EQ(apex.size(), 1u);
        RecordProperty(e == 0.5 ? "rebound_ratio_e05" : "rebound_ratio_e08", std::to_string(apex[0] / (e * e * height)));
        EXPECT_NEAR(apex[0], e * e * height, 0.02 * e * e * height) << "e = " << e;
    }
}

TEST(Restitution, PerfectlyElasticBallGainsNoEnergyOverTwentyBounces) {
    Drop s;
    const double height = 2.0;
    build(s, height, 1.0);
    const std::vector<double> apex = apexes(s, 20);
    ASSERT_EQ(apex.size(), 20u);
    // Sampled apexes sit up to one step's travel below the true apex (v = 0 there, so g dt^2 / 2 = 1.4 mm);
    // the bound allows that and rounding, nothing more: 1e-6 m over the drop height.
    for (std::size_t k = 0; k < apex.size(); ++k) EXPECT_LE(apex[k], height + 1e-6) << "bounce " << k;
    // And it keeps bouncing (no large loss either): within 2% of the drop height.
    EXPECT_GT(*std::min_element(apex.begin(), apex.end()), 0.98 * height);
    RecordProperty("max_apex_m", std::to_string(*std::max_element(apex.begin(), apex.end())));
}

}  // namespace
}  // namespace physim
