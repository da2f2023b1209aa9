#pragma once
// Revolute joints' shared points solved kLanes at a time (Wide.hpp): the rows of one joint colour share no dynamic
// body (ConstraintGraph.cpp), so a block's lanes are independent. Each lane does what RevoluteJoint's warmStart and
// solve do for a pin without motor or limits (RevoluteJoint::pointOnly), operation for operation, so a lane gives
// the bits the scalar row gives. Other rows of the colour take the scalar path (Joints.hpp). Internal.

#include "../SolverData.hpp"
#include "../Wide.hpp"
#include "JointShared.hpp"

#include <cstdint>
#include <vector>

namespace physim {

struct BodyData;
struct JointData;

/// Up to kLanes pin rows for a step: the rows' fields by lane and the points' accumulated impulses, N s. An unused
/// lane has no bodies (kNullIndex) and no mass: it changes nothing.
struct alignas(64) PinBlock {  // 64: the AVX builds assume their vectors aligned, which baseline code would not give
    Wide anchorAx, anchorAy, anchorBx, anchorBy;  // lever arms at the step's start, m
    Wide deltaX, deltaY;                           // centre of B minus centre of A at the start, m
    Wide invMassA, invMassB, invIA, invIB;
    Wide biasRate, massScale, impulseScale;        // the rod's softness (Softness.hpp)
    Wide impulseX, impulseY;                       // the point's impulse, N s
    Wide turnImpulse;                              // the warm start's angular impulse on B, N m s
    std::int32_t indexA[kLanes], indexB[kLanes];
    std::uint32_t joint[kLanes];
    unsigned writesA = 0, writesB = 0;  // a bit per lane whose side the row moves (Impulse.hpp's rowMoves)
    std::uint32_t count = 0;            // lanes in use
    double h = 0.0, invH = 0.0;         // the substep (s) and its inverse, the same for every row of a step
};

/// What refreshPins needs of a block's rows beyond the block: each lane's anchors in its bodies' frames from their
/// centres of mass (m) and its bodies' slots.
struct PinFrame {
    Wide armAx, armAy, armBx, armBy;
    std::uint32_t bodyA[kLanes], bodyB[kLanes];
};

/// Fills `block` from `count` (1..kLanes) prepared rows of revolute joints whose pointOnly() holds.
void packPins(PinBlock& block, const JointConstraint* const* rows, std::uint32_t count,
              const std::vector<JointData>& joints);
/// The same rows' frame, for refreshPins.
void framePins(PinFrame& frame, const JointConstraint* const* rows, std::uint32_t count,
               const std::vector<JointData>& joints, const std::vector<BodyData>& bodies);
/// Makes a block packed last step ready for this one, where the layout is kept (the same rows, joints, awake bodies
/// and body masses): the arms, the centres' offset and the masses at the step's start, from the awake bodies' step
/// records (sims) and the others' records, bit for bit as prepareJointRow and packPins would give them, without reading
/// the rows or the joints; the impulses stay (storePins left the joints the same). `arcStep`: the row's h (0
/// without WorldSettings::jointArcs), `invH` and `softness` the substep's.
void refreshPins(PinBlock& block, const PinFrame& frame, const SolverBodySim* sims,
                 const std::vector<BodyData>& bodies, double arcStep, double invH, const Softness& softness);
/// The blocks of one call share no dynamic body (one joint colour's; LaneBlocks.hpp's inPairs).
void warmStartPins(const PinBlock* begin, const PinBlock* end, SolverBody* states, WideCode code = WideCode::Best);
void solvePins(PinBlock* begin, PinBlock* end, SolverBody* states, bool useBias, WideCode code = WideCode::Best);
/// The blocks' impulses back into their joints (the next step's warm start, the reaction).
void storePins(const PinBlock* begin, const PinBlock* end, std::vector<JointData>& joints);

}  // namespace physim
