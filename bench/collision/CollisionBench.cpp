// Narrow phase: calls per second for each shape pair over a fixed set of random placements, about two thirds
// of them touching. Broad phase: cost per call for n bodies at constant density (so the true pair count grows
// like n), against the brute-force n^2 test and the previous sweep on x, in a scattered scene and a column.
// Run: build/core/bench/collision/collision_bench (docs/collision.md has the measured table).

#include "BroadPhase.hpp"

#include "physim/core/Collide.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace physim {
namespace {

enum class Kind { Circle, Box, Octagon };

Geometry make(Kind k, double size) {
    switch (k) {
        case Kind::Circle: return makeCircle(0.5 * size);
        case Kind::Box: return makeBox(0.5 * size, 0.35 * size);
        case Kind::Octagon: {
            std::vector<Vec2> pts;
            for (int i = 0; i < 8; ++i)
                pts.emplace_back(0.5 * size * std::cos(M_PI * i / 4), 0.5 * size * std::sin(M_PI * i / 4));
            return makePolygon(pts);
        }
    }
    return makeCircle(size);
}

struct Placement {
    Geometry a, b;
    Transform xa, xb;
};

std::vector<Placement> placements(Kind ka, Kind kb) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Placement> out;
    for (int i = 0; i < 4096; ++i) {
        // Unit shapes, centres up to 1.1 m apart per axis: about half the placements touch.
        out.push_back({make(ka, 1.0 + 0.3 * u(rng)), make(kb, 1.0 + 0.3 * u(rng)),
                       {Vec2::Zero(), Rotation::fromAngle(M_PI * u(rng))},
                       {{1.1 * u(rng), 1.1 * u(rng)}, Rotation::fromAngle(M_PI * u(rng))}});
    }
    return out;
}

void BM_Collide(benchmark::State& state, Kind ka, Kind kb) {
    const std::vector<Placement> set = placements(ka, kb);
    std::size_t i = 0, touching = 0;
    for (auto _ : state) {
        const Placement& p = set[i++ & 4095];
        const Manifold m = collide(p.a, p.xa, p.b, p.xb);
        touching += m.pointCount > 0;
        benchmark::DoNotOptimize(m);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
    state.counters["touching"] = static_cast<double>(touching) / static_cast<double>(state.iterations());
}
BENCHMARK_CAPTURE(BM_Collide, circle_circle, Kind::Circle, Kind::Circle);
BENCHMARK_CAPTURE(BM_Collide, box_circle, Kind::Box, Kind::Circle);
BENCHMARK_CAPTURE(BM_Collide, octagon_circle, Kind::Octagon, Kind::Circle);
BENCHMARK_CAPTURE(BM_Collide, box_box, Kind::Box, Kind::Box);
BENCHMARK_CAPTURE(BM_Collide, box_octagon, Kind::Box, Kind::Octagon);
BENCHMARK_CAPTURE(BM_Collide, octagon_octagon, Kind::Octagon, Kind::Octagon);

// n bodies of 0.2 to 0.8 m, 1 in 10 static, at about one body per 2 m^2: each overlaps a few others whatever n.
// column: the same bodies stacked in one vertical column 1 m wide (every x range overlaps every other).
std::vector<BodyData> scene(std::size_t n, bool column) {
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double side = std::sqrt(2.0 * static_cast<double>(n));
    std::vector<BodyData> bodies(n);
    for (std::size_t i = 0; i < n; ++i) {
        BodyData& b = bodies[i];
        b.alive = true;
        b.type = i % 10 == 0 ? BodyType::Static : BodyType::Dynamic;
        const double size = 0.2 + 0.6 * u(rng);
        b.shape = i % 2 ? Geometry{makeCircle(0.5 * size)} : Geometry{makeBox(0.5 * size, 0.3 * size)};
        const Vec2 p = column ? Vec2(u(rng) - 0.5, 0.5 * static_cast<double>(i)) : Vec2(side * u(rng), side * u(rng));
        b.xf = {p, Rotation::fromAngle(6.28 * u(rng))};
    }
    return bodies;
}

// warm: the scratch (and so last call's order) is reused, as the world does every step; the scene moves by up
// to 2 m/s for 1/60 s between calls (the moving is not timed). cold: a fresh scratch every call (a full sort).
void BM_BroadPhase(benchmark::State& state, bool column, bool warm) {
    std::vector<BodyData> bodies = scene(static_cast<std::size_t>(state.range(0)), column);
    std::vector<BodyPair> pairs;
    std::vector<std::uint32_t> scratch;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Vec2> velocity(bodies.size());
    for (Vec2& v : velocity) v = {2.0 * u(rng), 2.0 * u(rng)};
    std::size_t step = 0;
    for (auto _ : state) {
        if (warm) {
            state.PauseTiming();
            const double dt = (step++ / 60) % 2 ? -1.0 / 60.0 : 1.0 / 60.0;  // back and forth: density stays
            for (std::size_t i = 0; i < bodies.size(); ++i)
                if (bodies[i].movable()) bodies[i].xf.p += dt * velocity[i];
            state.ResumeTiming();
        } else {
            scratch.clear();
        }
        findCandidatePairs(bodies, pairs, scratch);
        benchmark::DoNotOptimize(pairs.data());
    }
    state.counters["pairs"] = static_cast<double>(pairs.size());
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));  // bodies/s
    state.SetComplexityN(state.range(0));
}
BENCHMARK_CAPTURE(BM_BroadPhase, scattered_warm, false, true)->RangeMultiplier(4)->Range(1 << 10, 1 << 16)
    ->Complexity(benchmark::oN)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BroadPhase, scattered_cold, false, false)->RangeMultiplier(4)->Range(1 << 10, 1 << 16)
    ->Complexity(benchmark::oNLogN)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_BroadPhase, column_warm, true, true)->RangeMultiplier(4)->Range(1 << 10, 1 << 14)
    ->Complexity(benchmark::oN)->Unit(benchmark::kMicrosecond);

// The floor any broad phase over the world's storage pays: one pass refreshing every body's box.
void BM_AabbRefresh(benchmark::State& state) {
    std::vector<BodyData> bodies = scene(static_cast<std::size_t>(state.range(0)), false);
    for (auto _ : state) {
        for (BodyData& b : bodies) b.aabb = computeAabb(b.shape, b.xf);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}
BENCHMARK(BM_AabbRefresh)->RangeMultiplier(4)->Range(1 << 10, 1 << 16)->Unit(benchmark::kMicrosecond);

// References for the table, written here only to be measured against.
void bruteForce(std::vector<BodyData>& bodies, std::vector<BodyPair>& pairs) {
    pairs.clear();
    for (BodyData& b : bodies) b.aabb = computeAabb(b.shape, b.xf);
    for (std::uint32_t i = 0; i < bodies.size(); ++i)
        for (std::uint32_t j = i + 1; j < bodies.size(); ++j)
            if ((bodies[i].movable() || bodies[j].movable()) && bodies[i].aabb.overlaps(bodies[j].aabb))
                pairs.emplace_back(i, j);
}

void BM_BruteForce(benchmark::State& state, bool column) {
    std::vector<BodyData> bodies = scene(static_cast<std::size_t>(state.range(0)), column);
    std::vector<BodyPair> pairs;
    for (auto _ : state) {
        bruteForce(bodies, pairs);
        benchmark::DoNotOptimize(pairs.data());
    }
    state.counters["pairs"] = static_cast<double>(pairs.size());
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}
BENCHMARK_CAPTURE(BM_BruteForce, scattered, false)->RangeMultiplier(4)->Range(1 << 10, 1 << 14)
    ->Unit(benchmark::kMicrosecond);

// The broad phase the world used before this one: sort and sweep on x only.
void sweepOnX(std::vector<BodyData>& bodies, std::vector<BodyPair>& pairs, std::vector<std::uint32_t>& order) {
    pairs.clear();
    order.clear();
    for (std::uint32_t i = 0; i < bodies.size(); ++i) {
        bodies[i].aabb = computeAabb(bodies[i].shape, bodies[i].xf);
        order.push_back(i);
    }
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t a, std::uint32_t b) { return bodies[a].aabb.lower.x() < bodies[b].aabb.lower.x(); });
    for (std::size_t i = 0; i < order.size(); ++i)
        for (std::size_t j = i + 1; j < order.size(); ++j) {
            const BodyData &a = bodies[order[i]], &b = bodies[order[j]];
            if (b.aabb.lower.x() > a.aabb.upper.x()) break;
            if ((a.movable() || b.movable()) && a.aabb.overlaps(b.aabb))
                pairs.emplace_back(std::min(order[i], order[j]), std::max(order[i], order[j]));
        }
    std::sort(pairs.begin(), pairs.end());
}

void BM_SweepOnX(benchmark::State& state, bool column) {
    std::vector<BodyData> bodies = scene(static_cast<std::size_t>(state.range(0)), column);
    std::vector<BodyPair> pairs;
    std::vector<std::uint32_t> order;
    for (auto _ : state) {
        sweepOnX(bodies, pairs, order);
        benchmark::DoNotOptimize(pairs.data());
    }
    state.counters["pairs"] = static_cast<double>(pairs.size());
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}
BENCHMARK_CAPTURE(BM_SweepOnX, scattered, false)->RangeMultiplier(4)->Range(1 << 10, 1 << 16)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_SweepOnX, column, true)->RangeMultiplier(4)->Range(1 << 10, 1 << 14)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace physim
