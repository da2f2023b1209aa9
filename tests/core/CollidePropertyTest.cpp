// Randomised narrow-phase checks against brute-force references that share no code with the narrow phase:
// - touching or not: exact geometric tests (point in polygon, segment crossings, point-segment distances);
// - penetration: the minimum over directions d of h(d) = max_A(x . d) - min_B(x . d) (how far B must move
//   along d to clear A), sampled at 720 directions and refined by golden-section search around the best
//   samples;
// - contact points: each lies within penetration / 2 of both shapes (plus half the 5e-4 m speculative margin
//   for a polygon point just off the reference face).
// Fixed seeds; 12 000 pairs per test keeps the suite fast under AddressSanitizer too.
// Tolerances: 1e-9 m for identities the narrow phase computes directly (shapes are O(1) m, so that is a
// million times rounding); 1e-7 m against the sampled minimum (what golden-section search reaches); and
// kReferenceFaceTolerance (1e-4 m, src/core/Manifolds.hpp) where two facing polygon edges tie.

#include "physim/core/Collide.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace physim {
namespace {

constexpr int kPairs = 12000;
constexpr double kExact = 1e-9;
constexpr double kSampled = 1e-7;
constexpr double kFacingTie = 1e-4;  // = kReferenceFaceTolerance
constexpr double kMargin = 2.5e-4 + kExact;  // half of kSpeculativeMargin: how far a kept point may lie outside

// World-space copy of a placed shape, for the references.
struct Placed {
    bool circle = false;
    Vec2 center = Vec2::Zero();
    double radius = 0.0;
    std::vector<Vec2> vertices;  // counter-clockwise
};

Placed place(const Geometry& g, const Transform& xf) {
    Placed p;
    if (const auto* c = std::get_if<Circle>(&g)) {
        p.circle = true;
        p.center = xf.apply(c->center);
        p.radius = c->radius;
    } else {
        const auto& poly = std::get<Polygon>(g);
        for (int i = 0; i < poly.count; ++i) p.vertices.push_back(xf.apply(poly.vertices[i]));
    }
    return p;
}

double support(const Placed& s, const Vec2& d) {
    if (s.circle) return s.center.dot(d) + s.radius;
    double best = -std::numeric_limits<double>::infinity();
    for (const Vec2& v : s.vertices) best = std::max(best, v.dot(d));
    return best;
}

// How far B must move along the unit direction d to clear A.
double push(const Placed& a, const Placed& b, const Vec2& d) { return support(a, d) + support(b, -d); }

double segmentDistance(const Vec2& p, const Vec2& s0, const Vec2& s1) {
    const Vec2 e = s1 - s0;
    const double u = std::clamp((p - s0).dot(e) / e.squaredNorm(), 0.0, 1.0);
    return (p - (s0 + u * e)).norm();
}

bool inside(const std::vector<Vec2>& poly, const Vec2& p) {
    for (std::size_t i = 0; i < poly.size(); ++i)
        if (cross(poly[(i + 1) % poly.size()] - poly[i], p - poly[i]) < 0.0) return false;
    return true;
}

// Distance from a point to a placed shape (0 inside).
double distanceTo(const Placed& s, const Vec2& p) {
    if (s.circle) return std::max((p - s.center).norm() - s.radius, 0.0);
    if (inside(s.vertices, p)) return 0.0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < s.vertices.size(); ++i)
        best = std::min(best, segmentDistance(p, s.vertices[i], s.vertices[(i + 1) % s.vertices.size()]));
    return best;
}

bool segmentsCross(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
    const double d1 = cross(p1 - p0, q0 - p0), d2 = cross(p1 - p0, q1 - p0);
    const double d3 = cross(q1 - q0, p0 - q0), d4 = cross(q1 - q0, p1 - q0);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

// Gap between two shapes: > 0 apart, 0 when they touch or overlap.
double gap(const Placed& a, const Placed& b) {
    if (a.circle && b.circle) return std::max((a.center - b.center).norm() - a.radius - b.radius, 0.0);
    if (a.circle) return std::max(distanceTo(b, a.center) - a.radius, 0.0);
    if (b.circle) return std::max(distanceTo(a, b.center) - b.radius, 0.0);
    // Convex polygons: they meet if two edges cross; otherwise the closest pair involves a vertex of one.
    const std::size_t na = a.vertices.size(), nb = b.vertices.size();
    for (std::size_t i = 0; i < na; ++i)
        for (std::size_t j = 0; j < nb; ++j)
            if (segmentsCross(a.vertices[i], a.vertices[(i + 1) % na], b.vertices[j], b.vertices[(j + 1) % nb]))
                return 0.0;
    double best = std::numeric_limits<double>::infinity();
    for (const Vec2& v : a.vertices) best = std::min(best, distanceTo(b, v));
    for (const Vec2& v : b.vertices) best = std::min(best, distanceTo(a, v));
    return best;
}

Vec2 direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

// Minimum translation distance by sampling directions, refining around the four best local minima.
double bruteForceDepth(const Placed& a, const Placed& b) {
    constexpr int n = 720;
    const double step = 2.0 * M_PI / n;
    std::vector<double> h(n);
    for (int i = 0; i < n; ++i) h[i] = push(a, b, direction(i * step));
    std::vector<int> minima;
    for (int i = 0; i < n; ++i)
        if (h[i] <= h[(i + n - 1) % n] && h[i] <= h[(i + 1) % n]) minima.push_back(i);
    std::sort(minima.begin(), minima.end(), [&](int x, int y) { return h[x] < h[y]; });
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < std::min<std::size_t>(4, minima.size()); ++k) {
        double lo = (minima[k] - 1) * step, hi = (minima[k] + 1) * step;
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        for (int it = 0; it < 80; ++it) {
            const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
            if (push(a, b, direction(m1)) < push(a, b, direction(m2))) hi = m2; else lo = m1;
        }
        best = std::min({best, h[minima[k]], push(a, b, direction(0.5 * (lo + hi)))});
    }
    return best;
}

class RandomShapes {
public:
    explicit RandomShapes(unsigned seed) : rng_(seed) {}

    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }

    Geometry shape() {
        switch (std::uniform_int_distribution<int>(0, 3)(rng_)) {
            case 0: return makeCircle(uniform(0.1, 1.5), {uniform(-0.3, 0.3), uniform(-0.3, 0.3)});
            case 1: return makeBox(uniform(0.05, 1.5), uniform(0.05, 1.5));
            default: return polygon();
        }
    }

    Transform transform(double spread) {
        return {{uniform(-spread, spread), uniform(-spread, spread)}, Rotation::fromAngle(uniform(-M_PI, M_PI))};
    }

private:
    // Points on an ellipse at sorted random angles: convex, 3 to 8 vertices, sometimes long and thin.
    Polygon polygon() {
        for (;;) {
            const int count = std::uniform_int_distribution<int>(3, Polygon::maxVertices)(rng_);
            std::vector<double> angles(count);
            for (double& t : angles) t = uniform(0.0, 2.0 * M_PI);
            std::sort(angles.begin(), angles.end());
            const double rx = uniform(0.1, 1.5), ry = uniform(0.1, 1.5);
            const Vec2 offset(uniform(-0.3, 0.3), uniform(-0.3, 0.3));
            std::vector<Vec2> pts;
            for (double t : angles) pts.emplace_back(offset.x() + rx * std::cos(t), offset.y() + ry * std::sin(t));
            try {
                return makePolygon(pts);
            } catch (const std::invalid_argument&) {
                // near-coincident or collinear draw: draw again
            }
        }
    }

    std::mt19937_64 rng_;
};

bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

TEST(CollideProperty, MatchesBruteForceReference) {
    RandomShapes random(20240512);
    int colliding = 0, twoPoints = 0, facingTies = 0;
    for (int k = 0; k < kPairs; ++k) {
        const Geometry ga = random.shape(), gb = random.shape();
        const Transform xa = random.transform(1.0), xb = random.transform(1.0);
        const Placed a = place(ga, xa), b = place(gb, xb);
        const Colliding c = computeColliding(ga, xa, gb, xb);
        const double apart = gap(a, b);
        SCOPED_TRACE("pair " + std::to_string(k));

        if (apart > kExact) {
            EXPECT_FALSE(c.collision) << "gap " << apart;
            continue;
        }
        const double depth = bruteForceDepth(a, b);
        if (depth < kExact) continue;  // grazing: either answer is right
        ASSERT_TRUE(c.collision) << "depth " << depth;
        ++colliding;
        ASSERT_TRUE(finite(c.normal));
        EXPECT_NEAR(c.normal.norm(), 1.0, 1e-12);
        // Moving B by penetration along the normal just clears A.
        EXPECT_NEAR(push(a, b, c.normal), c.penetration, kExact);
        // No shorter move exists (up to the facing-edge tie allowance).
        const double excess = c.penetration - depth;
        EXPECT_GT(excess, -kSampled) << "deeper than the sampled minimum?";
        if (excess > kSampled) {
            ++facingTies;
            EXPECT_LT(excess, kFacingTie + kSampled);
        }
        EXPECT_LE(c.overlap, c.penetration + kExact);
        const int n = c.collidingPoints.contactCount;
        ASSERT_TRUE(n == 1 || n == 2);
        if (n == 2) ++twoPoints;
        for (int i = 0; i < n; ++i) {
            const Vec2& p = i == 0 ? c.collidingPoints.pointA : c.collidingPoints.pointB;
            ASSERT_TRUE(finite(p));
            EXPECT_LE(distanceTo(a, p), 0.5 * c.penetration + kMargin);
            EXPECT_LE(distanceTo(b, p), 0.5 * c.penetration + kMargin);
        }
    }
    // The draw must exercise the interesting cases, not just misses.
    EXPECT_GT(colliding, kPairs / 4);
    EXPECT_GT(twoPoints, 50);
    EXPECT_LT(facingTies, kPairs / 1000) << "ties between facing edges should be rare in random draws";
}

TEST(CollideProperty, SwappingTheShapesReversesTheNormal) {
    RandomShapes random(7);
    int exactFlips = 0, colliding = 0;
    for (int k = 0; k < kPairs; ++k) {
        const Geometry ga = random.shape(), gb = random.shape();
        const Transform xa = random.transform(1.0), xb = random.transform(1.0);
        const Colliding ab = computeColliding(ga, xa, gb, xb);
        const Colliding ba = computeColliding(gb, xb, ga, xa);
        SCOPED_TRACE("pair " + std::to_string(k));
        ASSERT_EQ(ab.collision, ba.collision);
        if (!ab.collision) continue;
        ++colliding;
        EXPECT_NEAR(ab.penetration, ba.penetration, kFacingTie);
        // Either the exact reverse, or (a facing-edge tie resolved towards the first shape) another axis whose
        // push is the same depth to within the tie allowance.
        if ((ab.normal + ba.normal).norm() < kExact) {
            ++exactFlips;
            EXPECT_NEAR(ab.penetration, ba.penetration, kExact);
        } else {
            const Placed a = place(ga, xa), b = place(gb, xb);
            EXPECT_NEAR(push(a, b, -ba.normal), ab.penetration, kFacingTie + kExact);
        }
    }
    EXPECT_GT(exactFlips, colliding - colliding / 100);
}

TEST(CollideProperty, NeverNaNForFiniteAndDegenerateInputs) {
    RandomShapes random(99);
    auto check = [](const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
        const Manifold m = collide(a, xa, b, xb);
        ASSERT_GE(m.pointCount, 0);
        ASSERT_LE(m.pointCount, 2);
        if (m.pointCount == 0) return;
        ASSERT_TRUE(finite(m.normal));
        ASSERT_NEAR(m.normal.norm(), 1.0, 1e-12);
        for (int i = 0; i < m.pointCount; ++i) {
            ASSERT_TRUE(finite(m.points[i].point));
            ASSERT_TRUE(std::isfinite(m.points[i].separation));
            ASSERT_LE(m.points[i].separation, 5e-4);  // kSpeculativeMargin
        }
    };
    // Scaled shapes: micrometre to kilometre, near and very far from the origin, all placements.
    for (int k = 0; k < kPairs; ++k) {
        const double scale = std::pow(10.0, random.uniform(-6.0, 3.0));
        const Vec2 far = Vec2(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0)) * std::pow(10.0, random.uniform(0, 7));
        Geometry ga = random.shape(), gb = random.shape();
        for (Geometry* g : {&ga, &gb}) {
            if (auto* c = std::get_if<Circle>(g)) {
                c->radius *= scale;
                c->center *= scale;
            } else {
                auto& p = std::get<Polygon>(*g);
                for (int i = 0; i < p.count; ++i) p.vertices[i] *= scale;
            }
        }
        Transform xa = random.transform(scale), xb = random.transform(scale);
        xa.p += far;
        xb.p += far;
        check(ga, xa, gb, xb);
        check(gb, xb, ga, xa);
    }
    // Coincident placements and shared features: ties in every choice the narrow phase makes.
    const std::vector<Geometry> shapes = {makeCircle(1.0), makeBox(1.0, 1.0), makeBox(1e-3, 10.0),
                                          makePolygon({{0, 0}, {1, 0}, {0, 1}}), makeCircle(1.0, {0.5, 0.0})};
    const std::vector<Transform> poses = {
        {}, {{0, 0}, Rotation::fromAngle(M_PI / 4)}, {{1, 1}, {}}, {{2, 0}, {}}, {{1, 0}, Rotation::fromAngle(M_PI)},
        {{0.5, 0.5}, {}}, {{1e-300, 0}, {}}, {{0, 2}, Rotation::fromAngle(M_PI / 2)}};
    for (const Geometry& a : shapes)
        for (const Geometry& b : shapes)
            for (const Transform& xa : poses)
                for (const Transform& xb : poses) check(a, xa, b, xb);
}

}  // namespace
}  // namespace physim
