// The one mass rule (physim/core/MassData.hpp) in the World, on an off-centre polygon: a 5 m square with a corner
// at the body origin, centroid (2.5, 2.5). Expected values are the analytic moments of a square plate: m a^2 / 6
// about its centre, m (a^2 + a^2) / 3 about a corner, linked by the parallel-axis theorem.

#include <physim/core/MassData.hpp>
#include <physim/core/World.hpp>

#include <gtest/gtest.h>

namespace physim {
namespace {

constexpr double kSide = 5.0;

Polygon offCentreSquare() { return makePolygon({{0.0, 0.0}, {kSide, 0.0}, {kSide, kSide}, {0.0, kSide}}); }

TEST(MassData, OffCentreSquareMatchesTheParallelAxisTheorem) {
    const MassData d = massDataForDensity(offCentreSquare(), 2.0);
    const double mass = 2.0 * kSide * kSide;
    const double aboutCorner = mass * (kSide * kSide + kSide * kSide) / 3.0;
    EXPECT_NEAR(d.mass, mass, 1e-12);
    EXPECT_NEAR(d.density, 2.0, 1e-15);
    EXPECT_NEAR((d.center - Vec2(2.5, 2.5)).norm(), 0.0, 1e-12);
    EXPECT_NEAR(d.inertia, aboutCorner - mass * d.center.squaredNorm(), 1e-9) << "about the centroid";
    EXPECT_NEAR(d.inertia, mass * kSide * kSide / 6.0, 1e-9);
}

TEST(MassData, TheWorldUsesTheRuleWhenItCreatesAndChangesBodies) {
    World world;
    BodyDef def;
    def.shape = offCentreSquare();
    def.density = 2.0;
    def.position = {1.0, 2.0};
    const BodyId id = world.createBody(def);
    const MassData expected = massDataForDensity(def.shape, def.density);
    EXPECT_EQ(world.mass(id), expected.mass);
    EXPECT_EQ(world.inertia(id), expected.inertia);
    EXPECT_EQ(world.localCenterOfMass(id), expected.center);
    EXPECT_NEAR((world.centerOfMass(id) - Vec2(3.5, 4.5)).norm(), 0.0, 1e-12) << "origin + centroid";

    world.setMass(id, 10.0);
    const MassData heavier = massDataForMass(computeMassProperties(def.shape), 10.0);
    EXPECT_EQ(world.inertia(id), heavier.inertia);
    world.setType(id, BodyType::Static);
    EXPECT_EQ(world.inertia(id), 0.0);
    world.setType(id, BodyType::Dynamic);  // back to the mass its density gives
    EXPECT_EQ(world.inertia(id), heavier.inertia);
}

}  // namespace
}  // namespace physim
