// Narrow phase: calls per second for each shape pair over a fixed set of random placements, about two thirds
// of them touching (fewer with segments and chain pieces, which have no area; the shape against a chain piece is
// placed on the piece's solid side, as bodies on a chain are). Every pair of kinds: circle, polygon (box; octagon for the polygon routines' worst case),
// rounded polygon, segment, capsule and chain piece. (The broad phase's tree has its own program, bench/broadphase.)
// Run: build/core/bench/collision/collision_bench (docs/collision.md has the measured table).

#include "physim/core/Collide.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace physim {
namespace {

enum class Kind { Circle, Box, Octagon, Rounded, Segment, Capsule, Chain };

Geometry make(Kind k, double size) {
    switch (k) {
        case Kind::Circle: return makeCircle(0.5 * size);
        case Kind::Box: return makeBox(0.5 * size, 0.35 * size);
        case Kind::Rounded: return makeRoundedBox(0.4 * size, 0.25 * size, 0.1 * size);  // the box's outer size
        case Kind::Segment: return makeSegment({-0.5 * size, 0.0}, {0.5 * size, 0.0});
        case Kind::Capsule: return makeCapsule({-0.3 * size, 0.0}, {0.3 * size, 0.0}, 0.2 * size);
        case Kind::Chain: {
            // The middle piece of a chain that turns right (a convex joint) before it and left after it.
            const double h = 0.5 * size;
            return makeChain({{-2.0 * h, -0.3 * h}, {-h, 0.0}, {h, 0.0}, {2.0 * h, 0.3 * h}})[1];
        }
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
        // A chain piece answers only on its solid side: mirror a centre behind it to the front, where bodies are.
        Placement& p = out.back();
        if (ka == Kind::Chain) {
            const Vec2 local = p.xa.applyInverse(p.xb.p);
            if (local.y() < 0.0) p.xb.p = p.xa.apply({local.x(), -local.y()});
        }
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
BENCHMARK_CAPTURE(BM_Collide, rounded_circle, Kind::Rounded, Kind::Circle);
BENCHMARK_CAPTURE(BM_Collide, rounded_box, Kind::Rounded, Kind::Box);
BENCHMARK_CAPTURE(BM_Collide, rounded_rounded, Kind::Rounded, Kind::Rounded);
BENCHMARK_CAPTURE(BM_Collide, segment_circle, Kind::Segment, Kind::Circle);
BENCHMARK_CAPTURE(BM_Collide, segment_box, Kind::Segment, Kind::Box);
BENCHMARK_CAPTURE(BM_Collide, segment_rounded, Kind::Segment, Kind::Rounded);
BENCHMARK_CAPTURE(BM_Collide, segment_segment, Kind::Segment, Kind::Segment);
BENCHMARK_CAPTURE(BM_Collide, capsule_circle, Kind::Capsule, Kind::Circle);
BENCHMARK_CAPTURE(BM_Collide, capsule_box, Kind::Capsule, Kind::Box);
BENCHMARK_CAPTURE(BM_Collide, capsule_rounded, Kind::Capsule, Kind::Rounded);
BENCHMARK_CAPTURE(BM_Collide, capsule_segment, Kind::Capsule, Kind::Segment);
BENCHMARK_CAPTURE(BM_Collide, capsule_capsule, Kind::Capsule, Kind::Capsule);
BENCHMARK_CAPTURE(BM_Collide, chain_circle, Kind::Chain, Kind::Circle);
BENCHMARK_CAPTURE(BM_Collide, chain_box, Kind::Chain, Kind::Box);
BENCHMARK_CAPTURE(BM_Collide, chain_rounded, Kind::Chain, Kind::Rounded);
BENCHMARK_CAPTURE(BM_Collide, chain_segment, Kind::Chain, Kind::Segment);
BENCHMARK_CAPTURE(BM_Collide, chain_capsule, Kind::Chain, Kind::Capsule);
BENCHMARK_CAPTURE(BM_Collide, chain_chain, Kind::Chain, Kind::Chain);

}  // namespace
}  // namespace physim
