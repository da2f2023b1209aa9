#include "EnergyTally.hpp"

#include "ContactSolver.hpp"
#include "WorldImpl.hpp"

#include <cmath>

namespace physim {

void EnergyTally::startStep(std::size_t bodies, std::size_t groups, std::size_t blocks) {
    start_.assign(bodies, {});
    cursor_.assign(bodies, {});
    moved_.assign(bodies, {});
    drag_.assign(bodies, {});
    totals_.assign(blocks * kLanes * 3, 0.0);  // the step's totals start from nothing (prepareContacts)
    groups_.assign(groups, {});
    damping_.clear();
}

void EnergyTally::markStart(const SolverBody* st, const std::uint32_t* list, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t i = list[k];
        start_[i] = cursor_[i] = {st[i].v, st[i].w};
        drag_[i] = {};
    }
}

void EnergyTally::markEffect(LedgerEffect e, const SolverBody* st, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        if (e == LedgerEffect::Drag) {
            drag_[i].v += st[i].v - cursor_[i].v;
            drag_[i].w += st[i].w - cursor_[i].w;
        }
        cursor_[i] = {st[i].v, st[i].w};
    }
}

void EnergyTally::markMoved(const SolverBody* st, const std::uint32_t* list, std::size_t count) {
    for (std::size_t k = 0; k < count; ++k) moved_[list[k]] = {st[list[k]].v, st[list[k]].w};
}

namespace {

// Work of a motion change `d` (a body's impulse divided by its mass and inertia) at motion `at`, J.
double work(double mass, double inertia, const LedgerMotion& d, const LedgerMotion& at) {
    return mass * d.v.dot(at.v) + inertia * d.w * at.w;
}

}  // namespace

void EnergyTally::closeSubstep(const WorldImpl& w, std::size_t g, const SolverBodySim* sims, const SolverBody* st,
                               const std::uint32_t* list, std::size_t count, const ContactBlock* blocks,
                               const ContactBlockCold* cold, const BlockRows* rows, std::size_t first,
                               std::size_t blockCount, const JointConstraint* joints, std::size_t jointCount,
                               double h) {
    EnergyParts& parts = groups_[g];
    const double threshold = w.settings.restitutionThreshold;
    auto dynamic = [&](std::int32_t i) { return i >= 0 && sims[i].dynamic; };
    // A body's mean motion over the substep, and the one it moved with. A kinematic side's velocity is the same all
    // step (and another group may hold it): it is read as it is; a still side (kNullIndex) has none.
    auto mean = [&](std::int32_t i) {
        if (i < 0) return LedgerMotion{};
        if (!sims[i].dynamic) return LedgerMotion{st[i].v, st[i].w};
        const LedgerMotion& a = start_[static_cast<std::size_t>(i)];
        return LedgerMotion{0.5 * (a.v + st[i].v), 0.5 * (a.w + st[i].w)};
    };
    auto startOf = [&](std::int32_t i) {
        if (i < 0) return LedgerMotion{};
        return sims[i].dynamic ? start_[static_cast<std::size_t>(i)] : LedgerMotion{st[i].v, st[i].w};
    };
    auto movedOf = [&](std::int32_t i) {
        if (i < 0) return LedgerMotion{};
        return sims[i].dynamic ? moved_[static_cast<std::size_t>(i)] : LedgerMotion{st[i].v, st[i].w};
    };

    // Contact rows: each point's impulse over the substep is what its step total grew by (a bounce's blow
    // included). Normal impulses work at the mean motion: that is their exact share of the kinetic energy's change,
    // so a bounce with restitution e from normal speed v loses (1 - e^2) m v^2 / 2, and a resting contact none.
    // Friction works at the motion the bodies moved with: force times the distance slid. A kinematic side's share
    // at the mean motion is the work of what drives it.
    for (std::size_t b = first; b < first + blockCount; ++b) {
        const ContactBlock& block = blocks[b - first];
        const ContactBlockCold& c = cold[b - first];
        for (std::uint32_t lane = 0; lane < rows[b].count; ++lane) {
            const int k = static_cast<int>(lane);
            const std::int32_t indexA = block.indexA[k], indexB = block.indexB[k];
            const Vec2 normal(block.nx[k], block.ny[k]);
            const LedgerMotion A = mean(indexA), B = mean(indexB);
            double* const last = totals_.data() + (b * kLanes + lane) * 3;
            // Impulse `impulse` along `dir` (on B; its opposite on A), moments rA and rB (r x dir): its work at the
            // mean motions; a kinematic side's share goes to `work` (what drives it gives it).
            auto apply = [&](double impulse, const Vec2& dir, double rA, double rB) {
                const double onA = -impulse * (dir.dot(A.v) + rA * A.w), onB = impulse * (dir.dot(B.v) + rB * B.w);
                if (!dynamic(indexA) && indexA >= 0) parts.work -= onA;
                if (!dynamic(indexB) && indexB >= 0) parts.work -= onB;
                return onA + onB;
            };
            for (int i = 0; i < c.lanes[k].pointCount; ++i) {
                const double total = c.totalNormal[i][k], impulse = total - last[i];
                last[i] = total;
                if (impulse == 0.0) continue;
                const double rnA = -block.points[i].negRnA[k], rnB = block.points[i].rnB[k];
                const double done = apply(impulse, normal, rnA, rnB);
                // An impact: the point approached faster than restitution's threshold at the substep's start, or
                // bounced (a blow, not in the accumulated impulse, made the step's total grow by more than the rows
                // hold).
                const LedgerMotion sA = startOf(indexA), sB = startOf(indexB);
                const double approach = normal.dot(sB.v - sA.v) + rnB * sB.w - rnA * sA.w;
                const bool met = -approach > threshold;
                const bool bounced = impulse - block.points[i].normalImpulse[k] > 1e-9 * std::abs(impulse);
                (met || bounced ? parts.impacts : parts.soft) += done;
            }
            const double total = block.totalTangent[k], impulse = total - last[2];
            last[2] = total;
            if (impulse == 0.0) continue;
            const Vec2 t = perp(normal);
            const double rtA = -block.negRtA[k], rtB = block.rtB[k];
            apply(impulse, t, rtA, rtB);
            const LedgerMotion movedA = movedOf(indexA), movedB = movedOf(indexB);
            parts.friction += impulse * (t.dot(movedB.v) + rtB * movedB.w - t.dot(movedA.v) - rtA * movedA.w);
        }
    }
    // Springs' damping, at the mean motion.
    for (const LedgerDamping& d : damping_) {
        const LedgerMotion A = mean(d.indexA), B = mean(d.indexB);
        const double onB = d.impulse.dot(B.v + cross(B.w, d.rB)), onA = -d.impulse.dot(A.v + cross(A.w, d.rA));
        parts.soft += (dynamic(d.indexB) ? onB : 0.0) + (dynamic(d.indexA) ? onA : 0.0);
    }
    damping_.clear();

    // Motors (revolute, wheel and prismatic joints): the substep's motor impulse (what the joint holds at its end,
    // as for contacts) times the joint's relative speed at the mean motion: the work the motor does.
    for (std::size_t k = 0; k < jointCount; ++k) {
        const JointConstraint& row = joints[k];
        const JointData& joint = w.joints[row.joint];
        const LedgerMotion A = mean(row.indexA), B = mean(row.indexB);
        if (const auto* r = std::get_if<RevoluteJoint>(&joint.params); r && r->enableMotor)
            parts.work += r->motorImpulse * (B.w - A.w);
        else if (const auto* wh = std::get_if<WheelJoint>(&joint.params); wh && wh->enableMotor)
            parts.work += wh->motorImpulse * (B.w - A.w);
        else if (const auto* p = std::get_if<PrismaticJoint>(&joint.params); p && p->enableMotor)
            parts.work += p->motorImpulse * row.axis.dot(B.v + cross(B.w, row.anchorB) - A.v - cross(A.w, row.anchorA));
    }
    // Bodies: the user's forces and drag work at the mean motion. Joints' impulses are left to the residue: an
    // ideal joint does no work (its motor's share is counted above), and what the method's joint rows do to the energy (a pendulum's swing of kinetic
    // and potential energy against each other, bounded) is its own share.
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t i = list[k];
        const SolverBodySim& sim = sims[i];
        if (!sim.dynamic) continue;
        const BodyData& b = w.bodies[sim.body];
        const LedgerMotion at = mean(static_cast<std::int32_t>(i));
        parts.work += h * (b.force.dot(at.v) + b.torque * at.w);
        parts.drag += work(b.mass, b.inertia, drag_[i], at);
    }
}

EnergyParts EnergyTally::stepParts() const {
    EnergyParts sum;
    for (const EnergyParts& p : groups_) sum += p;
    return sum;
}

double kineticEnergyOf(const WorldImpl& w) {
    double e = 0.0;
    for (const BodyData& b : w.bodies)
        if (b.alive && b.type == BodyType::Dynamic) e += b.kineticEnergy();
    return e;
}

double potentialEnergyOf(const WorldImpl& w, GravitationPotential* cache) {
    double e = 0.0;
    for (const BodyData& b : w.bodies)
        if (b.alive && b.type == BodyType::Dynamic) e -= b.mass * b.gravityFactor() * w.settings.gravity.dot(b.center);
    for (const std::uint32_t index : w.effects.springs.members()) {
        const JointData& j = w.joints[index];
        const SpringJoint& spring = std::get<SpringJoint>(j.params);
        const BodyData& B = w.bodies[j.b];
        const Vec2 end = B.xf.apply(j.localB);
        const Vec2 start = j.toWorld ? j.localA : w.bodies[j.a].xf.apply(j.localA);
        const double stretch = (end - start).norm() - spring.restLength;
        e += 0.5 * spring.stiffness * stretch * stretch;
    }
    const GravitationEffect& gravitation = w.effects.gravitation;
    if (gravitation.active()) {
        // Over all pairs, from flat arrays (a pair costs a few multiplies and one square root).
        std::vector<double> x, y, m;
        for (const std::uint32_t slot : gravitation.members()) {
            const BodyData& b = w.bodies[slot];
            if (b.mass == 0.0) continue;
            x.push_back(b.center.x());
            y.push_back(b.center.y());
            m.push_back(b.mass);
        }
        const double G = gravitation.settings().G, eps2 = gravitation.settings().softening * gravitation.settings().softening;
        // With a cache: the last sum's bodies, masses and settings unchanged (a step's start after the step before),
        // its value.
        GravitationPotential fresh;
        GravitationPotential& last = cache ? *cache : fresh;
        if (!cache || !(last.x == x && last.y == y && last.m == m && last.G == G && last.eps2 == eps2)) {
            double sum = 0.0;
            for (std::size_t i = 0; i < m.size(); ++i) {
                double row = 0.0;  // m_j / r_ij over the bodies after i
                for (std::size_t k = i + 1; k < m.size(); ++k) {
                    const double dx = x[k] - x[i], dy = y[k] - y[i];
                    row += m[k] / std::sqrt(dx * dx + dy * dy + eps2);
                }
                sum -= G * m[i] * row;
            }
            last = {std::move(x), std::move(y), std::move(m), G, eps2, sum};
        }
        e += last.value;
    }
    return e;
}

}  // namespace physim
