// computeHull against a brute-force reference that shares no code with it: gift wrapping (Jarvis march) over
// every point, with its own shoelace area and inside test. Random clouds at three scales, then bad input.
// Tolerances are relative to the cloud's extent L (bounding-box diagonal): 1e-12 L for "on or inside" and
// 1e-12 L^2 for areas, far above the rounding of coordinates up to 10 L from the origin (about 1e-15 L) and
// far below the 1e-6 L that computeHull may move a boundary when it welds or straightens corners.

#include "physim/core/Geometry.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace physim {
namespace {

double crossOf(const Vec2& o, const Vec2& a, const Vec2& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Gift wrapping: from the leftmost (then lowest) point, the next corner is the point with every other point on
// its left (the farthest one when several are in line), until the start comes round again.
std::vector<Vec2> giftWrap(const std::vector<Vec2>& pts) {
    std::size_t start = 0;
    for (std::size_t i = 1; i < pts.size(); ++i)
        if (pts[i].x() < pts[start].x() || (pts[i].x() == pts[start].x() && pts[i].y() < pts[start].y())) start = i;
    std::vector<Vec2> hull;
    std::size_t cur = start;
    do {
        hull.push_back(pts[cur]);
        std::size_t best = cur;
        for (std::size_t q = 0; q < pts.size(); ++q) {
            if (pts[q] == pts[cur]) continue;
            if (best == cur) {
                best = q;
                continue;
            }
            const double c = crossOf(pts[cur], pts[best], pts[q]);
            const double dq = (pts[q] - pts[cur]).squaredNorm(), db = (pts[best] - pts[cur]).squaredNorm();
            if (c < 0.0 || (c == 0.0 && dq > db)) best = q;
        }
        cur = best;
    } while (pts[cur] != pts[start] && hull.size() <= pts.size());
    return hull;
}

double shoelace(const std::vector<Vec2>& v) {
    double twice = 0.0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const Vec2& a = v[i];
        const Vec2& b = v[(i + 1) % v.size()];
        twice += a.x() * b.y() - b.x() * a.y();
    }
    return 0.5 * twice;
}

double extentOf(const std::vector<Vec2>& pts) {
    double minX = pts[0].x(), maxX = minX, minY = pts[0].y(), maxY = minY;
    for (const Vec2& p : pts) {
        minX = std::min(minX, p.x());
        maxX = std::max(maxX, p.x());
        minY = std::min(minY, p.y());
        maxY = std::max(maxY, p.y());
    }
    return std::hypot(maxX - minX, maxY - minY);
}

// Every property the hull promises, checked against the points and their gift-wrapped hull.
void expectHullOf(const Polygon& p, const std::vector<Vec2>& pts) {
    const double L = extentOf(pts);
    const std::vector<Vec2> reference = giftWrap(pts);
    ASSERT_EQ(p.count, static_cast<int>(reference.size()));
    EXPECT_EQ(p.radius, 0.0);
    std::vector<Vec2> corners(p.vertices.begin(), p.vertices.begin() + p.count);
    for (const Vec2& c : corners)  // every corner is one of the input points, bit for bit
        EXPECT_NE(std::find(pts.begin(), pts.end(), c), pts.end()) << c.transpose();
    for (const Vec2& r : reference)  // and the same corners as the reference's
        EXPECT_NE(std::find(corners.begin(), corners.end(), r), corners.end()) << r.transpose();
    for (int i = 0; i < p.count; ++i) {  // strictly convex and counter-clockwise
        const Vec2& a = corners[i];
        const Vec2& b = corners[(i + 1) % p.count];
        const Vec2& c = corners[(i + 2) % p.count];
        EXPECT_GT(crossOf(a, b, c), 0.0) << "corner " << (i + 1) % p.count;
    }
    for (const Vec2& q : pts)  // nothing outside: signed distance to each edge's line at most 1e-12 L outward
        for (int i = 0; i < p.count; ++i) {
            const Vec2& a = corners[i];
            const Vec2& b = corners[(i + 1) % p.count];
            EXPECT_GE(crossOf(a, b, q) / (b - a).norm(), -1e-12 * L) << q.transpose() << " outside edge " << i;
        }
    EXPECT_NEAR(shoelace(corners), shoelace(reference), 1e-12 * L * L);
    EXPECT_NO_THROW(validate(Geometry{p}));
}

std::string rejection(const std::vector<Vec2>& pts) {
    try {
        computeHull(pts);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(accepted)";
}

#define EXPECT_REJECTED(pts, word) EXPECT_NE(rejection(pts).find(word), std::string::npos) << rejection(pts)

TEST(Hull, RandomCloudsMatchGiftWrapping) {
    std::mt19937 rng(52);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> size(3, 14);
    int checked = 0, tooMany = 0;
    for (double scale : {1e-3, 1.0, 1e3})
        for (int trial = 0; trial < 400; ++trial) {
            const Vec2 offset = 10.0 * scale * Vec2(unit(rng), unit(rng));
            std::vector<Vec2> pts;
            const int n = size(rng);
            while (static_cast<int>(pts.size()) < n) {  // uniform in a disc of radius `scale`
                const Vec2 u(unit(rng), unit(rng));
                if (u.squaredNorm() <= 1.0) pts.push_back(offset + scale * u);
            }
            const std::size_t corners = giftWrap(pts).size();
            if (corners > static_cast<std::size_t>(Polygon::maxVertices)) {
                EXPECT_REJECTED(pts, "has " + std::to_string(corners) + " vertices");
                ++tooMany;
                continue;
            }
            SCOPED_TRACE("scale " + std::to_string(scale) + " trial " + std::to_string(trial));
            expectHullOf(computeHull(pts), pts);
            ++checked;
        }
    EXPECT_GT(checked, 1000);  // the clouds are mostly small enough...
    EXPECT_GT(tooMany, 0);     // ...and some are not
}

TEST(Hull, DropsInsideEdgeAndRepeatedPointsOfAKnownPolygon) {
    // Corners of a random convex polygon (jittered angles on an ellipse, so no corner is nearly straight), then
    // points strictly inside, points on its edges and exact repeats of its corners, all shuffled.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        const int m = 3 + trial % (Polygon::maxVertices - 2);
        std::vector<Vec2> corners;
        const double phase = 2 * M_PI * u01(rng);
        for (int k = 0; k < m; ++k) {
            const double a = phase + 2 * M_PI * (k + 0.4 * u01(rng)) / m;
            corners.emplace_back(3.0 + 2.0 * std::cos(a), -1.0 + 0.7 * std::sin(a));
        }
        std::vector<Vec2> pts = corners;
        for (int k = 0; k < 20; ++k) {  // inside: a convex combination of three corners with positive weights
            double w[3] = {0.05 + u01(rng), 0.05 + u01(rng), 0.05 + u01(rng)};
            const double sum = w[0] + w[1] + w[2];
            pts.push_back((w[0] * corners[k % m] + w[1] * corners[(k + 1) % m] + w[2] * corners[(k + 2) % m]) / sum);
        }
        for (int k = 0; k < m; ++k) {  // on each edge, and each corner again
            const double t = 0.1 + 0.8 * u01(rng);
            pts.push_back((1 - t) * corners[k] + t * corners[(k + 1) % m]);
            pts.push_back(corners[k]);
        }
        std::shuffle(pts.begin(), pts.end(), rng);
        const Polygon p = computeHull(pts);
        ASSERT_EQ(p.count, m);
        for (int i = 0; i < p.count; ++i)
            EXPECT_NE(std::find(corners.begin(), corners.end(), p.vertices[i]), corners.end());
        EXPECT_NEAR(shoelace(corners), computeMassProperties(p).area, 1e-12 * 4.0 * 4.0);
    }
}

TEST(Hull, OrderOfThePointsDoesNotMatter) {
    const std::vector<Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const Polygon ccw = computeHull(square);
    const Polygon cw = computeHull({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    const Polygon mixed = computeHull({{1, 1}, {0, 0}, {0.5, 0.5}, {0, 1}, {1, 0}});
    for (const Polygon* p : {&ccw, &cw, &mixed}) {
        ASSERT_EQ(p->count, 4);
        for (int i = 0; i < 4; ++i) EXPECT_EQ(p->vertices[i], ccw.vertices[i]);  // same start, same order
    }
    EXPECT_EQ(ccw.vertices[0], Vec2(0, 0));  // the leftmost, then lowest, point first
    EXPECT_EQ(ccw.vertices[1], Vec2(1, 0));  // counter-clockwise from there
}

TEST(Hull, DenseSamplesAlongEdgesLeaveOnlyTheCorners) {
    // 40,000 points along a rotated square's edges: rounding puts some a hair outside their edge, where the chain
    // keeps them as corners turning by about 1e-16 rad; straightening leaves the four true corners.
    const Vec2 c[4] = {{1.0, 0.2}, {3.1, 1.1}, {2.2, 3.2}, {0.1, 2.3}};
    std::vector<Vec2> pts;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 10000; ++j) pts.push_back(c[k] + (c[(k + 1) % 4] - c[k]) * (j / 10000.0));
    const Polygon p = computeHull(pts);
    ASSERT_EQ(p.count, 4);
    for (int i = 0; i < 4; ++i) EXPECT_NE(std::find(std::begin(c), std::end(c), p.vertices[i]), std::end(c));
}

TEST(Hull, WeldsNearlyRepeatedPoints) {
    // Copies 1e-9 m off a 1 m square's corners: one corner each (the weld tolerance is 1e-6 of the extent).
    const std::vector<Vec2> pts{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1e-9, 0}, {1, 1e-9}, {1 - 1e-9, 1 + 1e-9}, {0, 1}};
    const Polygon p = computeHull(pts);
    EXPECT_EQ(p.count, 4);
    EXPECT_NEAR(computeMassProperties(p).area, 1.0, 1e-8);  // the welded corners move the edges by <= 1e-9 m
}

TEST(Hull, RadiusOverloadMakesARoundedHull) {
    const Polygon p = computeHull({{0, 0}, {2, 0}, {1, 1}, {1, 0.2}}, 0.25);
    EXPECT_EQ(p.count, 3);
    EXPECT_EQ(p.radius, 0.25);
    EXPECT_EQ(computeHull({{0, 0}, {2, 0}, {1, 1}}, 0.0).radius, 0.0);
}

TEST(Hull, RejectsTooFewPoints) {
    EXPECT_REJECTED(std::vector<Vec2>{}, "at least 3 points, got 0");
    EXPECT_REJECTED((std::vector<Vec2>{{0, 0}, {1, 0}}), "at least 3 points, got 2");
}

TEST(Hull, RejectsNonFinitePointsNamingIndexAndValue) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_REJECTED((std::vector<Vec2>{{0, 0}, {1, 0}, {nan, 1}, {0, 1}}), "point 2 must be finite, got (nan, 1)");
    EXPECT_REJECTED((std::vector<Vec2>{{0, 0}, {1, inf}, {0, 1}}), "point 1 must be finite, got (1, inf)");
}

TEST(Hull, RejectsCoincidentPoints) {
    EXPECT_REJECTED((std::vector<Vec2>{{1, 2}, {1, 2}, {1, 2}, {1, 2}}), "coincide at (1, 2)");
}

TEST(Hull, RejectsCollinearPoints) {
    EXPECT_REJECTED((std::vector<Vec2>{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {0.5, 0.5}}), "collinear");
    // Two distinct points, each repeated or nearly so: too few remain once welded.
    EXPECT_REJECTED((std::vector<Vec2>{{0, 0}, {1, 0}, {0, 0}, {1, 1e-12}, {1e-12, 0}}), "collinear");
    // Nearly in line: the middle point is 1e-9 m off a 2 m line, a turn far below 1e-6 rad.
    EXPECT_REJECTED((std::vector<Vec2>{{0, 0}, {1, 1e-9}, {2, 0}}), "collinear");
}

TEST(Hull, RejectsTooManyCornersSayingHowMany) {
    std::vector<Vec2> circle;
    for (int i = 0; i < 12; ++i) circle.emplace_back(std::cos(2 * M_PI * i / 12), std::sin(2 * M_PI * i / 12));
    circle.emplace_back(0.1, 0.2);  // inside: not counted
    EXPECT_REJECTED(circle, "has 12 vertices, more than Polygon::maxVertices (8)");
}

TEST(Hull, RejectsBadRadius) {
    const std::vector<Vec2> tri{{0, 0}, {1, 0}, {0, 1}};
    for (double r : {-0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        try {
            computeHull(tri, r);
            ADD_FAILURE() << "accepted radius " << r;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("convex hull radius"), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace physim
