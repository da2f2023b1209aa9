#pragma once
// What the joint blocks solved in lanes share (PinLanes.hpp, WheelLanes.hpp): the fields every row has, packed lane
// by lane the same way for each kind. Internal.

#include "../BodyLanes.hpp"
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

/// Runs `work(block, A, B)` on each block of [begin, end) between the gather and the scatter of its bodies. The
/// blocks must share no dynamic body (one joint colour's): two blocks' bodies are gathered before either is written
/// back, so that their rows are two independent chains of operations that the core overlaps (a block alone is one
/// long chain, and waits on it).
template <class Block, class Work>
[[gnu::always_inline]] inline void inPairs(Block* begin, Block* end, SolverBody* states, Work&& work) {
    Block* p = begin;
    for (; end - p >= 2; p += 2) {
        WideSide A0 = gather<true>(p[0].indexA, states), B0 = gather<true>(p[0].indexB, states);
        WideSide A1 = gather<true>(p[1].indexA, states), B1 = gather<true>(p[1].indexB, states);
        work(p[0], A0, B0);
        work(p[1], A1, B1);
        scatter(p[0].indexA, p[0].writesA, A0, states);
        scatter(p[0].indexB, p[0].writesB, B0, states);
        scatter(p[1].indexA, p[1].writesA, A1, states);
        scatter(p[1].indexB, p[1].writesB, B1, states);
    }
    if (p != end) {
        WideSide A = gather<true>(p->indexA, states), B = gather<true>(p->indexB, states);
        work(*p, A, B);
        scatter(p->indexA, p->writesA, A, states);
        scatter(p->indexB, p->writesB, B, states);
    }
}

}  // namespace physim
