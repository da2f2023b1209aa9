#pragma once
// Four lanes of doubles, for solving four contact rows of one colour at once (they share no dynamic body, so the
// lanes are independent). GCC vector extensions, which Clang has too: each operation is the scalar one, lane by
// lane, rounded the same way (the build turns floating-point contraction off), so a lane gives bit for bit what the
// scalar formula gives. The loops that use them are built twice, for baseline x86-64 (SSE2, which has neither
// four-double registers nor 64-bit lane compares: the compiler splits each operation) and for AVX2, and the
// processor picks (WideCode). Both give the same bits: contraction stays off, and AVX2 alone adds no fused
// multiply-add. Internal.

#include <cstdint>

namespace physim {

/// Which build of the four-lane loops runs: the best this processor has, or one named (tests compare them).
enum class WideCode { Best, Baseline, Avx2 };

#if defined(__GNUC__) && defined(__x86_64__)  // GCC and Clang
#define PHYSIM_HAS_AVX2_CODE 1
#define PHYSIM_AVX2_CODE __attribute__((target("avx2")))
#else
#define PHYSIM_HAS_AVX2_CODE 0
#define PHYSIM_AVX2_CODE
#endif

/// Whether the AVX2 build exists and this processor runs it.
inline bool avx2CodeRuns() {
#if PHYSIM_HAS_AVX2_CODE
    static const bool runs = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0;
    }();
    return runs;
#else
    return false;
#endif
}

constexpr int kLanes = 4;

using Wide = double __attribute__((vector_size(kLanes * sizeof(double))));
/// A lane-wise comparison's result: all ones (true) or zero per lane; `mask ? a : b` selects lane by lane.
using WideMask = std::int64_t __attribute__((vector_size(kLanes * sizeof(double))));

[[gnu::always_inline]] inline Wide splat(double x) { return Wide{x, x, x, x}; }

/// std::max and std::clamp lane by lane, with their exact rules (which operand wins a tie or a NaN).
[[gnu::always_inline]] inline Wide max(Wide a, Wide b) { return a < b ? b : a; }
[[gnu::always_inline]] inline Wide clamp(Wide v, Wide lo, Wide hi) { return v < lo ? lo : (hi < v ? hi : v); }
[[gnu::always_inline]] inline Wide abs(Wide v) { return v < 0.0 ? -v : v; }

[[gnu::always_inline]] inline bool any(WideMask m) { return (m[0] | m[1] | m[2] | m[3]) != 0; }

}  // namespace physim
