#pragma once
// Test inputs for continuous batches, shared by the core's and the CUDA layer's tests:
//   randomPairs / randomBatch: fast small shapes fired across obstacles (ccd_bench uses them too).
//   spinningPairs: fast-spinning pairs placed to graze (or just touch) at a chosen moment.
//   fillBulletBox: a closed box of thin walls with exact-continuous bullets (small circles and thin spinning boxes)
//     fired across it at 150 to 600 m/s, so every step has impacts and, without continuous detection, the bullets
//     would leave the box.

#include "physim/core/Collide.hpp"
#include "physim/core/ContinuousBatch.hpp"
#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

namespace physim::testing {

/// One moving pair: shape a sweeps across shape b (Geometry here; kernel shapes in KernelShapes.hpp).
template <class Shape>
struct MovingPair {
    Shape a, b;
    Sweep sa, sb;
};
using FastPair = MovingPair<Geometry>;

/// The random draws of the pair generators, all from one mt19937 stream of uniform [0, 1) draws.
class PairDraws {
public:
    explicit PairDraws(unsigned seed) : rng_(seed) {}

    double unit() { return u_(rng_); }
    double in(double lo, double hi) { return lo + (hi - lo) * unit(); }
    Vec2 direction() {
        const double a = in(0.0, 2.0 * M_PI);
        return Vec2(std::cos(a), std::sin(a));
    }
    // Log-uniform rates, so that slow and fast are both common: turns of 0.1 to 17 rad, either way; moves of 0.05
    // to 8 m. A share `still` of the draws is 0: some bodies neither turn nor move.
    double logUniform(double lo, double hi) { return lo * std::pow(hi / lo, unit()); }
    double turn(double still) {
        if (unit() < still) return 0.0;
        const double sign = unit() < 0.5 ? -1.0 : 1.0;
        return sign * logUniform(0.1, 17.0);
    }
    double move(double still) { return unit() < still ? 0.0 : logUniform(0.05, 8.0); }

    /// A shot at the origin from a random heading: it starts `nearest` to `farthest` m away, aimed within `aim` m
    /// of the origin, travels 1 to `longest` m over the motion and turns up to `turn` rad either way.
    Sweep aimedSweep(double nearest, double farthest, double aim, double longest, double turn) {
        const double heading = in(0.0, 2.0 * M_PI);
        const Vec2 dir(std::cos(heading), std::sin(heading)), side(-dir.y(), dir.x());
        const Vec2 start = -in(nearest, farthest) * dir + in(-aim, aim) * side;
        const double a0 = in(-M_PI, M_PI), travel = in(1.0, longest), spin = in(-turn, turn);
        return {start, start + travel * dir, a0, a0 + spin};
    }

private:
    std::mt19937 rng_;
    std::uniform_real_distribution<double> u_{0.0, 1.0};
};

/// A small fast shape (1 to 10 cm) crossing an obstacle at the origin: a thin plank (1 cm thick), a small circle
/// or a polygon. It starts 0.5 to 5 m away, apart from the obstacle, travels 1 to 20 m over the motion (60 to
/// 1200 m/s at 60 Hz), aimed within 0.3 m of the centre, turning up to 2 rad. About 2/3 of the pairs collide.
/// (ccd_bench's pairs too, so its tables and these tests see the same kind of input.)
inline std::vector<FastPair> randomPairs(int count, unsigned seed) {
    PairDraws draw(seed);
    auto in = [&](double lo, double hi) { return draw.in(lo, hi); };
    std::vector<FastPair> pairs;
    for (int i = 0; i < count; ++i) {
        FastPair p;
        const double size = in(0.01, 0.1);
        switch (i % 3) {
            case 0: p.a = makeCircle(size); break;
            case 1: p.a = makeBox(size, in(0.3, 1.0) * size); break;
            default: p.a = makePolygon({{-size, -0.5 * size}, {size, -0.8 * size}, {0.7 * size, 0.6 * size},
                                        {-0.2 * size, size}});
        }
        switch ((i / 3) % 3) {
            case 0: p.b = makeBox(0.005, in(0.2, 1.0)); break;
            case 1: p.b = makeCircle(in(0.01, 0.1)); break;
            default: p.b = makePolygon({{-0.1, -0.05}, {0.12, -0.08}, {0.15, 0.06}, {-0.02, 0.12}});
        }
        p.sa = draw.aimedSweep(0.5, 5.0, 0.3, 20.0, 2.0);
        const double b0 = in(-M_PI, M_PI);
        p.sb = Sweep{Vec2::Zero(), Vec2::Zero(), b0, b0};
        if (collide(p.a, p.sa.at(0.0), p.b, p.sb.at(0.0)).pointCount > 0) {
            --i;  // start apart
            continue;
        }
        pairs.push_back(p);
    }
    return pairs;
}

/// The gap at t* of pair i of a grazing set, by i % 12 (m): overlaps of 1 mm and 10 um, then 0.2 to 20 tolerances.
inline double grazingGap(int i) {
    const double tol = kToiTolerance;
    const double gaps[12] = {-1e-3, -1e-5, 0.2 * tol, 0.45 * tol, 0.55 * tol, 0.9 * tol,
                             1.1 * tol, 1.3 * tol, 1.6 * tol, 2.0 * tol, 3.0 * tol, 20.0 * tol};
    return gaps[i % 12];
}

/// The motions of pair i of a grazing set, for shapes of bounding radii ra and rb (spinningPairs' rule, below):
/// a turns and moves about the origin, b is placed at t* by distance(xa, xb) (a DistanceOutput between a at xa and
/// b at xb). False when the draw overlaps at t*: draw again.
template <class Distance>
bool placeGrazing(PairDraws& draw, int i, double ra, double rb, Sweep& sa, Sweep& sb, Distance distance) {
    const double spinA = draw.turn(0.2), spinB = draw.turn(0.5), speedA = draw.move(0.3), speedB = draw.move(0.5);
    const Vec2 vA = speedA * draw.direction();
    Vec2 vB = speedB * draw.direction();
    const double tStar = draw.in(0.05, 0.95), angleA = draw.in(-M_PI, M_PI), angleB = draw.in(-M_PI, M_PI);
    const Vec2 cA = Vec2::Zero();
    const double reach = draw.in(0.3, 1.0) * (ra + rb + 0.1);
    Vec2 cB = reach * draw.direction();
    const DistanceOutput d = distance(Transform{cA, Rotation::fromAngle(angleA)},
                                      Transform{cB, Rotation::fromAngle(angleB)});
    if (!(d.distance > 0.0)) return false;  // overlapping
    const bool graze = i % 4 != 0;
    const double shift = (graze ? grazingGap(i) : draw.in(0.0, 0.5)) - d.distance;
    cB += shift * d.normal;
    if (graze) {  // zero the rate of change of the gap between the closest points at t*
        auto velocity = [](const Vec2& v, double w, const Vec2& c, const Vec2& at) -> Vec2 {
            return v + w * perp(at - c);  // a Vec2, not an expression over perp's temporary
        };
        const Vec2 pointB = d.pointB + shift * d.normal;
        vB -= d.normal.dot(velocity(vB, spinB, cB, pointB) - velocity(vA, spinA, cA, d.pointA)) * d.normal;
    }
    sa = {cA - tStar * vA, cA + (1.0 - tStar) * vA, angleA - tStar * spinA, angleA + (1.0 - tStar) * spinA};
    sb = {cB - tStar * vB, cB + (1.0 - tStar) * vB, angleB - tStar * spinB, angleB + (1.0 - tStar) * spinB};
    return true;
}

/// Pairs of fast-spinning shapes, most of them built to graze. Shapes: circles (some off their body's origin),
/// boxes, 2 m planks 1 cm thick, thin boxes off the origin, random convex polygons of 3 to 8 vertices. Over the
/// motion each moves up to 8 m (480 m/s over a 1/60 s step) and turns up to 17 rad (1000 rad/s).
/// At a random moment t* in (0.05, 0.95) b is placed `grazingGap(i)` from a along their closest-point normal; in
/// three pairs of four, b's motion along that normal is then set so that the gap's rate of change at t* is zero,
/// which makes t* a minimum of the distance (a graze) or a maximum (a hit just after). Gaps around the tolerance
/// kToiTolerance: overlaps of 1 mm and 10 um, then 0.2 to 20 tolerances. The fourth pair has a random gap up to
/// 0.5 m and no such adjustment. Other parts of the shapes may still meet at other times (a spinning plank sweeps
/// through what it grazed). Every pair starts at least the tolerance apart.
inline std::vector<FastPair> spinningPairs(int count, unsigned seed) {
    PairDraws draw(seed);
    auto u = [&] { return draw.unit(); };
    auto in = [&](double lo, double hi) { return draw.in(lo, hi); };
    // Draws are taken one per statement: the order in which a call's arguments are evaluated is unspecified.
    auto shape = [&]() -> Geometry {
        const int kind = static_cast<int>(6.0 * u());
        const double r1 = u(), r2 = u(), r3 = u(), r4 = u(), r5 = u();
        switch (kind) {
            case 0: return makeCircle(0.01 + 0.29 * r1);
            case 1: return makeCircle(0.01 + 0.19 * r1, {0.4 * r2 - 0.2, 0.4 * r3 - 0.2});
            case 2: return makeBox(0.02 + 0.48 * r1, 0.02 + 0.48 * r2);
            case 3: return makeBox(1.0, 0.005);
            case 4:
                return makeBox(0.05 + 0.25 * r1, 0.005 + 0.045 * r2, {0.2 * r3 - 0.1, 0.2 * r4 - 0.1}, 6.0 * r5 - 3.0);
            default: {  // vertices at increasing angles around a circle, pulled in by up to 30% (makePolygon refuses
                        // the rare non-convex draw)
                const int n = 3 + static_cast<int>(6.0 * u());
                const double size = in(0.05, 0.4), phase = in(0.0, 2.0 * M_PI);
                std::vector<Vec2> points;
                for (int k = 0; k < n; ++k) {
                    const double angle = phase + 2.0 * M_PI * (k + 0.3 * u()) / n, r = size * in(0.7, 1.0);
                    points.emplace_back(r * std::cos(angle), r * std::sin(angle));
                }
                try {
                    return makePolygon(points);
                } catch (const std::invalid_argument&) {  // a reflex vertex after all
                    return makeBox(size, 0.5 * size);
                }
            }
        }
    };
    std::vector<FastPair> pairs;
    while (static_cast<int>(pairs.size()) < count) {
        const int i = static_cast<int>(pairs.size());
        FastPair p{shape(), shape(), {}, {}};
        auto distance = [&](const Transform& xa, const Transform& xb) { return shapeDistance(p.a, xa, p.b, xb); };
        if (!placeGrazing(draw, i, boundingRadius(p.a), boundingRadius(p.b), p.sa, p.sb, distance)) continue;
        if (shapeDistance(p.a, p.sa.at(0.0), p.b, p.sb.at(0.0)).distance < kToiTolerance) continue;
        pairs.push_back(p);
    }
    return pairs;
}

/// Appends the pair's two bodies (a, then b), each with its own shape, and the pair.
inline void appendPair(ContinuousBatch& batch, const FastPair& p) {
    const std::int32_t a = batch.addBody(batch.addShape(p.a), p.sa);
    const std::int32_t b = batch.addBody(batch.addShape(p.b), p.sb);
    batch.addPair(a, b);
}

/// The pairs as a batch: each body its own shape (as the World's continuous stage builds them), pair i = bodies
/// 2i (a) and 2i + 1 (b).
inline ContinuousBatch toBatch(const std::vector<FastPair>& pairs) {
    ContinuousBatch batch;
    for (const FastPair& p : pairs) appendPair(batch, p);
    return batch;
}

inline ContinuousBatch randomBatch(int pairs, unsigned seed) { return toBatch(randomPairs(pairs, seed)); }

/// How two solvers' answers to one batch compare (the GPU's against the CPU's). Two answers agree when their states
/// are equal and their times are equal, or apart by no more than the tolerance in distance: |t1 - t2| times the
/// fastest a point of the pair moves per unit t is at most batch.tolerance, the exact method's own accuracy. A
/// last-bit difference can add or drop one advancement step, of (gap - tolerance / 2) / closing speed; for a grazing
/// pair (closing far slower than its points move) that could exceed this bound. An empirical bound, then: measured,
/// no pair of 1.1 million on an H100 exceeded it (docs/cuda.md).
struct Agreement {
    int identical = 0;  ///< same state, same bits of t
    int within = 0;     ///< same state, t apart within the tolerance
    int disagree = 0;
};

inline Agreement compareResults(const ContinuousBatch& batch, const ContinuousBatchResult& x,
                                const ContinuousBatchResult& y) {
    Agreement a;
    for (std::size_t i = 0; i < batch.pairCount(); ++i) {
        double speed = 0.0;  // m per unit t, bounding every point of both shapes
        for (const std::int32_t body : {batch.pairs.a[i], batch.pairs.b[i]})
            speed += std::hypot(batch.bodies.x1[body] - batch.bodies.x0[body],
                                batch.bodies.y1[body] - batch.bodies.y0[body]) +
                     std::abs(batch.bodies.angle1[body] - batch.bodies.angle0[body]) *
                         batch.shapes.boundingRadius[batch.bodies.shape[body]];
        if (x.state[i] != y.state[i])
            ++a.disagree;
        else if (x.t[i] == y.t[i])
            ++a.identical;
        else if (std::abs(x.t[i] - y.t[i]) * speed <= batch.tolerance)
            ++a.within;
        else
            ++a.disagree;
    }
    return a;
}

/// fillBulletBox's walls' inner faces are at |x| = kBulletBoxInner and |y| = kBulletBoxInner (m): a bullet whose
/// centre is there or beyond is in or through a wall.
inline constexpr double kBulletBoxInner = 1.995;

/// Bullets in a 4 m x 4 m box centred on the origin (walls 1 cm thick); returns the bullets' ids.
inline std::vector<BodyId> fillBulletBox(World& world, int bullets, unsigned seed) {
    const double half = kBulletBoxInner + 0.005, wall = 0.005;  // m: the walls' centre lines and half thickness
    for (const auto& [x, y, hw, hh] : {std::array<double, 4>{-half, 0.0, wall, half + wall},
                                       std::array<double, 4>{half, 0.0, wall, half + wall},
                                       std::array<double, 4>{0.0, -half, half + wall, wall},
                                       std::array<double, 4>{0.0, half, half + wall, wall}}) {
        BodyDef d;
        d.type = BodyType::Static;
        d.shape = makeBox(hw, hh);
        d.position = {x, y};
        d.restitution = 1.0;
        world.createBody(d);
    }
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<BodyId> ids;
    for (int i = 0; i < bullets; ++i) {
        BodyDef d;
        d.shape = i % 2 ? Geometry(makeCircle(0.01 + 0.01 * u(rng))) : Geometry(makeBox(0.015, 0.005));
        d.position = {(2.0 * u(rng) - 1.0) * (half - 0.2), (2.0 * u(rng) - 1.0) * (half - 0.2)};
        const double heading = 2.0 * M_PI * u(rng), speed = 150.0 + 450.0 * u(rng);
        d.velocity = speed * Vec2(std::cos(heading), std::sin(heading));
        d.angularVelocity = 20.0 * (2.0 * u(rng) - 1.0);
        d.restitution = 1.0;
        d.collisionDetection = CollisionDetection::ContinuousExact;
        d.allowSleep = false;
        ids.push_back(world.createBody(d));
    }
    return ids;
}

/// Kinetic energy of the bodies, translational and rotational (J): the one in Scenes.hpp.
using test::kineticEnergy;

/// Steps fillBulletBox's scene (no gravity, 60 Hz) and returns the first step that ends with more kinetic energy
/// than it began with, beyond `tolerance` relative; -1 when none of `steps` does.
inline int firstEnergyGain(int bullets, unsigned seed, int steps, double tolerance) {
    WorldSettings settings;
    settings.gravity = Vec2::Zero();
    World world(settings);
    const std::vector<BodyId> ids = fillBulletBox(world, bullets, seed);
    for (int step = 0; step < steps; ++step) {
        const double before = kineticEnergy(world, ids);
        world.step(1.0 / 60.0);
        if (kineticEnergy(world, ids) > before * (1.0 + tolerance)) return step;
    }
    return -1;
}

}  // namespace physim::testing
