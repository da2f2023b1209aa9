// dynamics_bench: milliseconds per 60 Hz step at the default settings for the scenes: pyramids with
// 20 and 40 boxes on the base, and 1000 circles falling into a box. Each scene is built and run for 1 s
// first so the timed steps are the steady (mostly resting) state. Counters name the substeps and iterations.

#include "physim/core/World.hpp"
#include "support/Scenes.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace physim;

constexpr double kDt = 1.0 / 60.0;

using physim::test::addStaticBox;

void pyramid(World& w, int base) {
    physim::test::addGround(w, 100.0);
    physim::test::addPyramid(w, base);
}

void circlesInBox(World& w) {
    addStaticBox(w, {0.0, -0.5}, 10.0, 0.5);
    addStaticBox(w, {-10.5, 10.0}, 0.5, 10.5);
    addStaticBox(w, {10.5, 10.0}, 0.5, 10.5);
    for (int i = 0; i < 1000; ++i) {
        BodyDef d;
        d.shape = makeCircle(0.25);
        d.position = {-9.0 + 0.6 * (i % 30) + 0.05 * ((i / 30) % 2), 1.0 + 0.6 * (i / 30)};
        w.createBody(d);
    }
}

template <class Build>
void run(benchmark::State& state, Build build) {
    WorldSettings s;
    s.enableSleep = false;  // measure the solver, not sleeping
    World w(s);
    build(w);
    for (int i = 0; i < 60; ++i) w.step(kDt);
    for (auto _ : state) w.step(kDt);
    state.counters["bodies"] = static_cast<double>(w.bodyCount());
    state.counters["substeps"] = s.substeps;
    state.counters["velocity_iterations"] = s.velocityIterations;
    state.counters["relax_iterations"] = s.relaxIterations;
}

void BM_Pyramid(benchmark::State& state) {
    run(state, [&](World& w) { pyramid(w, static_cast<int>(state.range(0))); });
}
BENCHMARK(BM_Pyramid)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond);

void BM_CirclesInBox(benchmark::State& state) { run(state, circlesInBox); }
BENCHMARK(BM_CirclesInBox)->Unit(benchmark::kMillisecond);

}  // namespace
