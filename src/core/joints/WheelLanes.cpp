#include "WheelLanes.hpp"
#include "LaneBlocks.hpp"

#include "../BodyLanes.hpp"
#include "../Impulse.hpp"
#include "../JointData.hpp"

#include <variant>

namespace physim {
namespace {

// SliderShared.hpp's SliderFrame, lane by lane.
struct Frame {
    Wide axisX, axisY, normalX, normalY;
    Wide translation, offset;
    Wide a1, a2, n1, n2;
};
[[gnu::always_inline]] inline Frame frameOf(const WheelBlock& p, const WideSide& A, const WideSide& B) {
    const Wide rAx = A.qc * p.anchorAx - A.qs * p.anchorAy, rAy = A.qs * p.anchorAx + A.qc * p.anchorAy;
    const Wide rBx = B.qc * p.anchorBx - B.qs * p.anchorBy, rBy = B.qs * p.anchorBx + B.qc * p.anchorBy;
    const Wide dx = ((p.deltaX + (B.dpx - A.dpx)) + rBx) - rAx;
    const Wide dy = ((p.deltaY + (B.dpy - A.dpy)) + rBy) - rAy;
    Frame f;
    f.axisX = A.qc * p.axisX - A.qs * p.axisY;
    f.axisY = A.qs * p.axisX + A.qc * p.axisY;
    f.normalX = -f.axisY;
    f.normalY = f.axisX;
    f.translation = f.axisX * dx + f.axisY * dy;
    f.offset = f.normalX * dx + f.normalY * dy;
    const Wide ex = dx + rAx, ey = dy + rAy;  // d + rA
    f.a1 = ex * f.axisY - ey * f.axisX;
    f.a2 = rBx * f.axisY - rBy * f.axisX;
    f.n1 = ex * f.normalY - ey * f.normalX;
    f.n2 = rBx * f.normalY - rBy * f.normalX;
    return f;
}

// SliderShared.hpp's pushAlong in the lanes `on` (the others keep every bit, -0 included).
[[gnu::always_inline]] inline void pushAlong(const WheelBlock& p, WideSide& A, WideSide& B, WideMask on, Wide dirX,
                                             Wide dirY, Wide j1, Wide j2, Wide impulse) {
    A.vx = on ? A.vx - (p.invMassA * impulse) * dirX : A.vx;
    A.vy = on ? A.vy - (p.invMassA * impulse) * dirY : A.vy;
    A.w = on ? A.w - (p.invIA * impulse) * j1 : A.w;
    B.vx = on ? B.vx + (p.invMassB * impulse) * dirX : B.vx;
    B.vy = on ? B.vy + (p.invMassB * impulse) * dirY : B.vy;
    B.w = on ? B.w + (p.invIB * impulse) * j2 : B.w;
}

// SliderShared.hpp's rowInverseMass.
[[gnu::always_inline]] inline Wide inverseMass(const WheelBlock& p, Wide j1, Wide j2) {
    return ((p.invMassA + p.invMassB) + (p.invIA * j1) * j1) + (p.invIB * j2) * j2;
}

// WheelJoint::warmStart (with its limits off, their impulses +0) on one block's lanes, its bodies gathered.
[[gnu::always_inline]] inline void warmStartBlock(const WheelBlock& p, WideSide& A, WideSide& B) {
    const WideMask all = {-1, -1, -1, -1};
    const Frame f = frameOf(p, A, B);
    const Wide axial = (p.springImpulse + splat(0.0)) - splat(0.0);
    pushAlong(p, A, B, all, f.axisX, f.axisY, f.a1, f.a2, axial);
    pushAlong(p, A, B, all, f.normalX, f.normalY, f.n1, f.n2, p.normalImpulse);
    const Wide motor = splat(0.0) + p.motorImpulse;
    A.w = A.w - p.invIA * motor;
    B.w = B.w + p.invIB * motor;
}

// WheelJoint::solve on one block's lanes, its bodies gathered (the caller writes them back).
template <bool UseBias>
[[gnu::always_inline]] inline void solveBlock(WheelBlock& p, WideSide& A, WideSide& B) {
    const Frame f = frameOf(p, A, B);
    p.lastAxisX = f.axisX;
    p.lastAxisY = f.axisY;
    // The motor: an angular velocity row capped at maxImpulse.
    const Wide old = p.motorImpulse;
    const Wide motorImpulse =
        clamp(old - p.axialMass * ((B.w - A.w) - p.motorSpeed), -p.maxImpulse, p.maxImpulse);
    const Wide turn = motorImpulse - old;
    A.w = p.motor ? A.w - p.invIA * turn : A.w;
    B.w = p.motor ? B.w + p.invIB * turn : B.w;
    p.motorImpulse = p.motor ? motorImpulse : old;
    // The suspension, soft in both passes.
    const Wide kAxial = inverseMass(p, f.a1, f.a2);
    const WideMask spring = p.spring & (kAxial > splat(0.0));
    const Wide safeAxial = spring ? kAxial : splat(1.0);
    const Wide rate = ((f.axisX * (B.vx - A.vx) + f.axisY * (B.vy - A.vy)) + f.a2 * B.w) - f.a1 * A.w;
    const Wide springLambda = -(p.springMass / safeAxial) * (rate + p.springBias * f.translation) -
                              p.springImpulseScale * p.springImpulse;
    p.springImpulse = spring ? p.springImpulse + springLambda : p.springImpulse;
    pushAlong(p, A, B, spring, f.axisX, f.axisY, f.a1, f.a2, springLambda);
    // Across the axis: the anchor stays on A's line.
    const Wide kNormal = inverseMass(p, f.n1, f.n2);
    const WideMask solvable = kNormal > splat(0.0);
    const Wide safeNormal = solvable ? kNormal : splat(1.0);
    Wide bias = splat(0.0), massScale = splat(1.0), impulseScale = splat(0.0);
    if constexpr (UseBias) {
        bias = p.biasRate * f.offset;
        massScale = p.massScale;
        impulseScale = p.impulseScale;
    }
    const Wide cdot = ((f.normalX * (B.vx - A.vx) + f.normalY * (B.vy - A.vy)) + f.n2 * B.w) - f.n1 * A.w;
    const Wide lambda = -(massScale / safeNormal) * (cdot + bias) - impulseScale * p.normalImpulse;
    p.normalImpulse = solvable ? p.normalImpulse + lambda : p.normalImpulse;
    pushAlong(p, A, B, solvable, f.normalX, f.normalY, f.n1, f.n2, lambda);
}

struct WarmStartWheels {
    template <bool>
    [[gnu::always_inline]] static void run(const WheelBlock* begin, const WheelBlock* end, SolverBody* states) {
        inPairs(begin, end, states, [](const WheelBlock& p, WideSide& A, WideSide& B)
                    __attribute__((always_inline)) { warmStartBlock(p, A, B); });
    }
};
struct SolveWheels {
    template <bool>
    [[gnu::always_inline]] static void run(WheelBlock* begin, WheelBlock* end, SolverBody* states, bool useBias) {
        if (useBias)
            inPairs(begin, end, states, [](WheelBlock& p, WideSide& A, WideSide& B)
                        __attribute__((always_inline)) { solveBlock<true>(p, A, B); });
        else
            inPairs(begin, end, states, [](WheelBlock& p, WideSide& A, WideSide& B)
                        __attribute__((always_inline)) { solveBlock<false>(p, A, B); });
    }
};

}  // namespace

void packWheels(WheelBlock& block, const JointConstraint* const* rows, std::uint32_t count,
                const std::vector<JointData>& joints) {
    startBlock(block, count);
    for (std::uint32_t lane = 0; lane < count; ++lane) {
        const JointConstraint& row = *rows[lane];
        const WheelJoint& wheel = std::get<WheelJoint>(joints[row.joint].params);
        const int k = static_cast<int>(lane);
        packRowFields(block, row, lane);
        block.axisX[k] = row.axis.x();
        block.axisY[k] = row.axis.y();
        block.springBias[k] = row.spring.biasRate;
        block.springMass[k] = row.spring.massScale;
        block.springImpulseScale[k] = row.spring.impulseScale;
        block.axialMass[k] = row.axialMass;
        block.maxImpulse[k] = row.maxImpulse;
        block.motorSpeed[k] = wheel.motorSpeed;
        block.motor[k] = wheel.enableMotor && row.axialMass > 0.0 ? -1 : 0;
        block.spring[k] = wheel.enableSpring && wheel.hertz > 0.0 ? -1 : 0;
        block.normalImpulse[k] = wheel.normalImpulse;
        block.springImpulse[k] = wheel.springImpulse;
        block.motorImpulse[k] = wheel.motorImpulse;
        block.lastAxisX[k] = wheel.lastAxis.x();
        block.lastAxisY[k] = wheel.lastAxis.y();
    }
}

void warmStartWheels(const WheelBlock* begin, const WheelBlock* end, SolverBody* states, WideCode code) {
    runWide<WarmStartWheels>(code, begin, end, states);
}

void solveWheels(WheelBlock* begin, WheelBlock* end, SolverBody* states, bool useBias, WideCode code) {
    runWide<SolveWheels>(code, begin, end, states, useBias);
}

void storeWheels(const WheelBlock* begin, const WheelBlock* end, std::vector<JointData>& joints) {
    for (const WheelBlock* p = begin; p != end; ++p)
        for (std::uint32_t lane = 0; lane < p->count; ++lane) {
            const int k = static_cast<int>(lane);
            WheelJoint& wheel = std::get<WheelJoint>(joints[p->joint[lane]].params);
            wheel.normalImpulse = p->normalImpulse[k];
            wheel.springImpulse = p->springImpulse[k];
            wheel.motorImpulse = p->motorImpulse[k];
            wheel.lastAxis = {p->lastAxisX[k], p->lastAxisY[k]};
        }
}

}  // namespace physim
