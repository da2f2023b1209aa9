#include "PinChains.hpp"

#include "../JointData.hpp"
#include "RevoluteJoint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>

namespace physim {
namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

// The pin's neighbour through one of its bodies: the body's other pin, if it has two.
std::uint32_t neighbour(std::uint32_t pin, std::int32_t index, double invMass, const std::vector<std::uint32_t>& count,
                        const std::vector<std::uint32_t>& pinOf) {
    if (!rowMoves(index, invMass)) return kNone;
    const std::size_t b = static_cast<std::size_t>(index);
    if (count[b] != 2) return kNone;
    return pinOf[2 * b] == pin ? pinOf[2 * b + 1] : pinOf[2 * b];
}

// J's block of one body in a pin's row, times M^-1 times another pin's block on that body (signs aside): the
// body's share of K(i, j), where p = perp(r) is the velocity a unit spin gives the anchor.
Eigen::Matrix2d bodyShare(double invMass, double invI, const Vec2& ri, const Vec2& rj) {
    return invMass * Eigen::Matrix2d::Identity() + invI * perp(ri) * perp(rj).transpose();
}

// A symmetric positive 2x2 matrix's inverse; false when it is (nearly) singular.
bool invert(const Eigen::Matrix2d& m, Eigen::Matrix2d& inverse) {
    const double det = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
    const double scale = m(0, 0) + m(1, 1);
    if (!(det > 1e-12 * scale * scale)) return false;
    inverse << m(1, 1), -m(0, 1), -m(1, 0), m(0, 0);
    inverse /= det;
    return true;
}

}  // namespace

void PinChains::clear(std::size_t groups) {
    rows.clear();
    chainStart.assign(1, 0);
    groupChainStart.assign(groups + 1, 0);
}

void PinChains::find(std::vector<JointConstraint>& jointRows, std::size_t bodies, double massRatio) {
    rows.clear();
    chainStart.assign(1, 0);
    if (!std::isfinite(massRatio) || jointRows.size() < 2) return;
    const std::size_t n = jointRows.size();
    state_.assign(n, 0);
    pinCount_.assign(bodies, 0);
    pinOf_.resize(2 * bodies);
    auto count = [&](std::uint32_t k, bool store) {
        const JointConstraint& r = jointRows[k];
        for (const auto& [index, invMass] : {std::make_pair(r.indexA, r.invMassA), std::make_pair(r.indexB, r.invMassB)}) {
            if (!rowMoves(index, invMass)) continue;
            const std::size_t b = static_cast<std::size_t>(index);
            if (store && pinCount_[b] < 2) pinOf_[2 * b + pinCount_[b]] = k;
            ++pinCount_[b];
        }
    };
    // Pins, then those of a body pinned three times or more are left to the colours (a tree's fork).
    for (std::uint32_t k = 0; k < n; ++k) {
        const JointConstraint& r = jointRows[k];
        if (r.lanes != RowLanes::Pin || !(rowMoves(r.indexA, r.invMassA) || rowMoves(r.indexB, r.invMassB))) continue;
        state_[k] = 1;
        count(k, false);
    }
    for (std::uint32_t k = 0; k < n; ++k) {
        if (state_[k] != 1) continue;
        const JointConstraint& r = jointRows[k];
        const bool forkA = rowMoves(r.indexA, r.invMassA) && pinCount_[static_cast<std::size_t>(r.indexA)] > 2;
        const bool forkB = rowMoves(r.indexB, r.invMassB) && pinCount_[static_cast<std::size_t>(r.indexB)] > 2;
        if (forkA || forkB) state_[k] = 2;
    }
    std::fill(pinCount_.begin(), pinCount_.end(), 0u);
    for (std::uint32_t k = 0; k < n; ++k)
        if (state_[k] == 1) count(k, true);

    // Walk each chain from an end (a pin with at least one side that leads to no other pin); pins never reached
    // lie on loops, which stay with the colours.
    auto next = [&](std::uint32_t pin, std::uint32_t from) {
        const JointConstraint& r = jointRows[pin];
        const std::uint32_t a = neighbour(pin, r.indexA, r.invMassA, pinCount_, pinOf_);
        const std::uint32_t b = neighbour(pin, r.indexB, r.invMassB, pinCount_, pinOf_);
        return a != kNone && a != from ? a : (b != kNone && b != from ? b : kNone);
    };
    for (std::uint32_t k = 0; k < n; ++k) {
        if (state_[k] != 1) continue;
        const JointConstraint& r = jointRows[k];
        const bool end = neighbour(k, r.indexA, r.invMassA, pinCount_, pinOf_) == kNone ||
                         neighbour(k, r.indexB, r.invMassB, pinCount_, pinOf_) == kNone;
        if (!end) continue;
        const std::size_t first = rows.size();
        double minInvMass = std::numeric_limits<double>::infinity(), maxInvMass = 0.0;
        for (std::uint32_t pin = k, from = kNone; pin != kNone;) {
            state_[pin] = 3;
            rows.push_back(pin);
            const JointConstraint& p = jointRows[pin];
            for (const double inv : {p.invMassA, p.invMassB}) {
                if (inv == 0.0) continue;
                minInvMass = std::min(minInvMass, inv);
                maxInvMass = std::max(maxInvMass, inv);
            }
            const std::uint32_t after = next(pin, from);
            from = pin;
            pin = after;
        }
        const bool chain = rows.size() - first >= 2 && maxInvMass >= massRatio * minInvMass;
        if (!chain) {
            rows.resize(first);
            continue;
        }
        for (std::size_t i = first; i < rows.size(); ++i) jointRows[rows[i]].chained = true;
        chainStart.push_back(static_cast<std::uint32_t>(rows.size()));
    }
}

void solveChain(const std::uint32_t* order, std::size_t count, const JointConstraint* rows,
                std::vector<JointData>& joints, SolverBody* states, bool useBias, ChainScratch& scratch) {
    if (scratch.pins.size() < count) scratch.pins.resize(count);
    ChainScratch::Pin* const pins = scratch.pins.data();
    // K(i, i) and the right side; K(i, i-1) from the body pins i-1 and i share (A's side counts -1, B's +1).
    auto shared = [&](std::size_t i) {
        const JointConstraint& r = rows[order[i]];
        const JointConstraint& q = rows[order[i - 1]];
        const ChainScratch::Pin& pi = pins[i];
        const ChainScratch::Pin& pq = pins[i - 1];
        Eigen::Matrix2d k = Eigen::Matrix2d::Zero();
        auto add = [&](std::int32_t si, double sign, const Vec2& ri, std::int32_t sq, double signQ, const Vec2& rq,
                       double invMass, double invI) {
            if (si == sq && rowMoves(si, invMass)) k += sign * signQ * bodyShare(invMass, invI, ri, rq);
        };
        add(r.indexA, -1.0, pi.rA, q.indexA, -1.0, pq.rA, r.invMassA, r.invIA);
        add(r.indexA, -1.0, pi.rA, q.indexB, 1.0, pq.rB, r.invMassA, r.invIA);
        add(r.indexB, 1.0, pi.rB, q.indexA, -1.0, pq.rA, r.invMassB, r.invIB);
        add(r.indexB, 1.0, pi.rB, q.indexB, 1.0, pq.rB, r.invMassB, r.invIB);
        return k;
    };
    bool solvable = true;
    for (std::size_t i = 0; i < count && solvable; ++i) {
        const JointConstraint& r = rows[order[i]];
        ChainScratch::Pin& p = pins[i];
        p.a = loadSide(states, r.indexA);
        p.b = loadSide(states, r.indexB);
        p.rA = p.a.dq.apply(r.anchorA);
        p.rB = p.b.dq.apply(r.anchorB);
        p.rhs = relativeVelocity(p.a, p.b, p.rA, p.rB);
        if (useBias) {
            const Vec2 separation = r.deltaCenter + (p.b.dp - p.a.dp) + p.rB - p.rA;
            p.bend = r.h > 0.0 ? pointBend(r, p.a.w, p.b.w, p.rA, p.rB) : Vec2::Zero();
            p.rhs = r.softness.massScale * (p.rhs + r.softness.biasRate * separation) + p.bend;
        }
        Eigen::Matrix2d d = bodyShare(r.invMassA, r.invIA, p.rA, p.rA) + bodyShare(r.invMassB, r.invIB, p.rB, p.rB);
        if (i > 0) {
            const Eigen::Matrix2d below = shared(i);  // K(i, i-1)
            p.lower = below * pins[i - 1].invD;
            d -= p.lower * below.transpose();
            p.rhs -= p.lower * pins[i - 1].rhs;
        }
        solvable = invert(d, p.invD);
    }
    if (!solvable) {
        for (std::size_t i = 0; i < count; ++i) {
            const JointConstraint& r = rows[order[i]];
            MotionSide A = loadSide(states, r.indexA), B = loadSide(states, r.indexB);
            solvePoint(r, std::get<RevoluteJoint>(joints[r.joint].params).linearImpulse, A, B, useBias);
            storeSide(states, r.indexA, r.invMassA, A);
            storeSide(states, r.indexB, r.invMassB, B);
        }
        return;
    }
    // Back substitution: x(i) = D(i)^-1 y(i) - L(i+1)^T x(i+1); rhs now holds y, then x.
    pins[count - 1].rhs = pins[count - 1].invD * pins[count - 1].rhs;
    for (std::size_t i = count - 1; i-- > 0;)
        pins[i].rhs = pins[i].invD * pins[i].rhs - pins[i + 1].lower.transpose() * pins[i + 1].rhs;
    for (std::size_t i = 0; i < count; ++i) {
        const JointConstraint& r = rows[order[i]];
        const double impulseScale = useBias ? r.softness.impulseScale : 0.0;
        Vec2& accumulated = std::get<RevoluteJoint>(joints[r.joint].params).linearImpulse;
        const Vec2 impulse = -pins[i].rhs - impulseScale * accumulated;
        accumulated += impulse;
        if (rowMoves(r.indexA, r.invMassA)) {
            SolverBody& a = states[r.indexA];
            a.v -= r.invMassA * impulse;
            a.w -= r.invIA * cross(pins[i].rA, impulse);
        }
        if (rowMoves(r.indexB, r.invMassB)) {
            SolverBody& b = states[r.indexB];
            b.v += r.invMassB * impulse;
            b.w += r.invIB * cross(pins[i].rB, impulse);
        }
    }
    if (!useBias || count == 0 || rows[order[0]].h == 0.0) return;
    // The bend again with the turns the block gave, pin by pin (a small correction: solvePoint's second solve).
    for (std::size_t i = 0; i < count; ++i) {
        const JointConstraint& r = rows[order[i]];
        MotionSide A = loadSide(states, r.indexA), B = loadSide(states, r.indexB);
        const Vec2 change = pointBend(r, A.w, B.w, pins[i].rA, pins[i].rB) - pins[i].bend;
        Vec2 solved;
        if (!solvePointMass(r, pins[i].rA, pins[i].rB, change, solved)) continue;
        const Vec2 again = -solved;
        std::get<RevoluteJoint>(joints[r.joint].params).linearImpulse += again;
        applyImpulse(r, A, B, pins[i].rA, pins[i].rB, again);
        storeSide(states, r.indexA, r.invMassA, A);
        storeSide(states, r.indexB, r.invMassB, B);
    }
}

}  // namespace physim
