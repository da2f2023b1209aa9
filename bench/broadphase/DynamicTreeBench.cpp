// The dynamic AABB tree as a broad phase for scenes where few bodies move, and the World's BroadPhase built on
// it, against brute force and Box2D 2.4.1's tree on the same boxes.
//
// Scene: n unrotated boxes 0.2 to 0.8 m a side at about one per 2 m^2 (each overlaps a few others whatever n),
// 1 in 10 static. Each step 10% of the boxes move, each by 0.2 to 0.5 m per axis (back and forth, so the density
// stays), far enough to leave an enlarged box of margin 0.1 m. Timed per step:
//   tree: for each moved box, moveProxy with its box enlarged by the margin, then a query of that box in
//     the dynamic tree and the static tree; the pairs found (those of moved boxes: the new candidates) sorted
//     and deduplicated. This is what a broad phase that tracks only what moves does.
//   broadphase: the same moves given to BroadPhase::moveProxy (static boxes in its static tree), then
//     findNewPairs on a 1-thread Executor: the World's broad phase. Before timing, one step's pairs are checked
//     against brute force over the enlarged boxes (every pair with a moved box).
//   brute: the same moves, then all n^2/2 pairs of boxes tested.
// Build: n createProxy calls into an empty tree; rebuild(): the binned top-down rebuild of the same tree.
// Query: each of the n enlarged boxes queried in the built tree (the cost of a query, from the tree's quality).
// Patterns: insertion-order cases for the tree's height (a row left to right, a column, a grid in raster order,
// identical boxes, boxes nested in one another), with the height and area ratio reached.
// With Box2D 2.4.1 (Debian libbox2d-dev) found at configure time, its b2DynamicTree runs the same build and
// tree step, for reference (it holds the same enlarged boxes, in float).
// Run: build/<dir>/bench/broadphase/broadphase_bench (docs/collision.md, "Dynamic tree", has the table).

#include "BroadPhase.hpp"
#include "DynamicTree.hpp"
#include "Executor.hpp"

#include <benchmark/benchmark.h>

#ifdef PHYSIM_BENCH_BOX2D
#include <box2d/b2_dynamic_tree.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace physim {
namespace {

constexpr double kMargin = 0.1;    // m, how much the trees' boxes are enlarged
constexpr std::size_t kMovedPerStep = 10;  // one box in this many moves each step

// One box of the scene: where it is and the jump it makes when it moves.
struct Box {
    Aabb aabb;            // m, unrotated: the box the trees hold, before enlarging
    Vec2 jump;            // m, added or subtracted on each move
    bool movable = true;  // false: static, never moves
};

struct Scene {
    std::vector<Box> bodies;
    std::vector<std::uint32_t> dynamic;  // indices of the movable boxes
    std::size_t step = 0;

    explicit Scene(std::size_t n) : bodies(n) {
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        const double side = std::sqrt(2.0 * static_cast<double>(n));
        for (std::uint32_t i = 0; i < n; ++i) {
            Box& b = bodies[i];
            b.movable = i % 10 != 0;
            const double hx = 0.1 + 0.3 * u(rng), hy = 0.1 + 0.3 * u(rng);  // half sides
            const double x = side * u(rng), y = side * u(rng);
            b.aabb = {Vec2(x - hx, y - hy), Vec2(x + hx, y + hy)};
            const auto component = [&] { return (u(rng) < 0.5 ? -1.0 : 1.0) * (0.2 + 0.3 * u(rng)); };
            const double jx = component(), jy = component();
            b.jump = Vec2(jx, jy);
            if (b.movable) dynamic.push_back(i);
        }
    }

    // Moves this step's tenth of the dynamic bodies (a window that walks through them, each pass the other
    // way) and calls moved(body) for each, with its box refreshed.
    template <class Moved>
    void advance(Moved&& moved) {
        const std::size_t count = bodies.size() / kMovedPerStep;
        for (std::size_t j = 0; j < count; ++j) {
            const std::size_t k = step * count + j;
            const std::uint32_t i = dynamic[k % dynamic.size()];
            Aabb& box = bodies[i].aabb;
            const Vec2 delta = ((k / dynamic.size()) % 2 ? -1.0 : 1.0) * bodies[i].jump;
            box = {box.lower + delta, box.upper + delta};
            moved(i);
        }
        ++step;
    }
};

// A dynamic tree and a static tree over the scene's boxes, enlarged by the margin.
struct Trees {
    DynamicTree moving, fixed;
    std::vector<std::int32_t> proxy;  // by body

    explicit Trees(const Scene& s) : proxy(s.bodies.size()) {
        for (std::uint32_t i = 0; i < s.bodies.size(); ++i) {
            const Box& b = s.bodies[i];
            proxy[i] = (b.movable ? moving : fixed).createProxy(b.aabb.fattened(kMargin), i);
        }
    }
    // A body's proxy follows only when its box leaves the enlarged one.
    void update(const Box& b, std::uint32_t i) {
        if (!moving.fatAabb(proxy[i]).contains(b.aabb)) moving.moveProxy(proxy[i], b.aabb.fattened(kMargin));
    }
};

void finishPairs(std::vector<ShapePair>& pairs) {
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
}

void BM_TreeStep(benchmark::State& state) {
    Scene scene(static_cast<std::size_t>(state.range(0)));
    Trees trees(scene);
    std::vector<ShapePair> pairs;
    std::vector<std::uint32_t> moved;
    std::size_t reinserted = 0;
    for (auto _ : state) {
        moved.clear();
        pairs.clear();
        scene.advance([&](std::uint32_t i) {
            const bool escaped = !trees.moving.fatAabb(trees.proxy[i]).contains(scene.bodies[i].aabb);
            reinserted += escaped;
            trees.update(scene.bodies[i], i);
            moved.push_back(i);
        });
        for (const std::uint32_t i : moved) {
            const Aabb& box = trees.moving.fatAabb(trees.proxy[i]);
            const auto add = [&](std::int32_t, std::uint32_t other) {
                if (other != i) pairs.emplace_back(std::min(i, other), std::max(i, other));
            };
            trees.moving.query(box, add);
            trees.fixed.query(box, add);
        }
        finishPairs(pairs);  // two moved boxes find each other twice
        benchmark::DoNotOptimize(pairs.data());
    }
    state.counters["pairs"] = static_cast<double>(pairs.size());
    state.counters["moved"] = static_cast<double>(moved.size());
    state.counters["reinserted"] = static_cast<double>(reinserted) / static_cast<double>(state.iterations());
    state.counters["height"] = trees.moving.height();
    state.counters["area_ratio"] = trees.moving.areaRatio();
    trees.moving.rebuild();
    state.counters["area_ratio_rebuilt"] = trees.moving.areaRatio();
}
BENCHMARK(BM_TreeStep)->Arg(5000)->Arg(20000)->Unit(benchmark::kMicrosecond);

// The pairs of the boxes in `moved` (each flagged in isMoved) with every other box, from their enlarged boxes by
// brute force, each once, sorted: what findNewPairs must return. Static boxes never move, so no pair is static.
std::vector<ShapePair> bruteNewPairs(const std::vector<Aabb>& fat, const std::vector<std::uint32_t>& moved,
                                    const std::vector<std::uint8_t>& isMoved) {
    std::vector<ShapePair> pairs;
    for (const std::uint32_t i : moved)
        for (std::uint32_t j = 0; j < fat.size(); ++j)
            if (j != i && !(isMoved[j] && j < i) && fat[i].overlaps(fat[j]))
                pairs.emplace_back(std::min(i, j), std::max(i, j));
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

void BM_BroadPhaseStep(benchmark::State& state) {
    Scene scene(static_cast<std::size_t>(state.range(0)));
    BroadPhase broadPhase;
    Executor executor(1);
    std::vector<std::int32_t> proxy(scene.bodies.size());
    std::vector<Aabb> fat(scene.bodies.size());  // the enlarged boxes, kept apart for the check
    for (std::uint32_t i = 0; i < scene.bodies.size(); ++i) {
        fat[i] = scene.bodies[i].aabb.fattened(kMargin);
        proxy[i] = broadPhase.createProxy(fat[i], i, !scene.bodies[i].movable);
    }
    std::vector<ShapePair> pairs;
    const PairSet noContacts;  // every overlapping pair counts as new, as brute force reports it
    const auto takeAll = [](std::uint32_t, std::uint32_t) { return true; };
    broadPhase.findNewPairs(pairs, noContacts, takeAll, executor);  // the first step: every proxy is new
    std::vector<std::uint32_t> moved;
    std::size_t reinserted = 0;
    const auto step = [&] {
        moved.clear();
        scene.advance([&](std::uint32_t i) {
            if (broadPhase.fatBox(proxy[i]).contains(scene.bodies[i].aabb)) return;
            fat[i] = scene.bodies[i].aabb.fattened(kMargin);
            broadPhase.moveProxy(proxy[i], fat[i]);
            moved.push_back(i);
        });
        broadPhase.findNewPairs(pairs, noContacts, takeAll, executor);
    };

    step();  // untimed, checked
    std::vector<std::uint8_t> isMoved(scene.bodies.size(), 0);
    for (const std::uint32_t i : moved) isMoved[i] = 1;
    if (pairs != bruteNewPairs(fat, moved, isMoved)) {
        state.SkipWithError("findNewPairs differs from brute force over the enlarged boxes");
        return;
    }
    for (auto _ : state) {
        step();
        reinserted += moved.size();
        benchmark::DoNotOptimize(pairs.data());
    }
    state.counters["pairs"] = static_cast<double>(pairs.size());
    state.counters["reinserted"] = static_cast<double>(reinserted) / static_cast<double>(state.iterations());
}
BENCHMARK(BM_BroadPhaseStep)->Arg(5000)->Arg(20000)->Unit(benchmark::kMicrosecond);

void BM_BruteStep(benchmark::State& state) {
    Scene scene(static_cast<std::size_t>(state.range(0)));
    std::vector<ShapePair> pairs;
    const std::vector<Box>& bodies = scene.bodies;
    for (auto _ : state) {
        pairs.clear();
        scene.advance([](std::uint32_t) {});
        for (std::uint32_t i = 0; i < bodies.size(); ++i)
            for (std::uint32_t j = i + 1; j < bodies.size(); ++j)
                if ((bodies[i].movable || bodies[j].movable) && bodies[i].aabb.overlaps(bodies[j].aabb))
                    pairs.emplace_back(i, j);
        benchmark::DoNotOptimize(pairs.data());
    }
    state.counters["pairs"] = static_cast<double>(pairs.size());
}
BENCHMARK(BM_BruteStep)->Arg(5000)->Arg(20000)->Unit(benchmark::kMillisecond);

void BM_TreeBuild(benchmark::State& state) {
    const Scene scene(static_cast<std::size_t>(state.range(0)));
    DynamicTree tree;
    for (auto _ : state) {
        tree.clear();
        for (std::uint32_t i = 0; i < scene.bodies.size(); ++i)
            tree.createProxy(scene.bodies[i].aabb.fattened(kMargin), i);
        benchmark::DoNotOptimize(tree.root());
    }
    state.counters["height"] = tree.height();
    state.counters["area_ratio"] = tree.areaRatio();
}
BENCHMARK(BM_TreeBuild)->Arg(5000)->Arg(20000)->Unit(benchmark::kMicrosecond);

void BM_TreeQuery(benchmark::State& state) {
    const Scene scene(static_cast<std::size_t>(state.range(0)));
    DynamicTree tree;
    for (std::uint32_t i = 0; i < scene.bodies.size(); ++i) tree.createProxy(scene.bodies[i].aabb.fattened(kMargin), i);
    std::size_t hits = 0;
    for (auto _ : state) {
        for (const Box& b : scene.bodies) tree.query(b.aabb.fattened(kMargin), [&](std::int32_t, std::uint32_t) { ++hits; });
        benchmark::DoNotOptimize(hits);
    }
    state.counters["hits_per_query"] = static_cast<double>(hits) / static_cast<double>(state.iterations() * scene.bodies.size());
}
BENCHMARK(BM_TreeQuery)->Arg(5000)->Arg(20000)->Unit(benchmark::kMicrosecond);

void BM_TreeRebuild(benchmark::State& state) {
    const Scene scene(static_cast<std::size_t>(state.range(0)));
    DynamicTree tree;
    for (std::uint32_t i = 0; i < scene.bodies.size(); ++i) tree.createProxy(scene.bodies[i].aabb.fattened(kMargin), i);
    for (auto _ : state) {
        tree.rebuild();
        benchmark::DoNotOptimize(tree.root());
    }
    state.counters["height"] = tree.height();
    state.counters["area_ratio"] = tree.areaRatio();
}
BENCHMARK(BM_TreeRebuild)->Arg(5000)->Arg(20000)->Unit(benchmark::kMicrosecond);

// Insertion orders that unbalance trees built without care. Each yields n boxes; the tree's height and area
// ratio are reported.
enum class Pattern { Row, Column, Raster, Identical, Nested };

std::vector<Aabb> patternBoxes(Pattern pattern, std::size_t n) {
    std::vector<Aabb> boxes;
    const std::size_t perRow = static_cast<std::size_t>(std::sqrt(static_cast<double>(n)));
    for (std::size_t k = 0; k < n; ++k) {
        const double i = static_cast<double>(k);
        const double x = static_cast<double>(k % perRow), y = static_cast<double>(k / perRow);
        switch (pattern) {
            case Pattern::Row: boxes.push_back({Vec2(i, 0.0), Vec2(i + 1.0, 1.0)}); break;  // touching
            case Pattern::Column: boxes.push_back({Vec2(0.0, 1.1 * i), Vec2(1.0, 1.1 * i + 1.0)}); break;
            case Pattern::Raster: boxes.push_back({Vec2(x, y), Vec2(x + 0.9, y + 0.9)}); break;
            case Pattern::Identical: boxes.push_back({Vec2(3.0, 4.0), Vec2(3.5, 4.5)}); break;
            case Pattern::Nested: boxes.push_back({Vec2(-i, -i), Vec2(i + 1.0, i + 1.0)}); break;
        }
    }
    return boxes;
}

void BM_TreePattern(benchmark::State& state, Pattern pattern) {
    const std::vector<Aabb> boxes = patternBoxes(pattern, static_cast<std::size_t>(state.range(0)));
    DynamicTree tree;
    for (auto _ : state) {
        tree.clear();
        for (std::uint32_t i = 0; i < boxes.size(); ++i) tree.createProxy(boxes[i], i);
        benchmark::DoNotOptimize(tree.root());
    }
    state.counters["height"] = tree.height();
    state.counters["height_per_log2n"] = tree.height() / std::log2(static_cast<double>(boxes.size()));
    state.counters["area_ratio"] = tree.areaRatio();
    tree.rebuild();
    state.counters["height_rebuilt"] = tree.height();
    state.counters["area_ratio_rebuilt"] = tree.areaRatio();
}
BENCHMARK_CAPTURE(BM_TreePattern, row, Pattern::Row)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_TreePattern, column, Pattern::Column)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_TreePattern, raster, Pattern::Raster)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_TreePattern, identical, Pattern::Identical)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_TreePattern, nested, Pattern::Nested)->Arg(1000)->Unit(benchmark::kMicrosecond);

#ifdef PHYSIM_BENCH_BOX2D
// Box2D 2.4.1 enlarges the tight boxes it is given by b2_aabbExtension (0.1 m, the same as kMargin); with zero
// displacement it adds no prediction, so both trees hold the same boxes.
b2AABB toBox2D(const Aabb& b) {
    b2AABB out;
    out.lowerBound.Set(static_cast<float>(b.lower.x()), static_cast<float>(b.lower.y()));
    out.upperBound.Set(static_cast<float>(b.upper.x()), static_cast<float>(b.upper.y()));
    return out;
}

struct Box2DTrees {
    b2DynamicTree moving, fixed;
    std::vector<std::int32_t> proxy;
    explicit Box2DTrees(const Scene& s) : proxy(s.bodies.size()) {
        for (std::uint32_t i = 0; i < s.bodies.size(); ++i) {
            void* data = reinterpret_cast<void*>(static_cast<std::uintptr_t>(i));
            proxy[i] = (s.bodies[i].movable ? moving : fixed).CreateProxy(toBox2D(s.bodies[i].aabb), data);
        }
    }
};

// b2DynamicTree::Query's callback: collects the pairs of one moved body.
struct Box2DPairs {
    const b2DynamicTree* tree;
    std::uint32_t self;
    std::vector<ShapePair>* pairs;
    bool QueryCallback(std::int32_t proxy) {
        const auto other = static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(tree->GetUserData(proxy)));
        if (other != self) pairs->emplace_back(std::min(self, other), std::max(self, other));
        return true;
    }
};

void BM_Box2DStep(benchmark::State& state) {
    Scene scene(static_cast<std::size_t>(state.range(0)));
    Box2DTrees trees(scene);
    std::vector<ShapePair> pairs;
    std::vector<std::uint32_t> moved;
    for (auto _ : state) {
        moved.clear();
        pairs.clear();
        scene.advance([&](std::uint32_t i) {
            trees.moving.MoveProxy(trees.proxy[i], toBox2D(scene.bodies[i].aabb), b2Vec2(0.0f, 0.0f));
            moved.push_back(i);
        });
        for (const std::uint32_t i : moved) {
            const b2AABB box = trees.moving.GetFatAABB(trees.proxy[i]);
            Box2DPairs movingPairs{&trees.moving, i, &pairs}, fixedPairs{&trees.fixed, i, &pairs};
            trees.moving.Query(&movingPairs, box);
            trees.fixed.Query(&fixedPairs, box);
        }
        finishPairs(pairs);
        benchmark::DoNotOptimize(pairs.data());
    }
    state.counters["pairs"] = static_cast<double>(pairs.size());
    state.counters["height"] = trees.moving.GetHeight();
}
BENCHMARK(BM_Box2DStep)->Arg(5000)->Arg(20000)->Unit(benchmark::kMicrosecond);

void BM_Box2DBuild(benchmark::State& state) {
    const Scene scene(static_cast<std::size_t>(state.range(0)));
    for (auto _ : state) {
        b2DynamicTree tree;
        for (std::uint32_t i = 0; i < scene.bodies.size(); ++i)
            tree.CreateProxy(toBox2D(scene.bodies[i].aabb), reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
        benchmark::DoNotOptimize(tree.GetFatAABB(0));
    }
}
BENCHMARK(BM_Box2DBuild)->Arg(5000)->Arg(20000)->Unit(benchmark::kMicrosecond);

struct Box2DCount {
    std::size_t hits = 0;
    bool QueryCallback(std::int32_t) {
        ++hits;
        return true;
    }
};

void BM_Box2DQuery(benchmark::State& state) {
    const Scene scene(static_cast<std::size_t>(state.range(0)));
    b2DynamicTree tree;
    for (std::uint32_t i = 0; i < scene.bodies.size(); ++i)
        tree.CreateProxy(toBox2D(scene.bodies[i].aabb), reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
    Box2DCount count;
    for (auto _ : state) {
        for (const Box& b : scene.bodies) tree.Query(&count, toBox2D(b.aabb.fattened(kMargin)));
        benchmark::DoNotOptimize(count.hits);
    }
    state.counters["hits_per_query"] = static_cast<double>(count.hits) / static_cast<double>(state.iterations() * scene.bodies.size());
}
BENCHMARK(BM_Box2DQuery)->Arg(5000)->Arg(20000)->Unit(benchmark::kMicrosecond);
#endif

}  // namespace
}  // namespace physim
