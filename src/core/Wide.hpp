#pragma once
// Four lanes of doubles, for solving four contact rows of one colour at once (they share no dynamic body, so the
// lanes are independent). GCC vector extensions, which Clang has too: each operation is the scalar one, lane by
// lane, rounded the same way (the build turns floating-point contraction off), so a lane gives bit for bit what the
// scalar formula gives. The loops that use them are built three times, and the processor picks (WideCode):
//   - baseline x86-64 (SSE2, which has neither four-double registers nor 64-bit lane compares: the compiler splits
//     each operation);
//   - AVX2 with FMA: one 256-bit register per four lanes;
//   - AVX-512 (F, VL, DQ; FMA): the same four lanes in 256-bit registers, but 32 of them instead of 16, so fewer of a
//     block's values spill to the stack. Eight lanes in 512-bit registers were no faster (docs/performance.md,
//     "Lessons that still bind").
// All give the same bits because the build turns contraction off (-ffp-contract=off): the compiler never fuses a
// multiply and an add on its own, which the AVX builds could and the baseline could not. Where a fused
// multiply-add is wanted it is written (mulAdd): rounded once by IEEE 754's rule, it has the same bits on every
// build, one instruction on the AVX ones and the C library's fma on the baseline. Internal.

#include <cstdint>

namespace physim {

/// Which build of the four-lane loops runs: the best this processor has, or one named (tests compare them).
enum class WideCode { Best, Baseline, Avx2, Avx512 };

#if defined(__GNUC__) && defined(__x86_64__)  // GCC and Clang
#define PHYSIM_HAS_AVX2_CODE 1
#define PHYSIM_AVX2_CODE __attribute__((target("avx2,fma")))
#define PHYSIM_AVX512_CODE __attribute__((target("avx2,fma,avx512f,avx512vl,avx512dq")))
#else
#define PHYSIM_HAS_AVX2_CODE 0
#define PHYSIM_AVX2_CODE
#define PHYSIM_AVX512_CODE
#endif

/// Whether the AVX2 build (AVX2 with fused multiply-add) exists and this processor runs it.
inline bool avx2CodeRuns() {
#if PHYSIM_HAS_AVX2_CODE
    static const bool runs = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx2") != 0 && __builtin_cpu_supports("fma") != 0;
    }();
    return runs;
#else
    return false;
#endif
}

/// Whether the AVX-512 build exists (with the AVX2 one) and this processor runs it.
inline bool avx512CodeRuns() {
#if PHYSIM_HAS_AVX2_CODE
    static const bool runs = [] {
        __builtin_cpu_init();
        return avx2CodeRuns() && __builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("avx512vl") != 0 &&
               __builtin_cpu_supports("avx512dq") != 0;
    }();
    return runs;
#else
    return false;
#endif
}

/// The build a loop runs: the one named, or for Best the widest this processor runs.
inline WideCode pickWideCode(WideCode code) {
    if (code != WideCode::Best) return code;
    if (avx512CodeRuns()) return WideCode::Avx512;
    if (avx2CodeRuns()) return WideCode::Avx2;
    return WideCode::Baseline;
}

// The three builds of a loop (runWide). `Loop` names it: a type with an always-inline static `run<V>(args...)`,
// which each build below compiles with its own instructions; V says whether the build has vector instructions.
template <class Loop, class... Args>
decltype(auto) buildBaseline(Args&&... args) {
    return Loop::template run<false>(static_cast<Args&&>(args)...);
}
#if PHYSIM_HAS_AVX2_CODE
template <class Loop, class... Args>
PHYSIM_AVX2_CODE decltype(auto) buildAvx2(Args&&... args) {
    return Loop::template run<true>(static_cast<Args&&>(args)...);
}
template <class Loop, class... Args>
PHYSIM_AVX512_CODE decltype(auto) buildAvx512(Args&&... args) {
    return Loop::template run<true>(static_cast<Args&&>(args)...);
}
#endif

/// Runs the loop `Loop` (see buildBaseline) in the build `code` picks: the loop is written once, and built three
/// times.
template <class Loop, class... Args>
decltype(auto) runWide(WideCode code, Args&&... args) {
    switch (pickWideCode(code)) {
#if PHYSIM_HAS_AVX2_CODE
    case WideCode::Avx512: return buildAvx512<Loop>(static_cast<Args&&>(args)...);
    case WideCode::Avx2: return buildAvx2<Loop>(static_cast<Args&&>(args)...);
#endif
    default: return buildBaseline<Loop>(static_cast<Args&&>(args)...);
    }
}

constexpr int kLanes = 4;

using Wide = double __attribute__((vector_size(kLanes * sizeof(double))));
/// A lane-wise comparison's result: all ones (true) or zero per lane; `mask ? a : b` selects lane by lane.
using WideMask = std::int64_t __attribute__((vector_size(kLanes * sizeof(double))));

[[gnu::always_inline]] inline Wide splat(double x) { return Wide{x, x, x, x}; }

/// std::max and std::clamp lane by lane, with their exact rules (which operand wins a tie or a NaN).
[[gnu::always_inline]] inline Wide max(Wide a, Wide b) { return a < b ? b : a; }
[[gnu::always_inline]] inline Wide clamp(Wide v, Wide lo, Wide hi) { return v < lo ? lo : (hi < v ? hi : v); }
/// std::abs lane by lane: the sign bit cleared (so -0 gives +0, and a NaN keeps no sign, as std::abs does).
[[gnu::always_inline]] inline Wide abs(Wide v) {
    constexpr std::int64_t kMagnitude = 0x7fffffffffffffff;
    return (Wide)((WideMask)v & kMagnitude);
}

/// a * b + c rounded once, lane by lane: IEEE 754's fused multiply-add, whose bits are defined exactly, so every
/// build gives the same. Vector (the AVX builds, which have FMA) runs it as one instruction; otherwise each lane
/// calls the C library's fma. GCC gets the instruction in inline assembly: an intrinsic cannot be inlined into
/// these templates, which are compiled for baseline x86-64 before the AVX functions inline them, and GCC 12 makes
/// scalar fmas and shuffles of some of the four lanes' builtins, which is slower. Clang takes the builtins.
template <bool Vector>
[[gnu::always_inline]] inline Wide mulAdd(Wide a, Wide b, Wide c) {
#if PHYSIM_HAS_AVX2_CODE && !defined(__clang__)
    if constexpr (Vector) {
        asm("vfmadd231pd %2, %1, %0" : "+v"(c) : "v"(a), "vm"(b));  // c = a * b + c
        return c;
    }
#endif
    return Wide{__builtin_fma(a[0], b[0], c[0]), __builtin_fma(a[1], b[1], c[1]), __builtin_fma(a[2], b[2], c[2]),
                __builtin_fma(a[3], b[3], c[3])};
}

/// The square root lane by lane, rounded as IEEE 754 says (as std::sqrt is): one instruction on the AVX builds.
template <bool Vector>
[[gnu::always_inline]] inline Wide sqrtLanes(Wide v) {
#if PHYSIM_HAS_AVX2_CODE && !defined(__clang__)
    if constexpr (Vector) {
        Wide root;
        asm("vsqrtpd %1, %0" : "=v"(root) : "vm"(v));
        return root;
    }
#endif
    return Wide{__builtin_sqrt(v[0]), __builtin_sqrt(v[1]), __builtin_sqrt(v[2]), __builtin_sqrt(v[3])};
}

[[gnu::always_inline]] inline bool any(WideMask m) { return (m[0] | m[1] | m[2] | m[3]) != 0; }

}  // namespace physim
