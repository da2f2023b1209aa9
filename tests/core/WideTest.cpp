// mulAdd (src/core/Wide.hpp) must be IEEE 754's fused multiply-add on every build: one rounding of the exact
// a b + c, the same bits as std::fma, lane by lane, whether the AVX builds' instruction or the baseline's library
// calls compute it. Otherwise the contact passes' builds would part (ContactSolver.EveryBuildOfTheLoopsGivesTheSameBits
// checks them on rows; this checks the operation itself, on the values where fusing shows).

#include "Wide.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace physim {
namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Through memory, as the passes call it: a Wide passed by value travels in a register in an AVX function and in
// memory in a baseline one, so no call between the two passes one.
template <bool Vector>
[[gnu::always_inline]] inline void fused(const Wide* in, Wide* out) {
    *out = mulAdd<Vector>(in[0], in[1], in[2]);
}
void lanesBuild(const Wide* in, Wide* out) { fused<false>(in, out); }
#if PHYSIM_HAS_AVX2_CODE
PHYSIM_AVX2_CODE void avx2Build(const Wide* in, Wide* out) { fused<true>(in, out); }
PHYSIM_AVX512_CODE void avx512Build(const Wide* in, Wide* out) { fused<true>(in, out); }
#endif

struct Triple {
    double a, b, c;
};

// Values where a fused and an unfused multiply-add differ, and the edges of the range.
std::vector<Triple> cases() {
    const double tiny = std::numeric_limits<double>::denorm_min(), huge = std::numeric_limits<double>::max();
    const double e = std::ldexp(1.0, -30), inf = std::numeric_limits<double>::infinity();
    std::vector<Triple> t{
        {1.0 + e, 1.0 - e, -1.0},  // exact: -2^-60; unfused, (1 - 2^-60) rounds to 1 and gives 0
        {0.1, 10.0, -1.0},        // exact: 2^-54 or so; unfused: 0
        {-0.0, 1.0, 0.0},         // -0 + +0 = +0
        {-0.0, 1.0, -0.0},        // -0 + -0 = -0
        {tiny, 0.5, 0.0},         // a subnormal product, rounded once
        {tiny, 3.0, tiny},
        {huge, 2.0, -huge},       // the product overflows alone, not the sum
        {inf, 2.0, 1.0},
        {1e308, -1e308, 1.0},
    };
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> scale(-40, 40);
    for (int i = 0; i < 4000; ++i) {
        const double a = std::ldexp(u(rng), scale(rng)), b = std::ldexp(u(rng), scale(rng));
        const double c = i % 2 ? -a * b * (1.0 + 1e-9 * u(rng)) : std::ldexp(u(rng), scale(rng));  // near cancelling
        t.push_back({a, b, c});
    }
    return t;
}

using Build = void (*)(const Wide*, Wide*);

void expectFused(Build build, const char* name) {
    const std::vector<Triple> t = cases();
    for (std::size_t i = 0; i + kLanes <= t.size(); i += kLanes) {
        Wide in[3], r;
        for (int k = 0; k < kLanes; ++k) in[0][k] = t[i + k].a, in[1][k] = t[i + k].b, in[2][k] = t[i + k].c;
        build(in, &r);
        for (int k = 0; k < kLanes; ++k) {
            const double a = in[0][k], b = in[1][k], c = in[2][k], want = std::fma(a, b, c);
            EXPECT_TRUE(sameBits(r[k], want))
                << name << ": fma(" << a << ", " << b << ", " << c << ") gave " << r[k] << ", std::fma " << want;
        }
    }
}

TEST(Wide, MulAddIsTheFusedMultiplyAddOnEveryBuild) {
    // The first case tells fused from unfused: std::fma here must itself be fused.
    const double e = std::ldexp(1.0, -30);
    ASSERT_EQ(std::fma(1.0 + e, 1.0 - e, -1.0), -std::ldexp(1.0, -60));
    expectFused(lanesBuild, "baseline");
#if PHYSIM_HAS_AVX2_CODE
    if (avx2CodeRuns()) expectFused(avx2Build, "avx2");
    if (avx512CodeRuns()) expectFused(avx512Build, "avx512");
#endif
}

}  // namespace
}  // namespace physim
