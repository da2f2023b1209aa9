#pragma once
// Wheel joints without limits solved kLanes at a time (Wide.hpp), as PinLanes.hpp solves pins: the rows of one
// joint colour share no dynamic body, so a block's lanes are independent. Each lane does what WheelJoint's
// warmStart and solve do (motor, spring, the row across the axis), operation for operation, a part a lane's joint
// lacks masked off, so a lane gives the bits the scalar row gives. Internal.

#include "../SolverData.hpp"
#include "../Wide.hpp"
#include "JointShared.hpp"

#include <cstdint>
#include <vector>

namespace physim {

struct JointData;

/// Up to kLanes wheel rows for a step: the rows' fields by lane and the joints' accumulated impulses. An unused lane
/// has no bodies (kNullIndex) and no mass: it changes nothing.
struct alignas(64) WheelBlock {  // 64: the AVX builds assume their vectors aligned
    Wide anchorAx, anchorAy, anchorBx, anchorBy;  // lever arms at the step's start, m
    Wide deltaX, deltaY;                           // centre of B minus centre of A at the start, m
    Wide axisX, axisY;                             // the axis in the world at the start (turns with A)
    Wide invMassA, invMassB, invIA, invIB;
    Wide biasRate, massScale, impulseScale;        // the rod's softness, across the axis
    Wide springBias, springMass, springImpulseScale;  // the suspension's softness
    Wide axialMass, maxImpulse, motorSpeed;        // the motor's: kg m^2, N m s per substep, rad/s
    WideMask motor, spring;                        // lanes whose joint has the motor, the spring on
    Wide normalImpulse, springImpulse, motorImpulse;  // N s, N s, N m s
    Wide lastAxisX, lastAxisY;                     // the axis at the last solve (the reaction's)
    std::int32_t indexA[kLanes], indexB[kLanes];
    std::uint32_t joint[kLanes];
    unsigned writesA = 0, writesB = 0;  // a bit per lane whose side the row moves (Impulse.hpp's rowMoves)
    std::uint32_t count = 0;            // lanes in use
};

/// Fills `block` from `count` (1..kLanes) prepared rows of wheel joints whose solvesInLanes() holds.
void packWheels(WheelBlock& block, const JointConstraint* const* rows, std::uint32_t count,
                const std::vector<JointData>& joints);
/// The blocks of one call share no dynamic body (one joint colour's; LaneBlocks.hpp's inPairs).
void warmStartWheels(const WheelBlock* begin, const WheelBlock* end, SolverBody* states,
                     WideCode code = WideCode::Best);
void solveWheels(WheelBlock* begin, WheelBlock* end, SolverBody* states, bool useBias, WideCode code = WideCode::Best);
/// The blocks' impulses and last axes back into their joints (the next step's warm start, the reaction, the ledger).
void storeWheels(const WheelBlock* begin, const WheelBlock* end, std::vector<JointData>& joints);

}  // namespace physim
