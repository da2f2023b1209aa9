#include "ContactSolver.hpp"

#include <algorithm>
#include <cmath>

namespace physim {
namespace {

constexpr double kPositionBaumgarte = 0.2;  // fraction of the overlap removed per position pass
constexpr double kMaxPositionCorrection = 0.2;  // m per pass, so deep overlaps separate without a jump

double effectiveMass(const BodyData& A, const BodyData& B, const Vec2& rA, const Vec2& rB, const Vec2& dir) {
    const double ra = cross(rA, dir), rb = cross(rB, dir);
    const double k = A.invMass + B.invMass + A.invInertia * ra * ra + B.invInertia * rb * rb;
    return k > 0.0 ? 1.0 / k : 0.0;
}

Vec2 relativeVelocity(const BodyData& A, const BodyData& B, const Vec2& rA, const Vec2& rB) {
    return B.v + cross(B.w, rB) - A.v - cross(A.w, rA);
}

// Impulse P acts on B, -P on A (Newton's third law), at the given lever arms.
void applyImpulse(BodyData& A, BodyData& B, const Vec2& rA, const Vec2& rB, const Vec2& P) {
    A.v -= A.invMass * P;
    A.w -= A.invInertia * cross(rA, P);
    B.v += B.invMass * P;
    B.w += B.invInertia * cross(rB, P);
}

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
            const double vn = n.dot(relativeVelocity(A, B, pt.rA, pt.rB));
            pt.velocityBias = vn < -s.restitutionThreshold ? -ps.restitution * vn : 0.0;
            applyImpulse(A, B, pt.rA, pt.rB, cp.normalImpulse * n + cp.tangentImpulse * t);
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

            // Normal: non-penetration with the restitution target; the accumulated impulse only pushes.
            const double vn = n.dot(relativeVelocity(A, B, pt.rA, pt.rB));
            const double normal = std::max(cp.normalImpulse - pt.normalMass * (vn - pt.velocityBias), 0.0);
            applyImpulse(A, B, pt.rA, pt.rB, (normal - cp.normalImpulse) * n);
            cp.normalImpulse = normal;
        }
    }
}

void ContactSolver::correctPositions(std::vector<BodyData>& bodies, const std::vector<Manifold>& manifolds,
                                     const WorldSettings& s) {
    for (std::size_t k = 0; k < manifolds.size(); ++k) {
        const Manifold& m = manifolds[k];
        const PairState& ps = pairs_[k];
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
            const Vec2 P = (-C * mass) * n;
            A.xf.p -= A.invMass * P;
            A.angle -= A.invInertia * cross(rA, P);
            A.xf.q = Rotation::fromAngle(A.angle);
            B.xf.p += B.invMass * P;
            B.angle += B.invInertia * cross(rB, P);
            B.xf.q = Rotation::fromAngle(B.angle);
        }
    }
}

}  // namespace physim
