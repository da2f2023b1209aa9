#pragma once
// The wheel joint (WheelJointDef): across the axis, B's anchor held on A's line (stiff with the bias, exact in the
// relax pass); along it, the suspension spring (a soft row in both passes) and each limit a one-sided row,
// speculative while apart; the rotation free but for the motor, an angular velocity row capped at maxMotorTorque.
// Internal.

#include "SliderShared.hpp"

#include "physim/core/Joint.hpp"

namespace physim {

struct WheelJoint {
    using Def = WheelJointDef;
    static constexpr JointType kType = JointType::Wheel;
    static constexpr const char* kName = "wheel";
    static constexpr bool kRow = true;

    Vec2 localAxis = Vec2(0.0, 1.0);  // unit, in A's frame
    bool enableSpring = true, enableLimit = false, enableMotor = false;
    double hertz = 0.0, dampingRatio = 0.0;                 // Hz, 1
    double lowerTranslation = 0.0, upperTranslation = 0.0;  // m
    double motorSpeed = 0.0, maxMotorTorque = 0.0;           // rad/s, N m
    // Accumulated per substep: across the axis, the spring's and the limits' (N s), the motor's (N m s).
    double normalImpulse = 0.0, springImpulse = 0.0, lowerImpulse = 0.0, upperImpulse = 0.0, motorImpulse = 0.0;
    Vec2 lastAxis = Vec2(0.0, 1.0);  // the axis in the world at the last solve, for the reaction

    static JointEnds ends(const Def& def) { return {def.bodyA, def.bodyB, false}; }
    static WheelJoint make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB);
    /// As a definition or a setter sets them (values checked by the caller); turning one off forgets its impulses.
    void setSpring(bool enable, double springHertz, double ratio);
    void setLimits(bool enable, double lower, double upper);
    void setMotor(bool enable, double speed, double maxTorque);
    void prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                 const Softness& rodSoftness) const;
    void warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const;
    void solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias);
    /// Whether solve does no more than WheelLanes.hpp's lanes do (no limits): such rows are solved kLanes at a time.
    /// Whatever else solve comes to do must make this false.
    bool solvesInLanes() const { return !enableLimit; }
    JointReaction reaction(const JointEndsNow& now, double invH) const;
    /// World::jointMotorTorque: the motor's torque on B over the last step, N m (0 while it is off).
    double motorTorque(double invH) const { return motorImpulse * invH; }
    /// World::jointTranslation, jointSpeed: the suspension's travel along the axis, m and m/s.
    double jointTranslation(const BodyData& A, const BodyData& B, const Vec2& localA, const Vec2& localB) const {
        return sliderTranslation(localAxis, A, B, localA, localB);
    }
    double jointSpeed(const BodyData& A, const BodyData& B, const Vec2& localA, const Vec2& localB) const {
        return sliderSpeed(localAxis, A, B, localA, localB);
    }
};

}  // namespace physim
