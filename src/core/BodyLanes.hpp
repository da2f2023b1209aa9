#pragma once
// Four awake bodies' solver records as four lanes (Wide.hpp): what the passes over rows and over bodies load and
// store, a record's halves moved whole and transposed. Internal.

#include "SolverData.hpp"
#include "Wide.hpp"

#include <cstddef>
#include <cstdint>

namespace physim {

// kLanes bodies' motion, one per lane: a block's A sides or B sides, or four bodies of a pass over bodies.
struct WideSide {
    Wide vx, vy, w, dAngle, dpx, dpy, qc, qs;
};

// A 4x4 transpose: four lanes' rows of four values into four values' lanes (its own inverse).
[[gnu::always_inline]] inline void transpose(Wide& a, Wide& b, Wide& c, Wide& d) {
    const Wide t0 = __builtin_shufflevector(a, b, 0, 4, 2, 6), t1 = __builtin_shufflevector(a, b, 1, 5, 3, 7);
    const Wide t2 = __builtin_shufflevector(c, d, 0, 4, 2, 6), t3 = __builtin_shufflevector(c, d, 1, 5, 3, 7);
    a = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
    b = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    c = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
    d = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}

// A body record's two 32-byte halves, (v, w, dAngle) and (dp, dq), each moved whole as four lanes: one cache line.
static_assert(alignof(SolverBody) == 64, "a record is one cache line, never split across two");
static_assert(sizeof(SolverBody) == 2 * sizeof(Wide) && offsetof(SolverBody, w) == 2 * sizeof(double) &&
                  offsetof(SolverBody, dAngle) == 3 * sizeof(double) && offsetof(SolverBody, dp) == sizeof(Wide) &&
                  offsetof(SolverBody, dq) == sizeof(Wide) + 2 * sizeof(double),
              "a SolverBody is (v, w, dAngle) then (dp, dq), four doubles each");

// The access type may alias doubles and asks for no alignment (packed): GCC and Clang then load and store it whole
// with unaligned moves, which cost nothing on an aligned record. The loops then assume nothing of alignment.
struct [[gnu::packed, gnu::may_alias]] RecordHalf {
    Wide values;
};

[[gnu::always_inline]] inline Wide loadHalf(const SolverBody& s, int half) {
    return reinterpret_cast<const RecordHalf*>(&s)[half].values;
}
[[gnu::always_inline]] inline void storeHalf(SolverBody& s, int half, const Wide& values) {
    reinterpret_cast<RecordHalf*>(&s)[half].values = values;
}

// The lanes' bodies: each record's halves loaded whole and transposed. index kNullIndex reads states[-1], a still
// body.
template <bool Pose>
[[gnu::always_inline]] inline WideSide gather(const std::int32_t (&index)[kLanes], const SolverBody* states) {
    const SolverBody &s0 = states[index[0]], &s1 = states[index[1]], &s2 = states[index[2]], &s3 = states[index[3]];
    WideSide g{};  // first lane k's half-record in the k-th vector, then transposed into one field per vector
    g.vx = loadHalf(s0, 0);
    g.vy = loadHalf(s1, 0);
    g.w = loadHalf(s2, 0);
    g.dAngle = loadHalf(s3, 0);
    transpose(g.vx, g.vy, g.w, g.dAngle);
    if constexpr (Pose) {
        g.dpx = loadHalf(s0, 1);
        g.dpy = loadHalf(s1, 1);
        g.qc = loadHalf(s2, 1);
        g.qs = loadHalf(s3, 1);
        transpose(g.dpx, g.dpy, g.qc, g.qs);
    }
    return g;
}

// Writes the lanes' velocities back (and turns, which only a bounce changes), only for sides the row can move
// (`writes`, a bit per lane): a kinematic body is read by many rows of one colour, the still body by all.
[[gnu::always_inline]] inline void scatter(const std::int32_t (&index)[kLanes], unsigned writes, WideSide g,
                                           SolverBody* states) {
    transpose(g.vx, g.vy, g.w, g.dAngle);
    if (writes & 1u) storeHalf(states[index[0]], 0, g.vx);
    if (writes & 2u) storeHalf(states[index[1]], 0, g.vy);
    if (writes & 4u) storeHalf(states[index[2]], 0, g.w);
    if (writes & 8u) storeHalf(states[index[3]], 0, g.dAngle);
}

}  // namespace physim
