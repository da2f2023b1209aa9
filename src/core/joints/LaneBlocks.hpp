#pragma once
// What the joint blocks solved in lanes share (PinLanes.hpp, WheelLanes.hpp): the fields every row has, packed lane
// by lane the same way for each kind. Internal.

#include "../Wide.hpp"
#include "JointShared.hpp"

#include <cstdint>

namespace physim {

/// Empties `block` for `count` rows: unused lanes have no bodies (kNullIndex) and no mass, so they change nothing.
template <class Block>
void startBlock(Block& block, std::uint32_t count) {
    block = Block{};
    for (int k = 0; k < kLanes; ++k) block.indexA[k] = block.indexB[k] = kNullIndex;
    block.count = count;
}

/// The fields every joint row has into lane `lane`: the lever arms and centres, the masses, the rod's softness, the
/// bodies and joint, and which sides the row moves.
template <class Block>
void packRowFields(Block& block, const JointConstraint& row, std::uint32_t lane) {
    const int k = static_cast<int>(lane);
    block.anchorAx[k] = row.anchorA.x();
    block.anchorAy[k] = row.anchorA.y();
    block.anchorBx[k] = row.anchorB.x();
    block.anchorBy[k] = row.anchorB.y();
    block.deltaX[k] = row.deltaCenter.x();
    block.deltaY[k] = row.deltaCenter.y();
    block.invMassA[k] = row.invMassA;
    block.invMassB[k] = row.invMassB;
    block.invIA[k] = row.invIA;
    block.invIB[k] = row.invIB;
    block.biasRate[k] = row.softness.biasRate;
    block.massScale[k] = row.softness.massScale;
    block.impulseScale[k] = row.softness.impulseScale;
    block.indexA[k] = row.indexA;
    block.indexB[k] = row.indexB;
    block.joint[k] = row.joint;
    if (rowMoves(row.indexA, row.invMassA)) block.writesA |= 1u << lane;
    if (rowMoves(row.indexB, row.invMassB)) block.writesB |= 1u << lane;
}

}  // namespace physim
