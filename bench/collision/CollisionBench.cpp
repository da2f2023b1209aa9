// Narrow phase: calls per second for each shape pair over a fixed set of random placements, about two thirds
// of them touching. (The broad phase's tree has its own program, bench/broadphase.)
// Run: build/core/bench/collision/collision_bench (docs/collision.md has the measured table).

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

}  // namespace
}  // namespace physim
