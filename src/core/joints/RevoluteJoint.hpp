#pragma once
// The revolute joint (RevoluteJointDef), a pin: the shared point as the rod (stiff with the bias, exact in the relax
// pass); the spring, a soft angle row of its own frequency in both passes; the motor, an angular velocity row capped
// at maxMotorTorque; each limit a one-sided angle row, speculative while apart. Internal.

#include "JointShared.hpp"

#include "physim/core/Joint.hpp"

namespace physim {

struct RevoluteJoint {
    using Def = RevoluteJointDef;
    static constexpr JointType kType = JointType::Revolute;
    static constexpr const char* kName = "revolute";
    static constexpr bool kRow = true;

    double referenceAngle = 0.0;                    // angle(B) - angle(A) at creation, rad
    bool enableLimit = false, enableMotor = false, enableSpring = false;
    double lowerAngle = 0.0, upperAngle = 0.0;      // limits relative to the reference, rad
    double motorSpeed = 0.0, maxMotorTorque = 0.0;  // rad/s, N m
    double springHertz = 0.0, springDampingRatio = 0.0, springTargetAngle = 0.0;  // Hz, 1, rad
    // Accumulated per substep: the point's (N s), the motor's, the limits' and the spring's (N m s).
    Vec2 linearImpulse = Vec2::Zero();
    double motorImpulse = 0.0, lowerImpulse = 0.0, upperImpulse = 0.0, springImpulse = 0.0;

    static JointEnds ends(const Def& def) { return {def.bodyA, def.bodyB, false}; }
    static RevoluteJoint make(const Def& def, const BodyData& A, const BodyData& B, Vec2& localA, Vec2& localB);
    /// The motor and the limits as a definition or World::setJointMotor / setJointLimits set them (values checked
    /// by the caller); turning one off forgets its impulses.
    void setMotor(bool enable, double speed, double maxTorque);
    void setLimits(bool enable, double lower, double upper);
    void setSpring(bool enable, double hertz, double dampingRatio);
    void prepare(JointConstraint& row, const BodyData& A, const BodyData& B, double h,
                 const Softness& rodSoftness) const;
    void warmStart(const JointConstraint& row, MotionSide& A, MotionSide& B) const;
    void solve(const JointConstraint& row, MotionSide& A, MotionSide& B, bool useBias);
    /// Whether solve does only the shared point (no motor, no limits): such rows are solved kLanes at a time
    /// (PinLanes.hpp). Whatever else solve comes to do must make this false.
    bool pointOnly() const { return !enableMotor && !enableLimit && !enableSpring; }
    JointReaction reaction(const JointEndsNow& now, double invH) const;
    /// World::jointMotorTorque: the motor's torque on B over the last step, N m (0 while it is off).
    double motorTorque(double invH) const { return motorImpulse * invH; }
    /// World::jointAngle: angle(B) - angle(A) minus its value at creation, rad.
    double jointAngle(const BodyData& A, const BodyData& B) const { return B.angle - A.angle - referenceAngle; }
};

}  // namespace physim
