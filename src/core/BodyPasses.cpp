#include "BodyPasses.hpp"

#include "BodyLanes.hpp"

namespace physim {
namespace {

// The scalar rule, out of line so that it stays built for baseline x86-64: inlined into the AVX builds below, GCC
// 12's vectorizer fuses its rotation's products into a multiply-add (vfmaddsub) even with contraction off, and the
// bits would then depend on which build ran and on how many bodies a chunk left over.
[[gnu::noinline]] void integrateOne(SolverBody& s, double h) { integratePosition(s, h); }

// Four bodies at once: the same operations as integratePosition, lane by lane. A turning lane (w != 0) turns; the
// others keep their angle and rotation bit for bit. A turn past the series' range (rare: 0.2 rad in a substep)
// sends the four to the scalar rule, which then takes the library's sine and cosine.
[[gnu::always_inline]] inline void integrateLoop(SolverBody* states, const std::uint32_t* list, std::size_t count,
                                                 double h) {
    std::size_t k = 0;
    for (; k + kLanes <= count; k += kLanes) {
        const std::int32_t index[kLanes] = {static_cast<std::int32_t>(list[k]), static_cast<std::int32_t>(list[k + 1]),
                                            static_cast<std::int32_t>(list[k + 2]),
                                            static_cast<std::int32_t>(list[k + 3])};
        WideSide g = gather<true>(index, states);
        const Wide turn = h * g.w;
        const WideMask turning = g.w != 0.0;
        if (any(turning & ~(abs(turn) <= 0.2))) {
            for (int lane = 0; lane < kLanes; ++lane) integrateOne(states[index[lane]], h);
            continue;
        }
        g.dpx = g.dpx + h * g.vx;
        g.dpy = g.dpy + h * g.vy;
        if (any(turning)) {
            Wide c, s, qc, qs;
            rotationSeries(turn, c, s);
            composeParts(c, s, g.qc, g.qs, qc, qs);
            g.dAngle = turning ? g.dAngle + turn : g.dAngle;
            g.qc = turning ? qc : g.qc;
            g.qs = turning ? qs : g.qs;
        }
        transpose(g.vx, g.vy, g.w, g.dAngle);
        transpose(g.dpx, g.dpy, g.qc, g.qs);
        const Wide halves[2][kLanes] = {{g.vx, g.vy, g.w, g.dAngle}, {g.dpx, g.dpy, g.qc, g.qs}};
        for (int lane = 0; lane < kLanes; ++lane) {
            storeHalf(states[index[lane]], 0, halves[0][lane]);
            storeHalf(states[index[lane]], 1, halves[1][lane]);
        }
    }
    for (; k < count; ++k) integrateOne(states[list[k]], h);
}

void integrateBaseline(SolverBody* states, const std::uint32_t* list, std::size_t count, double h) {
    integrateLoop(states, list, count, h);
}
#if PHYSIM_HAS_AVX2_CODE
PHYSIM_AVX2_CODE void integrateAvx2(SolverBody* states, const std::uint32_t* list, std::size_t count, double h) {
    integrateLoop(states, list, count, h);
}
PHYSIM_AVX512_CODE void integrateAvx512(SolverBody* states, const std::uint32_t* list, std::size_t count,
                                        double h) {
    integrateLoop(states, list, count, h);
}
#endif

}  // namespace

void integratePositions(SolverBody* states, const std::uint32_t* list, std::size_t count, double h, WideCode code) {
    switch (pickWideCode(code)) {
#if PHYSIM_HAS_AVX2_CODE
    case WideCode::Avx512: return integrateAvx512(states, list, count, h);
    case WideCode::Avx2: return integrateAvx2(states, list, count, h);
#endif
    default: return integrateBaseline(states, list, count, h);
    }
}

}  // namespace physim
