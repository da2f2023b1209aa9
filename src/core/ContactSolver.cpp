#include "ContactSolver.hpp"

#include "ContactData.hpp"
#include "Impulse.hpp"

#include <algorithm>
#include <cmath>

namespace physim {

Softness makeSoftness(double hertz, double dampingRatio, double h) {
    if (hertz <= 0.0) return {};  // rigid
    constexpr double kMaxHertzPerSubstepRate = 0.25;
    const double omega = 2.0 * 3.14159265358979323846 * std::min(hertz, kMaxHertzPerSubstepRate * (1.0 / h));
    const double a1 = 2.0 * dampingRatio + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

namespace {

// The rows' impulses along their fixed directions, with the moments prepared once per step (Turns: see solveRow).
template <bool Turns = true>
void pushNormal(const ContactConstraint& c, MotionSide& A, MotionSide& B, const ContactConstraintPoint& p,
                double lambda) {
    const Vec2 P = lambda * c.normal;
    A.v -= c.invMassA * P;
    B.v += c.invMassB * P;
    if constexpr (Turns) {
        A.w -= c.invIA * lambda * p.rnA;
        B.w += c.invIB * lambda * p.rnB;
    }
}

inline double normalSpeed(const ContactConstraint& c, const MotionSide& A, const MotionSide& B,
                          const ContactConstraintPoint& p) {
    return c.normal.dot(B.v - A.v) + B.w * p.rnB - A.w * p.rnA;
}

template <bool Turns = true>
void pushTangent(const ContactConstraint& c, MotionSide& A, MotionSide& B, double lambda) {
    const Vec2 P = lambda * perp(c.normal);
    A.v -= c.invMassA * P;
    B.v += c.invMassB * P;
    if constexpr (Turns) {
        A.w -= c.invIA * lambda * c.rtA;
        B.w += c.invIB * lambda * c.rtB;
    }
}

template <bool Turns>
void warmStartRow(const ContactConstraint& c, SolverBody* states) {
    MotionSide A = loadSide(states, c.indexA), B = loadSide(states, c.indexB);
    for (int i = 0; i < c.pointCount; ++i) pushNormal<Turns>(c, A, B, c.points[i], c.points[i].normalImpulse);
    pushTangent<Turns>(c, A, B, c.tangentImpulse);
    storeSide(states, c.indexA, c.invMassA, A);
    storeSide(states, c.indexB, c.invMassB, B);
}

}  // namespace

void prepareContact(ContactConstraint& c, const ContactData& contact, const std::vector<BodyData>& bodies,
                    const Vec2& gravity) {
    const BodyData& A = bodies[contact.a];
    const BodyData& B = bodies[contact.b];
    const Manifold& m = contact.manifold;
    const RowSide sideA = rowSide(A), sideB = rowSide(B);
    c.indexA = sideA.index;
    c.indexB = sideB.index;
    c.invMassA = sideA.invMass;
    c.invIA = sideA.invI;
    c.invMassB = sideB.invMass;
    c.invIB = sideB.invI;
    c.turns = sideA.turns || sideB.turns;
    // The paper's combination rules: restitution min, friction coefficients averaged.
    c.restitution = std::min(A.restitution, B.restitution);
    c.staticFriction = 0.5 * (A.staticFriction + B.staticFriction);
    c.dynamicFriction = 0.5 * (A.dynamicFriction + B.dynamicFriction);
    c.normal = m.normal;
    c.pointCount = m.pointCount;
    auto acceleration = [&](const BodyData& b, bool moves) -> Vec2 {
        return moves ? Vec2(b.gravityFactor() * gravity + b.invMass * b.force) : Vec2::Zero();
    };
    c.normalAcceleration = c.normal.dot(acceleration(B, sideB.moves) - acceleration(A, sideA.moves));
    c.tangentImpulse = 0.0;
    c.sliding = contact.sliding;
    Vec2 sumA = Vec2::Zero(), sumB = Vec2::Zero();
    for (int i = 0; i < m.pointCount; ++i) {
        const ContactPoint& mp = m.points[i];
        ContactConstraintPoint& cp = c.points[i];
        cp.anchorA = mp.point - A.center;
        cp.anchorB = mp.point - B.center;
        cp.rnA = cross(cp.anchorA, c.normal);
        cp.rnB = cross(cp.anchorB, c.normal);
        cp.ndA = c.normal.dot(cp.anchorA);
        cp.ndB = c.normal.dot(cp.anchorB);
        cp.baseSeparation = mp.separation - c.normal.dot(cp.anchorB - cp.anchorA);
        cp.normalImpulse = mp.normalImpulse;
        cp.maxNormalImpulse = 0.0;
        cp.normalMass = massAlong(c, cp.anchorA, cp.anchorB, c.normal);
        cp.relativeVelocity = 0.0;
        cp.engaged = false;
        c.tangentImpulse += mp.tangentImpulse;
        sumA += cp.anchorA;
        sumB += cp.anchorB;
    }
    c.invDet = 0.0;
    if (m.pointCount == 2) {
        const Vec2 n = c.normal;
        const ContactConstraintPoint& p1 = c.points[0];
        const ContactConstraintPoint& p2 = c.points[1];
        const double a1 = cross(p1.anchorA, n), b1 = cross(p1.anchorB, n);
        const double a2 = cross(p2.anchorA, n), b2 = cross(p2.anchorB, n);
        const double lin = c.invMassA + c.invMassB;
        c.k11 = lin + c.invIA * a1 * a1 + c.invIB * b1 * b1;
        c.k22 = lin + c.invIA * a2 * a2 + c.invIB * b2 * b2;
        c.k12 = lin + c.invIA * a1 * a2 + c.invIB * b1 * b2;
        const double det = c.k11 * c.k22 - c.k12 * c.k12;
        // Nearly coincident points make K singular: then one point at a time.
        if (c.k11 * c.k11 < 1000.0 * det) c.invDet = 1.0 / det;
    }
    const double share = m.pointCount > 0 ? 1.0 / m.pointCount : 0.0;
    c.frictionAnchorA = share * sumA;
    c.frictionAnchorB = share * sumB;
    c.tangentMass = massAlong(c, c.frictionAnchorA, c.frictionAnchorB, perp(c.normal));
    c.rtA = cross(c.frictionAnchorA, perp(c.normal));
    c.rtB = cross(c.frictionAnchorB, perp(c.normal));
}

void warmStartContacts(ContactConstraint* begin, ContactConstraint* end, SolverBody* states) {
    for (ContactConstraint* c = begin; c != end; ++c) {
        if (c->turns) warmStartRow<true>(*c, states);
        else warmStartRow<false>(*c, states);
    }
}

namespace {


// A point that starts to push (it had no impulse): remember how it met; if it meets fast enough, it bounces now.
// It leaves at e times the meeting speed, placed so that for e = 1 semi-implicit Euler retraces the fall exactly (no energy
// gained or lost):
//   met in the solve pass (positions not yet moved this substep): the separation at the substep's end becomes e
//   times the gap it had at the substep's start, as if it had reflected off the surface on time;
//   met in the relax pass (positions already moved): the reflection of the next substep's fall leaves at the
//   speed before that substep's gravity.
// Bouncing at once, not after the substep, lets a struck body pass the blow on within the same pass (a cradle's
// balls, one in and one out). The bounce is not part of the accumulated impulse, so no later pass (relax) can take
// it back; a point that separates and meets again (a ball between a wall and another ball) bounces again.
// What a point owes when it bounces: the normal speed to reach (m/s) and the gap to open now (m).
struct Bounce {
    bool active = false;
    double target = 0.0;  // normal speed to leave at, m/s
    double gap = 0.0;     // separation to open now, m
};

Bounce planBounce(ContactConstraint& c, ContactConstraintPoint& cp, double vn, double separation,
                  const ContactPass& pass) {
    cp.relativeVelocity = cp.engaged ? std::min(cp.relativeVelocity, vn) : vn;  // the fastest meeting, for events
    cp.engaged = true;
    const double e = c.restitution;
    const double limit = e < 1.0 ? -pass.restitutionThreshold : 0.0;  // e = 1 bounces at any speed
    if (!(e > 0.0 && vn < limit)) return {};
    const double speed = -vn - (pass.useBias ? 0.0 : pass.h * c.normalAcceleration);
    const double target = e * speed;
    if (!pass.useBias) return {true, target, 0.0};
    // Met in the solve pass, a gap s before contact: open the gap now so that after this substep's move
    // (target h) the separation is e s, the mirror of the approach (an exact retrace for e = 1).
    const double s = std::max(separation, 0.0);
    return {true, target, (e - 1.0) * s - target * pass.h};
}

// Moves the bodies apart along the normal at the point as a position "impulse" q (kg m) would.
void shift(const ContactConstraint& c, const ContactConstraintPoint& cp, MotionSide& A, MotionSide& B, double q) {
    const Vec2 P = q * c.normal;
    const Vec2 rA = A.dq.apply(cp.anchorA), rB = B.dq.apply(cp.anchorB);
    const double turnA = -c.invIA * cross(rA, P), turnB = c.invIB * cross(rB, P);
    A.dp -= c.invMassA * P;
    B.dp += c.invMassB * P;
    A.dq = compose(rotationBy(turnA), A.dq);
    B.dq = compose(rotationBy(turnB), B.dq);
    A.dAngle += turnA;
    B.dAngle += turnB;
}

// Applies the bounces. Both points of a face bounce together (a box landing flat stays level): the impulses x >= 0
// bring each point to its target speed, or leave it at x = 0 already leaving faster, as the normal rows' 2x2
// complementarity problem does. Point by point would let the second point's blow undo the first's target and
// gain energy (a thin spinning box struck on both corners). A bounce is a blow, not a lasting push: nothing of it
// is warm-started into the next substep. What this pass gave the point to push an overlap apart (`push`) is taken
// back first: the pair leaves at e times its meeting speed, not at the push-out speed (an overlapping pair that met
// slowly would otherwise keep that speed: energy from nowhere); later passes push the overlap out as usual. What
// other contacts' push-out gave the bodies in this substep (`othersPush`, along each point's normal) is left out of
// the speeds the bounce answers, for the same reason: it stays on the bodies, and their relax pass takes it back.
void applyBounces(ContactConstraint& c, MotionSide& A, MotionSide& B, const Bounce (&bounce)[2],
                  const double (&push)[2], const double (&othersPush)[2]) {
    for (int i = 0; i < c.pointCount; ++i)
        if (bounce[i].active && push[i] > 0.0) pushNormal(c, A, B, c.points[i], -push[i]);
    // The speed the bounce answers leaves out what other contacts' push-out gave the bodies in this substep.
    auto speedAt = [&](int i) { return normalSpeed(c, A, B, c.points[i]) - othersPush[i]; };
    double x[2] = {0.0, 0.0}, q[2] = {0.0, 0.0};
    if (c.pointCount == 2 && bounce[0].active && bounce[1].active) {
        const double d1 = bounce[0].target - speedAt(0), d2 = bounce[1].target - speedAt(1);
        const double g1 = bounce[0].gap, g2 = bounce[1].gap;
        const double y1 = (c.k22 * d1 - c.k12 * d2) * c.invDet, y2 = (c.k11 * d2 - c.k12 * d1) * c.invDet;
        if (c.invDet > 0.0 && y1 >= 0.0 && y2 >= 0.0) {
            x[0] = y1, x[1] = y2;
            q[0] = (c.k22 * g1 - c.k12 * g2) * c.invDet, q[1] = (c.k11 * g2 - c.k12 * g1) * c.invDet;
        } else if (d1 > 0.0 && d2 - c.k12 * d1 / c.k11 <= 0.0) {
            x[0] = d1 / c.k11, q[0] = g1 / c.k11;  // the first bounces; the second then leaves fast enough
        } else if (d2 > 0.0 && d1 - c.k12 * d2 / c.k22 <= 0.0) {
            x[1] = d2 / c.k22, q[1] = g2 / c.k22;
        } else if (d1 > 0.0 || d2 > 0.0) {
            // Degenerate face (the points' rows nearly equal): one blow, at the point that needs more.
            const int i = d1 / c.k11 >= d2 / c.k22 ? 0 : 1;
            x[i] = (i == 0 ? d1 : d2) / (i == 0 ? c.k11 : c.k22);
            q[i] = (i == 0 ? g1 : g2) / (i == 0 ? c.k11 : c.k22);
        }
    } else {
        for (int i = 0; i < c.pointCount; ++i) {
            if (!bounce[i].active) continue;
            x[i] = std::max(c.points[i].normalMass * (bounce[i].target - speedAt(i)), 0.0);
            q[i] = bounce[i].gap * c.points[i].normalMass;
        }
    }
    for (int i = 0; i < c.pointCount; ++i) {
        if (!bounce[i].active) continue;
        ContactConstraintPoint& cp = c.points[i];
        pushNormal(c, A, B, cp, x[i]);
        cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, cp.normalImpulse + x[i]);
        cp.normalImpulse = 0.0;
    }
    for (int i = 0; i < c.pointCount; ++i)
        if (bounce[i].active && q[i] != 0.0) shift(c, c.points[i], A, B, q[i]);
}

}  // namespace

namespace {

// What the solve passes' push-out has given a body in the present substep, as a velocity (zero for an immovable
// side, or none yet).
MotionSide pushedSide(const ContactPass& pass, std::int32_t index) {
    MotionSide side;
    if (pass.pushes && index != kNullIndex && pass.pushes[index].substep == pass.substep) {
        side.v = pass.pushes[index].v;
        side.w = pass.pushes[index].w;
    }
    return side;
}

// Adds a point's push impulse (N s along the normal) to what its bodies have been given by push-out this substep.
// Only sides the row can move are written (a kinematic body is read by many rows of one colour).
void recordPush(const ContactPass& pass, const ContactConstraint& c, const ContactConstraintPoint& cp, double impulse) {
    if (!pass.pushes) return;
    MotionSide A = pushedSide(pass, c.indexA), B = pushedSide(pass, c.indexB);
    pushNormal(c, A, B, cp, impulse);
    if (c.indexA != kNullIndex && c.invMassA != 0.0) pass.pushes[c.indexA] = {A.v, A.w, pass.substep};
    if (c.indexB != kNullIndex && c.invMassB != 0.0) pass.pushes[c.indexB] = {B.v, B.w, pass.substep};
}

// One row's pass. Turns is false for a row neither of whose bodies can turn (rotation locked, or immovable and not
// spinning; prepareContact decides once per step): the same rule with its angular terms left out, so a scene whose
// bodies all have rotation locked does no rotation work in its hottest loop.
template <bool Turns>
void solveRow(ContactConstraint& c, SolverBody* states, SolverBody& still, const ContactPass& pass) {
    SolverBody& sa = c.indexA == kNullIndex ? still : states[c.indexA];
    SolverBody& sb = c.indexB == kNullIndex ? still : states[c.indexB];
    const double nx = c.normal.x(), ny = c.normal.y();
    const double mA = c.invMassA, iA = c.invIA, mB = c.invMassB, iB = c.invIB;
    double vAx = sa.v.x(), vAy = sa.v.y(), wA = Turns ? sa.w : 0.0;
    double vBx = sb.v.x(), vBy = sb.v.y(), wB = Turns ? sb.w : 0.0;
    // B's speed relative to A along (dx, dy) at lever-arm moments armA, armB; an impulse d along it (B +, A -).
    auto speed = [&](double dx, double dy, double armA, double armB) {
        if constexpr (Turns) return dx * (vBx - vAx) + dy * (vBy - vAy) + wB * armB - wA * armA;
        else return dx * (vBx - vAx) + dy * (vBy - vAy);
    };
    auto apply = [&](double d, double dx, double dy, double armA, double armB) {
        vAx -= mA * d * dx;
        vAy -= mA * d * dy;
        vBx += mB * d * dx;
        vBy += mB * d * dy;
        if constexpr (Turns) {
            wA -= iA * d * armA;
            wB += iB * d * armB;
        }
    };
    const double normalShift = nx * (sb.dp.x() - sa.dp.x()) + ny * (sb.dp.y() - sa.dp.y());
    const int count = c.pointCount;
    double separation[2], bias[2], massScale[2], leak[2], before[2];
    for (int i = 0; i < count; ++i) {
        const ContactConstraintPoint& cp = c.points[i];
        // Separation now: the start's, moved by the bodies' displacement and turn since the step began
        // (n . R a = cos(turn) n . a + sin(turn) a x n for an anchor a turned by R).
        double s;
        if constexpr (Turns)
            s = normalShift + (sb.dq.c * cp.ndB + sb.dq.s * cp.rnB) - (sa.dq.c * cp.ndA + sa.dq.s * cp.rnA) +
                cp.baseSeparation;
        else
            s = normalShift + cp.ndB - cp.ndA + cp.baseSeparation;
        separation[i] = s;
        if (s > 0.0) {  // speculative: close the gap in this substep, no further
            bias[i] = s * pass.invH;
            massScale[i] = 1.0;
            leak[i] = 0.0;
        } else if (pass.useBias) {
            bias[i] = std::max(pass.softness.biasRate * s, -pass.maxPushVelocity);
            massScale[i] = pass.softness.massScale;
            leak[i] = pass.softness.impulseScale;
        } else {
            bias[i] = 0.0;
            massScale[i] = 1.0;
            leak[i] = 0.0;
        }
        before[i] = speed(nx, ny, cp.rnA, cp.rnB);
    }
    double delta[2] = {0.0, 0.0};  // this pass's change of each accumulated impulse
    const bool block = count == 2 && c.invDet > 0.0;
    if (block) {
        // Both points at once: the 2x2 complementarity problem on the accumulated impulses
        // (w = K (y - x) + b >= 0, y >= 0, y . w = 0; four cases), then the soft scaling per point.
        const double x1 = c.points[0].normalImpulse, x2 = c.points[1].normalImpulse;
        const double b1 = before[0] + bias[0] - (c.k11 * x1 + c.k12 * x2);
        const double b2 = before[1] + bias[1] - (c.k12 * x1 + c.k22 * x2);
        double y1 = -(c.k22 * b1 - c.k12 * b2) * c.invDet;
        double y2 = -(c.k11 * b2 - c.k12 * b1) * c.invDet;
        if (!(y1 >= 0.0 && y2 >= 0.0)) {
            y1 = -b1 / c.k11;  // only point 1 pushes; point 2 must then separate
            y2 = 0.0;
            if (!(y1 >= 0.0 && c.k12 * y1 + b2 >= 0.0)) {
                y1 = 0.0;  // only point 2 pushes
                y2 = -b2 / c.k22;
                if (!(y2 >= 0.0 && c.k12 * y2 + b1 >= 0.0)) y1 = y2 = 0.0;  // neither
            }
        }
        delta[0] = std::max(x1 + massScale[0] * (y1 - x1) - leak[0] * x1, 0.0) - x1;
        delta[1] = std::max(x2 + massScale[1] * (y2 - x2) - leak[1] * x2, 0.0) - x2;
    }
    bool started[2] = {false, false};
    double push[2] = {0.0, 0.0};  // of a starting point's impulse, what pushes an overlap apart (bias < 0)
    double totalNormal = 0.0;
    for (int i = 0; i < count; ++i) {
        ContactConstraintPoint& cp = c.points[i];
        if (!block) {
            // One point at a time (Gauss-Seidel): the second sees the first's impulse.
            const double vn = i == 0 ? before[0] : speed(nx, ny, cp.rnA, cp.rnB);
            before[i] = vn;
            const double x = cp.normalImpulse;
            delta[i] = std::max(x - cp.normalMass * massScale[i] * (vn + bias[i]) - leak[i] * x, 0.0) - x;
        }
        apply(delta[i], nx, ny, cp.rnA, cp.rnB);
        started[i] = cp.normalImpulse == 0.0 && delta[i] > 0.0;
        if (started[i] && bias[i] < 0.0)
            push[i] = std::clamp(-cp.normalMass * massScale[i] * bias[i], 0.0, delta[i]);
        cp.normalImpulse += delta[i];
        cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, cp.normalImpulse);
        totalNormal += cp.normalImpulse;
    }
    if (started[0] || started[1]) {
        // Along each point's normal, what other contacts' push-out gave the pair in this substep (solve passes).
        double othersPush[2] = {0.0, 0.0};
        if (pass.useBias) {
            const MotionSide pushedA = pushedSide(pass, c.indexA), pushedB = pushedSide(pass, c.indexB);
            for (int i = 0; i < count; ++i) othersPush[i] = normalSpeed(c, pushedA, pushedB, c.points[i]);
        }
        Bounce bounce[2];
        for (int i = 0; i < count; ++i)
            if (started[i]) bounce[i] = planBounce(c, c.points[i], before[i] - othersPush[i], separation[i], pass);
        if (bounce[0].active || bounce[1].active) {
            MotionSide A{{vAx, vAy}, wA, sa.dp, sa.dq, sa.dAngle}, B{{vBx, vBy}, wB, sb.dp, sb.dq, sb.dAngle};
            applyBounces(c, A, B, bounce, push, othersPush);
            storeSideWithPose(states, c.indexA, mA, A);
            storeSideWithPose(states, c.indexB, mB, B);
            vAx = A.v.x(), vAy = A.v.y(), wA = A.w, vBx = B.v.x(), vBy = B.v.y(), wB = B.w;
            totalNormal = c.points[0].normalImpulse + (count == 2 ? c.points[1].normalImpulse : 0.0);
        }
        // A push that stays (its point did not bounce) is remembered on both bodies for their other contacts.
        for (int i = 0; i < count; ++i)
            if (push[i] > 0.0 && !bounce[i].active) recordPush(pass, c, c.points[i], push[i]);
    }
    // Friction after the normal rows, so its bound sees this pass's load; none at all for a frictionless pair.
    if (c.staticFriction > 0.0 || c.dynamicFriction > 0.0) {
        const double tx = -ny, ty = nx;
        const double vt = speed(tx, ty, c.rtA, c.rtB);
        // A sticking face holds up to mu_s times its load, a sliding one mu_d times. The relax pass, the
        // substep's last word, decides which it is for the next substep: sliding when even the bound leaves the
        // faces moving against each other faster than slipSpeed (a transient of one pass does not break a
        // face loose).
        const double bound = (c.sliding ? c.dynamicFriction : c.staticFriction) * totalNormal;
        const double tangent = std::clamp(c.tangentImpulse - c.tangentMass * vt, -bound, bound);
        if (!pass.useBias)
            c.sliding = c.tangentMass > 0.0 &&
                        std::abs(vt + (tangent - c.tangentImpulse) / c.tangentMass) > pass.slipSpeed;
        apply(tangent - c.tangentImpulse, tx, ty, c.rtA, c.rtB);
        c.tangentImpulse = tangent;
    }
    // Only bodies a row can move are written back: a kinematic body is read by many rows of one colour.
    if (mA != 0.0) {
        sa.v = {vAx, vAy};
        if constexpr (Turns) sa.w = wA;
    }
    if (mB != 0.0) {
        sb.v = {vBx, vBy};
        if constexpr (Turns) sb.w = wB;
    }
}

}  // namespace

void solveContacts(ContactConstraint* begin, ContactConstraint* end, SolverBody* states, const ContactPass& pass) {
    // The hot loop of the step, in plain scalars: each row reads its two bodies once and writes them back once.
    SolverBody still{};  // stands for an immovable body; never written (its rows' inverse masses are 0)
    for (ContactConstraint* c = begin; c != end; ++c) {
        if (c->turns) solveRow<true>(*c, states, still, pass);
        else solveRow<false>(*c, states, still, pass);
    }
}

void storeImpulses(const ContactConstraint& c, ContactData& contact) {
    contact.sliding = c.sliding;
    Manifold& m = contact.manifold;
    const double share = c.pointCount > 0 ? c.tangentImpulse / c.pointCount : 0.0;
    for (int i = 0; i < c.pointCount; ++i) {
        m.points[i].normalImpulse = c.points[i].normalImpulse;
        m.points[i].tangentImpulse = share;
    }
}

}  // namespace physim
