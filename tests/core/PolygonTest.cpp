// Polygon construction and validation, mass properties against closed forms, and rotated bounding boxes.
// Tolerance: 1e-12 (relative to O(1) m inputs) where the answer is a closed form evaluated with a few dozen
// floating-point operations; exact comparisons where the construction is exact.

#include "physim/core/Geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace physim {
namespace {

constexpr double kTol = 1e-12;

// Expects makePolygon(points) to throw std::invalid_argument whose message contains `word`.
void expectRejected(const std::vector<Vec2>& points, const std::string& word) {
    try {
        makePolygon(points);
        FAIL() << "accepted a polygon that should fail with '" << word << "'";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
}

TEST(MakePolygon, ClockwiseInputBecomesCounterClockwiseWithOutwardNormals) {
    const Polygon p = makePolygon({{0, 0}, {0, 1}, {2, 1}, {2, 0}});  // clockwise
    ASSERT_EQ(p.count, 4);
    for (int i = 0; i < p.count; ++i) {
        const Vec2 e = p.vertices[(i + 1) % 4] - p.vertices[i];
        EXPECT_GT(cross(e, p.vertices[(i + 2) % 4] - p.vertices[(i + 1) % 4]), 0.0) << "turns left at " << i;
        EXPECT_NEAR(p.normals[i].norm(), 1.0, kTol);
        EXPECT_NEAR(p.normals[i].dot(e), 0.0, kTol);
        // Outward: the centroid (1, 0.5) is behind every face.
        EXPECT_LT(p.normals[i].dot(Vec2(1.0, 0.5) - p.vertices[i]), 0.0);
    }
    EXPECT_NO_THROW(validate(Geometry{p}));
}

TEST(MakePolygon, KeepsCoordinatesAsGiven) {
    const Polygon p = makePolygon({{1, 1}, {3, 1}, {1, 4}});
    EXPECT_EQ(p.vertices[0], Vec2(1, 1));
    EXPECT_EQ(p.vertices[1], Vec2(3, 1));
    EXPECT_EQ(p.vertices[2], Vec2(1, 4));
}

TEST(MakePolygon, AcceptsThreeToEightVertices) {
    for (int n = 3; n <= Polygon::maxVertices; ++n) {
        std::vector<Vec2> pts;
        for (int i = 0; i < n; ++i) pts.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n));
        const Polygon p = makePolygon(pts);
        EXPECT_EQ(p.count, n);
        // Regular n-gon of circumradius 1: area n sin(2 pi / n) / 2, centroid at the origin.
        const MassProperties mp = computeMassProperties(p);
        EXPECT_NEAR(mp.area, 0.5 * n * std::sin(2 * M_PI / n), kTol);
        EXPECT_NEAR(mp.centroid.norm(), 0.0, kTol);
        // Polar second moment of a regular n-gon: A R^2 (1 + 2 cos^2(pi/n)) / 6.
        const double c = std::cos(M_PI / n);
        EXPECT_NEAR(mp.secondMoment, mp.area * (1.0 + 2.0 * c * c) / 6.0, kTol);
    }
}

TEST(MakePolygon, BadInputNamesTheProblem) {
    expectRejected({{0, 0}, {1, 0}}, "vertex count");
    expectRejected({{0, 0}, {1, 0}, {1, 1}, {0.5, 1.5}, {0, 1}, {-1, 1}, {-1, 0.5}, {-1, 0}, {-0.5, -0.5}},
                   "vertex count");
    expectRejected({{0, 0}, {1, 0}, {1, NAN}}, "finite");
    expectRejected({{0, 0}, {1, 0}, {INFINITY, 1}}, "finite");
    expectRejected({{0, 0}, {1, 0}, {1, 0}, {0, 1}}, "coincident");
    expectRejected({{0, 0}, {1e300, 0}, {0, 1e300}}, "too large");
    expectRejected({{0, 0}, {1, 0}, {2, 0}}, "collinear");                   // zero area
    expectRejected({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}, "collinear");   // a vertex mid-edge
    expectRejected({{0, 0}, {2, 0}, {1, 0.5}, {2, 2}, {0, 2}}, "convex");    // reflex vertex
    // A pentagram: every corner turns the same way, but the boundary winds twice.
    std::vector<Vec2> star;
    for (int i = 0; i < 5; ++i) star.emplace_back(std::cos(4 * M_PI * i / 5), std::sin(4 * M_PI * i / 5));
    expectRejected(star, "intersect");
}

TEST(ValidatePolygon, RejectsHandFilledMistakes) {
    Polygon p = makeBox(1.0, 0.5);
    EXPECT_NO_THROW(validate(Geometry{p}));
    Polygon bad = p;
    bad.normals[2] = {0.0, -1.0};  // inward
    EXPECT_THROW(validate(Geometry{bad}), std::invalid_argument);
    bad = p;
    std::swap(bad.vertices[1], bad.vertices[3]);  // clockwise
    EXPECT_THROW(validate(Geometry{bad}), std::invalid_argument);
    bad = p;
    bad.count = 2;
    EXPECT_THROW(validate(Geometry{bad}), std::invalid_argument);
    bad = p;
    bad.vertices[2] = {0.0, -0.1};  // reflex corner
    EXPECT_THROW(validate(Geometry{bad}), std::invalid_argument);
    EXPECT_THROW(validate(Geometry{Circle{Vec2::Zero(), -1.0}}), std::invalid_argument);
    EXPECT_THROW(validate(Geometry{Circle{Vec2(NAN, 0.0), 1.0}}), std::invalid_argument);
}

TEST(MakeBox, BadSizesThrowAndOffsetBoxIsPlaced) {
    EXPECT_THROW(makeBox(0.0, 1.0), std::invalid_argument);
    EXPECT_THROW(makeBox(1.0, -1.0), std::invalid_argument);
    EXPECT_THROW(makeBox(NAN, 1.0), std::invalid_argument);
    EXPECT_THROW(makeBox(1.0, 1.0, {0.0, 0.0}, INFINITY), std::invalid_argument);
    EXPECT_THROW(makeCircle(0.0), std::invalid_argument);
    EXPECT_THROW(makeCircle(-1.0), std::invalid_argument);

    const Polygon p = makeBox(1.0, 0.5, {2.0, 3.0}, M_PI / 2);
    EXPECT_NO_THROW(validate(Geometry{p}));
    const MassProperties mp = computeMassProperties(p);
    EXPECT_NEAR(mp.area, 2.0, kTol);
    EXPECT_NEAR((mp.centroid - Vec2(2.0, 3.0)).norm(), 0.0, kTol);
    EXPECT_NEAR(mp.secondMoment, 2.0 * (4.0 + 1.0) / 12.0, kTol);  // A (w^2 + h^2) / 12, about the centroid
    const Aabb box = computeAabb(p, Transform{});
    EXPECT_NEAR((box.lower - Vec2(1.5, 2.0)).norm(), 0.0, kTol);
    EXPECT_NEAR((box.upper - Vec2(2.5, 4.0)).norm(), 0.0, kTol);
}

TEST(MassProperties, TriangleAndCircleMatchClosedForms) {
    // Right triangle with legs 3 (x) and 4 (y): area 6, centroid (1, 4/3),
    // polar moment about the centroid = A (a^2 + b^2) / 18 for legs a, b.
    const MassProperties t = computeMassProperties(makePolygon({{0, 0}, {3, 0}, {0, 4}}));
    EXPECT_NEAR(t.area, 6.0, kTol);
    EXPECT_NEAR((t.centroid - Vec2(1.0, 4.0 / 3.0)).norm(), 0.0, kTol);
    EXPECT_NEAR(t.secondMoment, 6.0 * 25.0 / 18.0, kTol);
    const MassProperties c = computeMassProperties(makeCircle(2.0, {1.0, -1.0}));
    EXPECT_NEAR(c.area, 4.0 * M_PI, kTol);
    EXPECT_EQ(c.centroid, Vec2(1.0, -1.0));
    EXPECT_NEAR(c.secondMoment, 0.5 * 4.0 * M_PI * 4.0, kTol);
}

TEST(Aabb, RotatedShapesGetTightWorldBoxes) {
    // A 2 x 2 square turned 45 degrees spans +-sqrt(2) on both axes.
    const Transform xf{{10.0, -5.0}, Rotation::fromAngle(M_PI / 4)};
    const Aabb box = computeAabb(makeBox(1.0, 1.0), xf);
    EXPECT_NEAR(box.lower.x(), 10.0 - std::sqrt(2.0), kTol);
    EXPECT_NEAR(box.upper.y(), -5.0 + std::sqrt(2.0), kTol);
    // An offset circle moves with the body's rotation.
    const Aabb disc = computeAabb(makeCircle(0.5, {1.0, 0.0}), Transform{{0.0, 0.0}, Rotation::fromAngle(M_PI / 2)});
    EXPECT_NEAR((disc.lower - Vec2(-0.5, 0.5)).norm(), 0.0, kTol);
    EXPECT_NEAR((disc.upper - Vec2(0.5, 1.5)).norm(), 0.0, kTol);
}

}  // namespace
}  // namespace physim
