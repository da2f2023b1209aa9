#pragma once
// Impulses between two bodies at lever arms rA, rB (from their centres of mass), shared by the contact and
// joint solvers. Convention: P acts on B and -P on A (Newton's third law).

#include "BodyData.hpp"

namespace physim {

/// 1 / (the pair's inverse mass along `dir` at the lever arms), 0 when neither body can move that way.
inline double effectiveMass(const BodyData& A, const BodyData& B, const Vec2& rA, const Vec2& rB, const Vec2& dir) {
    const double ra = cross(rA, dir), rb = cross(rB, dir);
    const double k = A.invMass + B.invMass + A.invInertia * ra * ra + B.invInertia * rb * rb;
    return k > 0.0 ? 1.0 / k : 0.0;
}

/// Velocity of B's point relative to A's point, m/s.
inline Vec2 relativeVelocity(const BodyData& A, const BodyData& B, const Vec2& rA, const Vec2& rB) {
    return B.v + cross(B.w, rB) - A.v - cross(A.w, rA);
}

/// Changes velocities by the impulse P (N s).
inline void applyImpulse(BodyData& A, BodyData& B, const Vec2& rA, const Vec2& rB, const Vec2& P) {
    A.v -= A.invMass * P;
    A.w -= A.invInertia * cross(rA, P);
    B.v += B.invMass * P;
    B.w += B.invInertia * cross(rB, P);
}

/// Moves the bodies as the impulse P would over unit time, without touching velocities (position passes).
inline void applyPositionImpulse(BodyData& A, BodyData& B, const Vec2& rA, const Vec2& rB, const Vec2& P) {
    A.xf.p -= A.invMass * P;
    A.angle -= A.invInertia * cross(rA, P);
    A.xf.q = Rotation::fromAngle(A.angle);
    B.xf.p += B.invMass * P;
    B.angle += B.invInertia * cross(rB, P);
    B.xf.q = Rotation::fromAngle(B.angle);
}

}  // namespace physim
