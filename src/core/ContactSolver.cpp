#include "ContactSolver.hpp"

#include "Impulse.hpp"

#include <algorithm>
#include <cmath>

namespace physim {
namespace {

constexpr double kPositionBaumgarte = 0.2;  // fraction of the overlap removed per position pass
constexpr double kMaxPositionCorrection = 0.2;  // m per pass, so deep overlaps separate without a jump
// Largest condition number (k11^2 / det K) of a two-point manifold's normal mass matrix solved as a block;
// beyond it the two points are nearly the same constraint and K^-1 would amplify rounding.
constexpr double kMaxConditionNumber = 1000.0;

}  // namespace

void ContactSolver::prepare(std::vector<BodyData>& bodies, std::vector<Manifold>& manifolds,
                            const WorldSettings& s) {
    pairs_.resize(manifolds.size());
    for (std::size_t k = 0; k < manifolds.size(); ++k) {
        Manifold& m = manifolds[k];
        PairState& ps = pairs_[k];
        ps.a = m.bodyA.index;
        ps.b = m.bodyB.index;
        BodyData& A = bodies[ps.a];
        BodyData& B = bodies[ps.b];
        // Combination rules (the paper's): restitution min, friction coefficients averaged.
        ps.restitution = std::min(A.restitution, B.restitution);
        ps.staticFriction = 0.5 * (A.staticFriction + B.staticFriction);
        ps.dynamicFriction = 0.5 * (A.dynamicFriction + B.dynamicFriction);
        const Vec2 n = m.normal;
        const Vec2 t = perp(n);
        for (int i = 0; i < m.pointCount; ++i) {
            ContactPoint& cp = m.points[i];
            PointState& pt = ps.points[i];
            pt.rA = cp.point - A.xf.p;
            pt.rB = cp.point - B.xf.p;
            pt.localA = A.xf.applyInverse(cp.point - 0.5 * cp.separation * n);
            pt.localB = B.xf.applyInverse(cp.point + 0.5 * cp.separation * n);
            pt.normalMass = effectiveMass(A, B, pt.rA, pt.rB, n);
            pt.tangentMass = effectiveMass(A, B, pt.rA, pt.rB, t);
            // Restitution reverses the approach speed the bodies had before this substep: before any
            // impulse (warm starting included), so the bounce does not depend on the order contacts are
            // visited in, and before this substep's gravity, so a bounce mirrors the fall. Semi-implicit
            // Euler is time-reversible, so with e = 1 the ball retraces its fall and gains no energy;
            // reversing the speed after gravity would add m g h v per bounce (1.3% at 60 Hz for a 2 m drop).
            const double vn = n.dot(B.v0 + cross(B.w0, pt.rB) - A.v0 - cross(A.w0, pt.rA));
            pt.velocityBias = vn < -s.restitutionThreshold ? -ps.restitution * vn : 0.0;
        }
        ps.blockSolve = false;
        if (m.pointCount == 2) {
            // The 2x2 effective-mass matrix of the two normal constraints. Solved as a block when it is well
            // conditioned; two nearly coincident points make it singular and fall back to one-by-one.
            const PointState& p1 = ps.points[0];
            const PointState& p2 = ps.points[1];
            const double a1 = cross(p1.rA, n), b1 = cross(p1.rB, n);
            const double a2 = cross(p2.rA, n), b2 = cross(p2.rB, n);
            const double lin = A.invMass + B.invMass;
            const double k11 = lin + A.invInertia * a1 * a1 + B.invInertia * b1 * b1;
            const double k22 = lin + A.invInertia * a2 * a2 + B.invInertia * b2 * b2;
            const double k12 = lin + A.invInertia * a1 * a2 + B.invInertia * b1 * b2;
            const double det = k11 * k22 - k12 * k12;
            if (k11 * k11 < kMaxConditionNumber * det) {
                ps.blockSolve = true;
                ps.k11 = k11;
                ps.k12 = k12;
                ps.k22 = k22;
                ps.invDet = 1.0 / det;
            }
        }
    }
    // Warm start after every restitution target is known.
    for (std::size_t k = 0; k < manifolds.size(); ++k) {
        Manifold& m = manifolds[k];
        PairState& ps = pairs_[k];
        const Vec2 n = m.normal;
        const Vec2 t = perp(n);
        for (int i = 0; i < m.pointCount; ++i) {
            const ContactPoint& cp = m.points[i];
            applyImpulse(bodies[ps.a], bodies[ps.b], ps.points[i].rA, ps.points[i].rB,
                         cp.normalImpulse * n + cp.tangentImpulse * t);
        }
    }
}

void ContactSolver::solveVelocities(std::vector<BodyData>& bodies, std::vector<Manifold>& manifolds) {
    for (std::size_t k = 0; k < manifolds.size(); ++k) {
        Manifold& m = manifolds[k];
        PairState& ps = pairs_[k];
        BodyData& A = bodies[ps.a];
        BodyData& B = bodies[ps.b];
        const Vec2 n = m.normal;
        const Vec2 t = perp(n);
        for (int i = 0; i < m.pointCount; ++i) {
            ContactPoint& cp = m.points[i];
            const PointState& pt = ps.points[i];
            // Friction: the impulse that stops sliding, kept if static friction can supply it (Coulomb),
            // otherwise limited to the dynamic friction bound.
            const double vt = t.dot(relativeVelocity(A, B, pt.rA, pt.rB));
            double tangent = cp.tangentImpulse - pt.tangentMass * vt;
            if (std::abs(tangent) > ps.staticFriction * cp.normalImpulse) {
                const double bound = ps.dynamicFriction * cp.normalImpulse;
                tangent = std::clamp(tangent, -bound, bound);
            }
            applyImpulse(A, B, pt.rA, pt.rB, (tangent - cp.tangentImpulse) * t);
            cp.tangentImpulse = tangent;
        }
        if (ps.blockSolve) {
            solveNormalBlock(A, B, m, ps);
            continue;
        }
        for (int i = 0; i < m.pointCount; ++i) {
            ContactPoint& cp = m.points[i];
            const PointState& pt = ps.points[i];
            // Normal: non-penetration with the restitution target; the accumulated impulse only pushes.
            const double vn = n.dot(relativeVelocity(A, B, pt.rA, pt.rB));
            const double normal = std::max(cp.normalImpulse - pt.normalMass * (vn - pt.velocityBias), 0.0);
            applyImpulse(A, B, pt.rA, pt.rB, (normal - cp.normalImpulse) * n);
            cp.normalImpulse = normal;
        }
    }
}

void ContactSolver::solveNormalBlock(BodyData& A, BodyData& B, Manifold& m, const PairState& ps) {
    // Both normal constraints at once: find accumulated impulses x >= 0 with post-impulse velocities
    // w = K x + b >= 0 and x_i w_i = 0 (a 2x2 linear complementarity problem), where b is the velocity the
    // constraints would have with no accumulated impulse. Two points are few enough to try the four cases
    // (both pushing, only one, none) in turn; exactly one satisfies the conditions when K is positive definite.
    const Vec2 n = m.normal;
    ContactPoint& c1 = m.points[0];
    ContactPoint& c2 = m.points[1];
    const PointState& p1 = ps.points[0];
    const PointState& p2 = ps.points[1];
    const double x1 = c1.normalImpulse, x2 = c2.normalImpulse;  // >= 0 from the last iteration
    const double vn1 = n.dot(relativeVelocity(A, B, p1.rA, p1.rB));
    const double vn2 = n.dot(relativeVelocity(A, B, p2.rA, p2.rB));
    const double b1 = vn1 - p1.velocityBias - (ps.k11 * x1 + ps.k12 * x2);
    const double b2 = vn2 - p2.velocityBias - (ps.k12 * x1 + ps.k22 * x2);

    double y1 = 0.0, y2 = 0.0;
    // Case 1: both points push (w = 0): x = -K^-1 b.
    y1 = -(ps.k22 * b1 - ps.k12 * b2) * ps.invDet;
    y2 = -(ps.k11 * b2 - ps.k12 * b1) * ps.invDet;
    if (!(y1 >= 0.0 && y2 >= 0.0)) {
        // Case 2: only point 1 pushes; point 2 must then separate (w2 >= 0).
        y1 = -b1 / ps.k11;
        y2 = 0.0;
        if (!(y1 >= 0.0 && ps.k12 * y1 + b2 >= 0.0)) {
            // Case 3: only point 2 pushes.
            y1 = 0.0;
            y2 = -b2 / ps.k22;
            if (!(y2 >= 0.0 && ps.k12 * y2 + b1 >= 0.0)) {
                // Case 4: neither pushes; both separate on their own (b >= 0), or rounding left no exact
                // case, where releasing both is the safe choice.
                y1 = 0.0;
                y2 = 0.0;
            }
        }
    }
    applyImpulse(A, B, p1.rA, p1.rB, (y1 - x1) * n);
    applyImpulse(A, B, p2.rA, p2.rB, (y2 - x2) * n);
    c1.normalImpulse = y1;
    c2.normalImpulse = y2;
}

void ContactSolver::correctPositions(std::vector<BodyData>& bodies, const std::vector<Manifold>& manifolds,
                                     const WorldSettings& s, const std::vector<std::uint8_t>* moved) {
    for (std::size_t k = 0; k < manifolds.size(); ++k) {
        const Manifold& m = manifolds[k];
        const PairState& ps = pairs_[k];
        if (moved && ((*moved)[ps.a] || (*moved)[ps.b])) continue;
        BodyData& A = bodies[ps.a];
        BodyData& B = bodies[ps.b];
        const Vec2 n = m.normal;
        for (int i = 0; i < m.pointCount; ++i) {
            const PointState& pt = ps.points[i];
            const Vec2 pA = A.xf.apply(pt.localA);
            const Vec2 pB = B.xf.apply(pt.localB);
            const double separation = (pB - pA).dot(n);
            const double C = std::clamp(kPositionBaumgarte * (separation + s.linearSlop), -kMaxPositionCorrection, 0.0);
            const Vec2 rA = pA - A.xf.p;
            const Vec2 rB = pB - B.xf.p;
            const double mass = effectiveMass(A, B, rA, rB, n);
            applyPositionImpulse(A, B, rA, rB, (-C * mass) * n);
        }
    }
}

}  // namespace physim
