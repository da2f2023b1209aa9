#pragma once
// The prismatic joint (PrismaticJointDef), a slider: across the axis, B's anchor held on A's line and the relative
// angle held, one 2x2 block (stiff with the bias, exact in the relax pass); along it, a spring (a soft row in both
// passes), a motor (a velocity row capped at maxMotorForce) and each limit a one-sided row, speculative while apart.
// Internal.

#include "SliderShared.hpp"

#include "physim/core/Joint.hpp"

namespace physim {

struct PrismaticJoint {
    using Def = PrismaticJointDef;
    static constexpr JointType kType = JointType::Prismatic;
    static constexpr const char* kName = "prismatic";
    static constexpr bool kRow = true;

    Vec2 localAxis = Vec2(1.0, 0.0);  // unit, in A's frame
    double referenceAngle = 0.0;      // angle(B) - angle(A) at creation, rad
    bool enableLimit = false, enableMotor = false, enableSpring = false;
    double lowerTranslation = 0.0, upperTranslation = 0.0;  // m
    double motorSpeed = 0.0, maxMotorForce = 0.0;            // m/s, N
    double hertz = 0.0, dampingRatio = 0.0, targetTranslation = 0.0;  // Hz, 1, m
    // Accumulated per substep (N s; the block's second part N m s): across the axis and the angle, and along it.
    Vec2 blockImpulse = Vec2::Zero();
    double springImpulse = 0.0, motorImpulse = 0.0, lowerImpulse = 0.0, upperImpulse = 0.0;
    Vec2 lastAxis = Vec2(1.0, 0.0);  // the axis in the world at the last solve, for the reaction

    static JointEnds ends(const Def& def) { return {def.bodyA, def.bodyB, false}; }
    static PrismaticJoint make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB);
    /// As a definition or a setter sets them (values checked by the caller); turning one off forgets its impulses.
    void setLimits(bool enable, double lower, double upper);
    void setMotor(bool enable, double speed, double maxForce);
    void setSpring(bool enable, double springHertz, double ratio, double target);
    void prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                 const Softness& rodSoftness) const;
    void warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const;
    void solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias);
    JointReaction reaction(const JointEndsNow& now, double invH) const;
    /// World::jointMotorForce: the motor's force on B along the axis over the last step, N (0 while it is off).
    double motorForce(double invH) const { return motorImpulse * invH; }
    /// World::jointTranslation, jointSpeed: along the axis, m and m/s.
    double jointTranslation(const BodyData& A, const BodyData& B, const Vec2& localA, const Vec2& localB) const;
    double jointSpeed(const BodyData& A, const BodyData& B, const Vec2& localA, const Vec2& localB) const;
};

}  // namespace physim
