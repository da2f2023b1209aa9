// The new kinds' geometry: mass properties against closed forms and a numerical integration, boxes and outlines
// against the shapes' definitions, and the factories' and validate()'s bad input.

#include "physim/core/Geometry.hpp"

#include "support/ThrowsNaming.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace physim {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Closed forms are evaluated with other groupings than the code's: 1e-12 relative is rounding.
constexpr double kRelative = 1e-12;

double pointToSegment(const Vec2& p, const Vec2& s0, const Vec2& s1) {
    const Vec2 e = s1 - s0;
    const double u = std::clamp((p - s0).dot(e) / e.squaredNorm(), 0.0, 1.0);
    return (p - (s0 + u * e)).norm();
}

// Distance from p to the convex counter-clockwise polygon (0 inside).
double toPolygon(const std::vector<Vec2>& poly, const Vec2& p) {
    bool inside = true;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2& a = poly[i];
        const Vec2& b = poly[(i + 1) % poly.size()];
        if (cross(b - a, p - a) < 0.0) inside = false;
        best = std::min(best, pointToSegment(p, a, b));
    }
    return inside ? 0.0 : best;
}

TEST(CapsuleMass, MatchesRectanglePlusDisc) {
    const double r = 0.3, length = 2.0;
    const Capsule c = makeCapsule({1.0, 0.5}, {1.0 + length * std::cos(0.4), 0.5 + length * std::sin(0.4)}, r);
    const MassProperties m = computeMassProperties(c);
    // Rectangle 2r x L about its centre, plus two half discs whose moments about the capsule's centre follow from the
    // parallel-axis theorem through their centroids (4 r / (3 pi) beyond each end).
    const double rectArea = 2.0 * r * length, halfArea = 0.5 * M_PI * r * r, lever = 4.0 * r / (3.0 * M_PI);
    const double rect = rectArea * (length * length + 4.0 * r * r) / 12.0;
    const double halfOwn = M_PI * r * r * r * r / 4.0 - halfArea * lever * lever;  // about its centroid
    const double half = halfOwn + halfArea * std::pow(0.5 * length + lever, 2);
    EXPECT_NEAR(m.area, rectArea + 2.0 * halfArea, kRelative * m.area);
    EXPECT_NEAR((m.centroid - 0.5 * (c.center1 + c.center2)).norm(), 0.0, 1e-15);
    EXPECT_NEAR(m.secondMoment, rect + 2.0 * half, kRelative * m.secondMoment);
}

// w x h core grown by r: area w h + 2 r (w + h) + pi r^2; moment from the core, four side strips and four quarter
// discs (each about its corner: pi r^4 / 8, centroid 4 r / (3 pi) out along both axes).
TEST(RoundedBoxMass, MatchesCorePlusStripsPlusQuarterDiscs) {
    const double hx = 0.7, hy = 0.4, r = 0.15, w = 2.0 * hx, h = 2.0 * hy;
    const MassProperties m = computeMassProperties(makeRoundedBox(hx, hy, r));
    const double area = w * h + 2.0 * r * (w + h) + M_PI * r * r;
    const double core = w * h * (w * w + h * h) / 12.0;
    const double strips = 2.0 * (w * r * (w * w + r * r) / 12.0 + w * r * std::pow(hy + 0.5 * r, 2)) +
                          2.0 * (h * r * (h * h + r * r) / 12.0 + h * r * std::pow(hx + 0.5 * r, 2));
    const double quarter = 0.25 * M_PI * r * r, lever = 4.0 * r / (3.0 * M_PI);
    const double corners =
        4.0 * (M_PI * r * r * r * r / 8.0 + quarter * (hx * hx + hy * hy) + 2.0 * quarter * lever * (hx + hy));
    EXPECT_NEAR(m.area, area, kRelative * area);
    EXPECT_NEAR(m.centroid.norm(), 0.0, 1e-14);
    EXPECT_NEAR(m.secondMoment, core + strips + corners, kRelative * m.secondMoment);
}

// A rounded triangle off the origin against a jittered-grid integration (one random sample in each of 2000 x 2000
// cells; the shape is every point within r of the core). Jitter keeps the straight edges from lining up with the
// grid, so the boundary cells' errors average out to a few 1e-5 relative; 2e-4 is well above that.
TEST(RoundedPolygonMass, MatchesNumericalIntegration) {
    const std::vector<Vec2> core = {{0.3, 0.1}, {1.4, 0.4}, {0.6, 1.2}};
    const double r = 0.25;
    const MassProperties m = computeMassProperties(makeRoundedPolygon(core, r));
    const double lo = -0.2, hi = 1.7;  // the core's box grown by r, and a margin
    const int n = 2000;
    const double cell = (hi - lo) / n;
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    double area = 0.0, second = 0.0;
    Vec2 first = Vec2::Zero();
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Vec2 p(lo + (i + jitter(rng)) * cell, lo + (j + jitter(rng)) * cell);
            if (toPolygon(core, p) > r) continue;
            area += cell * cell;
            first += cell * cell * p;
            second += cell * cell * p.squaredNorm();
        }
    const Vec2 centroid = first / area;
    const double aboutCentroid = second - area * centroid.squaredNorm();
    EXPECT_NEAR(m.area, area, 2e-4 * area);
    EXPECT_NEAR((m.centroid - centroid).norm(), 0.0, 2e-4);
    EXPECT_NEAR(m.secondMoment, aboutCentroid, 2e-4 * aboutCentroid);
}

TEST(SegmentMass, HasNoAreaAndSitsAtItsMidpoint) {
    const MassProperties m = computeMassProperties(makeSegment({1.0, 2.0}, {3.0, -2.0}));
    EXPECT_EQ(m.area, 0.0);
    EXPECT_EQ(m.secondMoment, 0.0);
    EXPECT_EQ(m.centroid, Vec2(2.0, 0.0));
    const ChainSegment piece{{0.0, 2.0}, makeSegment({1.0, 2.0}, {3.0, -2.0}), {4.0, -2.0}};
    EXPECT_EQ(computeMassProperties(piece).area, 0.0);
}

// Boxes: the extreme points of the placed shape, from its definition.
TEST(RoundedSegmentCapsuleAabb, BoundTheShapesTightly) {
    const Transform xf{{1.0, -2.0}, Rotation::fromAngle(0.6)};
    const Capsule c = makeCapsule({-0.5, 0.0}, {0.5, 0.2}, 0.3);
    const Aabb cb = computeAabb(c, xf);
    const Vec2 c1 = xf.apply(c.center1), c2 = xf.apply(c.center2);
    EXPECT_NEAR(cb.lower.x(), std::min(c1.x(), c2.x()) - 0.3, 1e-12);
    EXPECT_NEAR(cb.upper.y(), std::max(c1.y(), c2.y()) + 0.3, 1e-12);
    const Aabb rb = computeAabb(makeRoundedBox(1.0, 0.5, 0.2), Transform{{2.0, 3.0}, Rotation{}});
    EXPECT_NEAR(rb.lower.x(), 2.0 - 1.2, 1e-12);
    EXPECT_NEAR(rb.upper.y(), 3.0 + 0.7, 1e-12);
    const Aabb sb = computeAabb(makeSegment({0.0, 0.0}, {1.0, 0.0}), xf);
    EXPECT_NEAR(sb.upper.x(), xf.apply(Vec2(1.0, 0.0)).x(), 1e-12);
}

// Twice the signed area of the closed path: positive when counter-clockwise.
double twiceSignedArea(const std::vector<Vec2>& points) {
    double sum = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) sum += cross(points[i], points[(i + 1) % points.size()]);
    return sum;
}

// Every outline point lies on the boundary (at distance radius from the core, 1e-12 m: a rotation and a translation
// of O(1) values) and the path runs counter-clockwise and turns convexly.
TEST(RoundedCapsuleOutline, PointsLieOnTheBoundaryCounterClockwise) {
    const Transform xf{{3.0, -2.0}, Rotation::fromAngle(0.7)};
    const Capsule c = makeCapsule({-0.5, 0.1}, {0.6, -0.2}, 0.25);
    const std::vector<Vec2> capsule = outline(c, xf);
    for (const Vec2& p : capsule)
        EXPECT_NEAR(pointToSegment(p, xf.apply(c.center1), xf.apply(c.center2)), 0.25, 1e-12);
    const std::vector<Vec2> coreLocal = {{0.0, 0.0}, {1.0, 0.0}, {1.2, 0.8}, {0.1, 1.0}};
    const Polygon rounded = makeRoundedPolygon(coreLocal, 0.2);
    const std::vector<Vec2> roundedOutline = outline(rounded, xf);
    std::vector<Vec2> core;
    for (const Vec2& v : coreLocal) core.push_back(xf.apply(v));
    for (const Vec2& p : roundedOutline) EXPECT_NEAR(toPolygon(core, p), 0.2, 1e-12);
    for (const std::vector<Vec2>* points : {&capsule, &roundedOutline}) {
        EXPECT_GT(twiceSignedArea(*points), 0.0);
        const std::size_t n = points->size();
        for (std::size_t i = 0; i < n; ++i) {
            const Vec2& a = (*points)[i];
            const Vec2& b = (*points)[(i + 1) % n];
            const Vec2& d = (*points)[(i + 2) % n];
            EXPECT_GE(cross(b - a, d - b), -1e-12) << "reflex turn at point " << i + 1;
        }
    }
}

using testing::expectThrowsNaming;

TEST(SegmentBadInput, NonFiniteOrZeroLengthThrows) {
    expectThrowsNaming([] { makeSegment({kNaN, 0.0}, {1.0, 0.0}); }, "segment point1");
    expectThrowsNaming([] { makeSegment({0.0, 0.0}, {1.0, kInf}); }, "segment point2");
    expectThrowsNaming([] { makeSegment({1.0, 2.0}, {1.0, 2.0}); }, "zero length");
    expectThrowsNaming([] { makeSegment({-1e308, 0.0}, {1e308, 0.0}); }, "too long");
    EXPECT_NO_THROW(makeSegment({0.0, 0.0}, {1e-9, 0.0}));
    expectThrowsNaming([] { validate(Segment{{0.0, 0.0}, {0.0, 0.0}}); }, "zero length");
}

TEST(CapsuleBadInput, BadCentresOrRadiusThrow) {
    expectThrowsNaming([] { makeCapsule({0.0, kNaN}, {1.0, 0.0}, 0.5); }, "capsule center1");
    expectThrowsNaming([] { makeCapsule({0.0, 0.0}, {0.0, 0.0}, 0.5); }, "zero length");
    for (double r : {0.0, -0.5, kNaN, kInf}) {
        expectThrowsNaming([r] { makeCapsule({0.0, 0.0}, {1.0, 0.0}, r); }, "capsule radius");
        expectThrowsNaming([r] { validate(Capsule{{0.0, 0.0}, {1.0, 0.0}, r}); }, "capsule radius");
    }
}

TEST(RoundedBadInput, BadRadiusOrCoreThrows) {
    for (double r : {0.0, -0.1, kNaN, kInf}) {
        expectThrowsNaming([r] { makeRoundedBox(1.0, 1.0, r); }, "rounded box radius");
        expectThrowsNaming([r] { makeRoundedPolygon({{0, 0}, {1, 0}, {0, 1}}, r); }, "rounded polygon radius");
    }
    expectThrowsNaming([] { makeRoundedBox(-1.0, 1.0, 0.1); }, "box half-width");
    expectThrowsNaming([] { makeRoundedPolygon({{0, 0}, {1, 0}, {2, 0}}, 0.1); }, "collinear");
    for (double r : {-0.1, kNaN, kInf}) {
        Polygon p = makeBox(1.0, 1.0);
        p.radius = r;
        expectThrowsNaming([p] { validate(p); }, "polygon radius");
    }
}

TEST(ChainSegmentBadInput, BadPointsOrGhostsThrow) {
    const Segment s = makeSegment({0.0, 0.0}, {1.0, 0.0});
    expectThrowsNaming([&] { validate(ChainSegment{{kNaN, 0.0}, s, {2.0, 0.0}}); }, "chain segment ghost1");
    expectThrowsNaming([&] { validate(ChainSegment{{-1.0, 0.0}, s, {kInf, 0.0}}); }, "chain segment ghost2");
    expectThrowsNaming([] { validate(ChainSegment{{-1.0, 0.0}, Segment{{0.0, 0.0}, {0.0, 0.0}}, {1.0, 0.0}}); },
                       "zero length");
    EXPECT_NO_THROW(validate(ChainSegment{s.point1, s, s.point2}));  // open at both ends
}

}  // namespace
}  // namespace physim
