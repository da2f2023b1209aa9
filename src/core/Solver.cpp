// The soft step over the awake bodies: gather them into contiguous arrays, colour the contact rows so rows of one
// colour share no dynamic body (they can be solved in any order, on any thread, with the same result), group whole
// islands, then per group substeps of integrate velocities -> warm start -> solve -> integrate positions -> relax,
// and finalize (poses, boxes, sleep timers, proxies that left their boxes). Islands share no moving body, so a
// group's substeps need nothing of another's: each group runs all of its substeps while its rows are in cache.

#include "BodyPasses.hpp"
#include "Impulse.hpp"
#include "Joints.hpp"
#include "Prefetch.hpp"
#include "WorldImpl.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>

namespace physim {
namespace {

// Colours tried per row before it goes to the overflow (solved serially after the coloured rows).
constexpr int kColours = 24;
constexpr std::size_t kSegments = kColours + 1;  // a group's rows: kColours colours, then the overflow
constexpr std::size_t kBodyGrain = 256;
constexpr std::size_t kBlockGrain = 16;  // blocks of kLanes rows
// Colouring asks for the bodies of the contact this far ahead, and for that contact twice as far ahead.
constexpr std::size_t kPrefetchContacts = 8;
// Gathering and writing back bodies asks for the record of the body this far ahead in the group.
constexpr std::size_t kPrefetchBodies = 4;
// Islands are solved in groups of about this many bodies: a group's rows (~260 bytes each, two or three per body)
// and bodies stay in a core's cache through all of its substeps' passes, where one sweep of a large scene's rows
// per pass streams them from memory. Smaller groups leave more lanes of their colours' last blocks empty.
constexpr std::size_t kGroupBodies = 256;

// Where two threads cut a colour's blocks [first, end) in halves: the second half starts here.
std::size_t middleBlock(std::size_t first, std::size_t end) { return first + (end - first) / 2; }

// The point of a row's impact event: its fastest meeting point faster than `threshold` (m/s); -1: none.
int impactPoint(const ContactBlockCold& cold, int lane, double threshold) {
    const ContactBlockCold::Lane& row = cold.lanes[lane];
    int fastest = -1;
    double fastestSpeed = 0.0;
    for (int p = 0; p < row.pointCount; ++p) {
        const double speed = cold.relativeVelocity[p][lane];
        if (row.engaged[p] && -speed > threshold && (fastest < 0 || speed < fastestSpeed)) {
            fastest = p;
            fastestSpeed = speed;
        }
    }
    return fastest;
}

class StageTimer {
public:
    StageTimer(StepProfile& profile, Stage stage) : profile_(profile), stage_(stage) {}
    ~StageTimer() {
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
        profile_.secondsOf(stage_) += elapsed.count();
        profile_.ran[static_cast<std::size_t>(stage_)] = true;
    }

private:
    StepProfile& profile_;
    Stage stage_;
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace

void WorldImpl::solve() {
    const std::size_t n = awake.size();
    const int substeps = settings.substeps;
    const double h = dt / substeps, invH = 1.0 / h;
    const Softness contactSoftness = makeSoftness(settings.contactHertz, settings.contactDampingRatio, h);
    const Softness rodSoftness = makeSoftness(settings.jointHertz, settings.jointDampingRatio, h);

    {
        StageTimer timer(profile, Stage::Forces);
        solverBodies.resize(n + 1);  // each group gathers its own bodies (startBody)
        solverBodies[0] = SolverBody{};  // the still body that kNullIndex reads (ContactSolver.hpp)
        states = solverBodies.data() + 1;
        sims.resize(n);
        enlarged.assign(n, 0);
    }

    // The rows' layout is the last step's while nothing that decides it has changed (WorldImpl::rowsStale); a kept
    // layout's joint rows are prepared again for this step, in their places.
    const bool byIsland = !effects.perSubstep();  // a per-substep effect may couple any bodies
    const bool keep = !rowsStale && byIsland == rowsByIsland;
    if (keep && !jointConstraints.empty()) {
        StageTimer timer(profile, Stage::Solve);
        for (JointConstraint& row : jointConstraints) row = jointRow(row.joint, h, rodSoftness);
    }
    const std::size_t rowCount = keep ? rowContacts.size() : layOutRows(byIsland, h, rodSoftness);
    rowsStale = false;
    rowsByIsland = byIsland;
    profile.rowsLaidOut = !keep && (rowCount > 0 || !jointConstraints.empty());
    const std::size_t groups = groupBodyStart.size() - 1;

    contactPassSettings.h = h;
    contactPassSettings.invH = invH;
    contactPassSettings.softness = contactSoftness;
    contactPassSettings.maxPushVelocity = settings.contactPushMaxVelocity;
    contactPassSettings.restitutionThreshold = settings.restitutionThreshold;
    contactPassSettings.slipSpeed = 0.1 * settings.linearSlop / dt;
    pushVelocities.assign(n, PushVelocity{});
    rowsBase.resize(n);
    warmStarts.resize(n);
    std::atomic<std::size_t> turningRows{0};
    for (std::size_t g = 0; g < groups; ++g)
        if (spreads(g)) turningRows += solveGroup(g, true, 0);
    if (groups > 1) {
        StageTimer timer(profile, Stage::Solve);
        executor.parallelFor(groups, 1, [&](std::size_t begin, std::size_t end, int worker) {
            for (std::size_t g = begin; g < end; ++g)
                if (!spreads(g)) turningRows += solveGroup(g, false, worker);
        });
    }
    profile.turningRows = turningRows.load();
    for (std::size_t g = 0; g < groups; ++g)
        if (spreads(g) && halvesInOrder(g)) {
            profile.headBlocks += headBlocks[g * 2];
            profile.halvedBlocks += headBlocks[g * 2 + 1];
        }

    if (rowCount > 0) {
        StageTimer timer(profile, Stage::Solve);
        // Impacts, in row order (deterministic); each group's store pass found its rows' points (impactPoint).
        for (std::size_t b = 0; b < blockRows.size(); ++b)
            for (std::uint32_t lane = 0; lane < blockRows[b].count; ++lane) {
                const int point = rowImpact[b * kLanes + lane];
                if (point < 0) continue;
                const Manifold& m = contacts[rowContacts[blockRows[b].first + lane].contact].manifold;
                events.impacts.push_back(
                    {m.bodyA, m.bodyB, m.points[point].point, m.normal, rowImpactSpeed[b * kLanes + lane]});
            }
    }

    StageTimer timer(profile, Stage::Integrate);
    fastBodies = std::any_of(enlarged.begin(), enlarged.end(), [](std::uint8_t f) { return (f & 2) != 0; });
    for (std::size_t i = 0; i < n; ++i) {
        if (!(enlarged[i] & 1)) continue;
        const BodyData& b = bodies[sims[i].body];
        // The Continuous stage may put this body back: its proxy moves after that stage, once (bit 2).
        if ((enlarged[i] & 2) || b.detection != CollisionDetection::Discrete) enlarged[i] |= 4;
        else moveProxy(b);
    }
}

JointConstraint WorldImpl::jointRow(std::uint32_t joint, double h, const Softness& rodSoftness) const {
    JointConstraint row;
    row.joint = joint;
    prepareJoint(row, joints[joint], bodies, h, rodSoftness);
    return row;
}

std::size_t WorldImpl::layOutRows(bool byIsland, double h, const Softness& rodSoftness) {
    const std::size_t n = awake.size();
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
    if (!awakeContacts.empty() || rowJointCount > 0) {
        StageTimer timer(profile, Stage::Solve);
        bodyColours.assign(n, 0);
        constexpr std::uint32_t kAllColours = (std::uint32_t{1} << kColours) - 1;
        constraintColour.assign(awakeContacts.size(), -1);
        rowRefs.resize(awakeContacts.size());
        for (std::size_t k = 0; k < awakeContacts.size(); ++k) {
            // The contacts lie close to their order in memory, their bodies do not: ask for the records ahead.
            if (k + 2 * kPrefetchContacts < awakeContacts.size())
                __builtin_prefetch(&contacts[awakeContacts[k + 2 * kPrefetchContacts]]);
            if (k + kPrefetchContacts < awakeContacts.size()) {
                const ContactData& ahead = contacts[awakeContacts[k + kPrefetchContacts]];
                __builtin_prefetch(&bodies[ahead.a].awakeIndex);
                __builtin_prefetch(&bodies[ahead.b].awakeIndex);
            }
            const ContactData& c = contacts[awakeContacts[k]];
            if (c.manifold.pointCount == 0) continue;
            const BodyData& A = bodies[c.a];
            const BodyData& B = bodies[c.b];
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
            rowRefs[k] = {awakeContacts[k], A.awakeIndex, B.awakeIndex};
            if (A.detection == CollisionDetection::ContinuousExact) keepRowsWarmStart(A.awakeIndex);
            if (B.detection == CollisionDetection::ContinuousExact) keepRowsWarmStart(B.awakeIndex);
            if (byIsland) joinBodies(A.awakeIndex, B.awakeIndex);
            ++rowCount;
        }
        for (std::uint32_t j = 0; j < joints.size(); ++j) {
            const JointData& joint = joints[j];
            if (!joint.alive || !joint.isRow()) continue;
            const bool active = bodies[joint.b].awake() || (joint.twoBodies() && bodies[joint.a].awake());
            if (!active) continue;
            const JointConstraint row = jointRow(j, h, rodSoftness);
            jointConstraints.push_back(row);
            keepRowsWarmStart(row.indexA);
            keepRowsWarmStart(row.indexB);
            if (byIsland) joinBodies(row.indexA, row.indexB);
        }
    }
    groupIslands(byIsland);
    const std::size_t groups = groupBodyStart.size() - 1;

    if (rowCount > 0 || !jointConstraints.empty()) {
        StageTimer timer(profile, Stage::Solve);
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
        for (std::size_t k = 0; k < awakeContacts.size(); ++k)
            if (coloured(k)) ++rowOrder[firstBody(k)];
        std::uint32_t sum = 0;
        for (std::uint32_t& count : rowOrder) sum += std::exchange(count, sum);
        sortedRows.resize(sum);
        for (std::size_t k = 0; k < awakeContacts.size(); ++k)
            if (coloured(k)) sortedRows[rowOrder[firstBody(k)]++] = static_cast<std::uint32_t>(k);
        segmentStart.assign(groups * kSegments + 1, 0);
        for (std::size_t k = 0; k < awakeContacts.size(); ++k)
            if (constraintColour[k] >= 0) ++segmentStart[segmentOf(k) + 1];
        for (std::size_t s = 0; s + 1 < segmentStart.size(); ++s) segmentStart[s + 1] += segmentStart[s];
        rowContacts.resize(rowCount);
        segmentFill.assign(segmentStart.begin(), segmentStart.end() - 1);
        for (const std::uint32_t k : sortedRows) rowContacts[segmentFill[segmentOf(k)]++] = rowRefs[k];
        for (std::size_t k = 0; k < awakeContacts.size(); ++k)
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
        std::size_t spreadBlocks = 0;
        for (std::size_t g = 0; g < groups; ++g) {
            const std::size_t blocks = blockStart[(g + 1) * kSegments] - blockStart[g * kSegments];
            std::size_t& most = spreads(g) ? spreadBlocks : regionBlocks;
            most = std::max(most, blocks);
        }
        const std::size_t size =
            std::max(spreadBlocks, regionBlocks * static_cast<std::size_t>(executor.workerSlots()));
        if (contactBlocks.size() < size) {
            contactBlocks.resize(size);  // each group fills its own (solveGroup), every lane of them
            contactCold.resize(size);
        }
        if (executor.threads() == 2) markShareHeads();
        else shareHeads.clear();
        rowImpact.resize(blockRows.size() * kLanes);  // each group sets its rows' lanes
        rowImpactSpeed.resize(blockRows.size() * kLanes);
        // Joint rows sorted by group, each group's in the joints' order.
        groupJointStart.assign(groups + 1, 0);
        auto groupOfJoint = [&](const JointConstraint& row) {
            return bodyGroup[static_cast<std::size_t>(row.indexB != kNullIndex ? row.indexB : row.indexA)];
        };
        for (const JointConstraint& row : jointConstraints) ++groupJointStart[groupOfJoint(row) + 1];
        for (std::size_t g = 0; g < groups; ++g) groupJointStart[g + 1] += groupJointStart[g];
        groupedJoints.resize(jointConstraints.size());
        segmentFill.assign(groupJointStart.begin(), groupJointStart.end() - 1);
        for (const JointConstraint& row : jointConstraints) groupedJoints[segmentFill[groupOfJoint(row)]++] = row;
        jointConstraints.swap(groupedJoints);
    } else {
        shareHeads.clear();
        segmentStart.assign(groups * kSegments + 1, 0);
        blockStart.assign(groups * kSegments + 1, 0);
        groupJointStart.assign(groups + 1, 0);
    }

    return rowCount;
}

// Two threads take each colour's blocks in halves, split at the middle (Team::forLoopsInOrder). A block that touches
// a body the other half also touches, in any colour, must run before the other half's next colour: those blocks
// are the half's head, [cut, mid) of the first half and [mid, cut) of the second, and run first; the rest touch
// bodies that only their own thread touches in the pass. Each colour's rows are laid out by first body
// (layOutRows), so the heads are the few blocks on either side of the middle where the bodies lie together.
void WorldImpl::markShareHeads() {
    const std::size_t groups = groupBodyStart.size() - 1;
    shareHeads.assign(groups * kColours * 2, 0);
    bodyShares.assign(awake.size(), 0);
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
bool WorldImpl::halvesInOrder(std::size_t g) const {
    return !shareHeads.empty() && 2 * headBlocks[g * 2] <= headBlocks[g * 2 + 1];
}

// Groups of one island or more run their substeps apart: a group's rows and bodies stay in cache through all of its
// passes. A large group (or one holding more than a thread's share of the bodies) spreads each of its loops over the
// threads; the others go to the threads whole. Either way a group gives the same bits.
bool WorldImpl::spreads(std::size_t g) const {
    const std::size_t groups = groupBodyStart.size() - 1, size = groupBodyStart[g + 1] - groupBodyStart[g];
    const std::size_t threads = static_cast<std::size_t>(executor.threads());
    return groups == 1 || size >= 4 * kGroupBodies || size * threads > awake.size();
}

void WorldImpl::joinBodies(std::int32_t a, std::int32_t b) {
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

void WorldImpl::groupIslands(bool byIsland) {
    const std::size_t n = awake.size();
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

void WorldImpl::startBody(std::size_t i) {
    const BodyData& b = bodies[awake[i]];
    const bool dynamic = b.type == BodyType::Dynamic;
    SolverBody& s = states[i];
    s.v = b.v;
    s.w = b.w;
    s.dAngle = 0.0;
    s.dp.setZero();
    s.dq = Rotation{};
    SolverBodySim& sim = sims[i];
    sim.center0 = b.center;
    sim.q0 = b.xf.q;
    sim.angle0 = b.angle;
    sim.acceleration = dynamic ? Vec2(b.gravityFactor() * settings.gravity + b.invMass * b.force) : Vec2::Zero();
    sim.angularAcceleration = dynamic ? b.invInertia * b.torque : 0.0;
    sim.invMass = dynamic ? b.invMass : 0.0;
    sim.invInertia = dynamic ? b.invInertia : 0.0;
    sim.restitution = b.restitution;
    sim.staticFriction = b.staticFriction;
    sim.dynamicFriction = b.dynamicFriction;
    sim.body = awake[i];
    sim.dynamic = dynamic;
    sim.turns = rowSide(b).turns;
}

void WorldImpl::finishBody(std::size_t i) {
    const SolverBody& s = states[i];
    const SolverBodySim& sim = sims[i];
    BodyData& b = bodies[sim.body];
    b.v = s.v;
    b.w = s.w;
    b.center = sim.center0 + s.dp;
    if (sim.turns) {
        b.angle = sim.angle0 + s.dAngle;
        b.xf.q = compose(s.dq, sim.q0);
    }
    b.xf.p = b.center - b.xf.q.apply(b.localCenter);
    b.force.setZero();
    b.torque = 0.0;
    b.aabb = computeAabb(b.shape, b.xf);
    if (settings.enableSleep && b.canSleep() && sim.dynamic && b.v.norm() <= settings.sleepLinearTolerance &&
        std::abs(b.w) <= settings.sleepAngularTolerance)
        b.sleepTime += dt;
    else
        b.sleepTime = 0.0;
    // Its proxy must move (bit 0); it moved far for its size this step (bit 1: the Continuous stage's).
    const double travel = s.dp.norm() + std::abs(s.dAngle) * b.extent;
    enlarged[i] = static_cast<std::uint8_t>(
        (proxyOutgrown(b) ? 1 : 0) | (sim.dynamic && b.proxy != kNullIndex && travel > 0.5 * b.coreRadius ? 2 : 0));
}

std::size_t WorldImpl::solveGroup(std::size_t g, bool timed, int worker) {
    const int substeps = settings.substeps;
    const double h = dt / substeps;
    const std::uint32_t* const bodyList = groupBodies.data() + groupBodyStart[g];
    const std::size_t bodyCount = groupBodyStart[g + 1] - groupBodyStart[g];
    const std::uint32_t* const segments = blockStart.data() + g * kSegments;
    const bool anyRows = segments[kSegments] > segments[0] || groupJointStart[g + 1] > groupJointStart[g];
    SolverBody* const st = states;
    // Block b of the group (numbered as blockRows) lies at blockAt(b) and coldAt(b), in the worker's region.
    const std::size_t firstBlock = segments[0], blockCount = segments[kSegments] - firstBlock;
    const std::size_t region = static_cast<std::size_t>(worker) * regionBlocks;
    auto blockAt = [&](std::size_t b) { return contactBlocks.data() + region + (b - firstBlock); };
    auto coldAt = [&](std::size_t b) { return contactCold.data() + region + (b - firstBlock); };
    // On the calling thread's share of the step: a stage's time counts only where one group runs at a time.
    auto stage = [&](Stage s) { return timed ? std::optional<StageTimer>(std::in_place, profile, s) : std::nullopt; };
    auto forBodies = [&](auto&& f) {
        executor.parallelFor(bodyCount, kBodyGrain, [&](std::size_t begin, std::size_t end, int) {
            for (std::size_t k = begin; k < end; ++k) f(bodyList[k]);
        });
    };
    // The same over the bodies' records, asking for each whole record a few bodies ahead: a group lists its
    // bodies island by island, not in memory order.
    auto forRecords = [&](auto&& f) {
        executor.parallelFor(bodyCount, kBodyGrain, [&](std::size_t begin, std::size_t end, int) {
            for (std::size_t k = begin; k < end; ++k) {
                if (k + kPrefetchBodies < end)
                    prefetchLines(&bodies[awake[bodyList[k + kPrefetchBodies]]], sizeof(BodyData));
                f(bodyList[k]);
            }
        });
    };
    // One pass over the group's rows: joints, then colour by colour (in parallel within a colour), then the
    // overflow. rowsWork(begin, end) over blocks; jointWork(row, joint) for each joint.
    // On a team of two the colours run as one sequence (Executor::forLoopsInOrder): each thread takes its half of
    // every colour, and waits only for the blocks of the other half that touch its bodies (markShareHeads).
    std::array<std::uint8_t, kColours> colours{};  // the group's colours that hold rows
    std::size_t colourCount = 0;
    for (std::size_t col = 0; col < kColours; ++col)
        if (segments[col + 1] > segments[col]) colours[colourCount++] = static_cast<std::uint8_t>(col);
    const bool ordered = executor.ordersLoops() && halvesInOrder(g);
    // A half's head or rest of colour colours[k]: blocks [begin, end) of the group's.
    auto halfOf = [&](std::size_t k, int share, bool head) {
        const std::size_t col = colours[k], first = segments[col], end = segments[col + 1];
        const std::size_t mid = middleBlock(first, end), cut = shareHeads[(g * kColours + col) * 2 + share];
        return share == 0 ? (head ? std::make_pair(cut, mid) : std::make_pair(first, cut))
                          : (head ? std::make_pair(mid, cut) : std::make_pair(cut, end));
    };
    auto pass = [&](auto&& rowsWork, auto&& jointWork) {
        for (std::uint32_t j = groupJointStart[g]; j < groupJointStart[g + 1]; ++j)
            jointWork(jointConstraints[j], joints[jointConstraints[j].joint]);
        if (ordered) {
            executor.forLoopsInOrder(colourCount, [&](std::size_t loop, int share, bool head) {
                const auto [begin, end] = halfOf(loop, share, head);
                if (begin < end) rowsWork(begin, end);
            });
        } else {
            for (std::size_t k = 0; k < colourCount; ++k) {
                const std::size_t first = segments[colours[k]], count = segments[colours[k] + 1] - first;
                executor.parallelFor(count, kBlockGrain, [&](std::size_t begin, std::size_t end, int) {
                    rowsWork(first + begin, first + end);
                });
            }
        }
        rowsWork(segments[kColours], segments[kSegments]);
    };
    {
        auto timer = stage(Stage::Forces);
        forRecords([&](std::size_t i) { startBody(i); });
    }
    // A block is prepared in the step's first pass over the rows, just before its warm start, and its impulses
    // stored in the last, just after its relax: the thread that solves it in every pass (Team.hpp) writes it first
    // and reads it last, so it never moves to another core's cache for that.
    std::atomic<std::size_t> turningRows{0};
    std::atomic<bool> bounces{false};  // some row can bounce: only then is what the warm start gave kept (bounces)
    const double impactSpeed = settings.impactSpeedThreshold;
    auto storeBlocks = [&](std::size_t begin, std::size_t end) {
        for (std::size_t b = begin; b < end; ++b)
            for (std::uint32_t lane = 0; lane < blockRows[b].count; ++lane) {
                const ContactBlockCold& cold = *coldAt(b);
                const int k = static_cast<int>(lane);
                storeImpulses(*blockAt(b), cold, k, contacts[cold.lanes[k].contact]);
                const int point = impactPoint(cold, k, impactSpeed);
                rowImpact[b * kLanes + lane] = static_cast<std::int8_t>(point);
                if (point >= 0) rowImpactSpeed[b * kLanes + lane] = -cold.relativeVelocity[point][k];
            }
    };
    const bool storeInRelax = settings.relaxIterations > 0;
    ContactPass contactPass = contactPassSettings;
    contactPass.pushes = pushVelocities.data();
    contactPass.holdPushes = settings.relaxIterations > 0;  // the relax pass takes held push-out back
    // After the first substep, the warm start runs on the bodies (integrateVelocity), not the rows: the same to
    // rounding, without a pass. Not with joints (their J turns with the bodies), an effect acting between substeps,
    // or an exact-continuous bullet: a bullet can leave its rows' geometry metres and radians behind within a step,
    // and there even a rounding change can decide whether a bounce keeps its energy (docs/performance.md,
    // "Thirteenth measurement").
    const bool bodiesWarmStart = !groupRowsWarmStart[g] && !effects.perSubstep();
    RowsBase* const base = rowsBase.data();
    if (bodiesWarmStart) contactPass.rowsBase = base;
    WarmStartVelocity* const warm = warmStarts.data();
    contactPass.warmStarts = warm;
    auto solvePass = [&](bool useBias, bool store) {
        contactPass.useBias = useBias;
        pass([&](std::size_t b, std::size_t e) {
                 solveContacts(blockAt(b), blockAt(e), coldAt(b), st, contactPass);
                 if (store) storeBlocks(b, e);
             },
             [&](const JointConstraint& row, JointData& joint) { solveJoint(row, joint, st, useBias); });
    };

    // On two threads, a substep's solve passes, position integration and relax passes are one ordered sequence
    // (each pass's colours, the bodies' loop between), where no joint or overflow row needs a thread alone between
    // passes. Where the warm start after the first substep is the bodies' (no pass) and nothing acts between
    // substeps, the substeps after it join the sequence too, each from its velocity integration: one wait for the
    // step's substeps. Each loop gets its own copy of the passes' settings: the threads may be in different passes.
    const bool oneSequence = ordered && colourCount > 0 && groupJointStart[g + 1] == groupJointStart[g] &&
                             segments[kSegments] == segments[kColours];
    auto solveInOrder = [&](int firstSub, int lastSub) {
        const std::size_t solves = static_cast<std::size_t>(settings.velocityIterations) * colourCount;
        const std::size_t relaxes = static_cast<std::size_t>(settings.relaxIterations) * colourCount;
        const std::size_t perSubstep = 1 + solves + 1 + relaxes;  // velocities, solve, positions, relax
        const std::uint32_t* const halves = shareBodies.data() + groupBodyStart[g];
        const std::size_t headEnd = shareBodyCuts[g * 2] - groupBodyStart[g];
        const std::size_t secondStart = shareBodyCuts[g * 2 + 1] - groupBodyStart[g];
        WarmStartVelocity* const keepWarm = bounces.load(std::memory_order_relaxed) ? warm : nullptr;
        // The first substep's velocities are done already.
        const std::size_t loops = static_cast<std::size_t>(lastSub - firstSub + 1) * perSubstep - 1;
        executor.forLoopsInOrder(loops, [&](std::size_t loop, int share, bool head) {
            const int sub = firstSub + static_cast<int>((loop + 1) / perSubstep);
            const std::size_t phase = (loop + 1) % perSubstep;
            if (phase == 0 || phase == solves + 1) {  // a bodies' loop: the first half's head, then each half's rest
                if (share == 1 && head) return;
                const std::size_t begin = share == 0 ? (head ? 0 : headEnd) : secondStart;
                const std::size_t end = share == 0 ? (head ? headEnd : secondStart) : bodyCount;
                if (begin >= end) return;
                if (phase == 0)
                    integrateVelocities(st, base, keepWarm, sims.data(), halves + begin, end - begin, h, true);
                else
                    integratePositions(st, halves + begin, end - begin, h);
                return;
            }
            const bool relax = phase > solves + 1;
            const std::size_t k = relax ? phase - solves - 2 : phase - 1;
            const auto [begin, end] = halfOf(k % colourCount, share, head);
            if (begin >= end) return;
            ContactPass rows = contactPass;
            rows.substep = sub;
            rows.useBias = !relax;
            solveContacts(blockAt(begin), blockAt(end), coldAt(begin), st, rows);
            if (relax && sub + 1 == substeps && storeInRelax && k + colourCount >= relaxes) storeBlocks(begin, end);
        });
    };

    for (int sub = 0; sub < substeps; ++sub) {
        contactPass.substep = sub;
        if (effects.perSubstep()) effects.substep(*this, h);  // then there is one group
        {
            auto timer = stage(Stage::Integrate);
            WarmStartVelocity* const keepWarm = bounces.load(std::memory_order_relaxed) ? warm : nullptr;
            executor.parallelFor(bodyCount, kBodyGrain, [&](std::size_t begin, std::size_t end, int) {
                integrateVelocities(st, base, keepWarm, sims.data(), bodyList + begin, end - begin, h,
                                    bodiesWarmStart && sub > 0);
            });
        }
        if (anyRows) {
            auto timer = stage(Stage::Solve);
            if (sub == 0 || !bodiesWarmStart) {
                pass([&](std::size_t b, std::size_t e) {
                         if (sub == 0) {
                             const PreparedRows prepared =
                                 prepareContacts(blockAt(b), coldAt(b), blockRows.data() + b, e - b,
                                                 rowContacts.data(), contacts.data(), sims.data(), bodies.data());
                             turningRows += prepared.turning;  // one add per chunk
                             if (prepared.bounce) bounces.store(true, std::memory_order_relaxed);
                         }
                         warmStartContacts(blockAt(b), blockAt(e), st);
                     },
                     [&](const JointConstraint& row, JointData& joint) { warmStartJoint(row, joint, st); });
                if (bounces.load(std::memory_order_relaxed))
                    forBodies([&](std::size_t i) {
                        if (sims[i].dynamic) recordWarmStart(st[i], base[i], warm[i]);
                    });
            }
            if (oneSequence) {
                const int last = bodiesWarmStart ? substeps - 1 : sub;
                solveInOrder(sub, last);
                sub = last;
                continue;
            }
            for (int it = 0; it < settings.velocityIterations; ++it) solvePass(true, false);
        }
        {
            auto timer = stage(Stage::Integrate);
            executor.parallelFor(bodyCount, kBodyGrain, [&](std::size_t begin, std::size_t end, int) {
                integratePositions(st, bodyList + begin, end - begin, h);
            });
        }
        if (anyRows) {
            auto timer = stage(Stage::Solve);
            for (int it = 0; it < settings.relaxIterations; ++it)
                solvePass(false, sub + 1 == substeps && it + 1 == settings.relaxIterations);
        }
    }
    if (blockCount > 0 && !storeInRelax) {
        auto timer = stage(Stage::Solve);
        executor.parallelFor(blockCount, kBlockGrain, [&](std::size_t begin, std::size_t end, int) {
            storeBlocks(firstBlock + begin, firstBlock + end);
        });
    }
    {
        auto timer = stage(Stage::Integrate);
        forRecords([&](std::size_t i) { finishBody(i); });
    }
    return turningRows.load();
}

void WorldImpl::moveDeferredProxies() {
    deferredKeys.clear();
    deferredBoxes.clear();
    for (std::size_t i = 0; i < enlarged.size(); ++i) {
        const BodyData& b = bodies[sims[i].body];
        if (!(enlarged[i] & 4) || !proxyOutgrown(b)) continue;
        deferredKeys.push_back(b.proxy);
        deferredBoxes.push_back(proxyBox(b, kAabbMargin));
    }
    broadPhase.moveProxies(deferredKeys, deferredBoxes);  // a crowd of fast bodies rebuilds the tree once
}

}  // namespace physim
