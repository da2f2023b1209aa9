// ccd_bench: time per query, share of missed collisions and contact-position error of each collision-detection
// method (discrete, the paper's sampled method at several precisions, exact time of impact) over one fixed
// random set of fast moving pairs. The paper's trade-off (section 5.1.4) made visible. Table in docs/ccd.md.
//
// Batch mode (--batch): the exact method over batches of N = 1e2 .. 1e6 pairs, on the CPU (one thread, all
// threads) and on the GPU (kernel alone, and with the copies), with the CPU-GPU agreement and the crossover N where
// the GPU wins. Table in docs/cuda.md. GPU rows need the `cuda` preset and a GPU; without them the table says why.
//
// Crowd mode (--crowd N): N bullets in the tests' closed 4 m box (tests/support/RandomBatch.hpp), stepped with
// exact continuous detection and, the same scene, with discrete detection, alternately R times in one run (the
// fastest of each is reported: the machines are shared), so their ratio is measured at the same time. Table on stdout; --json FILE writes
// {"bullets", "steps", "exact_ms_per_step", "discrete_ms_per_step", "escaped", "discrete_escaped"} (escaped: the
// exact run's bullets whose centre ends beyond a wall's inner face, i.e. in or through a wall).
//
// Usage: ccd_bench [pairs (default 20000)] [seed (default 5)]
//        ccd_bench --batch [largest N (default 1000000)] [seed (default 5)]
//        ccd_bench --crowd N [--steps S (default 60)] [--seed K (default 5)] [--repeats R (default 5)]
//                  [--json FILE]

#include "physim/core/Collide.hpp"
#include "physim/core/ContinuousBatch.hpp"
#include "physim/core/TimeOfImpact.hpp"
#include "physim/core/StepProfile.hpp"
#include "physim/core/World.hpp"
#ifdef PHYSIM_WITH_CUDA
#include "physim/cuda/ContinuousSolver.hpp"
#include "physim/cuda/Device.hpp"
#endif

#include "support/RandomBatch.hpp"  // the tests' fast pairs: one generator for the tests and this table

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <vector>

using namespace physim;

namespace {

using Pair = testing::FastPair;

struct Method {
    std::string name;
    int kind;  // 0 discrete, 1 sampled, 2 exact
    double precision;
};

ToiResult run(const Method& m, const Pair& p) {
    if (m.kind == 0) {  // the paper's discrete test: only the end position
        ToiResult r;
        if (collide(p.a, p.sa.at(1.0), p.b, p.sb.at(1.0)).pointCount > 0) r.state = ToiState::Hit;
        r.iterations = 1;
        return r;
    }
    if (m.kind == 1) return sampledTimeOfImpact(p.a, p.sa, p.b, p.sb, m.precision);
    return timeOfImpact(p.a, p.sa, p.b, p.sb);
}

// Best wall time (s) of `reps` calls (a shared machine: the minimum is the least disturbed).
template <typename F>
double bestOf(int reps, F&& f) {
    double best = 1e300;
    for (int r = 0; r < reps; ++r) {
        const auto start = std::chrono::steady_clock::now();
        f();
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return best;
}

// The first n pairs of one fixed stream (built in chunks so a million pairs never exist as Geometry at once).
ContinuousBatch batchOf(int n, unsigned seed) {
    ContinuousBatch batch;
    for (int done = 0, chunk = 0; done < n; ++chunk) {
        const int take = std::min(10000, n - done);
        for (const Pair& p : testing::randomPairs(take, seed + 7919u * static_cast<unsigned>(chunk)))
            testing::appendPair(batch, p);
        done += take;
    }
    return batch;
}

// Times a solver and counts what it is given (the World's Continuous stage hands it each step's batch).
class TimedSolver final : public ContinuousSolver {
public:
    explicit TimedSolver(std::shared_ptr<ContinuousSolver> inner) : inner_(std::move(inner)) {}
    void solve(const ContinuousBatch& batch, ContinuousBatchResult& result) override {
        const auto start = std::chrono::steady_clock::now();
        inner_->solve(batch, result);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        pairs += batch.pairCount();
    }
    std::string name() const override { return inner_->name(); }
    double seconds = 0.0;
    std::size_t pairs = 0;

private:
    std::shared_ptr<ContinuousSolver> inner_;
};

// Bullets in a box (the tests' scene) stepped with each solver: what the batch is worth inside a World, whose
// Continuous stage batches the exact pairs once per step (pairs whose bounding circles stay apart never enter it).
void worldTable([[maybe_unused]] const std::string& noGpu) {
    std::printf("\nWorld: exact-continuous bullets in a closed 4 m box (tests/support/RandomBatch.hpp), 30 steps at "
                "60 Hz\n\n| bullets | solver | ms per step | continuous stage ms per step | in the "
                "batch solver ms per step | batch pairs per step |\n| ---: | --- | ---: | ---: | ---: | ---: |\n");
    std::vector<std::shared_ptr<ContinuousSolver>> solvers{std::make_shared<CpuContinuousSolver>(1)};
#ifdef PHYSIM_WITH_CUDA
    if (noGpu.empty()) {
        cuda::GpuSolverOptions options;
        options.minPairs = 0;
        solvers.push_back(std::make_shared<cuda::GpuContinuousSolver>(options));
    }
#endif
    for (const int bullets : {50, 200}) {
        for (const auto& inner : solvers) {
            WorldSettings settings;
            settings.gravity = Vec2::Zero();
            World world(settings);
            testing::fillBulletBox(world, bullets, 7);
            auto timed = std::make_shared<TimedSolver>(inner);
            world.setContinuousSolver(timed);
            const int steps = 30;
            double stage = 0.0;
            const auto start = std::chrono::steady_clock::now();
            for (int i = 0; i < steps; ++i) {
                world.step(1.0 / 60.0);
                stage += world.profile().secondsOf(Stage::Continuous);
            }
            const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            std::printf("| %d | %s | %.2f | %.2f | %.3f | %.0f |\n", bullets, inner->name().c_str(), 1e3 * total / steps,
                        1e3 * stage / steps, 1e3 * timed->seconds / steps,
                        static_cast<double>(timed->pairs) / steps);
        }
    }
}

int batchTable(int largest, unsigned seed) {
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    CpuContinuousSolver single(1), all(cores);
    std::string noGpu;
#ifdef PHYSIM_WITH_CUDA
    const cuda::DeviceStatus status = cuda::queryDevices();
    if (status.deviceCount == 0) noGpu = status.message;
    cuda::GpuSolverOptions options;
    options.minPairs = 0;  // every batch on the GPU: this table is where the crossover is measured
    cuda::GpuContinuousSolver gpu(options);
    std::printf("GPU: %s\n", status.deviceCount ? status.message.c_str() : "none");
#else
    noGpu = "this ccd_bench was built without CUDA (configure the `cuda` preset)";
#endif
    std::printf("CPU: %u hardware threads. Exact method (conservative advancement, tolerance %.0e m), random fast "
                "pairs (seed %u), each body its own shape, as the World sends them.\n\n",
                cores, kToiTolerance, seed);
    std::printf("| pairs | CPU 1 thread (ms) | CPU %u threads (ms) | GPU kernel (ms) | GPU with copies (ms) | GPU, "
                "shapes kept on the device (ms) | pairs/s CPU 1 | pairs/s CPU %u | pairs/s GPU with copies | GPU with "
                "copies vs CPU %u | identical | within tolerance | disagreements |\n",
                cores, cores, cores);
    std::printf("| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    long crossoverSingle = -1, crossoverAll = -1;
    for (long n = 100; n <= largest; n *= 10) {
        ContinuousBatch batch = batchOf(static_cast<int>(n), seed);
        ContinuousBatchResult cpu, cpuAll;
        // Repeat small batches so each timing spans at least ~0.2 s of work at ~1 us a pair.
        const int reps = static_cast<int>(std::clamp(200000L / n, 3L, 200L));
        const double tSingle = bestOf(reps, [&] { single.solve(batch, cpu); });
        const double tAll = bestOf(reps, [&] { all.solve(batch, cpuAll); });
        std::printf("| %ld | %.3f | %.3f |", n, 1e3 * tSingle, 1e3 * tAll);
        if (!noGpu.empty()) {
            std::printf(" - | - | - | %.3g | %.3g | - | - | - | - | - |\n", n / tSingle, n / tAll);
            continue;
        }
#ifdef PHYSIM_WITH_CUDA
        ContinuousBatchResult onGpu;
        gpu.solve(batch, onGpu);  // warm: device buffers grown, kernel loaded
        double kernelMs = 1e300, bestTotal = 1e300;
        cuda::GpuTimings best;  // the fastest run's parts
        const double tGpu = bestOf(reps, [&] {
            gpu.solve(batch, onGpu);
            kernelMs = std::min(kernelMs, gpu.lastTimings().kernelMs);
            if (gpu.lastTimings().totalMs < bestTotal) best = gpu.lastTimings(), bestTotal = best.totalMs;
        });
        if (!gpu.lastRanOnGpu()) {
            std::printf(" GPU failed: %s |\n", gpu.error().c_str());
            return 1;
        }
        const std::vector<double> gpuT = onGpu.t;
        const testing::Agreement a = testing::compareResults(batch, onGpu, cpu);
        // The same batch with its shapes kept on the device (a World's shapes do not change between steps).
        batch.shapesRevision = 1;
        gpu.solve(batch, onGpu);  // copies the shapes once
        const double tResident = bestOf(reps, [&] { gpu.solve(batch, onGpu); });
        const bool residentSame = onGpu.t == gpuT;
        batch.shapesRevision = 0;
        std::printf(" %.3f | %.3f (in %.3f, out %.3f) | %.3f%s | %.3g | %.3g | %.3g | %.1fx | %d | %d | %d |\n",
                    kernelMs, 1e3 * tGpu, best.uploadMs, best.downloadMs, 1e3 * tResident,
                    residentSame ? "" : " (DIFFERENT RESULTS)", n / tSingle, n / tAll, n / tGpu, tAll / tGpu,
                    a.identical, a.within, a.disagree);
        if (crossoverSingle < 0 && tGpu < tSingle) crossoverSingle = n;
        if (crossoverAll < 0 && tGpu < tAll) crossoverAll = n;
#endif
    }
    worldTable(noGpu);
    if (!noGpu.empty()) {
        std::printf("\nGPU rows missing: %s.\n", noGpu.c_str());
        return 0;
    }
    auto say = [](long n) { return n < 0 ? std::string("not reached") : "N = " + std::to_string(n); };
    std::printf("\nCrossover (first N where the GPU with copies is faster): against 1 CPU thread %s, against %u "
                "threads %s.\n",
                say(crossoverSingle).c_str(), cores, say(crossoverAll).c_str());
    return 0;
}

struct CrowdRun {
    double msPerStep = 0.0;
    int escaped = 0;  // centre beyond a wall's inner face at the end
    std::array<double, StepProfile::stageCount> stageMs{};  // per step, from World::profile()
};

CrowdRun runCrowd(int bullets, unsigned seed, int steps, CollisionDetection mode) {
    WorldSettings settings;
    settings.gravity = Vec2::Zero();
    World world(settings);
    const std::vector<BodyId> ids = testing::fillBulletBox(world, bullets, seed);
    for (const BodyId id : ids) world.setCollisionDetection(id, mode);
    const auto start = std::chrono::steady_clock::now();
    CrowdRun run;
    for (int i = 0; i < steps; ++i) {
        world.step(1.0 / 60.0);
        for (std::size_t k = 0; k < StepProfile::stageCount; ++k)
            run.stageMs[k] += 1e3 * world.profile().seconds[k] / steps;
    }
    run.msPerStep = 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / steps;
    for (const BodyId id : ids)
        if (world.position(id).cwiseAbs().maxCoeff() >= testing::kBulletBoxInner) ++run.escaped;
    return run;
}

[[noreturn]] void usageError(const std::string& what) {
    std::fprintf(stderr, "ccd_bench: %s\nusage: ccd_bench --crowd N [--steps S] [--seed K] [--repeats R] [--json FILE]\n",
                 what.c_str());
    std::exit(2);
}

// A whole positive integer no larger than `most`, or a usage error naming the option and the value.
int positiveArgument(const std::string& option, const std::string& text, int most) {
    char* end = nullptr;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || value < 1 || value > most)
        usageError(option + " takes a whole number from 1 to " + std::to_string(most) + ", got '" + text + "'");
    return static_cast<int>(value);
}

int crowdMain(int argc, char** argv) {
    int bullets = 0, steps = 60, repeats = 5;
    unsigned seed = 5u;
    std::optional<std::string> json;
    for (int i = 1; i < argc; ++i) {
        const std::string option = argv[i];
        if (option != "--crowd" && option != "--steps" && option != "--seed" && option != "--repeats" &&
            option != "--json")
            usageError("unknown argument '" + option + "'");
        if (i + 1 >= argc) usageError(option + " needs a value");
        const std::string value = argv[++i];
        if (option == "--crowd") bullets = positiveArgument(option, value, 100000);
        if (option == "--steps") steps = positiveArgument(option, value, 100000);
        if (option == "--repeats") repeats = positiveArgument(option, value, 1000);
        if (option == "--seed") seed = static_cast<unsigned>(positiveArgument(option, value, 1 << 30));
        if (option == "--json") json = value;
    }
    if (bullets == 0) usageError("--crowd N is required");
    CrowdRun exact, discrete;
    for (int r = 0; r < repeats; ++r) {  // alternately, keeping each mode's fastest run (the same scene each time)
        const CrowdRun e = runCrowd(bullets, seed, steps, CollisionDetection::ContinuousExact);
        const CrowdRun d = runCrowd(bullets, seed, steps, CollisionDetection::Discrete);
        if (r == 0 || e.msPerStep < exact.msPerStep) exact = e;
        if (r == 0 || d.msPerStep < discrete.msPerStep) discrete = d;
    }
    std::printf("%d bullets (150 to 600 m/s) in a closed 4 m box, seed %u, %d steps at 60 Hz, fastest of %d runs "
                "each\n\n",
                bullets, seed, steps, repeats);
    std::printf("| detection | ms per step | escaped (centre beyond a wall's inner face at the end) |\n");
    std::printf("| --- | ---: | ---: |\n");
    std::printf("| exact continuous | %.2f | %d |\n", exact.msPerStep, exact.escaped);
    std::printf("| discrete | %.2f | %d |\n", discrete.msPerStep, discrete.escaped);
    std::printf("\nexact / discrete: %.1fx\n\nWhere a step's time goes (ms per step, World::profile()):\n\n"
                "| stage | exact | discrete |\n| --- | ---: | ---: |\n",
                exact.msPerStep / discrete.msPerStep);
    for (std::size_t k = 0; k < StepProfile::stageCount; ++k)
        std::printf("| %s | %.2f | %.2f |\n", std::string(stageName(static_cast<Stage>(k))).c_str(), exact.stageMs[k],
                    discrete.stageMs[k]);
    if (json) {
        std::ofstream out(*json);
        out << "{\"bullets\": " << bullets << ", \"steps\": " << steps
            << ", \"exact_ms_per_step\": " << exact.msPerStep << ", \"discrete_ms_per_step\": " << discrete.msPerStep
            << ", \"escaped\": " << exact.escaped << ", \"discrete_escaped\": " << discrete.escaped << "}\n";
        if (!out) {
            std::fprintf(stderr, "ccd_bench: cannot write '%s'\n", json->c_str());
            return 1;
        }
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc > 1 && std::string(argv[1]).rfind("--", 0) == 0 && std::string(argv[1]) != "--batch")
        return crowdMain(argc, argv);
    if (argc > 1 && std::string(argv[1]) == "--batch")
        return batchTable(argc > 2 ? std::atoi(argv[2]) : 1000000,
                          argc > 3 ? static_cast<unsigned>(std::atoi(argv[3])) : 5u);
    const int count = argc > 1 ? std::atoi(argv[1]) : 20000;
    const unsigned seed = argc > 2 ? static_cast<unsigned>(std::atoi(argv[2])) : 5u;
    const std::vector<Pair> pairs = testing::randomPairs(count, seed);

    // Reference: conservative advancement to 1e-9 m with a generous iteration budget. It never passes a
    // contact, so a pair it calls separated does not collide and its time is the true contact time to 1e-9 m.
    std::vector<ToiResult> truth;
    int colliding = 0, unsettled = 0;
    for (const Pair& p : pairs) {
        truth.push_back(timeOfImpact(p.a, p.sa, p.b, p.sb, 1e-9, 100000));
        if (truth.back().state == ToiState::Hit) ++colliding;
        if (truth.back().state == ToiState::Failed) ++unsettled;
    }

    std::vector<Method> methods{{"discrete (end position)", 0, 1.0}};
    for (const double precision : {1.0, 0.5, 0.25, 0.1, 0.05, 0.01})
        methods.push_back({"sampled, precision " + std::to_string(precision).substr(0, 4), 1, precision});
    methods.push_back({"exact (CA, 1e-4 m)", 2, 0.0});

    std::printf("%d pairs (seed %u), %d collide (reference: conservative advancement to 1e-9 m; %d it could not "
                "settle)\n\n",
                static_cast<int>(pairs.size()), seed, colliding, unsettled);
    std::printf("| method | ns per query | shape tests per query | missed collisions | false hits (near misses) | "
                "failed (no answer) | contact position error, mean (m) | max (m) |\n");
    std::printf("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (const Method& m : methods) {
        // Accuracy.
        int missed = 0, falseHits = 0, failed = 0, found = 0;
        double errorSum = 0.0, errorMax = 0.0, tests = 0.0;
        for (std::size_t i = 0; i < pairs.size(); ++i) {
            const ToiResult r = run(m, pairs[i]);
            tests += r.iterations;
            failed += r.state == ToiState::Failed;  // no impact found: counted as a miss where there is one
            const bool hit = r.state == ToiState::Hit || r.state == ToiState::Touching;
            const bool real = truth[i].state == ToiState::Hit;
            if (real && !hit) ++missed;
            if (!real && hit) ++falseHits;
            if (real && hit) {
                // Discrete has no time: it reports the end position.
                const double t = m.kind == 0 ? 1.0 : r.t;
                const double e = (pairs[i].sa.at(t).p - pairs[i].sa.at(truth[i].t).p).norm();
                errorSum += e;
                errorMax = std::max(errorMax, e);
                ++found;
            }
        }
        // Time: best of 5 passes over the whole set (a shared machine: the minimum is the least disturbed).
        double best = 1e300;
        volatile double sink = 0.0;
        for (int rep = 0; rep < 5; ++rep) {
            const auto start = std::chrono::steady_clock::now();
            for (const Pair& p : pairs) sink = sink + run(m, p).t;
            const std::chrono::duration<double> s = std::chrono::steady_clock::now() - start;
            best = std::min(best, s.count());
        }
        std::printf("| %s | %.0f | %.1f | %.1f%% | %d | %d | %.2e | %.2e |\n", m.name.c_str(),
                    1e9 * best / pairs.size(), tests / pairs.size(), 100.0 * missed / colliding, falseHits, failed,
                    found ? errorSum / found : 0.0, errorMax);
    }
    return 0;
}
