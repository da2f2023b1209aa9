#pragma once
// Brute-force references for the narrow phase (computeColliding, collide), sharing no code with it, and the checks
// the property tests run against them (CollidePropertyTest.cpp, CollideRoundedPropertyTest.cpp). Every kind but
// the one-sided chain segment is a core (1 point, 2 points or a convex polygon) grown by a radius (0 for polygons
// and segments), so:
// - touching or not: the distance between the cores (0 when edges cross or a point lies inside a polygon core;
//   otherwise the least point-to-edge distance) against the sum of the radii;
// - penetration: the minimum over directions d of h(d) = support_A(d) + support_B(-d) (how far B must move along d
//   to clear A), a shape's support being its core's plus its radius; sampled at 720 directions and refined by
//   golden-section search around the four best local minima;
// - contact points: each lies within penetration / 2 of both shapes (plus half the 5e-4 m speculative margin for a
//   point just off the reference face).
// A radius-0 shape's numbers are those of the sharp-polygon reference these replaced: adding 0.0 to a support and
// subtracting it from a distance change nothing.

#include "physim/core/Collide.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace physim::testing::reference {

// Tolerances: 1e-9 m for identities the narrow phase computes directly (shapes are O(1) m, so that is a million
// times rounding); 1e-7 m against the sampled minimum (what golden-section search reaches); and
// kReferenceFaceTolerance (1e-4 m, src/core/Manifolds.hpp) where two facing edges tie.
constexpr double kExact = 1e-9;
constexpr double kSampled = 1e-7;
constexpr double kFacingTie = 1e-4;          // = kReferenceFaceTolerance
constexpr double kMargin = 2.5e-4 + kExact;  // half of kSpeculativeMargin: how far a kept point may lie outside

/// World-space core and radius of a placed shape.
struct Placed {
    std::vector<Vec2> core;  ///< 1 point, 2 points, or a counter-clockwise convex polygon
    double radius = 0.0;
};

inline Placed place(const Geometry& g, const Transform& xf) {
    Placed s;
    if (const auto* c = std::get_if<Circle>(&g)) {
        s.core = {xf.apply(c->center)};
        s.radius = c->radius;
    } else if (const auto* p = std::get_if<Polygon>(&g)) {
        for (int i = 0; i < p->count; ++i) s.core.push_back(xf.apply(p->vertices[i]));
        s.radius = p->radius;
    } else if (const auto* seg = std::get_if<Segment>(&g)) {
        s.core = {xf.apply(seg->point1), xf.apply(seg->point2)};
    } else {
        const auto& cap = std::get<Capsule>(g);
        s.core = {xf.apply(cap.center1), xf.apply(cap.center2)};
        s.radius = cap.radius;
    }
    return s;
}

inline double support(const Placed& s, const Vec2& d) {
    double best = -std::numeric_limits<double>::infinity();
    for (const Vec2& v : s.core) best = std::max(best, v.dot(d));
    return best + s.radius;
}

/// How far B must move along the unit direction d to clear A.
inline double push(const Placed& a, const Placed& b, const Vec2& d) { return support(a, d) + support(b, -d); }

inline double pointToSegment(const Vec2& p, const Vec2& s0, const Vec2& s1) {
    const Vec2 e = s1 - s0;
    const double u = std::clamp((p - s0).dot(e) / e.squaredNorm(), 0.0, 1.0);
    return (p - (s0 + u * e)).norm();
}

inline bool insidePolygon(const std::vector<Vec2>& poly, const Vec2& p) {
    if (poly.size() < 3) return false;
    for (std::size_t i = 0; i < poly.size(); ++i)
        if (cross(poly[(i + 1) % poly.size()] - poly[i], p - poly[i]) < 0.0) return false;
    return true;
}

/// The core's edges as point pairs: none for a point, one for two points, the boundary of a polygon.
inline std::vector<std::array<Vec2, 2>> edges(const std::vector<Vec2>& core) {
    std::vector<std::array<Vec2, 2>> out;
    if (core.size() == 2) out.push_back({core[0], core[1]});
    if (core.size() >= 3)
        for (std::size_t i = 0; i < core.size(); ++i) out.push_back({core[i], core[(i + 1) % core.size()]});
    return out;
}

/// Distance from a point to a core (0 inside a polygon core).
inline double coreDistance(const std::vector<Vec2>& core, const Vec2& p) {
    if (insidePolygon(core, p)) return 0.0;
    if (core.size() == 1) return (p - core[0]).norm();
    double best = std::numeric_limits<double>::infinity();
    for (const auto& e : edges(core)) best = std::min(best, pointToSegment(p, e[0], e[1]));
    return best;
}

/// Distance from a point to a placed shape (0 inside).
inline double distanceTo(const Placed& s, const Vec2& p) { return std::max(coreDistance(s.core, p) - s.radius, 0.0); }

inline bool segmentsCross(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
    const double d1 = cross(p1 - p0, q0 - p0), d2 = cross(p1 - p0, q1 - p0);
    const double d3 = cross(q1 - q0, p0 - q0), d4 = cross(q1 - q0, p1 - q0);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

/// Gap between two shapes: > 0 apart, 0 when they touch or overlap. Convex cores meet if two edges cross or one
/// holds a point of the other; otherwise the closest pair involves a vertex of one.
inline double gap(const Placed& a, const Placed& b) {
    double cores = std::numeric_limits<double>::infinity();
    for (const auto& ea : edges(a.core))
        for (const auto& eb : edges(b.core))
            if (segmentsCross(ea[0], ea[1], eb[0], eb[1])) cores = 0.0;
    for (const Vec2& v : a.core) cores = std::min(cores, coreDistance(b.core, v));
    for (const Vec2& v : b.core) cores = std::min(cores, coreDistance(a.core, v));
    return std::max(cores - a.radius - b.radius, 0.0);
}

inline Vec2 direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

/// Minimum translation distance by sampling directions, refining around the four best local minima.
inline double bruteForceDepth(const Placed& a, const Placed& b) {
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

inline bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

/// Uniform draws and random placements for the property tests' shape generators.
class RandomDraws {
public:
    explicit RandomDraws(unsigned seed) : rng_(seed) {}

    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }

    Transform transform(double spread) {
        return {{uniform(-spread, spread), uniform(-spread, spread)}, Rotation::fromAngle(uniform(-M_PI, M_PI))};
    }

protected:
    std::mt19937_64 rng_;
};

/// What one pair showed (counted by the tests: the draws must exercise the interesting cases, not just misses).
struct PairOutcome {
    bool colliding = false;  ///< the reference found them overlapping deeper than kExact
    bool twoPoints = false;
    bool facingTie = false;  ///< the penetration exceeded the sampled minimum by more than kSampled
};

/// computeColliding against the references: apart means no collision; overlapping means a collision whose normal
/// clears A by exactly the penetration, no shorter move exists (up to the facing-edge tie allowance), and each
/// contact point lies within penetration / 2 (plus kMargin) of both shapes. Grazing pairs (depth under kExact)
/// may go either way. Fatal failures end the pair: call through ASSERT_NO_FATAL_FAILURE.
inline void checkAgainstReference(const Geometry& ga, const Transform& xa, const Geometry& gb, const Transform& xb,
                                  PairOutcome& outcome) {
    const Placed a = place(ga, xa), b = place(gb, xb);
    const Colliding c = computeColliding(ga, xa, gb, xb);
    const double apart = gap(a, b);
    if (apart > kExact) {
        EXPECT_FALSE(c.collision) << "gap " << apart;
        return;
    }
    const double depth = bruteForceDepth(a, b);
    if (depth < kExact) return;  // grazing: either answer is right
    ASSERT_TRUE(c.collision) << "depth " << depth;
    outcome.colliding = true;
    ASSERT_TRUE(finite(c.normal));
    EXPECT_NEAR(c.normal.norm(), 1.0, 1e-12);
    // Moving B by penetration along the normal just clears A.
    EXPECT_NEAR(push(a, b, c.normal), c.penetration, kExact);
    // No shorter move exists (up to the facing-edge tie allowance).
    const double excess = c.penetration - depth;
    EXPECT_GT(excess, -kSampled) << "deeper than the sampled minimum?";
    if (excess > kSampled) {
        outcome.facingTie = true;
        EXPECT_LT(excess, kFacingTie + kSampled);
    }
    EXPECT_LE(c.overlap, c.penetration + kExact);
    const int n = c.collidingPoints.contactCount;
    ASSERT_TRUE(n == 1 || n == 2);
    outcome.twoPoints = n == 2;
    for (int i = 0; i < n; ++i) {
        const Vec2& p = i == 0 ? c.collidingPoints.pointA : c.collidingPoints.pointB;
        ASSERT_TRUE(finite(p));
        EXPECT_LE(distanceTo(a, p), 0.5 * c.penetration + kMargin);
        EXPECT_LE(distanceTo(b, p), 0.5 * c.penetration + kMargin);
    }
}

/// Swapping the shapes reverses the normal: the same answer either way, and either the exact reverse (counted in
/// exactFlips) or, a facing-edge tie resolved towards the first shape, another axis whose push is the same depth
/// to within the tie allowance. Fatal failures end the pair: call through ASSERT_NO_FATAL_FAILURE.
inline void checkSwapReversesNormal(const Geometry& ga, const Transform& xa, const Geometry& gb,
                                    const Transform& xb, int& colliding, int& exactFlips) {
    const Colliding ab = computeColliding(ga, xa, gb, xb);
    const Colliding ba = computeColliding(gb, xb, ga, xa);
    ASSERT_EQ(ab.collision, ba.collision);
    if (!ab.collision) return;
    ++colliding;
    EXPECT_NEAR(ab.penetration, ba.penetration, kFacingTie);
    if ((ab.normal + ba.normal).norm() < kExact) {
        ++exactFlips;
        EXPECT_NEAR(ab.penetration, ba.penetration, kExact);
    } else {
        EXPECT_NEAR(push(place(ga, xa), place(gb, xb), -ba.normal), ab.penetration, kFacingTie + kExact);
    }
}

/// collide's manifold is sane: at most two points, a finite unit normal, finite points and separations no more
/// than the speculative margin.
inline void checkManifoldIsSane(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
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
}

/// The shape scaled about its body origin by `factor` (lengths and radii).
inline void scale(Geometry& g, double factor) {
    if (auto* c = std::get_if<Circle>(&g)) {
        c->radius *= factor;
        c->center *= factor;
    } else if (auto* p = std::get_if<Polygon>(&g)) {
        for (int i = 0; i < p->count; ++i) p->vertices[i] *= factor;
        p->radius *= factor;
    } else if (auto* s = std::get_if<Segment>(&g)) {
        s->point1 *= factor;
        s->point2 *= factor;
    } else {
        auto& c2 = std::get<Capsule>(g);
        c2.center1 *= factor;
        c2.center2 *= factor;
        c2.radius *= factor;
    }
}

/// `count` pairs from drawShape(), scaled from micrometres to kilometres and placed near and very far from the
/// origin: checkManifoldIsSane both ways round.
template <class DrawShape>
void checkScaledPairsAreSane(RandomDraws& random, int count, DrawShape drawShape) {
    for (int k = 0; k < count; ++k) {
        const double factor = std::pow(10.0, random.uniform(-6.0, 3.0));
        const Vec2 far =
            Vec2(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0)) * std::pow(10.0, random.uniform(0, 7));
        Geometry ga = drawShape(), gb = drawShape();
        scale(ga, factor);
        scale(gb, factor);
        Transform xa = random.transform(factor), xb = random.transform(factor);
        xa.p += far;
        xb.p += far;
        checkManifoldIsSane(ga, xa, gb, xb);
        checkManifoldIsSane(gb, xb, ga, xa);
    }
}

/// Every shape against every shape in every pair of poses: coincident placements and shared features tie every
/// choice the narrow phase makes.
inline void checkEveryPlacementIsSane(const std::vector<Geometry>& shapes, const std::vector<Transform>& poses) {
    for (const Geometry& a : shapes)
        for (const Geometry& b : shapes)
            for (const Transform& xa : poses)
                for (const Transform& xb : poses) checkManifoldIsSane(a, xa, b, xb);
}

}  // namespace physim::testing::reference
