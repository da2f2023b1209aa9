#include "PinLanes.hpp"
#include "LaneBlocks.hpp"

#include "../BodyLanes.hpp"
#include "../Impulse.hpp"
#include "../JointData.hpp"

#include <variant>

namespace physim {
namespace {

// The lanes' lever arms now: the anchors turned by each body's turn over the step so far (Rotation::apply).
struct Arms {
    Wide rAx, rAy, rBx, rBy;
};
[[gnu::always_inline]] inline Arms arms(const PinBlock& p, const WideSide& A, const WideSide& B) {
    return {A.qc * p.anchorAx - A.qs * p.anchorAy, A.qs * p.anchorAx + A.qc * p.anchorAy,
            B.qc * p.anchorBx - B.qs * p.anchorBy, B.qs * p.anchorBx + B.qc * p.anchorBy};
}

// Impulse.hpp's applyImpulse, lane by lane.
[[gnu::always_inline]] inline void apply(const PinBlock& p, WideSide& A, WideSide& B, const Arms& r, Wide Px,
                                         Wide Py) {
    A.vx = A.vx - p.invMassA * Px;
    A.vy = A.vy - p.invMassA * Py;
    A.w = A.w - p.invIA * (r.rAx * Py - r.rAy * Px);
    B.vx = B.vx + p.invMassB * Px;
    B.vy = B.vy + p.invMassB * Py;
    B.w = B.w + p.invIB * (r.rBx * Py - r.rBy * Px);
}

// RevoluteJoint::warmStart on one block's lanes, its bodies gathered.
[[gnu::always_inline]] inline void warmStartBlock(const PinBlock& p, WideSide& A, WideSide& B) {
    apply(p, A, B, arms(p, A, B), p.impulseX, p.impulseY);
    A.w = A.w - p.invIA * p.turnImpulse;
    B.w = B.w + p.invIB * p.turnImpulse;
}

// JointShared.hpp's pointBend: B's arm's bend less A's, for bodies turning at wA and wB.
[[gnu::always_inline]] inline void bend(const PinBlock& p, Wide wA, Wide wB, const Arms& r, Wide& x, Wide& y) {
    const Wide cap = splat(kMaxBendTurn), h = splat(p.h), invH = splat(p.invH);
    Wide ax, ay, bx, by;
    bendRate(clamp(h * wA, -cap, cap), invH, r.rAx, r.rAy, ax, ay);
    bendRate(clamp(h * wB, -cap, cap), invH, r.rBx, r.rBy, bx, by);
    x = bx - ax;
    y = by - ay;
}

// JointShared.hpp's solvePoint and solvePointMass on one block's lanes, its bodies gathered.
template <bool UseBias>
[[gnu::always_inline]] inline void solveBlock(PinBlock& p, WideSide& A, WideSide& B) {
    const Arms r = arms(p, A, B);
    // The relative velocity of the points, B.v + w x rB - A.v - w x rA.
    const Wide cdotX = ((B.vx + -B.w * r.rBy) - A.vx) - -A.w * r.rAy;
    const Wide cdotY = ((B.vy + B.w * r.rBx) - A.vy) - A.w * r.rAx;
    Wide rhsX = cdotX, rhsY = cdotY, bendX = splat(0.0), bendY = splat(0.0), impulseScale = splat(0.0);
    if constexpr (UseBias) {
        const Wide sepX = ((p.deltaX + (B.dpx - A.dpx)) + r.rBx) - r.rAx;
        const Wide sepY = ((p.deltaY + (B.dpy - A.dpy)) + r.rBy) - r.rAy;
        if (p.h > 0.0) bend(p, A.w, B.w, r, bendX, bendY);
        rhsX = p.massScale * (cdotX + p.biasRate * sepX) + bendX;
        rhsY = p.massScale * (cdotY + p.biasRate * sepY) + bendY;
        impulseScale = p.impulseScale;
    }
    const Wide m = p.invMassA + p.invMassB;
    const Wide k11 = (m + p.invIA * r.rAy * r.rAy) + p.invIB * r.rBy * r.rBy;
    const Wide k12 = -p.invIA * r.rAx * r.rAy - p.invIB * r.rBx * r.rBy;
    const Wide k22 = (m + p.invIA * r.rAx * r.rAx) + p.invIB * r.rBx * r.rBx;
    const Wide det = k11 * k22 - k12 * k12;
    const WideMask solvable = det > splat(0.0);  // else the scalar row does nothing (an unused lane)
    const Wide invDet = splat(1.0) / (solvable ? det : splat(1.0));
    const Wide solvedX = (k22 * rhsX - k12 * rhsY) * invDet, solvedY = (k11 * rhsY - k12 * rhsX) * invDet;
    Wide ix = -solvedX - impulseScale * p.impulseX;
    Wide iy = -solvedY - impulseScale * p.impulseY;
    if (UseBias && p.h > 0.0) {
        const Wide wA = A.w - p.invIA * (r.rAx * iy - r.rAy * ix);
        const Wide wB = B.w + p.invIB * (r.rBx * iy - r.rBy * ix);
        Wide againX, againY;
        bend(p, wA, wB, r, againX, againY);
        againX = againX - bendX;
        againY = againY - bendY;
        ix = ix - (k22 * againX - k12 * againY) * invDet;
        iy = iy - (k11 * againY - k12 * againX) * invDet;
    }
    const Wide Px = solvable ? ix : splat(0.0), Py = solvable ? iy : splat(0.0);
    p.impulseX = solvable ? p.impulseX + Px : p.impulseX;
    p.impulseY = solvable ? p.impulseY + Py : p.impulseY;
    apply(p, A, B, r, Px, Py);
}

struct WarmStartPins {
    template <bool>
    [[gnu::always_inline]] static void run(const PinBlock* begin, const PinBlock* end, SolverBody* states) {
        inPairs(begin, end, states, [](const PinBlock& p, WideSide& A, WideSide& B)
                    __attribute__((always_inline)) { warmStartBlock(p, A, B); });
    }
};
struct SolvePins {
    template <bool>
    [[gnu::always_inline]] static void run(PinBlock* begin, PinBlock* end, SolverBody* states, bool useBias) {
        if (useBias)
            inPairs(begin, end, states, [](PinBlock& p, WideSide& A, WideSide& B)
                        __attribute__((always_inline)) { solveBlock<true>(p, A, B); });
        else
            inPairs(begin, end, states, [](PinBlock& p, WideSide& A, WideSide& B)
                        __attribute__((always_inline)) { solveBlock<false>(p, A, B); });
    }
};

}  // namespace

void packPins(PinBlock& block, const JointConstraint* const* rows, std::uint32_t count,
              const std::vector<JointData>& joints) {
    startBlock(block, count);
    for (std::uint32_t lane = 0; lane < count; ++lane) {
        const JointConstraint& row = *rows[lane];
        const RevoluteJoint& pin = std::get<RevoluteJoint>(joints[row.joint].params);
        const int k = static_cast<int>(lane);
        packRowFields(block, row, lane);
        block.h = row.h;
        block.invH = row.invH;
        block.impulseX[k] = pin.linearImpulse.x();
        block.impulseY[k] = pin.linearImpulse.y();
        // As RevoluteJoint::warmStart sums it (from +0.0).
        block.turnImpulse[k] = 0.0 + pin.springImpulse + pin.motorImpulse + pin.lowerImpulse - pin.upperImpulse;
    }
}

void framePins(PinFrame& frame, const JointConstraint* const* rows, std::uint32_t count,
               const std::vector<JointData>& joints, const std::vector<BodyData>& bodies) {
    for (std::uint32_t lane = 0; lane < count; ++lane) {
        const JointData& joint = joints[rows[lane]->joint];
        const int k = static_cast<int>(lane);
        const Vec2 armA = armFromCenter(joint.localA, bodies[joint.a]);
        const Vec2 armB = armFromCenter(joint.localB, bodies[joint.b]);
        frame.armAx[k] = armA.x();
        frame.armAy[k] = armA.y();
        frame.armBx[k] = armB.x();
        frame.armBy[k] = armB.y();
        frame.bodyA[k] = joint.a;
        frame.bodyB[k] = joint.b;
    }
}

namespace {

// A side's centre, rotation and masses at the step's start, as prepareJoint takes them (rowSide).
struct SideNow {
    Vec2 center;
    Rotation q;
    double invMass, invI;
};
SideNow sideNow(std::int32_t index, std::uint32_t body, const SolverBodySim* sims,
                const std::vector<BodyData>& bodies) {
    if (index != kNullIndex) {  // awake: its step record holds rowSide's masses (dynamic ones, 0 otherwise)
        const SolverBodySim& s = sims[index];
        return {s.center0, s.q0, s.invMass, s.invInertia};
    }
    const BodyData& b = bodies[body];
    const RowSide side = rowSide(b);
    return {b.center, b.xf.q, side.invMass, side.invI};
}

}  // namespace

void refreshPins(PinBlock& block, const PinFrame& frame, const SolverBodySim* sims,
                 const std::vector<BodyData>& bodies, double arcStep, double invH, const Softness& softness) {
    block.writesA = block.writesB = 0;
    for (std::uint32_t lane = 0; lane < block.count; ++lane) {
        const int k = static_cast<int>(lane);
        // The fields prepareJoint gives a pin's row, into the lane as packPins puts them.
        JointConstraint row;
        row.joint = block.joint[k];
        row.indexA = block.indexA[k];
        row.indexB = block.indexB[k];
        const SideNow A = sideNow(row.indexA, frame.bodyA[k], sims, bodies);
        const SideNow B = sideNow(row.indexB, frame.bodyB[k], sims, bodies);
        row.anchorA = A.q.apply({frame.armAx[k], frame.armAy[k]});
        row.anchorB = B.q.apply({frame.armBx[k], frame.armBy[k]});
        row.deltaCenter = B.center - A.center;
        row.invMassA = A.invMass;
        row.invMassB = B.invMass;
        row.invIA = A.invI;
        row.invIB = B.invI;
        row.softness = softness;
        packRowFields(block, row, lane);
    }
    block.h = arcStep;
    block.invH = invH;
}

void warmStartPins(const PinBlock* begin, const PinBlock* end, SolverBody* states, WideCode code) {
    runWide<WarmStartPins>(code, begin, end, states);
}

void solvePins(PinBlock* begin, PinBlock* end, SolverBody* states, bool useBias, WideCode code) {
    runWide<SolvePins>(code, begin, end, states, useBias);
}

void storePins(const PinBlock* begin, const PinBlock* end, std::vector<JointData>& joints) {
    for (const PinBlock* p = begin; p != end; ++p)
        for (std::uint32_t lane = 0; lane < p->count; ++lane) {
            const int k = static_cast<int>(lane);
            std::get<RevoluteJoint>(joints[p->joint[lane]].params).linearImpulse = {p->impulseX[k], p->impulseY[k]};
        }
}

}  // namespace physim
