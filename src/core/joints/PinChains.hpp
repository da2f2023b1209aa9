#pragma once
// Chains of pins solved as one block (WorldSettings::directChainMassRatio). Internal.
//
// A pass of Gauss-Seidel moves a pin's impulse only to its neighbours, and each soft pin pulls back with its own
// row's effective mass: along light links holding a heavy weight, every pin stretches by its give under the whole
// weight. Solved together, the pins see the chain's mass: consecutive pins share one body, so their 2x2 blocks of
// K = J M^-1 J^T form a block-tridiagonal system, solved exactly by block elimination in O(pins). The softness is
// the rows' own (one jointHertz for all), applied to the block's solution: settled, only the top pin gives.

#include "JointShared.hpp"

#include <cstdint>
#include <vector>

namespace physim {

struct JointData;

struct PinChains {
    // Chains as runs of joint-row indices, in order along each chain: chain c is rows[chainStart[c], chainStart[c+1]).
    std::vector<std::uint32_t> rows;
    std::vector<std::uint32_t> chainStart{0};
    std::vector<std::uint32_t> groupChainStart;  // group g's chains: [groupChainStart[g], groupChainStart[g + 1])

    /// Finds the chains among `jointRows` (laid-out order): runs of at least two pins (rows in RowLanes::Pin) in which
    /// each moving body has at most two of the pins and whose moving bodies' masses differ by massRatio or more.
    /// Marks their rows chained (they are then solved here, not coloured). `bodies`: awake bodies.
    void find(std::vector<JointConstraint>& jointRows, std::size_t bodies, double massRatio);
    /// After the rows were sorted: row k now lies at newIndex[k]; rowGroup(sorted index) is its group.
    template <class GroupOf>
    void sorted(const std::vector<std::uint32_t>& newIndex, std::size_t groups, GroupOf&& rowGroup);
    void clear(std::size_t groups);

private:
    std::vector<std::uint32_t> pinCount_, pinOf_;  // per awake body: its pins (up to two, pinOf_[2 b + i])
    std::vector<std::uint8_t> state_;              // per row: 0 no pin, 1 pin, 2 blocked, 3 visited
    std::vector<std::uint32_t> byGroup_, fill_, sortedRows_, sortedStart_;  // sorted()'s scratch
};

/// Scratch for solveChain, kept between steps (grows to the longest chain).
struct ChainScratch {
    struct Pin {
        MotionSide a, b;
        Vec2 rA, rB, rhs;
        Vec2 bend;  // the anchors' bend the solve pass aimed at (pointBend)
        Eigen::Matrix2d invD, lower;  // the elimination's D^-1 and L = K(i, i-1) D(i-1)^-1
    };
    std::vector<Pin> pins;
};

/// One pass over a chain's pins (rows in chain order), exactly: with the bias and softness and the anchors' bend
/// (solve pass, as solvePoint; the bend's correction for the turns the block gave is then taken pin by pin) or
/// rigid (relax pass). Falls back to pin after pin where the chain's block is singular (pins at one point).
void solveChain(const std::uint32_t* order, std::size_t count, const JointConstraint* rows,
                std::vector<JointData>& joints, SolverBody* states, bool useBias, ChainScratch& scratch);

template <class GroupOf>
void PinChains::sorted(const std::vector<std::uint32_t>& newIndex, std::size_t groups, GroupOf&& rowGroup) {
    for (std::uint32_t& r : rows) r = newIndex[r];
    // Chains group by group (a chain's rows all lie in one group: its bodies are one island), in the order found.
    const std::size_t chains = chainStart.size() - 1;
    groupChainStart.assign(groups + 1, 0);
    for (std::size_t c = 0; c < chains; ++c) ++groupChainStart[rowGroup(rows[chainStart[c]]) + 1];
    for (std::size_t g = 0; g < groups; ++g) groupChainStart[g + 1] += groupChainStart[g];
    fill_.assign(groupChainStart.begin(), groupChainStart.end() - 1);
    byGroup_.resize(chains);
    for (std::size_t c = 0; c < chains; ++c) byGroup_[fill_[rowGroup(rows[chainStart[c]])]++] = static_cast<std::uint32_t>(c);
    std::vector<std::uint32_t>& out = sortedRows_;
    std::vector<std::uint32_t>& starts = sortedStart_;
    out.clear();
    starts.assign(1, 0);
    for (const std::uint32_t c : byGroup_) {
        out.insert(out.end(), rows.begin() + chainStart[c], rows.begin() + chainStart[c + 1]);
        starts.push_back(static_cast<std::uint32_t>(out.size()));
    }
    rows.swap(out);
    chainStart.swap(starts);
}

}  // namespace physim
