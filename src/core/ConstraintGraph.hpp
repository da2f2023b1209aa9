#pragma once
// The constraint graph: how a step's rows are laid out for the solver (Solver.hpp). Internal.
//
// Contact rows are coloured greedily, in the awake contacts' order, so that rows of one colour share no dynamic body:
// they can be solved in any order, on any thread, with the same result. The bodies each row couples are joined into
// this step's islands, and whole islands are gathered into groups that the solver runs apart (a group's rows and
// bodies stay in a core's cache through all of its substeps). On two threads each colour of a group is cut in
// halves, one per thread (markShareHeads). A segment is one group's rows of one colour, or its overflow: segment
// g * kSegments + c.

#include "ContactSolver.hpp"
#include "JointData.hpp"
#include "SolverData.hpp"
#include "joints/PinChains.hpp"

#include "physim/core/WorldSettings.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace physim {

struct WorldImpl;

// Colours tried per row before it goes to the overflow (solved serially after the coloured rows).
constexpr int kColours = 24;
constexpr std::size_t kSegments = kColours + 1;  // a group's rows: kColours colours, then the overflow

// Where two threads cut a colour's blocks [first, end) in halves: the second half starts here.
inline std::size_t middleBlock(std::size_t first, std::size_t end) { return first + (end - first) / 2; }

/// Makes `row` joint `joint`'s row for this step (substep h), every field anew (in place: a row is 224 bytes).
void prepareJointRow(JointConstraint& row, const WorldImpl& w, std::uint32_t joint, double h,
                     const Softness& rodSoftness);
/// The substep a pin's or weld's row bends its aim over (solvePoint): h, or 0 (no bend) without
/// WorldSettings::jointArcs.
inline double arcStep(const WorldSettings& settings, double h) { return settings.jointArcs ? h : 0.0; }

struct ConstraintGraph {
    /// Colours the rows and sorts them into groups and blocks; returns the rows (jointConstraints: the joint rows).
    std::size_t layOut(WorldImpl& w, bool byIsland, double h, const Softness& rodSoftness);
    std::size_t groupCount() const { return groupBodyStart.size() - 1; }
    bool halvesInOrder(std::size_t g) const;  // on two threads, group g's halves meet in few blocks: run in order
    /// Group g's loops are spread over the `threads` threads (else it goes to one whole); `bodies`: the awake ones.
    bool spreads(std::size_t g, int threads, std::size_t bodies) const;

    std::vector<std::int32_t> bodyRoot;          // per awake body: union-find parent, then its island's root
    std::vector<std::uint32_t> islandSize;       // per root: its island's bodies
    std::vector<std::uint32_t> bodyGroup;        // per awake body: its group
    // Per awake body, then per island root: its island keeps the warm start as a pass over the rows (it has a joint
    // or an exact-continuous bullet; Solver.cpp); such islands are grouped apart from the others.
    std::vector<std::uint8_t> rowsWarmStart;
    std::vector<std::uint8_t> groupRowsWarmStart;  // per group: the same for all its islands
    std::vector<std::uint32_t> groupBodies;      // awake indices, group by group
    std::vector<std::uint32_t> groupBodyStart;   // group g's bodies: [groupBodyStart[g], groupBodyStart[g + 1])
    std::vector<std::uint32_t> groupJointStart;  // group g's joint rows in jointConstraints, likewise
    // Joint rows of segment s in jointConstraints: [jointSegmentStart[s], jointSegmentStart[s + 1]). Colours are
    // the joint rows' own (their passes run apart from the contacts'); the overflow is solved row after row.
    std::vector<std::uint32_t> jointSegmentStart;
    std::vector<RowRef> rowContacts;             // the contact of each row, segment by segment
    std::vector<std::uint32_t> segmentStart;     // rows of segment s: [segmentStart[s], segmentStart[s + 1])
    std::vector<std::uint32_t> blockStart;       // blocks of segment s: [blockStart[s], blockStart[s + 1])
    std::vector<BlockRows> blockRows;            // per block: its first row and how many lanes it uses
    // A group's blocks live only while it is solved, in a region of `regionBlocks` blocks per worker (Solver.cpp);
    // a spread group uses the start of the blocks, `spreadBlocks` at most.
    std::size_t regionBlocks = 0;
    std::size_t spreadBlocks = 0;
    std::vector<std::uint32_t> shareHeads;       // on two threads, per group and colour: where the halves' heads end
    std::vector<std::uint8_t> bodyShares;        // markShareHeads: which halves touch each awake body (bits)
    std::vector<std::size_t> headBlocks;         // markShareHeads: per group, blocks in heads and all blocks
    std::vector<std::uint32_t> shareBodies;      // on two threads, each group's bodies by half: head, first, second
    std::vector<std::uint32_t> shareBodyCuts;    // per group: where the first half's head ends, and the second's starts
    std::vector<std::uint32_t> segmentFill;      // counting sorts' next free place
    std::vector<std::uint32_t> bodyColours;      // per awake body, a bit per colour its rows already have
    std::vector<std::int32_t> constraintColour;  // per awake contact with points; -1: none
    std::vector<RowRef> rowRefs;                 // per awake contact with points: its row's contact and bodies
    std::vector<std::uint32_t> rowList;          // the awake contacts with rows (as rowRefs' indices), in order
    std::vector<std::uint32_t> rowOrder;         // layOut's counting sort: per awake body, where its rows go
    std::vector<std::uint32_t> sortedRows;       // the coloured rows (as rowRefs' indices) by first body
    std::vector<JointConstraint> jointConstraints;  // group by group
    std::vector<JointConstraint> groupedJoints;
    std::vector<std::uint32_t> jointSegment;     // per joint row while laying out: its segment
    std::vector<std::uint32_t> sortedJointIndex; // per joint row while laying out: its place once sorted
    PinChains chains;                            // chains of pins solved as blocks, group by group
    // The layout above (colours, rows, blocks, groups) depends only on the awake bodies and contacts (their order,
    // the bodies' types and detection, which contacts have points), the joints and the thread count: while none of
    // that changes, a step keeps the last one's (Solver::solve). Whatever changes it sets stale.
    bool stale = true;
    bool laidOutByIsland = true;  // the layout's byIsland

private:
    void markShareHeads(std::size_t bodies);
    static constexpr std::uint32_t kPointWindow = 64;  // rows; a multiple of kLanes, so windows start blocks
    void putOnePointRowsFirst(const WorldImpl& w, std::uint32_t first, std::uint32_t end);
    void joinBodies(std::int32_t a, std::int32_t b);  // awake indices: one island (kNullIndex: no-op)
    void groupIslands(std::size_t bodies, bool byIsland);  // bodyGroup, groupBodies; one group unless byIsland
};

}  // namespace physim
