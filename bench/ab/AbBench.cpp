// Two builds of the core in one process, timed in turns: scripts/ab.sh builds the core of two revisions with their
// namespaces renamed (physim_a, physim_b) and links both here. Each scene runs in a world of each build, a few
// steps of one and then a few of the other, so that whatever the machine does to one does it to the other within
// milliseconds; rounds alternate which world is made first (memory placement). Prints B's time over A's per scene
// and thread count: the geometric mean over rounds, and the spread of one round's ratio. --swap: the build linked
// as physim_b is A (scripts/ab.sh links each revision in both places, since where a copy of the code lands in the
// program alone moves its time by a few percent).
#include "Engine.hpp"
#include "Scenes.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace peers {
// physimEngines (Engine.hpp) of each build, renamed by scripts/ab.sh; declared by its type, so that they follow it.
decltype(physimEngines) physimEngines_a;
decltype(physimEngines) physimEngines_b;
}  // namespace peers

namespace {

struct Options {
    std::vector<std::string> scenes{"pyramid40", "large_pyramid"};
    int steps = 300;   // per world and round; the first kUntimed are not timed
    int rounds = 4;    // worlds made afresh each round
    int turn = 8;      // steps of one world before the other's; the first of each turn is not timed (its caches)
    bool swap = false; // A is the build linked as physim_b
};
constexpr int kUntimed = 100;

[[noreturn]] void usage(const std::string& why) {
    std::cerr << why << "\nusage: ab_bench [--scenes a,b] [--steps n] [--rounds n] [--turn n] [--swap]\n"
              << "  scenes as peer_bench names them; steps > " << kUntimed << " (default 300); rounds >= 1 (4);"
              << " turn >= 2 (8)\n";
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--swap") {
            o.swap = true;
            continue;
        }
        if (i + 1 >= argc) usage(arg + " needs a value");
        const std::string value = argv[++i];
        auto number = [&](int least) {
            const int n = std::atoi(value.c_str());
            if (n < least) usage(arg + " must be at least " + std::to_string(least) + ", got '" + value + "'");
            return n;
        };
        if (arg == "--scenes") {
            o.scenes.clear();
            std::stringstream list(value);
            for (std::string s; std::getline(list, s, ',');) o.scenes.push_back(s);
        } else if (arg == "--steps") {
            o.steps = number(kUntimed + 1);
        } else if (arg == "--rounds") {
            o.rounds = number(1);
        } else if (arg == "--turn") {
            o.turn = number(2);
        } else {
            usage("unknown option " + arg);
        }
    }
    return o;
}

double seconds(peers::EngineRun& run) {
    const auto start = std::chrono::steady_clock::now();
    run.step();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    const Options o = parse(argc, argv);
    std::vector<peers::Engine> a = peers::physimEngines_a({}), b = peers::physimEngines_b({});
    if (o.swap) std::swap(a, b);
    std::printf("| scene | threads | A ms/step | B ms/step | B / A | one round's spread |\n|---|---|---|---|---|---|\n");
    for (const std::string& name : o.scenes) {
        const peers::Scene scene = peers::makeScene(name);
        for (std::size_t e = 0; e < std::min(a.size(), b.size()); ++e) {
            std::vector<double> logRatios;
            double totalA = 0.0, totalB = 0.0;
            int timed = 0;
            for (int round = 0; round < o.rounds; ++round) {
                std::unique_ptr<peers::EngineRun> runA, runB;
                if (round % 2 == 0) {
                    runA = a[e].start(scene);
                    runB = b[e].start(scene);
                } else {
                    runB = b[e].start(scene);
                    runA = a[e].start(scene);
                }
                double roundA = 0.0, roundB = 0.0;
                for (int step = 0; step < o.steps; step += o.turn) {
                    for (int side = 0; side < 2; ++side) {
                        const bool isA = (side == 0) == ((step / o.turn + round) % 2 == 0);
                        for (int k = 0; k < o.turn && step + k < o.steps; ++k) {
                            const double t = seconds(isA ? *runA : *runB);
                            if (step + k < kUntimed || k == 0) continue;
                            (isA ? roundA : roundB) += t;
                            if (isA) ++timed;
                        }
                    }
                }
                logRatios.push_back(std::log(roundB / roundA));
                totalA += roundA;
                totalB += roundB;
            }
            double mean = 0.0, spread = 0.0;
            for (const double r : logRatios) mean += r / static_cast<double>(logRatios.size());
            for (const double r : logRatios) spread += (r - mean) * (r - mean);
            spread = logRatios.size() > 1 ? std::sqrt(spread / static_cast<double>(logRatios.size() - 1)) : 0.0;
            std::printf("| %s | %d | %.4f | %.4f | %.3f | x%.3f |\n", name.c_str(), a[e].threads,
                        1e3 * totalA / timed, 1e3 * totalB / timed, std::exp(mean), std::exp(spread));
        }
    }
    return 0;
}
