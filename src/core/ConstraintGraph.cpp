// The constraint graph's layout of a step's rows: colouring, this step's islands and their groups, blocks, and the
// halves of two threads (ConstraintGraph.hpp).

#include "ConstraintGraph.hpp"

#include "Joints.hpp"
#include "StageTimer.hpp"
#include "WorldImpl.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace physim {
namespace {

// Islands are solved in groups of about this many bodies: a group's rows (~260 bytes each, two or three per body)
// and bodies stay in a core's cache through all of its substeps' passes, where one sweep of a large scene's rows
// per pass streams them from memory. Smaller groups leave more lanes of their colours' last blocks empty.
constexpr std::size_t kGroupBodies = 256;

}  // namespace

void prepareJointRow(JointConstraint& row, const WorldImpl& w, std::uint32_t joint, double h,
                     const Softness& rodSoftness) {
    row = JointConstraint{};
    row.joint = joint;
    prepareJoint(row, w.joints[joint], w.bodies, h, rodSoftness);
    row.h = arcStep(w.settings, row.h);
}

// A colour's rows may lie in any order (they share no dynamic body), and a block whose rows all have one point
// skips the second point's work (ContactSolver.cpp): within each window of kPointWindow rows, the one-point rows go
// first, each part still in body order. Windows keep the rows of nearby bodies together, as two threads need
// (markShareHeads); a window has at most one block of rows of both kinds.
void ConstraintGraph::putOnePointRowsFirst(const WorldImpl& w, std::uint32_t first, std::uint32_t end) {
    std::array<RowRef, kPointWindow> twos;
    for (std::uint32_t window = first; window < end; window += kPointWindow) {
        const std::uint32_t last = std::min<std::uint32_t>(window + kPointWindow, end);
        std::uint32_t ones = window;
        std::size_t twoCount = 0;
        for (std::uint32_t r = window; r < last; ++r) {
            const RowRef ref = rowContacts[r];
            if (w.contacts[ref.contact].manifold.pointCount == 2) twos[twoCount++] = ref;
            else rowContacts[ones++] = ref;
        }
        std::copy(twos.begin(), twos.begin() + static_cast<std::ptrdiff_t>(twoCount), rowContacts.begin() + ones);
    }
}

std::size_t ConstraintGraph::layOut(WorldImpl& w, bool byIsland, double h, const Softness& rodSoftness) {
    const std::size_t n = w.awake.size();
    // Colour the rows: greedy, in the awake list's order (deterministic), each dynamic body's colours as bits.
    // Meanwhile join the bodies each row couples (union-find over awake indices) to solve islands apart.
    std::size_t rowCount = 0;
    rowContacts.clear();
    blockRows.clear();
    jointConstraints.clear();
    bodyRoot.resize(n);
    for (std::size_t i = 0; i < n; ++i) bodyRoot[i] = static_cast<std::int32_t>(i);
    rowsWarmStart.assign(n, 0);
    auto keepRowsWarmStart = [&](std::int32_t index) {
        if (index != kNullIndex) rowsWarmStart[static_cast<std::size_t>(index)] = 1;
    };
    if (!w.awakeContacts.empty() || w.rowJointCount > 0) {
        StageTimer timer(w.profile, Stage::Solve);
        bodyColours.assign(n, 0);
        constexpr std::uint32_t kAllColours = (std::uint32_t{1} << kColours) - 1;
        constraintColour.assign(w.awakeContacts.size(), -1);
        rowRefs.resize(w.awakeContacts.size());
        rowList.clear();
        const bool hooked = static_cast<bool>(w.preSolve);  // contacts may be disabled (WorldImpl::runPreSolve)
        // Only the contacts with points are read (awakeHasPoints): on a terrain most awake contacts have none.
        const std::size_t contactCount = w.awakeContacts.size();
        const std::uint8_t* const hasPoints = w.awakeHasPoints.data();
        assert(w.awakeHasPoints.size() == contactCount);
        for (std::size_t k = 0; k < contactCount; ++k) {
            assert(hasPoints[k] == (w.contacts[w.awakeContacts[k]].manifold.pointCount > 0 ? 1 : 0));
            if (!hasPoints[k]) continue;
            const ContactData& c = w.contacts[w.awakeContacts[k]];
            if (hooked && c.disabled) continue;
            const BodyData& A = w.bodies[c.a()];
            const BodyData& B = w.bodies[c.b()];
            // The lowest colour neither dynamic body has yet; the overflow if both have them all.
            auto used = [&](const BodyData& b) -> std::uint32_t* {
                const bool moves = b.type == BodyType::Dynamic && b.awakeIndex != kNullIndex;
                return moves ? &bodyColours[static_cast<std::size_t>(b.awakeIndex)] : nullptr;
            };
            std::uint32_t* const usedA = used(A);
            std::uint32_t* const usedB = used(B);
            const std::uint32_t free = ~((usedA ? *usedA : 0u) | (usedB ? *usedB : 0u)) & kAllColours;
            int colour = kColours;
            if (free != 0) {
                colour = __builtin_ctz(free);
                if (usedA) *usedA |= std::uint32_t{1} << colour;
                if (usedB) *usedB |= std::uint32_t{1} << colour;
            }
            constraintColour[k] = colour;
            rowRefs[k] = {w.awakeContacts[k], A.awakeIndex, B.awakeIndex};
            rowList.push_back(static_cast<std::uint32_t>(k));
            if (A.detection == CollisionDetection::ContinuousExact) keepRowsWarmStart(A.awakeIndex);
            if (B.detection == CollisionDetection::ContinuousExact) keepRowsWarmStart(B.awakeIndex);
            if (byIsland) joinBodies(A.awakeIndex, B.awakeIndex);
            ++rowCount;
        }
        // Joint rows are coloured the same way, with colours of their own (jointSegment holds the colour for now).
        bodyColours.assign(n, 0);
        jointSegment.clear();
        for (std::uint32_t j = 0; j < w.joints.size(); ++j) {
            const JointData& joint = w.joints[j];
            if (!joint.alive || !joint.isRow()) continue;
            const bool active = w.bodies[joint.b].awake() || (joint.twoBodies() && w.bodies[joint.a].awake());
            if (!active) continue;
            prepareJointRow(jointConstraints.emplace_back(), w, j, h, rodSoftness);
        }
        // Chains of pins under a large mass ratio are solved as blocks, after the colours (PinChains.hpp).
        chains.find(jointConstraints, n, w.settings.directChainMassRatio);
        for (const JointConstraint& row : jointConstraints) {
            const JointData& joint = w.joints[row.joint];
            auto used = [&](std::uint32_t body) -> std::uint32_t* {
                const BodyData& b = w.bodies[body];
                const bool moves = b.type == BodyType::Dynamic && b.awakeIndex != kNullIndex;
                return moves ? &bodyColours[static_cast<std::size_t>(b.awakeIndex)] : nullptr;
            };
            std::uint32_t* const usedA = joint.twoBodies() ? used(joint.a) : nullptr;
            std::uint32_t* const usedB = used(joint.b);
            const std::uint32_t free = ~((usedA ? *usedA : 0u) | (usedB ? *usedB : 0u)) & kAllColours;
            std::uint32_t colour = kColours;
            if (free != 0 && jointColoured(joint) && !row.chained) {
                colour = static_cast<std::uint32_t>(__builtin_ctz(free));
                if (usedA) *usedA |= std::uint32_t{1} << colour;
                if (usedB) *usedB |= std::uint32_t{1} << colour;
            }
            jointSegment.push_back(colour);
            keepRowsWarmStart(row.indexA);
            keepRowsWarmStart(row.indexB);
            if (byIsland) joinBodies(row.indexA, row.indexB);
        }
    }
    groupIslands(n, byIsland);
    const std::size_t groups = groupBodyStart.size() - 1;

    if (rowCount > 0 || !jointConstraints.empty()) {
        StageTimer timer(w.profile, Stage::Solve);
        // Rows sorted by group, then colour, each colour's in the order of the rows' first awake body; the overflow's
        // in the awake contacts' order. A colour's rows share no dynamic body, so their order changes no result;
        // in the bodies' order, the passes walk the body records in order, and two threads, each taking half of a
        // colour, take rows of bodies that lie together (markShareHeads), however the contacts began. The overflow
        // is solved row after row, where the order decides the result: that order stays the colouring's.
        auto segmentOf = [&](std::size_t k) {
            const RowRef& r = rowRefs[k];
            return bodyGroup[static_cast<std::size_t>(r.indexA != kNullIndex ? r.indexA : r.indexB)] * kSegments +
                   static_cast<std::size_t>(constraintColour[k]);
        };
        auto coloured = [&](std::size_t k) { return constraintColour[k] >= 0 && constraintColour[k] < kColours; };
        auto firstBody = [&](std::size_t k) -> std::size_t {  // kNullIndex (-1) as unsigned: past every awake index
            const auto a = static_cast<std::uint32_t>(rowRefs[k].indexA);
            const auto b = static_cast<std::uint32_t>(rowRefs[k].indexB);
            return std::min<std::size_t>(std::min(a, b), n);
        };
        rowOrder.assign(n + 1, 0);  // a counting sort by first body: where each body's rows start
        for (const std::uint32_t k : rowList)
            if (coloured(k)) ++rowOrder[firstBody(k)];
        std::uint32_t sum = 0;
        for (std::uint32_t& count : rowOrder) sum += std::exchange(count, sum);
        sortedRows.resize(sum);
        for (const std::uint32_t k : rowList)
            if (coloured(k)) sortedRows[rowOrder[firstBody(k)]++] = k;
        segmentStart.assign(groups * kSegments + 1, 0);
        for (const std::uint32_t k : rowList) ++segmentStart[segmentOf(k) + 1];
        for (std::size_t s = 0; s + 1 < segmentStart.size(); ++s) segmentStart[s + 1] += segmentStart[s];
        rowContacts.resize(rowCount);
        segmentFill.assign(segmentStart.begin(), segmentStart.end() - 1);
        for (const std::uint32_t k : sortedRows) rowContacts[segmentFill[segmentOf(k)]++] = rowRefs[k];
        for (std::size_t s = 0; s + 1 < segmentStart.size(); ++s)
            if (s % kSegments < kColours && segmentStart[s + 1] - segmentStart[s] > 1)
                putOnePointRowsFirst(w, segmentStart[s], segmentStart[s + 1]);
        for (const std::uint32_t k : rowList)
            if (constraintColour[k] == kColours) rowContacts[segmentFill[segmentOf(k)]++] = rowRefs[k];
        // kLanes rows of a colour to a block; an overflow row shares no block (it may share a body with the next).
        blockStart.assign(groups * kSegments + 1, 0);
        for (std::size_t s = 0; s + 1 < segmentStart.size(); ++s) {
            const std::uint32_t first = segmentStart[s], end = segmentStart[s + 1];
            const std::uint32_t lanes = s % kSegments < kColours ? kLanes : 1;
            for (std::uint32_t r = first; r < end; r += lanes) blockRows.push_back({r, std::min(lanes, end - r)});
            blockStart[s + 1] = static_cast<std::uint32_t>(blockRows.size());
        }
        // A group's blocks are needed only while it is solved. Each worker solves its groups one after another in
        // a region of its own, so the blocks the step writes and reads stay in the worker's cache, where one array
        // of a large scene's blocks (about 400 bytes a row) would be written and read from memory. A spread group is
        // solved by all workers before the others start: it uses the start of the array, whatever its size.
        regionBlocks = 0;
        spreadBlocks = 0;
        for (std::size_t g = 0; g < groups; ++g) {
            const std::size_t blocks = blockStart[(g + 1) * kSegments] - blockStart[g * kSegments];
            std::size_t& most = spreads(g, w.executor.threads(), n) ? spreadBlocks : regionBlocks;
            most = std::max(most, blocks);
        }
        if (w.executor.threads() == 2) markShareHeads(n);
        else shareHeads.clear();
        // Joint rows sorted by group, then colour (the overflow last), each segment's in the joints' order.
        for (std::size_t k = 0; k < jointConstraints.size(); ++k) {
            const JointConstraint& row = jointConstraints[k];
            const std::size_t group =
                bodyGroup[static_cast<std::size_t>(row.indexB != kNullIndex ? row.indexB : row.indexA)];
            jointSegment[k] += static_cast<std::uint32_t>(group * kSegments);
        }
        jointSegmentStart.assign(groups * kSegments + 1, 0);
        for (const std::uint32_t s : jointSegment) ++jointSegmentStart[s + 1];
        for (std::size_t s = 0; s + 1 < jointSegmentStart.size(); ++s) jointSegmentStart[s + 1] += jointSegmentStart[s];
        groupJointStart.assign(groups + 1, 0);
        for (std::size_t g = 0; g <= groups; ++g) groupJointStart[g] = jointSegmentStart[g * kSegments];
        groupedJoints.resize(jointConstraints.size());
        segmentFill.assign(jointSegmentStart.begin(), jointSegmentStart.end() - 1);
        sortedJointIndex.resize(jointConstraints.size());
        for (std::size_t k = 0; k < jointConstraints.size(); ++k) {
            sortedJointIndex[k] = segmentFill[jointSegment[k]]++;
            groupedJoints[sortedJointIndex[k]] = jointConstraints[k];
        }
        jointConstraints.swap(groupedJoints);
        chains.sorted(sortedJointIndex, groups, [&](std::uint32_t r) {
            const JointConstraint& row = jointConstraints[r];
            return bodyGroup[static_cast<std::size_t>(row.indexB != kNullIndex ? row.indexB : row.indexA)];
        });
    } else {
        shareHeads.clear();
        segmentStart.assign(groups * kSegments + 1, 0);
        blockStart.assign(groups * kSegments + 1, 0);
        groupJointStart.assign(groups + 1, 0);
        jointSegmentStart.assign(groups * kSegments + 1, 0);
        chains.clear(groups);
    }

    return rowCount;
}

// Two threads take each colour's blocks in halves, split at the middle (Team::forLoopsInOrder). A block that touches
// a body the other half also touches, in any colour, must run before the other half's next colour: those blocks
// are the half's head, [cut, mid) of the first half and [mid, cut) of the second, and run first; the rest touch
// bodies that only their own thread touches in the pass. Each colour's rows are laid out by first body
// (layOut), so the heads are the few blocks on either side of the middle where the bodies lie together.
void ConstraintGraph::markShareHeads(std::size_t bodies) {
    const std::size_t groups = groupBodyStart.size() - 1;
    shareHeads.assign(groups * kColours * 2, 0);
    bodyShares.assign(bodies, 0);
    auto forBodies = [&](std::size_t b, auto&& f) {
        for (std::uint32_t r = blockRows[b].first; r < blockRows[b].first + blockRows[b].count; ++r) {
            if (rowContacts[r].indexA != kNullIndex) f(static_cast<std::size_t>(rowContacts[r].indexA));
            if (rowContacts[r].indexB != kNullIndex) f(static_cast<std::size_t>(rowContacts[r].indexB));
        }
    };
    auto forHalves = [&](auto&& f) {  // f(group, colour, first, mid, end) for every colour of every group
        for (std::size_t g = 0; g < groups; ++g)
            for (std::size_t col = 0; col < kColours; ++col) {
                const std::size_t first = blockStart[g * kSegments + col], end = blockStart[g * kSegments + col + 1];
                f(g, col, first, middleBlock(first, end), end);
            }
    };
    forHalves([&](std::size_t, std::size_t, std::size_t first, std::size_t mid, std::size_t end) {
        for (std::size_t b = first; b < end; ++b)
            forBodies(b, [&](std::size_t i) { bodyShares[i] |= b < mid ? 1 : 2; });
    });
    auto touchesBoth = [&](std::size_t b) {
        bool both = false;
        forBodies(b, [&](std::size_t i) { both = both || bodyShares[i] == 3; });
        return both;
    };
    headBlocks.assign(groups * 2, 0);
    forHalves([&](std::size_t g, std::size_t col, std::size_t first, std::size_t mid, std::size_t end) {
        std::size_t low = mid, high = mid;
        for (std::size_t b = first; b < mid && low == mid; ++b)
            if (touchesBoth(b)) low = b;
        for (std::size_t b = end; b > mid && high == mid; --b)
            if (touchesBoth(b - 1)) high = b;
        shareHeads[(g * kColours + col) * 2] = static_cast<std::uint32_t>(low);
        shareHeads[(g * kColours + col) * 2 + 1] = static_cast<std::uint32_t>(high);
        headBlocks[g * 2] += high - low;
        headBlocks[g * 2 + 1] += end - first;
    });
    // The bodies' loops in the same halves: a body both halves touch is in the first half's head, one that only
    // a half touches in that half's rest, one no row touches in the half of the group's list it lies in.
    shareBodies.resize(groupBodies.size());
    shareBodyCuts.assign(groups * 2, 0);
    for (std::size_t g = 0; g < groups; ++g) {
        const std::size_t first = groupBodyStart[g], end = groupBodyStart[g + 1], mid = first + (end - first) / 2;
        auto half = [&](std::size_t k) {
            const std::uint8_t bits = bodyShares[groupBodies[k]];
            return bits == 3 ? 0 : bits == 1 ? 1 : bits == 2 ? 2 : k < mid ? 1 : 2;  // 0 head, 1 first, 2 second
        };
        std::size_t fill = first;
        for (const int wanted : {0, 1, 2}) {
            if (wanted > 0)
                shareBodyCuts[g * 2 + static_cast<std::size_t>(wanted - 1)] = static_cast<std::uint32_t>(fill);
            for (std::size_t k = first; k < end; ++k)
                if (half(k) == wanted) shareBodies[fill++] = groupBodies[k];
        }
    }
}

// Where most blocks are heads (bodies made in no order of where they lie), each colour would in effect be a wait for
// the whole other half, without the team's sharing out of what is left: such a group keeps one stage per loop.
bool ConstraintGraph::halvesInOrder(std::size_t g) const {
    return !shareHeads.empty() && 2 * headBlocks[g * 2] <= headBlocks[g * 2 + 1];
}

// Groups of one island or more run their substeps apart: a group's rows and bodies stay in cache through all of its
// passes. A large group (or one holding more than a thread's share of the bodies) spreads each of its loops over the
// threads; the others go to the threads whole. Either way a group gives the same bits.
bool ConstraintGraph::spreads(std::size_t g, int threads, std::size_t bodies) const {
    const std::size_t groups = groupBodyStart.size() - 1, size = groupBodyStart[g + 1] - groupBodyStart[g];
    return groups == 1 || size >= 4 * kGroupBodies || size * static_cast<std::size_t>(threads) > bodies;
}

// This step's islands, apart from the persistent ones of Islands.cpp, on purpose: those exist only while sleep is
// on, link only touching contacts, and split only when one is about to sleep, so they can hold bodies no row
// couples any more (one large group where the rows make many small ones) or miss a speculative row's coupling (a
// row between two groups, solved at once on two threads). The union-find here follows exactly the rows this step
// solves, roots each island at its lowest awake index (a fixed group order), and rides on the colouring's pass.
void ConstraintGraph::joinBodies(std::int32_t a, std::int32_t b) {
    if (a == kNullIndex || b == kNullIndex) return;  // a static or sleeping side couples nothing
    auto root = [&](std::int32_t i) {
        while (bodyRoot[static_cast<std::size_t>(i)] != i) {
            auto& parent = bodyRoot[static_cast<std::size_t>(i)];
            parent = bodyRoot[static_cast<std::size_t>(parent)];  // path halving
            i = parent;
        }
        return i;
    };
    a = root(a);
    b = root(b);
    if (a < b) bodyRoot[static_cast<std::size_t>(b)] = a;  // the lower index roots: the same tree on any run
    else if (b < a) bodyRoot[static_cast<std::size_t>(a)] = b;
}

void ConstraintGraph::groupIslands(std::size_t bodies, bool byIsland) {
    const std::size_t n = bodies;
    bodyGroup.assign(n, 0);
    groupBodies.resize(n);
    groupBodyStart.assign(2, 0);
    groupBodyStart[1] = static_cast<std::uint32_t>(n);
    const bool anyRowsWarmStart = std::find(rowsWarmStart.begin(), rowsWarmStart.end(), 1) != rowsWarmStart.end();
    if (!byIsland || (n <= kGroupBodies && !anyRowsWarmStart)) {
        for (std::size_t i = 0; i < n; ++i) groupBodies[i] = static_cast<std::uint32_t>(i);
        groupRowsWarmStart.assign(1, anyRowsWarmStart ? 1 : 0);
        return;
    }
    // Flatten the trees (a root has the lowest index of its island, so one pass in index order does it) and
    // count each island's bodies at its root.
    islandSize.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const auto root = static_cast<std::size_t>(bodyRoot[static_cast<std::size_t>(bodyRoot[i])]);
        bodyRoot[i] = static_cast<std::int32_t>(root);
        ++islandSize[root];
        if (rowsWarmStart[i]) rowsWarmStart[root] = 1;
    }
    // Islands join groups in the order of their first body, a group closing once it holds kGroupBodies. Islands that
    // keep the rows' warm start fill groups of their own, so an island's warm start, and so its bits, never depend
    // on which islands share its group.
    std::uint32_t groups = 0;
    std::uint32_t openGroup[2] = {0, 0}, open[2] = {kGroupBodies, kGroupBodies};  // per kind; full: none open
    groupRowsWarmStart.clear();
    for (std::size_t i = 0; i < n; ++i) {
        const auto root = static_cast<std::size_t>(bodyRoot[i]);
        if (root == i) {
            const std::uint8_t kind = rowsWarmStart[i];
            if (open[kind] >= kGroupBodies) {
                openGroup[kind] = groups++;
                open[kind] = 0;
                groupRowsWarmStart.push_back(kind);
            }
            open[kind] += islandSize[root];
            bodyGroup[i] = openGroup[kind];
        } else {
            bodyGroup[i] = bodyGroup[root];
        }
    }
    groupBodyStart.assign(groups + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++groupBodyStart[bodyGroup[i] + 1];
    for (std::uint32_t g = 0; g < groups; ++g) groupBodyStart[g + 1] += groupBodyStart[g];
    segmentFill.assign(groupBodyStart.begin(), groupBodyStart.end() - 1);
    for (std::size_t i = 0; i < n; ++i) groupBodies[segmentFill[bodyGroup[i]]++] = static_cast<std::uint32_t>(i);
}

}  // namespace physim
