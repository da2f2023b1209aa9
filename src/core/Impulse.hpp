#pragma once
// What every solver row does to its two bodies, shared by the contact and joint rows. Internal.
// Convention: an impulse P acts on B and -P on A (Newton's third law), at lever arms rA, rB from the centres of
// mass. kNullIndex names an immovable body, seen as a still one.

#include "SolverData.hpp"

namespace physim {

/// What the solver sees of a body for a step: a body asleep, static or kinematic is immovable (zero inverse mass
/// and inertia), so no row can move it; a sleeping one wakes if a row's contact touches. It turns during the step
/// only if rows can turn it or it spins already: otherwise its rows and its integration skip all rotation work.
struct RowSide {
    std::int32_t index = kNullIndex;  // awake body index, kNullIndex when not awake
    bool moves = false;
    bool turns = false;
    double invMass = 0.0, invI = 0.0;
};

inline RowSide rowSide(const BodyData& b) {
    const bool moves = b.awake() && b.type == BodyType::Dynamic;
    const double invI = moves ? b.invInertia : 0.0;
    return {b.awakeIndex, moves, invI != 0.0 || b.w != 0.0, moves ? b.invMass : 0.0, invI};
}

/// A row's working copy of one body's motion.
struct MotionSide {
    Vec2 v = Vec2::Zero();
    double w = 0.0;
    Vec2 dp = Vec2::Zero();
    Rotation dq{};
    double dAngle = 0.0;
};

inline MotionSide loadSide(const SolverBody* states, std::int32_t index) {
    if (index == kNullIndex) return {};
    const SolverBody& s = states[index];
    return {s.v, s.w, s.dp, s.dq, s.dAngle};
}

/// Whether a row can move its side: only those are written back, since a kinematic body is read by many rows of one
/// colour at once, and every row reads the static side from one still record (states[-1]).
inline bool rowMoves(std::int32_t index, double invMass) { return index != kNullIndex && invMass != 0.0; }

inline void storeSide(SolverBody* states, std::int32_t index, double invMass, const MotionSide& side) {
    if (!rowMoves(index, invMass)) return;
    states[index].v = side.v;
    states[index].w = side.w;
}

/// Also writes the displacement and turn (rows that move positions: bounces).
inline void storeSideWithPose(SolverBody* states, std::int32_t index, double invMass, const MotionSide& side) {
    if (!rowMoves(index, invMass)) return;
    SolverBody& s = states[index];
    s.v = side.v;
    s.w = side.w;
    s.dp = side.dp;
    s.dq = side.dq;
    s.dAngle = side.dAngle;
}

/// Row: any type with invMassA, invIA, invMassB, invIB.
template <class Row>
void applyImpulse(const Row& r, MotionSide& A, MotionSide& B, const Vec2& rA, const Vec2& rB, const Vec2& P) {
    A.v -= r.invMassA * P;
    A.w -= r.invIA * cross(rA, P);
    B.v += r.invMassB * P;
    B.w += r.invIB * cross(rB, P);
}

/// Velocity of B's point relative to A's point, m/s.
inline Vec2 relativeVelocity(const MotionSide& A, const MotionSide& B, const Vec2& rA, const Vec2& rB) {
    return B.v + cross(B.w, rB) - A.v - cross(A.w, rA);
}

}  // namespace physim
