// The world's queries (World.hpp, "queries") against references that share no code with them: every shape is
// described here as the set of points within `radius` of a convex core (its vertices in the world), and a ray's entry,
// a point's containment, two shapes' overlap and a swept shape's first contact are found from that description by
// brute force over every shape, with distances written out below and searched by ternary search and bisection.

#include "physim/core/ContinuousBatch.hpp"
#include "physim/core/Query.hpp"
#include "physim/core/World.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace physim {
namespace {

// --- the reference ----------------------------------------------------------------------------------------------

// A shape as the points within radius of the convex hull of `core` (world m); chain pieces and segments have no area.
struct RefShape {
    std::vector<Vec2> core;  // 1 point, 2 (a segment) or a counter-clockwise polygon
    double radius = 0.0;
    bool area = true;        // false: segment or chain piece (a ray crosses it, a point is never inside)
    bool oneSided = false;   // chain piece: seen from the left of core[0] -> core[1] only
};

// The shape's bounding box from its own description (core points grown by the radius), for pruning the search.
struct Box {
    Vec2 lower, upper;
    bool meets(const Box& o) const {
        return lower.x() <= o.upper.x() && o.lower.x() <= upper.x() && lower.y() <= o.upper.y() &&
               o.lower.y() <= upper.y();
    }
};

double crossOf(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

Box boxOf(const std::vector<Vec2>& points, double grow) {
    Box b{points[0], points[0]};
    for (const Vec2& p : points) b.lower = b.lower.cwiseMin(p), b.upper = b.upper.cwiseMax(p);
    b.lower.array() -= grow;
    b.upper.array() += grow;
    return b;
}

double pointSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 e = b - a;
    double s = (p - a).dot(e) / e.dot(e);
    s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
    return (a + s * e - p).norm();
}

bool insidePolygon(const std::vector<Vec2>& poly, const Vec2& p) {
    for (std::size_t i = 0; i < poly.size(); ++i)
        if (crossOf(poly[(i + 1) % poly.size()] - poly[i], p - poly[i]) < 0.0) return false;
    return true;
}

// Signed distance from p to the core: negative inside a polygon core (minus the distance to its boundary), so a
// ray's distance along it is convex without flat stretches.
double coreDistance(const std::vector<Vec2>& core, const Vec2& p) {
    if (core.size() == 1) return (p - core[0]).norm();
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < core.size(); ++i) {
        if (core.size() == 2 && i == 1) break;
        best = std::min(best, pointSegment(p, core[i], core[(i + 1) % core.size()]));
    }
    return core.size() >= 3 && insidePolygon(core, p) ? -best : best;
}

bool segmentsCross(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
    const double d1 = crossOf(b - a, c - a), d2 = crossOf(b - a, d - a);
    const double d3 = crossOf(d - c, a - c), d4 = crossOf(d - c, b - c);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

// Distance between two cores (0 when they meet).
double coresDistance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
    auto edges = [](const std::vector<Vec2>& c) { return c.size() == 1 ? 0 : (c.size() == 2 ? 1 : c.size()); };
    for (std::size_t i = 0; i < edges(a); ++i)
        for (std::size_t j = 0; j < edges(b); ++j)
            if (segmentsCross(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()])) return 0.0;
    double best = std::numeric_limits<double>::infinity();
    for (const Vec2& p : a) best = std::min(best, coreDistance(b, p));
    for (const Vec2& p : b) best = std::min(best, coreDistance(a, p));
    return best;
}

// Where t -> f(t) (convex on [0, hi]) first reaches <= 0, or nullopt when its minimum stays above `grace`; sets
// `ambiguous` when the minimum lies within `grace` of 0 (a grazing case neither answer is wrong for).
template <class F>
std::optional<double> firstRoot(F f, double hi, double grace, bool& ambiguous) {
    double lo = 0.0, top = hi;
    for (int i = 0; i < 200; ++i) {  // ternary search for the minimum
        const double m1 = lo + (top - lo) / 3.0, m2 = top - (top - lo) / 3.0;
        if (f(m1) <= f(m2)) top = m2;
        else lo = m1;
    }
    double tMin = 0.5 * (lo + top);
    double fMin = f(tMin);
    // Two overlapping radius-0 cores are at distance 0 all along a stretch, where the search may end at its edge:
    // samples across the range find its inside.
    for (int i = 0; i <= 64; ++i) {
        const double t = hi * i / 64.0, v = f(t);
        if (v < fMin) tMin = t, fMin = v;
    }
    // Exactly 0 is inside such a stretch: a clear contact.
    if (std::abs(fMin) <= grace && fMin != 0.0) ambiguous = true;
    if (fMin > 0.0) return std::nullopt;
    double a = 0.0, b = tMin;  // f(a) > 0 >= f(b)
    for (int i = 0; i < 200; ++i) {
        const double m = 0.5 * (a + b);
        if (f(m) > 0.0) a = m;
        else b = m;
    }
    return b;
}

// The fraction where the ray o + t d (t in [0, 1]) enters the shape; nullopt when it misses or starts inside.
std::optional<double> refRay(const RefShape& s, const Vec2& o, const Vec2& d, bool& ambiguous) {
    if (!s.area) {  // Cramer's rule on o + t d = a + u (b - a)
        const Vec2 a = s.core[0], e = s.core[1] - s.core[0];
        const double det = crossOf(e, d);
        if (std::abs(det) < 1e-12) return std::nullopt;
        const double t = crossOf(e, a - o) / det;
        const double u = crossOf(d, a - o) / det;
        if (std::abs(u) < 1e-9 || std::abs(u - 1.0) < 1e-9 || std::abs(t - 1.0) < 1e-9) ambiguous = true;
        if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0) return std::nullopt;
        if (s.oneSided && crossOf(e, d) >= 0.0) return std::nullopt;  // moving out of the front: from behind
        return t;
    }
    const double start = coreDistance(s.core, o) - s.radius;
    if (std::abs(start) < 1e-9) ambiguous = true;
    if (start <= 0.0) return std::nullopt;
    return firstRoot([&](double t) { return coreDistance(s.core, o + t * d) - s.radius; }, 1.0, 1e-9, ambiguous);
}

// The world's shapes, described from what World reports of them (geometry and body pose), not from its internals.
RefShape describe(const World& world, ShapeId id) {
    const Transform xf = world.transform(world.body(id));
    RefShape r;
    std::visit(
        [&](const auto& g) {
            using G = std::decay_t<decltype(g)>;
            if constexpr (std::is_same_v<G, Circle>) {
                r.core = {xf.apply(g.center)};
                r.radius = g.radius;
            } else if constexpr (std::is_same_v<G, Polygon>) {
                for (int i = 0; i < g.count; ++i) r.core.push_back(xf.apply(g.vertices[i]));
                r.radius = g.radius;
            } else if constexpr (std::is_same_v<G, Segment>) {
                r.core = {xf.apply(g.point1), xf.apply(g.point2)};
                r.area = false;
            } else if constexpr (std::is_same_v<G, Capsule>) {
                r.core = {xf.apply(g.center1), xf.apply(g.center2)};
                r.radius = g.radius;
            } else {
                r.core = {xf.apply(g.segment.point1), xf.apply(g.segment.point2)};
                r.area = false;
                r.oneSided = true;
            }
        },
        world.geometry(id));
    return r;
}

RefShape describe(const Geometry& g, const Transform& xf) {
    World scratch;
    BodyDef def;
    def.type = BodyType::Static;
    def.position = xf.p;
    def.angle = xf.q.angle();
    def.shape = g;
    const BodyId b = scratch.createBody(def);
    return describe(scratch, scratch.shapes(b)[0]);
}

// --- scenes -----------------------------------------------------------------------------------------------------

struct Scene {
    World world;
    std::vector<ShapeId> shapes;  // every shape, sensors and hidden ones included
    std::vector<ShapeId> sensors;
    std::vector<ShapeId> hidden;  // category 2: the test filter's mask leaves them out
};

constexpr std::uint64_t kHiddenCategory = 2;
const QueryFilter kTestFilter{1, ~kHiddenCategory};

Geometry randomGeometry(std::mt19937& rng, int kind) {
    std::uniform_real_distribution<double> size(0.2, 1.2), unit(-1.0, 1.0);
    switch (kind) {
        case 0: return makeCircle(size(rng));
        case 1: return makeBox(size(rng), size(rng));
        case 2: {
            std::vector<Vec2> points;
            for (int i = 0; i < 7; ++i) points.emplace_back(unit(rng), unit(rng));
            return computeHull(points);
        }
        case 3: return makeRoundedBox(size(rng), 0.5 * size(rng), 0.3 * size(rng));
        case 4: return makeSegment(Vec2(-size(rng), unit(rng)), Vec2(size(rng), unit(rng)));
        default: return makeCapsule(Vec2(-size(rng), 0.0), Vec2(size(rng), 0.2 * unit(rng)), 0.5 * size(rng));
    }
}

// Static and dynamic bodies of every kind at random poses in a 30 m square, a chain, some sensors and hidden shapes.
std::unique_ptr<Scene> randomScene(unsigned seed) {
    auto scene = std::make_unique<Scene>();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(-15.0, 15.0), angle(-M_PI, M_PI);
    for (int i = 0; i < 90; ++i) {
        const int kind = i % 6;
        BodyDef def;
        const bool noArea = kind == 4;
        def.type = noArea || i % 3 == 0 ? BodyType::Static : BodyType::Dynamic;
        def.position = Vec2(pos(rng), pos(rng));
        def.angle = angle(rng);
        def.shape = randomGeometry(rng, kind);
        if (i % 11 == 5) def.filter.categoryBits = kHiddenCategory;
        const BodyId b = scene->world.createBody(def);
        const ShapeId first = scene->world.shapes(b)[0];
        scene->shapes.push_back(first);
        if (i % 11 == 5) scene->hidden.push_back(first);
        if (i % 13 == 7 && !noArea) {  // a second shape, a sensor, on some bodies
            ShapeDef sensor;
            sensor.geometry = transformed(makeCircle(0.6), Transform{Vec2(1.0, 0.5), Rotation{}});
            sensor.isSensor = true;
            sensor.density = 0.0;
            const ShapeId s = scene->world.createShape(b, sensor);
            scene->shapes.push_back(s);
            scene->sensors.push_back(s);
        }
    }
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.shape = makeSegment(Vec2(-1, 0), Vec2(1, 0));
    const BodyId g = scene->world.createBody(ground);
    scene->shapes.push_back(scene->world.shapes(g)[0]);
    ChainDef chain;
    chain.points = {Vec2(-16, -16), Vec2(-4, -17), Vec2(5, -16.5), Vec2(16, -15), Vec2(16, 16), Vec2(-16, 16)};
    chain.loop = true;  // counter-clockwise: solid outside, bodies held inside
    for (const ShapeId s : scene->world.createChain(g, chain)) scene->shapes.push_back(s);
    return scene;
}

bool isIn(const std::vector<ShapeId>& list, ShapeId id) {
    return std::find(list.begin(), list.end(), id) != list.end();
}

bool visible(const Scene& s, ShapeId id) { return !isIn(s.sensors, id) && !isIn(s.hidden, id); }

// --- ray casts --------------------------------------------------------------------------------------------------

TEST(RayCast, CircleExactFraction) {
    World world;
    BodyDef def;
    def.type = BodyType::Static;
    def.position = Vec2(2.0, 1.0);
    def.shape = makeCircle(1.0);
    const BodyId b = world.createBody(def);
    // From (-3, 1) along +x by 10 m: the circle's left point (1, 1) is 4 m on, fraction 0.4 (exact in doubles).
    const std::optional<RayHit> hit = world.castRayClosest(Vec2(-3.0, 1.0), Vec2(10.0, 0.0));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->fraction, 0.4);
    EXPECT_EQ(hit->body, b);
    EXPECT_EQ(hit->shape, world.shapes(b)[0]);
    EXPECT_NEAR(hit->point.x(), 1.0, 1e-15);
    EXPECT_NEAR(hit->point.y(), 1.0, 1e-15);
    EXPECT_NEAR(hit->normal.x(), -1.0, 1e-15);
    EXPECT_NEAR(hit->normal.y(), 0.0, 1e-15);
    // Off-axis: the ray y = 1.6 meets the circle at x = 2 - sqrt(1 - 0.36) = 1.2, fraction 4.2 / 10.
    const std::optional<RayHit> off = world.castRayClosest(Vec2(-3.0, 1.6), Vec2(10.0, 0.0));
    ASSERT_TRUE(off);
    EXPECT_NEAR(off->fraction, 0.42, 1e-15);  // a few ulps of the quadratic's rounding
    EXPECT_NEAR(off->normal.x(), -0.8, 1e-14);
    EXPECT_NEAR(off->normal.y(), 0.6, 1e-14);
    // Too short, and passing above: no hit.
    EXPECT_FALSE(world.castRayClosest(Vec2(-3.0, 1.0), Vec2(3.9, 0.0)));
    EXPECT_FALSE(world.castRayClosest(Vec2(-3.0, 2.01), Vec2(10.0, 0.0)));
}

TEST(RayCast, FromInsideDoesNotHitThatShape) {
    World world;
    BodyDef def;
    def.type = BodyType::Static;
    def.shape = makeBox(1.0, 1.0);
    world.createBody(def);
    def.position = Vec2(5.0, 0.0);
    def.shape = makeCircle(1.0);
    const BodyId far = world.createBody(def);
    // From the box's centre: the box is not hit, the circle beyond it is (its left point at x = 4).
    const std::optional<RayHit> hit = world.castRayClosest(Vec2::Zero(), Vec2(10.0, 0.0));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, far);
    EXPECT_DOUBLE_EQ(hit->fraction, 0.4);
    // overlapPoint says what the ray starts in.
    EXPECT_EQ(world.overlapPoint(Vec2::Zero()).size(), 1u);
}

TEST(RayCast, ChainIsOneSided) {
    World world;
    BodyDef def;
    def.type = BodyType::Static;
    def.withShape = false;
    const BodyId ground = world.createBody(def);
    ChainDef chain;
    chain.points = {Vec2(-5, 0), Vec2(5, 0)};  // left to right: its front (normal) is up
    world.createChain(ground, chain);
    const std::optional<RayHit> down = world.castRayClosest(Vec2(0, 2), Vec2(0, -4));
    ASSERT_TRUE(down);
    EXPECT_DOUBLE_EQ(down->fraction, 0.5);
    EXPECT_NEAR(down->normal.y(), 1.0, 1e-15);
    EXPECT_FALSE(world.castRayClosest(Vec2(0, -2), Vec2(0, 4)));  // from behind: passes
}

TEST(RayCast, CallbackIgnoresClipsAndStops) {
    World world;
    BodyDef def;
    def.type = BodyType::Static;
    for (int i = 1; i <= 5; ++i) {  // circles of radius 0.25 centred at x = 2, 4, ..., 10: entries at 1.75, 3.75, ...
        def.position = Vec2(2.0 * i, 0.0);
        def.shape = makeCircle(0.25);
        world.createBody(def);
    }
    const Vec2 origin = Vec2::Zero(), translation(20.0, 0.0);
    const std::vector<RayHit> all = world.castRayAll(origin, translation);
    ASSERT_EQ(all.size(), 5u);
    for (std::size_t i = 0; i < all.size(); ++i) EXPECT_NEAR(all[i].fraction, (2.0 * (i + 1) - 0.25) / 20.0, 1e-15);
    // Ignoring everything: every hit is reported once and nothing is clipped.
    int count = 0;
    world.castRay(origin, translation, {}, [&](const RayHit&) { ++count; return -1.0; });
    EXPECT_EQ(count, 5);
    // Clipping at each hit: the last hit reported is the closest one; nothing past a clip is reported.
    double clip = 1.0;
    world.castRay(origin, translation, {}, [&](const RayHit& h) {
        EXPECT_LE(h.fraction, clip);
        clip = h.fraction;
        return h.fraction;
    });
    EXPECT_NEAR(clip, 1.75 / 20.0, 1e-15);
    // Stopping at the first one reported.
    count = 0;
    world.castRay(origin, translation, {}, [&](const RayHit&) { ++count; return 0.0; });
    EXPECT_EQ(count, 1);
    // Clipping to 0.3 (6 m): only the entries at 1.75 and 3.75 m may come after that.
    world.castRay(origin, translation, {}, [&](const RayHit& h) {
        if (h.fraction > 0.3) ADD_FAILURE() << "hit past the clip at " << h.fraction;
        return 0.3;
    });
}

TEST(RayCast, FilterAndSensorsHide) {
    World world;
    BodyDef def;
    def.type = BodyType::Static;
    def.position = Vec2(2.0, 0.0);
    def.shape = makeCircle(0.5);
    def.isSensor = true;
    world.createBody(def);  // a sensor: never hit
    def.isSensor = false;
    def.position = Vec2(4.0, 0.0);
    def.filter.categoryBits = 4;
    const BodyId four = world.createBody(def);
    def.position = Vec2(6.0, 0.0);
    def.filter.categoryBits = 1;
    const BodyId one = world.createBody(def);
    EXPECT_EQ(world.castRayClosest(Vec2::Zero(), Vec2(10.0, 0.0))->body, four);
    EXPECT_EQ(world.castRayClosest(Vec2::Zero(), Vec2(10.0, 0.0), QueryFilter{1, ~std::uint64_t{4}})->body, one);
    // The query's category must be in the shape's mask too.
    EXPECT_FALSE(world.castRayClosest(Vec2::Zero(), Vec2(10.0, 0.0), QueryFilter{0, ~std::uint64_t{0}}));
    EXPECT_EQ(world.castRayAll(Vec2::Zero(), Vec2(10.0, 0.0)).size(), 2u);
}

// Every kind, 3000 random rays per scene against the brute-force reference. Tolerance 1e-9 of a fraction (1e-8 m
// on a 10 m ray): the reference's bisection ends far below it; the engine's closed forms are a few ulps of the 30 m
// scene off. Cases the reference finds within 1e-9 m of grazing are skipped (either answer is right).
TEST(RayCast, RandomScenesMatchBruteForce) {
    int checked = 0, hits = 0;
    for (unsigned seed = 1; seed <= 3; ++seed) {
        const std::unique_ptr<Scene> scene = randomScene(seed);
        const World& world = scene->world;
        std::vector<RefShape> refs;
        for (const ShapeId id : scene->shapes) refs.push_back(describe(world, id));
        std::mt19937 rng(seed * 7919);
        std::uniform_real_distribution<double> pos(-18.0, 18.0), angle(-M_PI, M_PI), length(0.5, 25.0);
        for (int r = 0; r < 3000; ++r) {
            const Vec2 origin(pos(rng), pos(rng));
            const double a = angle(rng), l = length(rng);
            const Vec2 translation(l * std::cos(a), l * std::sin(a));
            bool ambiguous = false;
            std::vector<std::pair<double, std::size_t>> expected;
            const Box rayBox = boxOf({origin, origin + translation}, 1e-6);
            for (std::size_t i = 0; i < refs.size(); ++i) {
                if (!visible(*scene, scene->shapes[i])) continue;
                if (!rayBox.meets(boxOf(refs[i].core, refs[i].radius + 1e-6))) continue;  // cannot meet the ray
                const std::optional<double> t = refRay(refs[i], origin, translation, ambiguous);
                if (t) expected.emplace_back(*t, i);
            }
            if (ambiguous) continue;
            std::sort(expected.begin(), expected.end());
            const std::vector<RayHit> all = world.castRayAll(origin, translation, kTestFilter);
            ASSERT_EQ(all.size(), expected.size()) << "seed " << seed << " ray " << r;
            for (std::size_t k = 0; k < all.size(); ++k) {
                EXPECT_NEAR(all[k].fraction, expected[k].first, 1e-9);
                // The point is where the fraction says, on the surface; the normal is a unit vector against the ray.
                EXPECT_NEAR((all[k].point - (origin + all[k].fraction * translation)).norm(), 0.0, 1e-9);
                const RefShape& ref = refs[static_cast<std::size_t>(
                    std::find(scene->shapes.begin(), scene->shapes.end(), all[k].shape) - scene->shapes.begin())];
                if (ref.area) EXPECT_NEAR(coreDistance(ref.core, all[k].point), ref.radius, 1e-9);
                EXPECT_NEAR(all[k].normal.norm(), 1.0, 1e-12);
                EXPECT_LT(all[k].normal.dot(translation), 0.0);
                if (ref.area) {  // outward: a step along it leaves the shape, a step against it enters
                    EXPECT_GT(coreDistance(ref.core, all[k].point + 1e-6 * all[k].normal) - ref.radius, 0.0);
                }
            }
            const std::optional<RayHit> closest = world.castRayClosest(origin, translation, kTestFilter);
            ASSERT_EQ(closest.has_value(), !expected.empty());
            if (closest) {
                EXPECT_NEAR(closest->fraction, expected.front().first, 1e-9);
                ++hits;
            }
            ++checked;
        }
    }
    EXPECT_GT(checked, 8900) << hits;  // few rays graze (none of these 9000)
    EXPECT_GT(hits, 5000) << checked;
}

// --- overlaps ---------------------------------------------------------------------------------------------------

std::vector<std::uint32_t> sorted(std::vector<ShapeId> ids) {
    std::vector<std::uint32_t> out;
    for (const ShapeId id : ids) out.push_back(id.index);
    std::sort(out.begin(), out.end());
    return out;
}

// Boxes, points and shapes against brute force over every shape. Boxes: exact (the tight boxes, compared as
// numbers); points and shapes: within 1e-9 m of a boundary a case is skipped (the reference's own rounding).
TEST(Overlap, RandomScenesMatchBruteForce) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
        const std::unique_ptr<Scene> scene = randomScene(seed);
        const World& world = scene->world;
        std::vector<RefShape> refs;
        for (const ShapeId id : scene->shapes) refs.push_back(describe(world, id));
        std::mt19937 rng(seed * 104729);
        std::uniform_real_distribution<double> pos(-18.0, 18.0), size(0.0, 4.0), angle(-M_PI, M_PI);
        for (int q = 0; q < 500; ++q) {
            // A box.
            const Vec2 c(pos(rng), pos(rng));
            const Aabb box{c - Vec2(size(rng), size(rng)), c + Vec2(size(rng), size(rng))};
            std::vector<std::uint32_t> expected;
            for (std::size_t i = 0; i < refs.size(); ++i) {
                const Aabb b = world.bounds(scene->shapes[i]);
                const bool overlaps = b.lower.x() <= box.upper.x() && box.lower.x() <= b.upper.x() &&
                                      b.lower.y() <= box.upper.y() && box.lower.y() <= b.upper.y();
                if (overlaps && visible(*scene, scene->shapes[i])) expected.push_back(scene->shapes[i].index);
            }
            std::sort(expected.begin(), expected.end());
            EXPECT_EQ(sorted(world.overlapAabb(box, kTestFilter)), expected);
            std::vector<ShapeId> viaCallback;
            world.overlapAabb(box, kTestFilter, [&](ShapeId id) { viaCallback.push_back(id); return true; });
            EXPECT_EQ(sorted(viaCallback), expected);

            // A point.
            bool ambiguous = false;
            expected.clear();
            for (std::size_t i = 0; i < refs.size(); ++i) {
                if (!refs[i].area || !visible(*scene, scene->shapes[i])) continue;
                const double g = coreDistance(refs[i].core, c) - refs[i].radius;
                if (std::abs(g) < 1e-9) ambiguous = true;
                if (g <= 0.0) expected.push_back(scene->shapes[i].index);
            }
            std::sort(expected.begin(), expected.end());
            if (!ambiguous) EXPECT_EQ(sorted(world.overlapPoint(c, kTestFilter)), expected);

            // A shape of a random kind at a random pose.
            const Geometry g = randomGeometry(rng, q % 6);
            const Transform xf{c, Rotation::fromAngle(angle(rng))};
            const RefShape probe = describe(g, xf);
            ambiguous = false;
            expected.clear();
            for (std::size_t i = 0; i < refs.size(); ++i) {
                if (!visible(*scene, scene->shapes[i])) continue;
                const double gap = coresDistance(probe.core, refs[i].core) - probe.radius - refs[i].radius;
                if (std::abs(gap) < 1e-9) ambiguous = true;
                if (gap <= 0.0) expected.push_back(scene->shapes[i].index);
            }
            std::sort(expected.begin(), expected.end());
            if (!ambiguous) EXPECT_EQ(sorted(world.overlapShape(g, xf, kTestFilter)), expected) << "query " << q;
        }
    }
}

TEST(Overlap, TightBoxesNotFatOnes) {
    World world;
    BodyDef def;
    def.shape = makeCircle(1.0);  // dynamic: its proxy box is fattened by the margin
    world.createBody(def);
    EXPECT_EQ(world.overlapAabb(Aabb{Vec2(1.0, -0.1), Vec2(2.0, 0.1)}).size(), 1u);  // touching counts
    EXPECT_TRUE(world.overlapAabb(Aabb{Vec2(1.05, -0.1), Vec2(2.0, 0.1)}).empty());  // inside the fat box only
}

// 40 unit boxes on a grid of 8 x 5, 2 m apart, from the origin; and a query box around the grid.
std::vector<BodyId> gridOfBoxes(World& world) {
    BodyDef def;
    def.shape = makeBox(0.5, 0.5);
    std::vector<BodyId> bodies;
    for (int i = 0; i < 40; ++i) {
        def.position = Vec2(2.0 * (i % 8), 2.0 * (i / 8));
        bodies.push_back(world.createBody(def));
    }
    return bodies;
}
const Aabb kAroundGrid{Vec2(-1.0, -1.0), Vec2(15.0, 9.0)};
constexpr int kManyQueries = 3000;  // more than any threshold for 40 bodies

// Many box queries on unchanged boxes go through a tree built for them (BroadPhase::queryOften): after thousands,
// moving, creating and destroying bodies must still show at once in every kind of overlap query.
TEST(Overlap, ManyQueriesFollowChangedBoxes) {
    World world;
    const std::vector<BodyId> bodies = gridOfBoxes(world);
    BodyDef def;
    def.shape = makeBox(0.5, 0.5);
    const Aabb far{Vec2(100.0, 100.0), Vec2(101.0, 101.0)};
    const auto hammer = [&](std::size_t inGrid) {
        std::size_t seen = 0;
        for (int q = 0; q < kManyQueries; ++q) seen += world.overlapAabb(kAroundGrid).size();
        EXPECT_EQ(seen, kManyQueries * inGrid);
    };
    hammer(40);
    EXPECT_TRUE(world.overlapAabb(far).empty());
    world.setTransform(bodies[3], Vec2(100.5, 100.5), 0.0);
    ASSERT_EQ(world.overlapAabb(far).size(), 1u);
    EXPECT_EQ(world.overlapPoint(Vec2(100.5, 100.5)).size(), 1u);
    EXPECT_EQ(world.overlapShape(makeCircle(0.2), Transform{Vec2(100.5, 100.5), Rotation{}}).size(), 1u);
    EXPECT_TRUE(world.overlapPoint(Vec2(6.0, 0.0)).empty());  // where it was

    hammer(39);
    world.destroyBody(bodies[3]);
    EXPECT_TRUE(world.overlapAabb(far).empty());
    hammer(39);
    def.position = Vec2(100.5, 100.2);
    world.createBody(def);
    EXPECT_EQ(world.overlapAabb(far).size(), 1u);
    hammer(39);
    world.setVelocity(bodies[0], Vec2(0.0, -40.0));  // falls 1 m in one step: its proxy moves
    world.step(1.0 / 40.0);
    EXPECT_EQ(world.overlapAabb(Aabb{Vec2(-0.4, -1.2), Vec2(0.4, -1.1)}).size(), 1u);  // below where it was
}

// The tree built for many queries belongs to the boxes it was built from: a restored world (its boxes' revision
// counter back where the snapshot was) that then changes differently, reaching the count the tree was built at,
// must not be answered from the tree of the future it left.
TEST(Overlap, ManyQueriesAfterARestoreFollowTheRestoredBoxes) {
    World world;
    const std::vector<BodyId> bodies = gridOfBoxes(world);
    const Aabb placeA{Vec2(100.0, 100.0), Vec2(101.0, 101.0)}, placeB{Vec2(200.0, 200.0), Vec2(201.0, 201.0)};
    const auto hammer = [&] {
        for (int q = 0; q < kManyQueries; ++q) world.overlapAabb(kAroundGrid);
    };
    const WorldSnapshot before = world.snapshot();
    world.setTransform(bodies[3], Vec2(100.5, 100.5), 0.0);
    hammer();
    ASSERT_EQ(world.overlapAabb(placeA).size(), 1u);
    world.restore(before);
    world.setTransform(bodies[5], Vec2(200.5, 200.5), 0.0);  // one box moved, as in the future left behind
    hammer();
    EXPECT_TRUE(world.overlapAabb(placeA).empty()) << "body 3 never went there in this run";
    EXPECT_EQ(world.overlapAabb(placeB).size(), 1u);
    EXPECT_EQ(world.overlapPoint(Vec2(200.5, 200.5)).size(), 1u);
}

// --- shape casts ------------------------------------------------------------------------------------------------

// A circle of radius 0.5 cast down onto a box whose top is at y = 0 from y = 3: contact after 2.5 m of 5, fraction
// 0.5; the cast stops within kToiTolerance (1e-4 m) before it, never past.
TEST(ShapeCast, CircleOntoBoxAnalytic) {
    World world;
    BodyDef def;
    def.type = BodyType::Static;
    def.position = Vec2(0.0, -1.0);
    def.shape = makeBox(4.0, 1.0);
    const BodyId ground = world.createBody(def);
    const std::optional<RayHit> hit =
        world.castShape(makeCircle(0.5), Transform{Vec2(0.3, 3.0), Rotation{}}, Vec2(0.0, -5.0));
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->body, ground);
    EXPECT_LE(hit->fraction, 0.5);
    EXPECT_GE(hit->fraction, 0.5 - 1e-4 / 5.0);
    EXPECT_NEAR(hit->normal.y(), 1.0, 1e-9);
    EXPECT_NEAR(hit->point.x(), 0.3, 1e-9);
    EXPECT_NEAR(hit->point.y(), 0.0, 1e-4);
    // Starting in contact: fraction 0, no normal.
    const std::optional<RayHit> touching =
        world.castShape(makeCircle(0.5), Transform{Vec2(0.0, 0.2), Rotation{}}, Vec2(1.0, 0.0));
    ASSERT_TRUE(touching);
    EXPECT_EQ(touching->fraction, 0.0);
    EXPECT_EQ(touching->normal, Vec2::Zero());
    // Missing it.
    EXPECT_FALSE(world.castShape(makeCircle(0.5), Transform{Vec2(0.0, 3.0), Rotation{}}, Vec2(0.0, 2.0)));
}

// Random shapes swept through the random scenes: the first contact against a reference (the gap between the swept
// shape and each other shape, convex along the sweep, searched by ternary search and bisection). The cast is
// conservative: its fraction never passes the true first contact (beyond 1e-9 of rounding) and leaves a gap below
// kToiTolerance = 1e-4 m to the shape it reports. A sweep whose least gap to some shape lies within 1.1e-4 m of 0
// is skipped: the cast may count such a graze as a contact (its tolerance), the reference does not.
TEST(ShapeCast, RandomScenesMatchBruteForce) {
    int hits = 0, checked = 0;
    for (unsigned seed = 1; seed <= 2; ++seed) {
        const std::unique_ptr<Scene> scene = randomScene(seed);
        const World& world = scene->world;
        std::vector<RefShape> refs;
        for (const ShapeId id : scene->shapes) refs.push_back(describe(world, id));
        std::mt19937 rng(seed * 31337);
        std::uniform_real_distribution<double> pos(-14.0, 14.0), angle(-M_PI, M_PI), length(0.5, 12.0);
        for (int q = 0; q < 600; ++q) {
            const Geometry g = randomGeometry(rng, q % 6);
            const Transform xf{Vec2(pos(rng), pos(rng)), Rotation::fromAngle(angle(rng))};
            const double a = angle(rng), l = length(rng);
            const Vec2 translation(l * std::cos(a), l * std::sin(a));
            const RefShape probe = describe(g, xf);
            auto gapAt = [&](const RefShape& target, double t) {
                std::vector<Vec2> moved = probe.core;
                for (Vec2& p : moved) p += t * translation;
                return coresDistance(moved, target.core) - probe.radius - target.radius;
            };
            bool ambiguous = false;
            double first = std::numeric_limits<double>::infinity();
            std::vector<Vec2> sweptPoints = probe.core;
            for (const Vec2& p : probe.core) sweptPoints.push_back(p + translation);
            const Box sweptBox = boxOf(sweptPoints, probe.radius + 1e-3);
            for (std::size_t i = 0; i < refs.size(); ++i) {
                if (!visible(*scene, scene->shapes[i])) continue;
                if (!sweptBox.meets(boxOf(refs[i].core, refs[i].radius))) continue;  // cannot meet the sweep
                if (refs[i].oneSided) {  // a chain piece is met from its front only: skip one the probe starts behind
                    Vec2 centre = Vec2::Zero();
                    for (const Vec2& p : probe.core) centre += p;
                    centre /= static_cast<double>(probe.core.size());
                    const double side = crossOf(refs[i].core[1] - refs[i].core[0], centre - refs[i].core[0]);
                    if (std::abs(side) < 1e-6) ambiguous = true;
                    if (side < 0.0) continue;
                }
                const std::optional<double> t =
                    firstRoot([&](double t) { return gapAt(refs[i], t); }, 1.0, 1.1e-4, ambiguous);
                if (t) first = std::min(first, *t);
            }
            if (ambiguous) continue;
            ++checked;
            const std::optional<RayHit> hit = world.castShape(g, xf, translation, kTestFilter);
            ASSERT_EQ(hit.has_value(), std::isfinite(first)) << "query " << q;
            if (!hit) continue;
            ++hits;
            EXPECT_LE(hit->fraction, first + 1e-9);
            const std::size_t k = static_cast<std::size_t>(
                std::find(scene->shapes.begin(), scene->shapes.end(), hit->shape) - scene->shapes.begin());
            EXPECT_LT(gapAt(refs[k], hit->fraction), 1e-4 + 1e-9);
            if (hit->fraction > 0.0) EXPECT_NEAR(hit->normal.norm(), 1.0, 1e-9);
        }
    }
    EXPECT_GT(checked, 1150) << hits;  // 1192 of these 1200: the rest graze within the cast's tolerance
    EXPECT_GT(hits, 900) << checked;
}

// --- bad input --------------------------------------------------------------------------------------------------

template <class F>
void expectRefusal(F f, const std::string& mentions) {
    try {
        f();
        ADD_FAILURE() << "no exception; expected one naming " << mentions;
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(mentions), std::string::npos) << e.what();
    }
}

TEST(RayCastBadInput, RefusedNamingTheValue) {
    World world;
    BodyDef def;
    def.shape = makeCircle(1.0);
    world.createBody(def);
    const double nan = std::nan(""), inf = INFINITY;
    expectRefusal([&] { world.castRayClosest(Vec2(nan, 0.0), Vec2(1.0, 0.0)); }, "origin");
    expectRefusal([&] { world.castRayAll(Vec2::Zero(), Vec2(inf, 0.0)); }, "translation");
    expectRefusal([&] { world.castRayClosest(Vec2::Zero(), Vec2::Zero()); }, "translation must not be zero");
    expectRefusal([&] { world.castRay(Vec2::Zero(), Vec2(1.0, 0.0), {}, RayCallback{}); }, "callback");
    expectRefusal([&] { world.overlapAabb(Aabb{Vec2(nan, 0.0), Vec2(1.0, 1.0)}); }, "box lower");
    expectRefusal([&] { world.overlapAabb(Aabb{Vec2(2.0, 0.0), Vec2(1.0, 1.0)}); }, "exceeds upper");
    expectRefusal([&] { world.overlapPoint(Vec2(0.0, nan)); }, "point");
    expectRefusal([&] { world.castShape(makeCircle(1.0), Transform{Vec2(nan, 0.0), Rotation{}}, Vec2(1, 0)); },
                  "pose position");
    expectRefusal([&] { world.castShape(makeCircle(1.0), Transform{Vec2::Zero(), Rotation{nan, 0.0}}, Vec2(1, 0)); },
                  "pose rotation");
    expectRefusal([&] { world.castShape(Circle{Vec2::Zero(), -1.0}, Transform{}, Vec2(1, 0)); }, "circle radius");
    expectRefusal([&] { world.overlapShape(Circle{Vec2::Zero(), nan}, Transform{}); }, "circle radius");
    expectRefusal([&] { world.castShape(makeCircle(1.0), Transform{}, Vec2(0, 0)); }, "translation");
    EXPECT_EQ(world.bodyCount(), 1u);
    EXPECT_EQ(world.stepCount(), 0u);
}

// A continuous solver that asks the world a question from inside the step: refused with std::logic_error.
class QueryingSolver final : public ContinuousSolver {
public:
    explicit QueryingSolver(const World& world) : world_(world) {}
    void solve(const ContinuousBatch& batch, ContinuousBatchResult& result) override {
        ++calls;
        try {
            world_.castRayClosest(Vec2::Zero(), Vec2(1.0, 0.0));
        } catch (const std::logic_error& e) {
            if (std::string(e.what()).find("castRayClosest") != std::string::npos) ++refused;
        }
        CpuContinuousSolver().solve(batch, result);
    }
    std::string name() const override { return "querying"; }
    int calls = 0, refused = 0;

private:
    const World& world_;
};

TEST(RayCastBadInput, RefusedDuringTheStep) {
    World world;
    BodyDef ground;
    ground.type = BodyType::Static;
    ground.shape = makeBox(10.0, 0.5);
    world.createBody(ground);
    BodyDef ball;
    ball.position = Vec2(0.0, 3.0);
    ball.velocity = Vec2(0.0, -300.0);  // crosses the ground within a step: the continuous stage's
    ball.shape = makeCircle(0.1);
    const BodyId b = world.createBody(ball);
    world.setCollisionDetection(b, CollisionDetection::ContinuousExact);
    auto solver = std::make_shared<QueryingSolver>(world);
    world.setContinuousSolver(solver);
    world.step(1.0 / 60.0);
    ASSERT_GT(solver->calls, 0);
    EXPECT_EQ(solver->refused, solver->calls);
    EXPECT_TRUE(world.castRayClosest(Vec2(0.0, 5.0), Vec2(0.0, -10.0)));  // after the step: answered
}

}  // namespace
}  // namespace physim
