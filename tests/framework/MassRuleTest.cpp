// One mass rule before and after a body joins a world (physim/core/MassData.hpp), and where an Object's position
// is, checked on an off-centre shape: a 5 m square with a corner at the body origin, so the centroid is at
// (2.5, 2.5). Expected values come from the analytic moments of a square and the parallel-axis theorem.

#include <physim/core/PolygonShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Simulation.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace physim {
namespace {

constexpr double kSide = 5.0;
constexpr double kDensity = 2.0;
const std::vector<Vec2> kSquare{{0.0, 0.0}, {kSide, 0.0}, {kSide, kSide}, {0.0, kSide}};

std::unique_ptr<Object> offCentreSquare() {
    auto o = std::make_unique<Object>(Mesh::PolygonMesh(kSquare, sf::Color::White), PolygonShape(kSquare));
    o->rb.setDensity(kDensity);
    return o;
}

// A square plate of mass m and side a: m a^2 / 6 about its centre; about a corner, m (a^2 + a^2) / 3. The
// parallel-axis theorem links the two through the centre's distance d from the corner, d^2 = 2 (a/2)^2.
constexpr double kMass = kDensity * kSide * kSide;
constexpr double kInertiaAboutCorner = kMass * (kSide * kSide + kSide * kSide) / 3.0;
constexpr double kCentreDistanceSquared = 2.0 * (kSide / 2.0) * (kSide / 2.0);
constexpr double kInertiaAboutCentre = kInertiaAboutCorner - kMass * kCentreDistanceSquared;

TEST(MassRule, OffCentreShapeHasTheSameInertiaBeforeAndAfterJoining) {
    auto made = offCentreSquare();
    const double before = made->rb.inertia();
    EXPECT_NEAR(made->rb.mass(), kMass, 1e-12);
    EXPECT_NEAR(before, kInertiaAboutCentre, 1e-9);
    EXPECT_NEAR(made->rb.inv_inertia(), 1.0 / kInertiaAboutCentre, 1e-15);

    Simulation sim;
    Object& o = sim.addEntity(std::move(made));
    EXPECT_EQ(o.rb.inertia(), before) << "the world and the unattached body use the same rule, to the bit";
    EXPECT_EQ(o.rb.mass(), kMass);
    EXPECT_NEAR(sim.world().inertia(o.rb.bodyId()), kInertiaAboutCentre, 1e-9);
}

TEST(MassRule, SetMassAndFixedRotationAgreeBeforeAndAfterJoining) {
    auto made = offCentreSquare();
    made->rb.setMass(10.0);
    made->rb.setFixedRotation(true);
    const double inertia = made->rb.inertia();
    EXPECT_NEAR(inertia, 10.0 * kSide * kSide / 6.0, 1e-9);
    EXPECT_EQ(made->rb.inv_inertia(), 0.0) << "fixed rotation: the shape's inertia stays, its inverse is 0";

    Simulation sim;
    Object& o = sim.addEntity(std::move(made));
    EXPECT_EQ(o.rb.inertia(), inertia);
    EXPECT_EQ(o.rb.inv_inertia(), 0.0);
    o.rb.setFixedRotation(false);
    EXPECT_EQ(o.rb.inv_inertia(), 1.0 / inertia);
}

TEST(ObjectPosition, SetPositionPlacesTheOriginNotTheCentreOfMass) {
    auto made = offCentreSquare();
    made->setPosition({1.0, 2.0});
    EXPECT_EQ(made->getPosition(), Vec2(1.0, 2.0));
    EXPECT_NEAR((made->getCenterOfMass() - Vec2(3.5, 4.5)).norm(), 0.0, 1e-12);

    Simulation sim;
    sim.world().setSettings([] {
        WorldSettings s;
        s.gravity = Vec2::Zero();
        return s;
    }());
    Object& o = sim.addEntity(std::move(made));
    EXPECT_EQ(o.getPosition(), Vec2(1.0, 2.0));
    EXPECT_NEAR((o.getCenterOfMass() - Vec2(3.5, 4.5)).norm(), 0.0, 1e-12);

    // setRotation turns about the origin: a quarter turn carries the centre from (+2.5, +2.5) to (-2.5, +2.5).
    o.setRotation(std::acos(0.0));
    EXPECT_NEAR((o.getPosition() - Vec2(1.0, 2.0)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((o.getCenterOfMass() - Vec2(-1.5, 4.5)).norm(), 0.0, 1e-12);

    // Spinning freely, the body turns about its centre of mass: that point stays, the origin circles it.
    const Vec2 centre = o.getCenterOfMass();
    o.rb.setAngularVelocity(1.0);
    for (int i = 0; i < 10; ++i) sim.fixedStep();
    EXPECT_NEAR((o.getCenterOfMass() - centre).norm(), 0.0, 1e-9);
    EXPECT_GT((o.getPosition() - Vec2(1.0, 2.0)).norm(), 0.1);
    EXPECT_NEAR((o.getPosition() - centre).norm(), std::sqrt(kCentreDistanceSquared), 1e-9);
}

}  // namespace
}  // namespace physim
