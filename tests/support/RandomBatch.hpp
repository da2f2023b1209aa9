#pragma once
// Test inputs for continuous batches, shared by the core's and the CUDA layer's tests:
//   randomPairs / randomBatch: fast small shapes fired across obstacles (ccd_bench uses them too).
//   fillBulletBox: a closed box of thin walls with exact-continuous bullets (small circles and thin spinning boxes)
//     fired across it at 150 to 600 m/s, so every step has impacts and, without continuous detection, the bullets
//     would leave the box.

#include "physim/core/Collide.hpp"
#include "physim/core/ContinuousBatch.hpp"
#include "physim/core/World.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace physim::testing {

/// One moving pair: shape a sweeps across shape b.
struct FastPair {
    Geometry a, b;
    Sweep sa, sb;
};

/// A small fast shape (1 to 10 cm) crossing an obstacle at the origin: a thin plank (1 cm thick), a small circle
/// or a polygon. It starts 0.5 to 5 m away, apart from the obstacle, travels 1 to 20 m over the motion (60 to
/// 1200 m/s at 60 Hz), aimed within 0.3 m of the centre, turning up to 2 rad. About 2/3 of the pairs collide.
/// (ccd_bench's pairs too, so its tables and these tests see the same kind of input.)
inline std::vector<FastPair> randomPairs(int count, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    auto in = [&](double lo, double hi) { return lo + (hi - lo) * u(rng); };
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
        const double heading = in(0.0, 2.0 * M_PI);
        const Vec2 dir(std::cos(heading), std::sin(heading));
        const Vec2 side(-dir.y(), dir.x());
        const Vec2 start = -in(0.5, 5.0) * dir + in(-0.3, 0.3) * side;
        const double a0 = in(-M_PI, M_PI);
        p.sa = Sweep{start, start + in(1.0, 20.0) * dir, a0, a0 + in(-2.0, 2.0)};
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

/// Bullets in a 4 m x 4 m box centred on the origin (walls 1 cm thick); returns the bullets' ids.
inline std::vector<BodyId> fillBulletBox(World& world, int bullets, unsigned seed) {
    const double half = 2.0, wall = 0.005;
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

/// Kinetic energy of the bodies, translational and rotational (J).
inline double kineticEnergy(const World& world, const std::vector<BodyId>& bodies) {
    double e = 0.0;
    for (const BodyId b : bodies)
        e += 0.5 * world.mass(b) * world.velocity(b).squaredNorm() +
             0.5 * world.inertia(b) * world.angularVelocity(b) * world.angularVelocity(b);
    return e;
}

}  // namespace physim::testing
