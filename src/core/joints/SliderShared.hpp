#pragma once
// What the prismatic and wheel joints share: an axis fixed in A along which B's anchor moves. The axis's frame
// now, the rows along it and across it, and the limits on the translation. Internal.

#include "JointShared.hpp"

#include "physim/core/Validate.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace physim {

/// A slider's geometry now, from the start of the step and the displacements since (m, unit vectors).
struct SliderFrame {
    Vec2 rA, rB;          // lever arms of the anchors
    Vec2 axis, normal;    // the axis (turned with A) and its left perpendicular
    double translation;   // axis . (anchorB - anchorA), m
    double offset;        // normal . (anchorB - anchorA): off the line, m
    double a1, a2;        // the axial row's angular parts on A and B: (d + rA) x axis, rB x axis
    double n1, n2;        // the normal row's likewise
};

inline SliderFrame sliderFrame(const JointConstraint& row, const MotionSide& A, const MotionSide& B) {
    SliderFrame f;
    f.rA = A.dq.apply(row.anchorA);
    f.rB = B.dq.apply(row.anchorB);
    const Vec2 d = row.deltaCenter + (B.dp - A.dp) + f.rB - f.rA;
    f.axis = A.dq.apply(row.axis);
    f.normal = perp(f.axis);
    f.translation = f.axis.dot(d);
    f.offset = f.normal.dot(d);
    f.a1 = cross(d + f.rA, f.axis);
    f.a2 = cross(f.rB, f.axis);
    f.n1 = cross(d + f.rA, f.normal);
    f.n2 = cross(f.rB, f.normal);
    return f;
}

/// The inverse effective mass of a row along `direction` whose angular parts are j1 (A) and j2 (B), 1/kg.
inline double rowInverseMass(const JointConstraint& row, double j1, double j2) {
    return row.invMassA + row.invMassB + row.invIA * j1 * j1 + row.invIB * j2 * j2;
}

/// An impulse (N s) along `direction` on B's anchor, its reaction on A's; j1, j2 the row's angular parts.
inline void pushAlong(const JointConstraint& row, MotionSide& A, MotionSide& B, const Vec2& direction, double j1,
                      double j2, double impulse) {
    A.v -= row.invMassA * impulse * direction;
    A.w -= row.invIA * impulse * j1;
    B.v += row.invMassB * impulse * direction;
    B.w += row.invIB * impulse * j2;
}

/// The translation's rate, m/s: axis . (vB + wB x rB - vA - wA x (d + rA)), the axis turning with A.
inline double axialRate(const SliderFrame& f, const MotionSide& A, const MotionSide& B) {
    return f.axis.dot(B.v - A.v) + f.a2 * B.w - f.a1 * A.w;
}

/// A one-sided row along the axis: C = sign (translation - limit) must stay >= 0. Apart it is speculative (it stops
/// the bodies at the limit within the substep); past it, pushed back softly with the bias, rigidly in the relax
/// pass. `accumulated`: its impulse, N s, >= 0.
inline void solveAxialLimit(const JointConstraint& row, const SliderFrame& f, double C, double sign,
                            double& accumulated, MotionSide& A, MotionSide& B, bool useBias) {
    const double k = rowInverseMass(row, f.a1, f.a2);
    if (!(k > 0.0)) return;
    double bias = 0.0, massScale = 1.0, impulseScale = 0.0;
    if (C > 0.0) {
        bias = C * row.invH;
    } else if (useBias) {
        bias = row.softness.biasRate * C;
        massScale = row.softness.massScale;
        impulseScale = row.softness.impulseScale;
    }
    const double lambda = -massScale * (sign * axialRate(f, A, B) + bias) / k - impulseScale * accumulated;
    const double total = std::max(accumulated + lambda, 0.0);
    pushAlong(row, A, B, f.axis, f.a1, f.a2, sign * (total - accumulated));
    accumulated = total;
}

/// The limits' values as a definition or setter gives them: finite, lower <= upper.
inline void requireTranslationLimits(const char* kind, double lower, double upper) {
    requireFinite(std::string(kind) + " joint lowerTranslation", lower);
    requireFinite(std::string(kind) + " joint upperTranslation", upper);
    if (lower > upper)
        throw std::invalid_argument(std::string("physim: ") + kind +
                                    " joint lowerTranslation must be <= upperTranslation, got " +
                                    std::to_string(lower) + " > " + std::to_string(upper));
}

/// A slider at a world anchor along a world axis: the anchors in the bodies' frames, and the axis as a unit vector
/// in A's frame.
inline Vec2 slideAt(const char* kind, const Vec2& anchor, const Vec2& axis, const BodyData& A, const BodyData& B,
                    Vec2& localA, Vec2& localB) {
    requireWithin(std::string(kind) + " joint anchor", anchor, kMaxCoordinate);
    requireFinite(std::string(kind) + " joint axis", axis);
    const double length = axis.norm();
    if (!(length > 1e-12))
        throw std::invalid_argument(std::string("physim: ") + kind + " joint axis must have a length > 0, got (" +
                                    std::to_string(axis.x()) + ", " + std::to_string(axis.y()) + ")");
    localA = A.xf.applyInverse(anchor);
    localB = B.xf.applyInverse(anchor);
    return A.xf.q.applyInverse(axis / length);
}

/// World::jointTranslation and jointSpeed of a slider whose axis is `localAxis` in A's frame: axis . (pB - pA), m,
/// and its rate, m/s (the axis turning with A).
inline double sliderTranslation(const Vec2& localAxis, const BodyData& A, const BodyData& B, const Vec2& localA,
                                const Vec2& localB) {
    return A.xf.q.apply(localAxis).dot(B.xf.apply(localB) - A.xf.apply(localA));
}
inline double sliderSpeed(const Vec2& localAxis, const BodyData& A, const BodyData& B, const Vec2& localA,
                          const Vec2& localB) {
    const Vec2 axis = A.xf.q.apply(localAxis);
    const Vec2 rA = A.xf.q.apply(localA - A.localCenter), rB = B.xf.q.apply(localB - B.localCenter);
    const Vec2 d = B.center + rB - A.center - rA;
    return axis.dot(B.v + cross(B.w, rB) - A.v - cross(A.w, rA)) + cross(A.w, axis).dot(d);
}

}  // namespace physim
