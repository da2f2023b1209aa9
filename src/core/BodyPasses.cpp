#include "BodyPasses.hpp"

#include "BodyLanes.hpp"

#include <cstddef>

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

// The velocity rule, out of line like integrateOne.
[[gnu::noinline]] void integrateVelocityOne(SolverBody& s, RowsBase& base, WarmStartVelocity* warm,
                                            const SolverBodySim& sim, double h, bool again) {
    if (sim.dynamic)
        integrateVelocity(s, base, warm, h * sim.acceleration, h * sim.angularAcceleration, sim.turns, again);
}

// A 32-byte record (RowsBase, WarmStartVelocity: v, then w, then padding) moved whole as four lanes.
static_assert(sizeof(RowsBase) == sizeof(Wide) && offsetof(RowsBase, w) == 2 * sizeof(double) &&
                  sizeof(WarmStartVelocity) == sizeof(Wide) && offsetof(WarmStartVelocity, w) == 2 * sizeof(double),
              "RowsBase and WarmStartVelocity are (vx, vy, w, padding)");
template <class T>
[[gnu::always_inline]] inline Wide loadWhole(const T& x) {
    return reinterpret_cast<const RecordHalf*>(&x)->values;
}
template <class T>
[[gnu::always_inline]] inline void storeWhole(T& x, const Wide& values) {
    reinterpret_cast<RecordHalf*>(&x)->values = values;
}

// Four bodies at once: integrateVelocity's operations, lane by lane, on the dynamic lanes; the others are not
// written.
[[gnu::always_inline]] inline void integrateVelocityLoop(SolverBody* states, RowsBase* base, WarmStartVelocity* warm,
                                                         const SolverBodySim* sims, const std::uint32_t* list,
                                                         std::size_t count, double h, bool again) {
    std::size_t k = 0;
    for (; k + kLanes <= count; k += kLanes) {
        const std::uint32_t index[kLanes] = {list[k], list[k + 1], list[k + 2], list[k + 3]};
        Wide ax, ay, alpha;
        WideMask turns;
        unsigned dynamic = 0;
        for (int lane = 0; lane < kLanes; ++lane) {
            const SolverBodySim& sim = sims[index[lane]];
            ax[lane] = sim.acceleration.x();
            ay[lane] = sim.acceleration.y();
            alpha[lane] = sim.angularAcceleration;
            turns[lane] = sim.turns ? -1 : 0;
            dynamic |= sim.dynamic ? 1u << lane : 0u;
        }
        if (dynamic == 0) continue;
        Wide vx = loadHalf(states[index[0]], 0), vy = loadHalf(states[index[1]], 0);
        Wide w = loadHalf(states[index[2]], 0), dAngle = loadHalf(states[index[3]], 0);
        transpose(vx, vy, w, dAngle);
        const Wide zero{};
        Wide rowsX = zero, rowsY = zero, rowsW = zero;
        if (again) {  // what the rows gave the bodies over the last substep
            Wide bx = loadWhole(base[index[0]]), by = loadWhole(base[index[1]]);
            Wide bw = loadWhole(base[index[2]]), pad = loadWhole(base[index[3]]);
            transpose(bx, by, bw, pad);
            rowsX = vx - bx;
            rowsY = vy - by;
            rowsW = w - bw;
        }
        vx = vx + h * ax;
        vy = vy + h * ay;
        w = turns ? w + h * alpha : w;
        Wide bx = vx, by = vy, bw = w, pad = zero;
        transpose(bx, by, bw, pad);
        const Wide bases[kLanes] = {bx, by, bw, pad};
        if (again) {
            vx = vx + rowsX;
            vy = vy + rowsY;
            w = w + rowsW;
        }
        transpose(vx, vy, w, dAngle);
        const Wide halves[kLanes] = {vx, vy, w, dAngle};
        Wide wx = rowsX, wy = rowsY, ww = rowsW, wpad = zero;
        if (again && warm) transpose(wx, wy, ww, wpad);
        const Wide warms[kLanes] = {wx, wy, ww, wpad};
        for (int lane = 0; lane < kLanes; ++lane) {
            if (!(dynamic >> lane & 1u)) continue;
            storeHalf(states[index[lane]], 0, halves[lane]);
            storeWhole(base[index[lane]], bases[lane]);
            if (again && warm) storeWhole(warm[index[lane]], warms[lane]);
        }
    }
    for (; k < count; ++k)
        integrateVelocityOne(states[list[k]], base[list[k]], warm ? &warm[list[k]] : nullptr, sims[list[k]], h, again);
}

void integrateBaseline(SolverBody* states, const std::uint32_t* list, std::size_t count, double h) {
    integrateLoop(states, list, count, h);
}
void integrateVelocityBaseline(SolverBody* states, RowsBase* base, WarmStartVelocity* warm, const SolverBodySim* sims,
                               const std::uint32_t* list, std::size_t count, double h, bool again) {
    integrateVelocityLoop(states, base, warm, sims, list, count, h, again);
}
#if PHYSIM_HAS_AVX2_CODE
PHYSIM_AVX2_CODE void integrateAvx2(SolverBody* states, const std::uint32_t* list, std::size_t count, double h) {
    integrateLoop(states, list, count, h);
}
PHYSIM_AVX512_CODE void integrateAvx512(SolverBody* states, const std::uint32_t* list, std::size_t count,
                                        double h) {
    integrateLoop(states, list, count, h);
}
PHYSIM_AVX2_CODE void integrateVelocityAvx2(SolverBody* states, RowsBase* base, WarmStartVelocity* warm,
                                            const SolverBodySim* sims, const std::uint32_t* list, std::size_t count,
                                            double h, bool again) {
    integrateVelocityLoop(states, base, warm, sims, list, count, h, again);
}
PHYSIM_AVX512_CODE void integrateVelocityAvx512(SolverBody* states, RowsBase* base, WarmStartVelocity* warm,
                                                const SolverBodySim* sims, const std::uint32_t* list,
                                                std::size_t count, double h, bool again) {
    integrateVelocityLoop(states, base, warm, sims, list, count, h, again);
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

void integrateVelocities(SolverBody* states, RowsBase* base, WarmStartVelocity* warm, const SolverBodySim* sims,
                         const std::uint32_t* list, std::size_t count, double h, bool again, WideCode code) {
    switch (pickWideCode(code)) {
#if PHYSIM_HAS_AVX2_CODE
    case WideCode::Avx512: return integrateVelocityAvx512(states, base, warm, sims, list, count, h, again);
    case WideCode::Avx2: return integrateVelocityAvx2(states, base, warm, sims, list, count, h, again);
#endif
    default: return integrateVelocityBaseline(states, base, warm, sims, list, count, h, again);
    }
}

}  // namespace physim
