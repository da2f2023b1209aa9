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
[[gnu::noinline]] void integrateVelocityOne(SolverBody& s, RowsBase* base, WarmStartVelocity* warm,
                                            const SolverBodySim& sim, double h, bool again) {
    if (sim.dynamic)
        integrateVelocity(s, base, warm, h * sim.acceleration, h * sim.angularAcceleration, sim.turns, again);
}

// RowsBase and WarmStartVelocity are (vx, vy, w, padding): four lanes' records transposed whole, as SolverBody's
// halves are (BodyLanes.hpp).
static_assert(sizeof(RowsBase) == sizeof(Wide) && offsetof(RowsBase, w) == 2 * sizeof(double) &&
                  sizeof(WarmStartVelocity) == sizeof(Wide) && offsetof(WarmStartVelocity, w) == 2 * sizeof(double),
              "RowsBase and WarmStartVelocity are (vx, vy, w, padding)");
template <class Record>
[[gnu::always_inline]] inline void gatherMotions(const Record* records, const std::int32_t (&index)[kLanes], Wide& vx,
                                                 Wide& vy, Wide& w) {
    const auto lane = [&](int k) { return reinterpret_cast<const RecordHalf*>(&records[index[k]])->values; };
    Wide pad = lane(3);
    vx = lane(0), vy = lane(1), w = lane(2);
    transpose(vx, vy, w, pad);
}
template <class Record>
[[gnu::always_inline]] inline void scatterMotions(Record* records, const std::int32_t (&index)[kLanes], unsigned lanes,
                                                  Wide vx, Wide vy, Wide w) {
    Wide pad{};
    transpose(vx, vy, w, pad);
    const Wide values[kLanes] = {vx, vy, w, pad};
    for (int k = 0; k < kLanes; ++k)
        if (lanes >> k & 1u) reinterpret_cast<RecordHalf*>(&records[index[k]])->values = values[k];
}

// Four bodies at once: integrateVelocity's operations, lane by lane, on the dynamic lanes; the others are not
// written.
[[gnu::always_inline]] inline void integrateVelocityLoop(SolverBody* states, RowsBase* base, WarmStartVelocity* warm,
                                                         const SolverBodySim* sims, const std::uint32_t* list,
                                                         std::size_t count, double h, bool again) {
    std::size_t k = 0;
    for (; k + kLanes <= count; k += kLanes) {
        const std::int32_t index[kLanes] = {static_cast<std::int32_t>(list[k]), static_cast<std::int32_t>(list[k + 1]),
                                            static_cast<std::int32_t>(list[k + 2]),
                                            static_cast<std::int32_t>(list[k + 3])};
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
        WideSide g = gather<false>(index, states);
        const Wide zero{};
        Wide rowsX = zero, rowsY = zero, rowsW = zero;
        if (again) {  // what the rows gave the bodies over the last substep
            Wide bx, by, bw;
            gatherMotions(base, index, bx, by, bw);
            rowsX = g.vx - bx;
            rowsY = g.vy - by;
            rowsW = g.w - bw;
        }
        g.vx = g.vx + h * ax;
        g.vy = g.vy + h * ay;
        g.w = turns ? g.w + h * alpha : g.w;
        if (base) scatterMotions(base, index, dynamic, g.vx, g.vy, g.w);
        if (again) {
            g.vx = g.vx + rowsX;
            g.vy = g.vy + rowsY;
            g.w = g.w + rowsW;
            if (warm) scatterMotions(warm, index, dynamic, rowsX, rowsY, rowsW);
        }
        scatter(index, dynamic, g, states);
    }
    for (; k < count; ++k)
        integrateVelocityOne(states[list[k]], base ? &base[list[k]] : nullptr, warm ? &warm[list[k]] : nullptr,
                             sims[list[k]], h, again);
}

struct IntegratePositions {
    template <bool>
    [[gnu::always_inline]] static void run(SolverBody* states, const std::uint32_t* list, std::size_t count,
                                           double h) {
        integrateLoop(states, list, count, h);
    }
};
struct IntegrateVelocities {
    template <bool>
    [[gnu::always_inline]] static void run(SolverBody* states, RowsBase* base, WarmStartVelocity* warm,
                                           const SolverBodySim* sims, const std::uint32_t* list, std::size_t count,
                                           double h, bool again) {
        integrateVelocityLoop(states, base, warm, sims, list, count, h, again);
    }
};

}  // namespace

void integratePositions(SolverBody* states, const std::uint32_t* list, std::size_t count, double h, WideCode code) {
    runWide<IntegratePositions>(code, states, list, count, h);
}

void integrateVelocities(SolverBody* states, RowsBase* base, WarmStartVelocity* warm, const SolverBodySim* sims,
                         const std::uint32_t* list, std::size_t count, double h, bool again, WideCode code) {
    runWide<IntegrateVelocities>(code, states, base, warm, sims, list, count, h, again);
}

}  // namespace physim
