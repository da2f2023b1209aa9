// Randomised narrow-phase checks for every pair of the kinds circle, polygon, rounded polygon, segment and capsule
// against brute-force references that share no code with the narrow phase. Every kind is a core (1 point, 2 points or
// a convex polygon) grown by a radius (0 for polygons and segments), so:
// - touching or not: the distance between the cores (0 when edges cross or a point lies inside a polygon core;
//   otherwise the least point-to-edge distance) against the sum of the radii;
// - penetration: the minimum over directions d of h(d) = support_A(d) + support_B(-d), the support of a rounded
//   shape being its core's support plus its radius; sampled at 720 directions and refined by golden-section search;
// - contact points: each lies within penetration / 2 of both shapes (plus half the 5e-4 m speculative margin for a
//   point just off the reference face).
// Tolerances as CollidePropertyTest.cpp: 1e-9 m for what the narrow phase computes directly, 1e-7 m against the
// sampled minimum, kReferenceFaceTolerance (1e-4 m) where two facing edges tie. Chain segments are one-sided and
// have tests of their own (ChainSegmentTest.cpp).

#include "Manifolds.hpp"  // collideGeometries with a margin (internal: src/core is on this program's include path)

#include "physim/core/Collide.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace physim {
namespace {

constexpr int kPairs = 12000;
constexpr double kExact = 1e-9;
constexpr double kSampled = 1e-7;
constexpr double kFacingTie = 1e-4;          // = kReferenceFaceTolerance
constexpr double kMargin = 2.5e-4 + kExact;  // half of kSpeculativeMargin

constexpr int kKinds = 5;  // circle, polygon, rounded polygon, segment, capsule
const char* const kKindNames[kKinds] = {"circle", "polygon", "rounded polygon", "segment", "capsule"};

// World-space core and radius of a placed shape.
struct Rounded {
    std::vector<Vec2> core;  // 1 point, 2 points, or a counter-clockwise convex polygon
    double radius = 0.0;
};

Rounded place(const Geometry& g, const Transform& xf) {
    Rounded s;
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

double support(const Rounded& s, const Vec2& d) {
    double best = -std::numeric_limits<double>::infinity();
    for (const Vec2& v : s.core) best = std::max(best, v.dot(d));
    return best + s.radius;
}

double push(const Rounded& a, const Rounded& b, const Vec2& d) { return support(a, d) + support(b, -d); }

double pointToSegment(const Vec2& p, const Vec2& s0, const Vec2& s1) {
    const Vec2 e = s1 - s0;
    const double u = std::clamp((p - s0).dot(e) / e.squaredNorm(), 0.0, 1.0);
    return (p - (s0 + u * e)).norm();
}

bool insidePolygon(const std::vector<Vec2>& poly, const Vec2& p) {
    if (poly.size() < 3) return false;
    for (std::size_t i = 0; i < poly.size(); ++i)
        if (cross(poly[(i + 1) % poly.size()] - poly[i], p - poly[i]) < 0.0) return false;
    return true;
}

// The core's edges as point pairs: none for a point, one for two points, the boundary of a polygon.
std::vector<std::array<Vec2, 2>> edges(const std::vector<Vec2>& core) {
    std::vector<std::array<Vec2, 2>> out;
    if (core.size() == 2) out.push_back({core[0], core[1]});
    if (core.size() >= 3)
        for (std::size_t i = 0; i < core.size(); ++i) out.push_back({core[i], core[(i + 1) % core.size()]});
    return out;
}

double coreDistance(const std::vector<Vec2>& core, const Vec2& p) {
    if (insidePolygon(core, p)) return 0.0;
    if (core.size() == 1) return (p - core[0]).norm();
    double best = std::numeric_limits<double>::infinity();
    for (const auto& e : edges(core)) best = std::min(best, pointToSegment(p, e[0], e[1]));
    return best;
}

double distanceTo(const Rounded& s, const Vec2& p) { return std::max(coreDistance(s.core, p) - s.radius, 0.0); }

bool segmentsCross(const Vec2& p0, const Vec2& p1, const Vec2& q0, const Vec2& q1) {
    const double d1 = cross(p1 - p0, q0 - p0), d2 = cross(p1 - p0, q1 - p0);
    const double d3 = cross(q1 - q0, p0 - q0), d4 = cross(q1 - q0, p1 - q0);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

double gap(const Rounded& a, const Rounded& b) {
    double cores = std::numeric_limits<double>::infinity();
    for (const auto& ea : edges(a.core))
        for (const auto& eb : edges(b.core))
            if (segmentsCross(ea[0], ea[1], eb[0], eb[1])) cores = 0.0;
    for (const Vec2& v : a.core) cores = std::min(cores, coreDistance(b.core, v));
    for (const Vec2& v : b.core) cores = std::min(cores, coreDistance(a.core, v));
    return std::max(cores - a.radius - b.radius, 0.0);
}

Vec2 direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

double bruteForceDepth(const Rounded& a, const Rounded& b) {
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
    int kind() { return std::uniform_int_distribution<int>(0, kKinds - 1)(rng_); }

    Geometry shape(int kind) {
        const Vec2 offset(uniform(-0.3, 0.3), uniform(-0.3, 0.3));
        switch (kind) {
            case 0: return makeCircle(uniform(0.1, 1.5), offset);
            case 1: return polygon(0.0);
            case 2: return polygon(uniform(0.02, 0.6));
            case 3: return makeSegment(offset + Vec2(uniform(-1.5, 1.5), uniform(-1.5, 1.5)),
                                       offset + Vec2(uniform(-1.5, 1.5), uniform(-1.5, 1.5)));
            default: return makeCapsule(offset + Vec2(uniform(-1.2, 1.2), uniform(-1.2, 1.2)),
                                        offset + Vec2(uniform(-1.2, 1.2), uniform(-1.2, 1.2)), uniform(0.05, 0.8));
        }
    }

    Transform transform(double spread) {
        return {{uniform(-spread, spread), uniform(-spread, spread)}, Rotation::fromAngle(uniform(-M_PI, M_PI))};
    }

private:
    // A box (a third of the draws) or points on an ellipse at sorted random angles; grown by radius when > 0.
    Polygon polygon(double radius) {
        for (;;) {
            std::vector<Vec2> pts;
            const double rx = uniform(0.05, 1.3), ry = uniform(0.05, 1.3);
            if (uniform(0.0, 1.0) < 1.0 / 3.0) {
                pts = {{-rx, -ry}, {rx, -ry}, {rx, ry}, {-rx, ry}};
            } else {
                const int count = std::uniform_int_distribution<int>(3, Polygon::maxVertices)(rng_);
                std::vector<double> angles(count);
                for (double& t : angles) t = uniform(0.0, 2.0 * M_PI);
                std::sort(angles.begin(), angles.end());
                const Vec2 offset(uniform(-0.3, 0.3), uniform(-0.3, 0.3));
                for (double t : angles) pts.push_back(offset + Vec2(rx * std::cos(t), ry * std::sin(t)));
            }
            try {
                return radius > 0.0 ? makeRoundedPolygon(pts, radius) : makePolygon(pts);
            } catch (const std::invalid_argument&) {
                // near-coincident or collinear draw: draw again
            }
        }
    }

    std::mt19937_64 rng_;
};

bool finite(const Vec2& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

TEST(CollidePropertyRoundedSegmentCapsule, EveryPairOfKindsMatchesBruteForceReference) {
    RandomShapes random(52);
    int colliding[kKinds][kKinds] = {}, drawn[kKinds][kKinds] = {};
    int twoPoints = 0, facingTies = 0;
    for (int k = 0; k < 4 * kPairs; ++k) {
        const int ka = random.kind(), kb = random.kind();
        const Geometry ga = random.shape(ka), gb = random.shape(kb);
        const Transform xa = random.transform(1.0), xb = random.transform(1.0);
        const Rounded a = place(ga, xa), b = place(gb, xb);
        const Colliding c = computeColliding(ga, xa, gb, xb);
        const double apart = gap(a, b);
        SCOPED_TRACE("pair " + std::to_string(k) + ": " + kKindNames[ka] + " and " + kKindNames[kb]);
        ++drawn[ka][kb];

        if (apart > kExact) {
            EXPECT_FALSE(c.collision) << "gap " << apart;
            continue;
        }
        const double depth = bruteForceDepth(a, b);
        if (depth < kExact) continue;  // grazing: either answer is right
        ASSERT_TRUE(c.collision) << "depth " << depth;
        ++colliding[ka][kb];
        ASSERT_TRUE(finite(c.normal));
        EXPECT_NEAR(c.normal.norm(), 1.0, 1e-12);
        EXPECT_NEAR(push(a, b, c.normal), c.penetration, kExact);
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
    // Every ordered pair of kinds must be drawn and collide often enough to mean something.
    for (int i = 0; i < kKinds; ++i)
        for (int j = 0; j < kKinds; ++j)
            EXPECT_GT(colliding[i][j], drawn[i][j] / 10) << kKindNames[i] << " and " << kKindNames[j];
    EXPECT_GT(twoPoints, 500);
    EXPECT_LT(facingTies, 4 * kPairs / 1000) << "ties between facing edges should be rare in random draws";
}

// Apart but within the margin: a speculative manifold whose separation is the gap; beyond it nothing. (Two radius-0
// polygons keep their separating-axis routine, whose separation is a lower bound of the gap at a corner.)
TEST(CollidePropertyRoundedSegmentCapsule, SpeculativeSeparationIsTheGap) {
    RandomShapes random(5252);
    int speculative = 0;
    for (int k = 0; k < kPairs; ++k) {
        const int ka = random.kind(), kb = random.kind();
        const Geometry ga = random.shape(ka), gb = random.shape(kb);
        const Transform xa = random.transform(1.5), xb = random.transform(1.5);
        const double apart = gap(place(ga, xa), place(gb, xb));
        if (apart <= 1e-6) continue;
        constexpr double margin = 0.2;
        const NarrowResult r = collideGeometries(ga, xa, gb, xb, margin);
        SCOPED_TRACE("pair " + std::to_string(k) + ": " + kKindNames[ka] + " and " + kKindNames[kb]);
        const bool polygons = ka == 1 && kb == 1;
        if (apart > margin + kExact) {
            if (!polygons) {
                EXPECT_EQ(r.manifold.pointCount, 0);
            }
            continue;
        }
        if (apart < margin - kExact) {
            ASSERT_GT(r.manifold.pointCount, 0);
            ++speculative;
            double deepest = r.manifold.points[0].separation;
            for (int i = 1; i < r.manifold.pointCount; ++i)
                deepest = std::min(deepest, r.manifold.points[i].separation);
            if (polygons) {
                EXPECT_LE(r.separation, apart + kExact);
            } else {
                EXPECT_NEAR(r.separation, apart, kExact);
                EXPECT_NEAR(deepest, apart, kExact);
            }
        }
    }
    EXPECT_GT(speculative, 500);
}

TEST(CollidePropertyRoundedSegmentCapsule, SwappingTheShapesReversesTheNormal) {
    RandomShapes random(77);
    int exactFlips = 0, colliding = 0;
    for (int k = 0; k < kPairs; ++k) {
        const int ka = random.kind(), kb = random.kind();
        const Geometry ga = random.shape(ka), gb = random.shape(kb);
        const Transform xa = random.transform(1.0), xb = random.transform(1.0);
        const Colliding ab = computeColliding(ga, xa, gb, xb);
        const Colliding ba = computeColliding(gb, xb, ga, xa);
        SCOPED_TRACE("pair " + std::to_string(k) + ": " + kKindNames[ka] + " and " + kKindNames[kb]);
        ASSERT_EQ(ab.collision, ba.collision);
        if (!ab.collision) continue;
        ++colliding;
        EXPECT_NEAR(ab.penetration, ba.penetration, kFacingTie);
        if ((ab.normal + ba.normal).norm() < kExact) {
            ++exactFlips;
            EXPECT_NEAR(ab.penetration, ba.penetration, kExact);
        } else {
            EXPECT_NEAR(push(place(ga, xa), place(gb, xb), -ba.normal), ab.penetration, kFacingTie + kExact);
        }
    }
    EXPECT_GT(exactFlips, colliding - colliding / 100);
}

// A segment, capsule or rounded polygon scaled from micrometres to kilometres and placed far from the origin, and
// every kind (chain pieces too) in coincident placements that tie every choice: never NaN, at most two points.
TEST(CollidePropertyRoundedSegmentCapsule, NeverNaNForFiniteAndDegenerateInputs) {
    RandomShapes random(999);
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
    for (int k = 0; k < kPairs; ++k) {
        const double scale = std::pow(10.0, random.uniform(-6.0, 3.0));
        const Vec2 far =
            Vec2(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0)) * std::pow(10.0, random.uniform(0, 7));
        Geometry ga = random.shape(random.kind()), gb = random.shape(random.kind());
        for (Geometry* g : {&ga, &gb}) {
            if (auto* c = std::get_if<Circle>(g)) {
                c->radius *= scale;
                c->center *= scale;
            } else if (auto* p = std::get_if<Polygon>(g)) {
                for (int i = 0; i < p->count; ++i) p->vertices[i] *= scale;
                p->radius *= scale;
            } else if (auto* s = std::get_if<Segment>(g)) {
                s->point1 *= scale;
                s->point2 *= scale;
            } else {
                auto& c2 = std::get<Capsule>(*g);
                c2.center1 *= scale;
                c2.center2 *= scale;
                c2.radius *= scale;
            }
        }
        Transform xa = random.transform(scale), xb = random.transform(scale);
        xa.p += far;
        xb.p += far;
        check(ga, xa, gb, xb);
        check(gb, xb, ga, xa);
    }
    const std::vector<Geometry> shapes = {
        makeCircle(1.0), makeBox(1.0, 1.0), makeRoundedBox(1.0, 1.0, 0.5), makeRoundedBox(1e-3, 10.0, 1e-3),
        makeSegment({-1, 0}, {1, 0}), makeSegment({0, 0}, {0, 1}), makeCapsule({-1, 0}, {1, 0}, 0.5),
        makeCapsule({0, 0}, {0, 1e-3}, 1.0), makeRoundedPolygon({{0, 0}, {1, 0}, {0, 1}}, 0.1),
        ChainSegment{{-2, 0}, makeSegment({-1, 0}, {1, 0}), {2, 0}},
        ChainSegment{{-1, 0}, makeSegment({-1, 0}, {1, 0}), {2, 1}},
        ChainSegment{{-2, 1}, makeSegment({-1, 0}, {1, 0}), {1, 0}}};
    const std::vector<Transform> poses = {
        {}, {{0, 0}, Rotation::fromAngle(M_PI / 4)}, {{1, 1}, {}}, {{2, 0}, {}}, {{1, 0}, Rotation::fromAngle(M_PI)},
        {{0.5, 0.5}, {}}, {{1e-300, 0}, {}}, {{0, 2}, Rotation::fromAngle(M_PI / 2)}, {{0, 1.5}, {}}};
    for (const Geometry& a : shapes)
        for (const Geometry& b : shapes)
            for (const Transform& xa : poses)
                for (const Transform& xb : poses) check(a, xa, b, xb);
}

}  // namespace
}  // namespace physim
