// energy_sweep: runs the energy tests' scenes (tests/support) over a range of random starts and prints, per scene,
// the starts whose kinetic energy rose above the start by more than 1e-6 (relative) in some step, and for the
// elastic gas those that kept under 99% of it after 60 s. The tests check chosen starts; this is the wide view.
//
// usage: energy_sweep [--gas FIRST LAST] [--bullets COUNT FIRST LAST]...
//   default: --gas 1 600 --bullets 1 1 20000 --bullets 2 1 20000 --bullets 3 1 10000

#include "support/RandomBatch.hpp"
#include "support/Scenes.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

struct Range {
    int bullets = 0;  // 0: the elastic gas
    unsigned first = 1, last = 1;
};

void sweepGas(unsigned first, unsigned last) {
    int rose = 0, lost = 0;
    double worst = 0.0;
    for (unsigned seed = first; seed <= last; ++seed) {
        const physim::test::GasRun r = physim::test::runElasticGas(seed, 60 * 60);
        const bool rises = r.rise > 1e-6, loses = r.kept < 0.99;
        if (rises || loses) std::printf("  gas seed %u: rise %.3g, kept %.4f\n", seed, r.rise, r.kept);
        rose += rises ? 1 : 0;
        lost += loses ? 1 : 0;
        worst = std::max(worst, r.rise);
    }
    std::printf("| elastic gas, 60 s | %u to %u | %d | %.3g | %d |\n", first, last, rose, worst, lost);
}

void sweepBullets(int bullets, unsigned first, unsigned last) {
    int rose = 0;
    for (unsigned seed = first; seed <= last; ++seed) {
        const int step = physim::testing::firstEnergyGain(bullets, seed, 60, 1e-6);
        if (step >= 0) std::printf("  %d bullets, seed %u: rose in step %d\n", bullets, seed, step);
        rose += step >= 0 ? 1 : 0;
    }
    std::printf("| %d bullets, 60 steps | %u to %u | %d | - | - |\n", bullets, first, last, rose);
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<Range> ranges;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--gas" && i + 2 < argc) {
            ranges.push_back(
                {0, static_cast<unsigned>(std::atoi(argv[i + 1])), static_cast<unsigned>(std::atoi(argv[i + 2]))});
            i += 2;
        } else if (arg == "--bullets" && i + 3 < argc) {
            ranges.push_back({std::atoi(argv[i + 1]), static_cast<unsigned>(std::atoi(argv[i + 2])),
                              static_cast<unsigned>(std::atoi(argv[i + 3]))});
            i += 3;
        } else {
            std::fprintf(stderr, "usage: energy_sweep [--gas FIRST LAST] [--bullets COUNT FIRST LAST]...\n");
            return 2;
        }
    }
    if (ranges.empty()) ranges = {{0, 1, 600}, {1, 1, 20000}, {2, 1, 20000}, {3, 1, 10000}};
    for (const Range& r : ranges)
        if (r.first < 1 || r.last < r.first || r.bullets < 0) {
            std::fprintf(stderr, "energy_sweep: bad range (bullets %d, seeds %u to %u)\n", r.bullets, r.first, r.last);
            return 2;
        }
    std::printf("Starts whose kinetic energy rose above the start by more than 1e-6 in some step (and, for the gas, "
                "kept under 99%%); each such start is listed above its scene's row.\n\n"
                "| scene | seeds | starts that rose | largest rise | starts under 99%% |\n|---|---|---|---|---|\n");
    for (const Range& r : ranges) {
        if (r.bullets == 0) sweepGas(r.first, r.last);
        else sweepBullets(r.bullets, r.first, r.last);
    }
    return 0;
}
