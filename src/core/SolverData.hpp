#pragma once
// The solver's view of the awake bodies for one step, laid out for its loops. Internal.
//
// Index i of each array is the i-th awake body (World::awake_[i]). Constraints name bodies by that index;
// kNullIndex stands for a static body, whose state is all zero (it never moves).

#include "BodyData.hpp"

#include "physim/core/Math.hpp"

#include <cstdint>

namespace physim {

/// What every constraint pass reads and writes: 64 bytes, aligned to a cache line, so that a record is one line: a
/// load never spans two, and a record never shares a line with one another thread writes in the same loop.
struct alignas(64) SolverBody {
    Vec2 v = Vec2::Zero();    // velocity of the centre of mass, m/s
    double w = 0.0;           // rad/s
    double dAngle = 0.0;      // rad turned since the step began (exact sum; dq caches its rotation)
    Vec2 dp = Vec2::Zero();   // centre-of-mass displacement since the step began, m
    Rotation dq{};            // rotation since the step began
};

/// A contact row before preparation: its contact and its bodies' awake indices (kNullIndex: static or asleep).
struct RowRef {
    std::uint32_t contact = 0;
    std::int32_t indexA = kNullIndex, indexB = kNullIndex;
};

/// The velocity the solve pass's soft push-out has given a body in the present substep (m/s, rad/s), kept apart
/// so that a bounce is planned without it: a bounce must answer how the bodies met, not how fast an overlap with a
/// third body is being pushed out (the relax pass takes that back). Valid while `substep` is the present one.
struct PushVelocity {
    Vec2 v = Vec2::Zero();
    double w = 0.0;
    int substep = -1;
};

/// A body's velocity as the present substep's rows found it (after integration, before the warm start), plus the
/// blows of the bounces they dealt: what the body gained beyond it is then the rows' accumulated impulses'
/// M^-1 J^T lambda, which the next substep's warm start would apply again (m/s, rad/s). 32 bytes, like the
/// next: the pass over bodies moves each whole, four bodies' at once (BodyPasses.cpp).
struct alignas(32) RowsBase {
    Vec2 v = Vec2::Zero();
    double w = 0.0;
};

/// What the present substep's warm start gave a body (m/s, rad/s): a guess at the substep's impulses, which the
/// passes then keep or take back, so a bounce leaves it out of the speeds it answers (ContactSolver.cpp).
struct alignas(32) WarmStartVelocity {
    Vec2 v = Vec2::Zero();
    double w = 0.0;
};

/// A substep's velocity integration of a dynamic body: dv, and dw if it can turn. It keeps in `base` the velocity
/// the rows start from (none where nothing reads it: null). With `again` (the warm start on the bodies, from a
/// step's second substep on; base given) it adds again what the rows gave the body over the substep before, and
/// keeps that in `warm` if given: M^-1 J^T lambda for their accumulated impulses lambda, since a row's J is fixed
/// for the step, so what a warm start over the rows would add.
inline void integrateVelocity(SolverBody& s, RowsBase* base, WarmStartVelocity* warm, const Vec2& dv, double dw,
                              bool turns, bool again) {
    const RowsBase rows = again ? RowsBase{s.v - base->v, s.w - base->w} : RowsBase{};
    s.v += dv;
    if (turns) s.w += dw;
    if (base) *base = {s.v, s.w};
    if (again) {
        s.v += rows.v;
        s.w += rows.w;
        if (warm) *warm = {rows.v, rows.w};
    }
}

/// After a warm-start pass over the rows: what it gave the body (integrateVelocity kept the velocity before it).
inline void recordWarmStart(const SolverBody& s, const RowsBase& base, WarmStartVelocity& warm) {
    warm = {s.v - base.v, s.w - base.w};
}

/// Read by row preparation, integration and finalization: what they need of an awake body's record, copied once
/// per step into the solver's order, so that preparing a row reads two bodies' lines here instead of scattered
/// lines of their records. Two cache lines, aligned to them; what each substep's integration reads is in the first.
struct alignas(64) SolverBodySim {
    Vec2 acceleration = Vec2::Zero();  // m/s^2 from gravity and forces, constant over the step; 0 unless dynamic
    double angularAcceleration = 0.0;  // rad/s^2
    bool dynamic = false;
    bool turns = false;            // it can turn this step (free to, or spinning): else no rotation work at all
    std::uint32_t body = 0;        // slot in World::bodies_
    Vec2 center0 = Vec2::Zero();   // centre of mass at the step's start, m
    Rotation q0{};                 // rotation at the step's start
    double angle0 = 0.0;           // rad
    double invMass = 0.0;          // 1/kg; 0 unless dynamic
    double invInertia = 0.0;       // 0 unless dynamic
};
static_assert(sizeof(SolverBodySim) == 128, "two cache lines");

/// The series rotationBy uses for |theta| <= 0.2: cosine and sine of theta (rad), on a double or, lane by lane, on
/// four (Wide.hpp), with the same operations in the same order, so a lane's bits are the scalar's. Accurate to
/// rounding there (the first term left out, theta^12 / 12!, is below 1e-17). The series' factors are reciprocals
/// folded at compile time: a division per term would cost more than the rest of the body's update.
template <class T>
[[gnu::always_inline]] inline void rotationSeries(const T& theta, T& c, T& s) {
    const T t2 = theta * theta;
    constexpr double k6 = 1.0 / 6.0, k20 = 1.0 / 20.0, k42 = 1.0 / 42.0, k72 = 1.0 / 72.0, k110 = 1.0 / 110.0;
    constexpr double k2 = 1.0 / 2.0, k12 = 1.0 / 12.0, k30 = 1.0 / 30.0, k56 = 1.0 / 56.0, k90 = 1.0 / 90.0;
    s = theta * (1.0 - t2 * k6 * (1.0 - t2 * k20 * (1.0 - t2 * k42 * (1.0 - t2 * k72 * (1.0 - t2 * k110)))));
    c = 1.0 - t2 * k2 * (1.0 - t2 * k12 * (1.0 - t2 * k30 * (1.0 - t2 * k56 * (1.0 - t2 * k90))));
}

/// Small-angle rotation by theta (rad): the series above for |theta| <= 0.2, and the library functions beyond.
/// Substeps turn bodies by far less than that, so the step pays for a few multiplications instead of a sine and a
/// cosine per body per substep.
inline Rotation rotationBy(double theta) {
    if (!(std::abs(theta) <= 0.2)) return Rotation::fromAngle(theta);
    Rotation r;
    rotationSeries(theta, r.c, r.s);
    return r;
}

/// (c1, s1) * (c2, s2): rotation by the second, then by the first, as cosine and sine; on doubles or lanes.
template <class T>
[[gnu::always_inline]] inline void composeParts(const T& c1, const T& s1, const T& c2, const T& s2, T& c, T& s) {
    c = c1 * c2 - s1 * s2;
    s = s1 * c2 + c1 * s2;
}

/// q1 * q2: rotation by q2, then by q1.
inline Rotation compose(const Rotation& q1, const Rotation& q2) {
    Rotation q;
    composeParts(q1.c, q1.s, q2.c, q2.s, q.c, q.s);
    return q;
}

/// A substep's position integration of one body: its centre moves by h v, and a turning one (w != 0) turns by h w.
inline void integratePosition(SolverBody& s, double h) {
    s.dp += h * s.v;
    if (s.w != 0.0) {
        const double turn = h * s.w;
        s.dAngle += turn;
        s.dq = compose(rotationBy(turn), s.dq);
    }
}

}  // namespace physim
