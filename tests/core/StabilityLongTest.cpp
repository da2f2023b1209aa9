// The hard cases that take minutes (ctest label stability_long, run by CI after the default preset's suite):
// a pyramid with a 100-box base, and a million steps of a bouncing scene. Criteria as in StabilityTest.cpp.

#include "support/Scenes.hpp"

#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace physim {
namespace {

using test::addBox;
using test::addGround;
using test::awakeSettings;

constexpr double kDt = 1.0 / 60.0;

// The pyramid criterion at a 100-box base (5050 boxes): after 1 s the top box drifts under 5 cm, and no
// box moves sideways more than 25 cm over 500 steps.
TEST(StabilityLong, PyramidWith100BoxBaseStands) {
    World world(awakeSettings());
    addGround(world);
    const int base = 100;
    std::vector<BodyId> ids;
    std::vector<double> x0;
    for (int row = 0; row < base; ++row)
        for (int i = 0; i < base - row; ++i) {
            const Vec2 at{-0.5 * (base - row - 1) + 1.0 * i, 0.5 + 1.0 * row};
            ids.push_back(addBox(world, at, 0.5, 0.5));
            x0.push_back(at.x());
        }
    const BodyId top = ids.back();
    Vec2 settled = Vec2::Zero();
    double drift = 0.0, sideways = 0.0;
    for (int s = 0; s < 500; ++s) {
        world.step(kDt);
        if (s + 1 == 60) settled = world.position(top);
        if (s + 1 > 60) drift = std::max(drift, (world.position(top) - settled).norm());
        for (std::size_t k = 0; k < ids.size(); ++k)
            sideways = std::max(sideways, std::abs(world.position(ids[k]).x() - x0[k]));
    }
    RecordProperty("top_drift_m", std::to_string(drift));
    RecordProperty("sideways_m", std::to_string(sideways));
    EXPECT_LT(drift, 0.05);
    EXPECT_LT(sideways, 0.25);
}

// 10^6 steps (4.6 simulated hours) of 16 discs and 8 boxes bouncing in a closed 10 m box under gravity, every
// collision elastic and frictionless (e = 1, mu = 0), so the scene keeps bouncing and colliding to the end:
// no position or velocity ever becomes NaN or infinite, and the kinetic plus potential energy never rises above
// its start by more than 1%. (Semi-implicit Euler's energy error stays bounded, of order g v h per body; the
// solver's push-out of overlaps is removed by its relax pass. Measured: docs/stability.md.)
TEST(StabilityLong, MillionStepsOfBouncingStayFiniteAndGainNoEnergy) {
    World world(awakeSettings());
    const double half = 5.0, wall = 0.5;
    for (const auto& [size, at] : {std::pair{Vec2(half + 2 * wall, wall), Vec2(0.0, -half - wall)},
                                   std::pair{Vec2(half + 2 * wall, wall), Vec2(0.0, half + wall)},
                                   std::pair{Vec2(wall, half + 2 * wall), Vec2(-half - wall, 0.0)},
                                   std::pair{Vec2(wall, half + 2 * wall), Vec2(half + wall, 0.0)}}) {
        BodyDef d;
        d.type = BodyType::Static;
        d.shape = makeBox(size.x(), size.y());
        d.position = at;
        d.restitution = 1.0;
        d.staticFriction = d.dynamicFriction = 0.0;
        world.createBody(d);
    }
    std::vector<BodyId> ids;
    for (int i = 0; i < 24; ++i) {
        BodyDef d;
        d.shape = i < 16 ? Geometry(makeCircle(0.2 + 0.02 * (i % 5))) : Geometry(makeBox(0.3, 0.2 + 0.03 * (i % 3)));
        d.position = {-4.0 + 1.6 * (i % 6), -3.5 + 1.8 * (i / 6)};
        d.angle = 0.4 * i;
        d.velocity = {3.0 * std::cos(1.3 * i), 3.0 * std::sin(1.3 * i)};
        d.angularVelocity = i % 2 ? 1.0 : -1.0;
        d.restitution = 1.0;
        d.staticFriction = d.dynamicFriction = 0.0;
        ids.push_back(world.createBody(d));
    }
    const double e0 = test::mechanicalEnergy(world, ids);
    // The tolerance's scale: the energy above every body lying at the floor's height (what keeps them moving).
    double scale = e0;
    for (const BodyId id : ids) scale -= world.mass(id) * world.settings().gravity.norm() * -half;
    double highest = e0, lowest = e0;
    bool finite = true;
    const long steps = std::getenv("STEPS") ? std::atol(std::getenv("STEPS")) : 1000000;
    for (long s = 0; s < steps && finite; ++s) {
        world.step(kDt);
        if (s % 10 != 0) continue;  // energy every 10 steps: the scene's cost, not the check's, should dominate
        for (const BodyId id : ids) {
            const Vec2 p = world.position(id), v = world.velocity(id);
            finite = finite && std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(v.x()) &&
                     std::isfinite(v.y()) && std::isfinite(world.angle(id)) && std::isfinite(world.angularVelocity(id));
        }
        const double e = test::mechanicalEnergy(world, ids);
        highest = std::max(highest, e);
        lowest = std::min(lowest, e);
    }
    RecordProperty("energy_rise_fraction", std::to_string((highest - e0) / scale));
    RecordProperty("energy_loss_fraction", std::to_string((e0 - lowest) / scale));
    EXPECT_TRUE(finite);
    EXPECT_LT(highest - e0, 0.01 * scale);
    EXPECT_EQ(world.stepCount(), static_cast<std::uint64_t>(steps));
}

}  // namespace
}  // namespace physim
