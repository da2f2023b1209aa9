#include "ContactSolver.hpp"

#include "ContactData.hpp"
#include "Impulse.hpp"

#include <algorithm>
#include <cmath>

namespace physim {

Softness makeSoftness(double hertz, double dampingRatio, double h) {
    if (hertz <= 0.0) return {};  // rigid
    const double omega = 2.0 * 3.14159265358979323846 * hertz;
    const double a1 = 2.0 * dampingRatio + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

void prepareContact(ContactConstraint& c, const ContactData& contact, const std::vector<BodyData>& bodies,
                    const Vec2& gravity) {
    const BodyData& A = bodies[contact.a];
    const BodyData& B = bodies[contact.b];
    const Manifold& m = contact.manifold;
    // A sleeping body in an awake contact acts as immovable for this step (it wakes if the contact touches).
    const bool movesA = A.awake() && A.type == BodyType::Dynamic;
    const bool movesB = B.awake() && B.type == BodyType::Dynamic;
    c.indexA = A.awakeIndex;
    c.indexB = B.awakeIndex;
    c.invMassA = movesA ? A.invMass : 0.0;
    c.invIA = movesA ? A.invInertia : 0.0;
    c.invMassB = movesB ? B.invMass : 0.0;
    c.invIB = movesB ? B.invInertia : 0.0;
    // The paper's combination rules: restitution min, friction coefficients averaged.
    c.restitution = std::min(A.restitution, B.restitution);
    c.staticFriction = 0.5 * (A.staticFriction + B.staticFriction);
    c.dynamicFriction = 0.5 * (A.dynamicFriction + B.dynamicFriction);
    c.normal = m.normal;
    c.pointCount = m.pointCount;
    auto acceleration = [&](const BodyData& b, bool moves) -> Vec2 {
        return moves ? Vec2((b.useGravity ? gravity : Vec2::Zero()) + b.invMass * b.force) : Vec2::Zero();
    };
    c.normalAcceleration = c.normal.dot(acceleration(B, movesB) - acceleration(A, movesA));
    c.bouncePending = false;
    c.tangentImpulse = 0.0;
    Vec2 sumA = Vec2::Zero(), sumB = Vec2::Zero();
    for (int i = 0; i < m.pointCount; ++i) {
        const ContactPoint& mp = m.points[i];
        ContactConstraintPoint& cp = c.points[i];
        cp.anchorA = mp.point - A.center;
        cp.anchorB = mp.point - B.center;
        cp.baseSeparation = mp.separation - c.normal.dot(cp.anchorB - cp.anchorA);
        cp.normalImpulse = mp.normalImpulse;
        cp.maxNormalImpulse = 0.0;
        cp.normalMass = massAlong(c, cp.anchorA, cp.anchorB, c.normal);
        cp.relativeVelocity = 0.0;
        cp.engaged = false;
        cp.bouncePending = false;
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
}

void warmStartContacts(ContactConstraint* begin, ContactConstraint* end, SolverBody* states) {
    for (ContactConstraint* c = begin; c != end; ++c) {
        MotionSide A = loadSide(states, c->indexA), B = loadSide(states, c->indexB);
        const Vec2 n = c->normal, t = perp(n);
        for (int i = 0; i < c->pointCount; ++i) {
            const ContactConstraintPoint& cp = c->points[i];
            applyImpulse(*c, A, B, cp.anchorA, cp.anchorB, cp.normalImpulse * n);
        }
        applyImpulse(*c, A, B, c->frictionAnchorA, c->frictionAnchorB, c->tangentImpulse * t);
        storeSide(states, c->indexA, c->invMassA, A);
        storeSide(states, c->indexB, c->invMassB, B);
    }
}

namespace {

// Called when a point first pushes in the step: remember how it met, and whether it bounces. The bounce waits for
// the end of the substep (applyBounces), after the relax pass, which would otherwise undo it.
void engage(ContactConstraint& c, ContactConstraintPoint& cp, double vn, double s, bool inRelax, double threshold,
            bool& anyBounce) {
    cp.engaged = true;
    cp.relativeVelocity = vn;
    cp.engageSeparation = std::max(s, 0.0);
    cp.engagedInRelax = inRelax;
    // Perfectly elastic points bounce at any speed; below e = 1 the threshold keeps resting contacts quiet.
    const double limit = c.restitution < 1.0 ? -threshold : 0.0;
    if (c.restitution > 0.0 && vn < limit) {
        cp.bouncePending = true;
        c.bouncePending = true;
        anyBounce = true;
    }
}

}  // namespace

bool solveContacts(ContactConstraint* begin, ContactConstraint* end, SolverBody* states, double invH, bool useBias,
                   const Softness& softness, double maxPushVelocity, double restitutionThreshold) {
    bool anyBounce = false;
    for (ContactConstraint* c = begin; c != end; ++c) {
        MotionSide A = loadSide(states, c->indexA), B = loadSide(states, c->indexB);
        const Vec2 n = c->normal;
        const Vec2 dp = B.dp - A.dp;
        double totalNormal = 0.0;
        double bias[2] = {0.0, 0.0}, massScale[2] = {1.0, 1.0}, impulseScale[2] = {0.0, 0.0}, vn[2] = {0.0, 0.0};
        double sep[2] = {0.0, 0.0};
        for (int i = 0; i < c->pointCount; ++i) {
            ContactConstraintPoint& cp = c->points[i];
            // Separation now: the start's, moved by the bodies' displacement and turn since the step began.
            const Vec2 prA = A.dq.apply(cp.anchorA), prB = B.dq.apply(cp.anchorB);
            const double s = n.dot(dp + prB - prA) + cp.baseSeparation;
            sep[i] = s;
            if (s > 0.0) {
                bias[i] = s * invH;  // speculative: close the gap in this substep, no further
            } else if (useBias) {
                bias[i] = std::max(softness.biasRate * s, -maxPushVelocity);
                massScale[i] = softness.massScale;
                impulseScale[i] = softness.impulseScale;
            }
        }
        if (c->pointCount == 2 && c->invDet > 0.0) {
            ContactConstraintPoint& p1 = c->points[0];
            ContactConstraintPoint& p2 = c->points[1];
            vn[0] = n.dot(relativeVelocity(A, B, p1.anchorA, p1.anchorB));
            vn[1] = n.dot(relativeVelocity(A, B, p2.anchorA, p2.anchorB));
            const double x1 = p1.normalImpulse, x2 = p2.normalImpulse;
            // Rigid 2x2 LCP on the increments: w = K (y - x) + (vn + bias) >= 0, y >= 0, y . w = 0.
            const double b1 = vn[0] + bias[0] - (c->k11 * x1 + c->k12 * x2);
            const double b2 = vn[1] + bias[1] - (c->k12 * x1 + c->k22 * x2);
            double y1 = -(c->k22 * b1 - c->k12 * b2) * c->invDet;
            double y2 = -(c->k11 * b2 - c->k12 * b1) * c->invDet;
            if (!(y1 >= 0.0 && y2 >= 0.0)) {
                y1 = -b1 / c->k11; y2 = 0.0;
                if (!(y1 >= 0.0 && c->k12 * y1 + b2 >= 0.0)) {
                    y1 = 0.0; y2 = -b2 / c->k22;
                    if (!(y2 >= 0.0 && c->k12 * y2 + b1 >= 0.0)) { y1 = 0.0; y2 = 0.0; }
                }
            }
            // Soft: move a massScale fraction of the way, and leak impulseScale of the old impulse.
            const double n1 = std::max(x1 + massScale[0] * (y1 - x1) - impulseScale[0] * x1, 0.0);
            const double n2 = std::max(x2 + massScale[1] * (y2 - x2) - impulseScale[1] * x2, 0.0);
            const double totals[2] = {n1, n2};
            for (int i = 0; i < 2; ++i) {
                ContactConstraintPoint& cp = c->points[i];
                if (totals[i] > 0.0 && !cp.engaged) engage(*c, cp, vn[i], sep[i], !useBias, restitutionThreshold, anyBounce);
                applyImpulse(*c, A, B, cp.anchorA, cp.anchorB, (totals[i] - cp.normalImpulse) * n);
                cp.normalImpulse = totals[i];
                cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, totals[i]);
                totalNormal += totals[i];
            }
        } else
        for (int i = 0; i < c->pointCount; ++i) {
            ContactConstraintPoint& cp = c->points[i];
            const double vni = n.dot(relativeVelocity(A, B, cp.anchorA, cp.anchorB));
            const double lambda = -cp.normalMass * massScale[i] * (vni + bias[i]) - impulseScale[i] * cp.normalImpulse;
            const double total = std::max(cp.normalImpulse + lambda, 0.0);
            if (total > 0.0 && !cp.engaged) engage(*c, cp, vni, sep[i], !useBias, restitutionThreshold, anyBounce);
            applyImpulse(*c, A, B, cp.anchorA, cp.anchorB, (total - cp.normalImpulse) * n);
            cp.normalImpulse = total;
            cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, total);
            totalNormal += total;
        }
        // Friction after the normal rows, so its bound sees this pass's load.
        const Vec2 t = perp(n);
        const Vec2 rA = c->frictionAnchorA, rB = c->frictionAnchorB;
        const double vt = t.dot(relativeVelocity(A, B, rA, rB));
        double tangent = c->tangentImpulse - c->tangentMass * vt;
        if (std::abs(tangent) > c->staticFriction * totalNormal) {
            const double bound = c->dynamicFriction * totalNormal;
            tangent = std::clamp(tangent, -bound, bound);
        }
        applyImpulse(*c, A, B, rA, rB, (tangent - c->tangentImpulse) * t);
        c->tangentImpulse = tangent;
        storeSide(states, c->indexA, c->invMassA, A);
        storeSide(states, c->indexB, c->invMassB, B);
    }
    return anyBounce;
}

void applyBounces(ContactConstraint* begin, ContactConstraint* end, SolverBody* states, double h) {
    for (ContactConstraint* c = begin; c != end; ++c) {
        if (!c->bouncePending) continue;
        c->bouncePending = false;
        MotionSide A = loadSide(states, c->indexA), B = loadSide(states, c->indexB);
        const Vec2 n = c->normal;
        const double e = c->restitution;
        for (int i = 0; i < c->pointCount; ++i) {
            ContactConstraintPoint& cp = c->points[i];
            if (!cp.bouncePending) continue;
            cp.bouncePending = false;
            // Leave at e times the meeting speed, placed so that for e = 1 semi-implicit Euler retraces the fall
            // exactly (no energy gained or lost). Met in the solve pass: the speculative row stopped the bodies at
            // contact a fraction of the substep early; moving them apart by e times the gap they had at the
            // substep's start makes the substep a reflection. Met in the relax pass (the positions already moved):
            // the reflection of the next substep's fall is the speed before that substep's gravity.
            const double speed = -cp.relativeVelocity - (cp.engagedInRelax ? h * c->normalAcceleration : 0.0);
            const double vn = n.dot(relativeVelocity(A, B, cp.anchorA, cp.anchorB));
            const double impulse = cp.normalMass * (e * speed - vn);
            if (impulse > 0.0) {
                applyImpulse(*c, A, B, cp.anchorA, cp.anchorB, impulse * n);
                cp.maxNormalImpulse = std::max(cp.maxNormalImpulse, cp.normalImpulse + impulse);
            }
            const double shift = cp.engagedInRelax ? 0.0 : e * cp.engageSeparation * cp.normalMass;  // kg m
            if (shift > 0.0) {
                const Vec2 rA = A.dq.apply(cp.anchorA), rB = B.dq.apply(cp.anchorB);
                const Vec2 P = shift * n;
                A.dp -= c->invMassA * P;
                B.dp += c->invMassB * P;
                const double turnA = -c->invIA * cross(rA, P), turnB = c->invIB * cross(rB, P);
                A.dq = compose(rotationBy(turnA), A.dq);
                B.dq = compose(rotationBy(turnB), B.dq);
                A.dAngle += turnA;
                B.dAngle += turnB;
            }
        }
        storeSideWithPose(states, c->indexA, c->invMassA, A);
        storeSideWithPose(states, c->indexB, c->invMassB, B);
    }
}

void storeImpulses(const ContactConstraint& c, ContactData& contact) {
    Manifold& m = contact.manifold;
    const double share = c.pointCount > 0 ? c.tangentImpulse / c.pointCount : 0.0;
    for (int i = 0; i < c.pointCount; ++i) {
        m.points[i].normalImpulse = c.points[i].normalImpulse;
        m.points[i].tangentImpulse = share;
    }
}

}  // namespace physim
