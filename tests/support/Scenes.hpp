#pragma once
// Small scene builders and measures shared by the stability, determinism and bad-input tests (and the programs
// ctest runs twice to compare). Header-only; no global state.

#include "physim/core/World.hpp"
#include "support/Pyramid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <utility>
#include <vector>

namespace physim::test {

/// Default settings with sleep off (so the solver, not sleeping, holds a scene) and the given gravity.
inline WorldSettings awakeSettings(const Vec2& gravity = {0.0, -9.81}) {
    WorldSettings s;
    s.gravity = gravity;
    s.enableSleep = false;
    return s;
}

/// How much deeper a box resting on a face sinks into soft contacts than its bare mass would. The solver holds each of
/// the face's two points alone as a spring: a point carrying impulse x overlaps K_ii x / w^2 (K_ii its inverse
/// effective mass), not the pair's (K_11 + K_12) x / w^2. For points at the face's ends of a box of half width a and
/// half height b, K_ii / (K_11 + K_12) = (1 + m a^2 / I) / 2 = (1 + 3 a^2 / (a^2 + b^2)) / 2: 1.25 for a square.
inline double pointCompliance(double halfWidth, double halfHeight) {
    const double a2 = halfWidth * halfWidth, b2 = halfHeight * halfHeight;
    return (1.0 + 3.0 * a2 / (a2 + b2)) / 2.0;
}

/// A static box of half-extents (m) centred at `position`, turned by `angle` rad.
inline BodyId addStaticBox(World& world, const Vec2& position, double halfWidth, double halfHeight,
                           double angle = 0.0) {
    BodyDef def;
    def.type = BodyType::Static;
    def.shape = makeBox(halfWidth, halfHeight);
    def.position = position;
    def.angle = angle;
    return world.createBody(def);
}

/// A static point to hang joints from: a 1 cm disc at `at` that collides with nothing.
inline BodyId addStaticPivot(World& world, const Vec2& at = Vec2::Zero()) {
    BodyDef d;
    d.type = BodyType::Static;
    d.shape = makeCircle(0.01);
    d.position = at;
    d.collides = false;
    return world.createBody(d);
}

/// A static slab whose top face is the line y = 0, `halfWidth` m each side of x = 0.
inline BodyId addGround(World& world, double halfWidth = 200.0) {
    return addStaticBox(world, {0.0, -0.5}, halfWidth, 0.5);
}

/// The farthest (m) any of `ids` gets from where it was before `steps` steps of 60 Hz.
inline double farthestMove(World& world, const std::vector<BodyId>& ids, int steps) {
    std::vector<Vec2> start;
    for (const BodyId id : ids) start.push_back(world.position(id));
    double farthest = 0.0;
    for (int s = 0; s < steps; ++s) {
        world.step(1.0 / 60.0);
        for (std::size_t k = 0; k < ids.size(); ++k)
            farthest = std::max(farthest, (world.position(ids[k]) - start[k]).norm());
    }
    return farthest;
}

inline BodyId addBox(World& world, const Vec2& position, double halfWidth, double halfHeight, double density = 1.0) {
    BodyDef def;
    def.shape = makeBox(halfWidth, halfHeight);
    def.position = position;
    def.density = density;
    return world.createBody(def);
}

/// A discrete disc (r = 0.1 m) resting at x = 0.3 on a ground whose surface is the line y = 0 (the caller's), struck
/// from above by a 1 m box falling at `speed` m/s with `density` kg/m^2 (the disc has density 1). Returns the lowest
/// height of the disc's centre over the strike: 20 steps at 60 Hz. After that the box rests on the disc or tips
/// off it and comes down again slowly, and a slow press by a body 300 to 30 000 times heavier squeezes the disc
/// through the ground's line about half the time (a mass-ratio limit of the contacts, not the strike's business).
inline double lowestDiscUnderAFallingBox(World& world, double speed, double density) {
    BodyDef disc;
    disc.shape = makeCircle(0.1);
    disc.position = {0.3, 0.1};
    const BodyId id = world.createBody(disc);
    BodyDef box;
    box.shape = makeBox(0.5, 0.5);
    box.position = {0.3, 0.7};
    box.velocity = {0.0, -speed};
    box.density = density;
    world.createBody(box);
    double lowest = world.position(id).y();
    for (int i = 0; i < 20; ++i) {
        world.step(1.0 / 60.0);
        lowest = std::min(lowest, world.position(id).y());
    }
    return lowest;
}

/// A pyramid of touching 1 m boxes (scenes::forEachPyramidBox), `base` in its bottom row, standing on y = 0 centred on
/// x = centerX. Returns the boxes in creation order: the top one last.
inline std::vector<BodyId> addPyramid(World& world, int base, double centerX = 0.0) {
    std::vector<BodyId> ids;
    scenes::forEachPyramidBox(base, 1.0, centerX, 0.0,
                              [&](double x, double y) { ids.push_back(addBox(world, {x, y}, 0.5, 0.5)); });
    return ids;
}

/// Kinetic energy (J) of the bodies, translation and rotation about the centre of mass.
inline double kineticEnergy(const World& world, const std::vector<BodyId>& ids) {
    double e = 0.0;
    for (const BodyId id : ids) {
        const double w = world.angularVelocity(id);
        e += 0.5 * world.mass(id) * world.velocity(id).squaredNorm() + 0.5 * world.inertia(id) * w * w;
    }
    return e;
}

/// Kinetic plus potential energy (J) in uniform gravity g (m/s^2), potential 0 at the origin.
inline double mechanicalEnergy(const World& world, const std::vector<BodyId>& ids) {
    double e = kineticEnergy(world, ids);
    const Vec2 g = world.settings().gravity;
    for (const BodyId id : ids) e -= world.mass(id) * g.dot(world.centerOfMass(id));
    return e;
}

/// FNV-1a over the bits of every live body's pose and velocities, in creation-slot order of `ids`: equal hashes
/// mean bit-identical states (up to the 2^-64 chance of a collision).
inline std::uint64_t stateHash(const World& world, const std::vector<BodyId>& ids) {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&](double v) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        for (int i = 0; i < 8; ++i) {
            h ^= (bits >> (8 * i)) & 0xffu;
            h *= 1099511628211ull;
        }
    };
    for (const BodyId id : ids) {
        const Transform xf = world.transform(id);
        for (const double v : {xf.p.x(), xf.p.y(), xf.q.c, xf.q.s, world.angle(id), world.velocity(id).x(),
                               world.velocity(id).y(), world.angularVelocity(id)})
            mix(v);
    }
    return h;
}

/// The determinism scene: a closed 12 m box with a tilted pyramid of `rows` rows of boxes and 24 discs and small
/// boxes thrown through it (restitution 0.5 and 1, friction on), gravity, sleep off, so it keeps colliding for the
/// whole run. Returns the dynamic bodies in creation order.
inline std::vector<BodyId> buildDeterminismScene(World& world, int rows = 8) {
    const double half = 6.0, wall = 0.5;
    for (const auto& [size, at] : {std::pair{Vec2(half + 2 * wall, wall), Vec2(0.0, -wall)},
                                   std::pair{Vec2(half + 2 * wall, wall), Vec2(0.0, 2 * half + wall)},
                                   std::pair{Vec2(wall, half + 2 * wall), Vec2(-half - wall, half)},
                                   std::pair{Vec2(wall, half + 2 * wall), Vec2(half + wall, half)}})
        addStaticBox(world, at, size.x(), size.y());
    std::vector<BodyId> ids;
    const double size = 0.4 * 8 / rows;  // half-size: the pyramid fills the same 6.4 m base at any row count
    for (int row = 0; row < rows; ++row)
        for (int i = 0; i < rows - row; ++i) {
            BodyDef d;
            d.shape = makeBox(size, size);
            d.position = {-3.0 + 2 * size * (i + 0.5 * row) + 0.01 * row, size + 2 * size * row};
            d.angle = 0.01 * row;
            ids.push_back(world.createBody(d));
        }
    for (int k = 0; k < 24; ++k) {
        BodyDef d;
        d.shape = k % 3 ? Geometry(makeCircle(0.2)) : Geometry(makeBox(0.2, 0.15));
        d.position = {-5.0 + 0.45 * k, 9.0 + 0.3 * (k % 4)};
        d.velocity = {6.0 * std::cos(0.7 * k), -8.0 + std::sin(1.1 * k)};
        d.angularVelocity = 0.5 * (k % 5) - 1.0;
        d.restitution = k % 2 ? 1.0 : 0.5;
        ids.push_back(world.createBody(d));
    }
    return ids;
}

/// The elastic gas: 200 frictionless discs (r = 0.2 m, e = 1) at 5 m/s in directions drawn from `seed`, in a closed
/// 16 m box of elastic, frictionless walls. Returns the discs in creation order; the world's settings are the caller's.
inline std::vector<BodyId> buildElasticGas(World& world, unsigned seed) {
    const double half = 8.0, t = 1.0;
    for (const auto& [size, at] : {std::pair{Vec2(half + t, t / 2), Vec2(0.0, -half - t / 2)},
                                   std::pair{Vec2(half + t, t / 2), Vec2(0.0, half + t / 2)},
                                   std::pair{Vec2(t / 2, half + t), Vec2(-half - t / 2, 0.0)},
                                   std::pair{Vec2(t / 2, half + t), Vec2(half + t / 2, 0.0)}}) {
        BodyDef wall;
        wall.type = BodyType::Static;
        wall.shape = makeBox(size.x(), size.y());
        wall.position = at;
        wall.restitution = 1.0;
        wall.staticFriction = wall.dynamicFriction = 0.0;
        world.createBody(wall);
    }
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> turn(0.0, 2.0 * M_PI);
    std::vector<BodyId> discs;
    for (int i = 0; i < 200; ++i) {
        const double a = turn(rng);
        BodyDef d;
        d.shape = makeCircle(0.2);
        d.restitution = 1.0;
        d.staticFriction = d.dynamicFriction = 0.0;
        d.position = {-half + 0.8 * (i % 20 + 0.5), -half + 0.8 * (i / 20 + 0.5)};
        d.velocity = 5.0 * Vec2(std::cos(a), std::sin(a));
        discs.push_back(world.createBody(d));
    }
    return discs;
}

struct GasRun {
    double rise = 0.0;  // highest kinetic energy over the start, relative (0: never above)
    double kept = 1.0;  // kinetic energy at the end over the start
};

/// buildElasticGas(seed) without gravity and with sleep off, stepped `steps` times at 60 Hz.
inline GasRun runElasticGas(unsigned seed, int steps) {
    WorldSettings settings;
    settings.gravity = Vec2::Zero();
    settings.enableSleep = false;
    World world(settings);
    const std::vector<BodyId> discs = buildElasticGas(world, seed);
    const double k0 = kineticEnergy(world, discs);
    double highest = k0;
    for (int s = 0; s < steps; ++s) {
        world.step(1.0 / 60.0);
        highest = std::max(highest, kineticEnergy(world, discs));
    }
    return {highest / k0 - 1.0, kineticEnergy(world, discs) / k0};
}

/// Leaves `count` freed body slots behind (and freed broad-phase nodes and contacts): creates that many touching
/// discs, steps once so they meet, then destroys them in creation order.
inline void churn(World& world, int count) {
    std::vector<BodyId> ids;
    for (int i = 0; i < count; ++i) {
        BodyDef d;
        d.shape = makeCircle(0.3);
        d.position = {100.0 + 0.5 * i, 100.0};
        ids.push_back(world.createBody(d));
    }
    if (count > 0) world.step(1.0 / 60.0);
    for (const BodyId id : ids) world.destroyBody(id);
}

struct PyramidRun {
    double topDrift = 0.0;  // m: farthest the top box gets from where it was at t = 1 s
    double sideways = 0.0;  // m: largest |x - x0| of any box over the run
};

/// A pyramid of 1 m boxes with `base` boxes in its bottom row, touching, on the ground, stepped `steps` times at
/// 60 Hz with sleep off (and the default solver settings, unless given others).
inline PyramidRun runPyramid(int base, int steps, const WorldSettings& settings = awakeSettings()) {
    World world(settings);
    addGround(world);
    const std::vector<BodyId> ids = addPyramid(world, base);
    std::vector<double> x0;
    for (const BodyId id : ids) x0.push_back(world.position(id).x());
    const BodyId top = ids.back();
    PyramidRun r;
    Vec2 settled = Vec2::Zero();
    for (int s = 0; s < steps; ++s) {
        world.step(1.0 / 60.0);
        if (s + 1 == 60) settled = world.position(top);
        if (s + 1 > 60) r.topDrift = std::max(r.topDrift, (world.position(top) - settled).norm());
        for (std::size_t k = 0; k < ids.size(); ++k)
            r.sideways = std::max(r.sideways, std::abs(world.position(ids[k]).x() - x0[k]));
    }
    return r;
}

}  // namespace physim::test
