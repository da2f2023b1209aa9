// The soft step over the awake bodies (Solver.hpp): gather them into contiguous arrays, lay the rows out in the
// constraint graph (ConstraintGraph.cpp), then per group substeps of integrate velocities -> warm start -> solve ->
// integrate positions -> relax, and finalize (poses, boxes, sleep timers, proxies that left their boxes). Islands
// share no moving body, so a group's substeps need nothing of another's: each group runs all of its substeps while
// its rows are in cache.

#include "Solver.hpp"

#include "BodyPasses.hpp"
#include "Impulse.hpp"
#include "Joints.hpp"
#include "Prefetch.hpp"
#include "StageTimer.hpp"
#include "WorldImpl.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>

namespace physim {
namespace {

constexpr std::size_t kBodyGrain = 256;
constexpr std::size_t kBlockGrain = 16;  // blocks of kLanes rows
constexpr std::size_t kJointGrain = 16;  // a joint colour's pin blocks and other rows
constexpr std::size_t kJointPrepareGrain = 256;  // joint rows prepared again in a kept layout
// Gathering and writing back bodies asks for the record of the body this far ahead in the group.
constexpr std::size_t kPrefetchBodies = 4;

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

// A substep's stages, in the order they run: one list that both executors expand. The loop over substeps runs
// each stage's passes one after another; on two threads the ordered path (solveGroup's solveInOrder) runs the same
// list as one sequence of loops, a bodies' stage one loop, a row pass one loop per colour, and the warm start none:
// the sequence starts after a substep's warm start, and later substeps' is the bodies' (inside their velocities).
enum class SubstepStage : std::uint8_t { Velocities, WarmStart, Solve, Positions, Relax };

struct StagePasses {
    SubstepStage stage;
    int passes;
};
using SubstepList = std::array<StagePasses, 5>;

/// The substep's stages in order, with `solves` solve and `relaxes` relax passes (WorldSettings' iterations).
SubstepList substepStages(int solves, int relaxes) {
    return {{{SubstepStage::Velocities, 1},
             {SubstepStage::WarmStart, 1},
             {SubstepStage::Solve, solves},
             {SubstepStage::Positions, 1},
             {SubstepStage::Relax, relaxes}}};
}

/// The ordered path's loops for one pass of `stage`, where a pass over the rows has `colours` colours.
std::size_t loopsPerPass(SubstepStage stage, std::size_t colours) {
    switch (stage) {
        case SubstepStage::Velocities:
        case SubstepStage::Positions: return 1;
        case SubstepStage::WarmStart: return 0;
        case SubstepStage::Solve:
        case SubstepStage::Relax: return colours;
    }
    return 0;
}

/// The ordered path's loops for the stages [first, last) of the list, each stage all its passes.
std::size_t loopsOf(const SubstepList& list, std::size_t first, std::size_t last, std::size_t colours) {
    std::size_t loops = 0;
    for (std::size_t s = first; s < last; ++s)
        loops += static_cast<std::size_t>(list[s].passes) * loopsPerPass(list[s].stage, colours);
    return loops;
}

/// Where the ordered path's loop `loop` of a substep (from 0, < loopsOf the whole list) lies in the list.
struct OrderedLoop {
    SubstepStage stage;
    bool lastPass;       // the last pass of its stage
    std::size_t colour;  // a row pass's colour, as the group's colours are counted
};
OrderedLoop orderedLoop(const SubstepList& list, std::size_t loop, std::size_t colours) {
    for (const StagePasses& s : list) {
        const std::size_t perPass = loopsPerPass(s.stage, colours);
        const std::size_t loops = static_cast<std::size_t>(s.passes) * perPass;
        if (loop < loops) return {s.stage, loop / perPass + 1 == static_cast<std::size_t>(s.passes), loop % perPass};
        loop -= loops;
    }
    return {SubstepStage::Positions, true, 0};  // past the list: not reached
}

/// The ordered path's loops of a substep before its sequence starts: those of the stages up to the warm start.
std::size_t loopsThroughWarmStart(const SubstepList& list, std::size_t colours) {
    std::size_t s = 0;
    while (s < list.size() && list[s].stage != SubstepStage::WarmStart) ++s;
    return loopsOf(list, 0, s + 1, colours);
}

}  // namespace

void Solver::solve(WorldImpl& w) {
    const std::size_t n = w.awake.size();
    const int substeps = w.settings.substeps;
    const double h = w.dt / substeps, invH = 1.0 / h;
    const Softness contactSoftness = makeSoftness(w.settings.contactHertz, w.settings.contactDampingRatio, h);
    const Softness rodSoftness = makeSoftness(w.settings.jointHertz, w.settings.jointDampingRatio, h);

    {
        StageTimer timer(w.profile, Stage::Forces);
        solverBodies_.resize(n + 1);  // each group gathers its own bodies (startBody)
        solverBodies_[0] = SolverBody{};  // the still body that kNullIndex reads (ContactSolver.hpp)
        states_ = solverBodies_.data() + 1;
        sims_.resize(n);
        enlarged_.assign(n, 0);
    }

    // The rows' layout is the last step's while nothing that decides it has changed (ConstraintGraph::stale); a
    // kept layout's joint rows are prepared again for this step, in their places, but for its pin blocks' rows:
    // those blocks are made ready from the bodies (refreshPins).
    const bool byIsland = !w.effects.perSubstep();  // a per-substep effect may couple any bodies
    const bool keep = !graph_.stale && byIsland == graph_.laidOutByIsland;
    // The ledger reads the wheels' motor impulses after each substep, in their joints: it keeps them out of lanes.
    const bool wheelsInLanes = !w.ledger.enabled;
    // A kept layout's pin blocks are made ready from the bodies alone (refreshPins), not from their rows: those
    // rows are not prepared again. The ledger reads every row in its place.
    refreshPins_ = keep && pinsPacked_ && wheelsInLanes == sortedWheelsInLanes_ && !w.ledger.enabled;
    rodSoftness_ = rodSoftness;
    if (keep && !graph_.jointConstraints.empty()) {
        StageTimer timer(w.profile, Stage::Solve);
        std::vector<JointConstraint>& rows = graph_.jointConstraints;
        const std::size_t count = refreshPins_ ? inPlaceRows_.size() : rows.size();
        w.executor.parallelFor(count, kJointPrepareGrain, [&](std::size_t begin, std::size_t end, int) {
            for (std::size_t i = begin; i < end; ++i) {
                const std::size_t k = refreshPins_ ? inPlaceRows_[i] : i;
                const bool chained = rows[k].chained;
                prepareJointRow(rows[k], w, rows[k].joint, h, rodSoftness);
                rows[k].chained = chained;
            }
        });
    }
    std::size_t rowCount = graph_.rowContacts.size();
    if (!keep) {
        rowCount = graph_.layOut(w, byIsland, h, rodSoftness);
        if (rowCount > 0 || !graph_.jointConstraints.empty()) {
            StageTimer timer(w.profile, Stage::Solve);
            const std::size_t size = std::max(
                graph_.spreadBlocks, graph_.regionBlocks * static_cast<std::size_t>(w.executor.workerSlots()));
            if (contactBlocks_.size() < size) {
                contactBlocks_.resize(size);  // each group fills its own (solveGroup), every lane of them
                contactCold_.resize(size);
                contactEnds_.resize(size);
            }
            rowImpact_.resize(graph_.blockRows.size() * kLanes);  // each group sets its rows' lanes
            rowImpactSpeed_.resize(graph_.blockRows.size() * kLanes);
        }
    }
    // Surface materials: their terms' array beside the cold blocks, from the first step of a world that uses them.
    if (w.surfaceMaterials) {
        if (contactMaterial_.size() < contactCold_.size()) contactMaterial_.resize(contactCold_.size());
        if (w.contactSurfaces.size() < w.contacts.size()) w.contactSurfaces.resize(w.contacts.size());
    }
    graph_.stale = false;
    graph_.laidOutByIsland = byIsland;
    w.profile.rowsLaidOut = !keep && (rowCount > 0 || !graph_.jointConstraints.empty());
    const std::size_t groups = graph_.groupBodyStart.size() - 1;
    // A kept layout keeps its rows' places in blocks (a joint that joins or leaves lanes lays the rows out again:
    // WorldImpl::changeJoint), unless the ledger came or went (it takes wheels out of lanes).
    if (!keep || wheelsInLanes != sortedWheelsInLanes_) {
        if (graph_.jointConstraints.empty()) {
            sortJointRows(wheelsInLanes);  // no rows: nothing to time (a step without rows runs no Solve stage)
        } else {
            StageTimer timer(w.profile, Stage::Solve);
            sortJointRows(wheelsInLanes);
        }
    }

    contactPassSettings_.h = h;
    contactPassSettings_.invH = invH;
    contactPassSettings_.softness = contactSoftness;
    contactPassSettings_.maxPushVelocity = w.settings.contactPushMaxVelocity;
    contactPassSettings_.restitutionThreshold = w.settings.restitutionThreshold;
    contactPassSettings_.slipSpeed = 0.1 * w.settings.linearSlop / w.dt;
    if (w.ledger.enabled) tally_.startStep(n, groups, graph_.blockRows.size());
    pushVelocities_.assign(n, PushVelocity{});
    rowsBase_.resize(n);
    warmStarts_.resize(n);
    if (!graph_.chains.rows.empty()) chainScratch_.resize(static_cast<std::size_t>(w.executor.workerSlots()));
    if (roundedRows_.value.load(std::memory_order_relaxed) && roundedSides_.size() < w.contacts.size())
        roundedSides_.resize(w.contacts.size());
    std::atomic<std::size_t> turningRows{0};
    for (std::size_t g = 0; g < groups; ++g)
        if (graph_.spreads(g, w.executor.threads(), n)) turningRows += solveGroup(w, g, true, 0);
    if (groups > 1) {
        StageTimer timer(w.profile, Stage::Solve);
        w.executor.parallelFor(groups, 1, [&](std::size_t begin, std::size_t end, int worker) {
            for (std::size_t g = begin; g < end; ++g)
                if (!graph_.spreads(g, w.executor.threads(), n)) turningRows += solveGroup(w, g, false, worker);
        });
    }
    w.profile.turningRows = turningRows.load();
    pinsPacked_ = true;  // every group packed its pin blocks, or made them ready
    for (std::size_t g = 0; g < groups; ++g)
        if (graph_.spreads(g, w.executor.threads(), n) && graph_.halvesInOrder(g)) {
            w.profile.headBlocks += graph_.headBlocks[g * 2];
            w.profile.halvedBlocks += graph_.headBlocks[g * 2 + 1];
        }

    if (rowCount > 0) {
        StageTimer timer(w.profile, Stage::Solve);
        // Impacts, in row order (deterministic); each group's store pass found its rows' points (impactPoint).
        for (std::size_t b = 0; b < graph_.blockRows.size(); ++b)
            for (std::uint32_t lane = 0; lane < graph_.blockRows[b].count; ++lane) {
                const int point = rowImpact_[b * kLanes + lane];
                if (point < 0) continue;
                const Manifold& m = w.contacts[graph_.rowContacts[graph_.blockRows[b].first + lane].contact].manifold;
                w.events.impacts.push_back({m.bodyA, m.bodyB, m.shapeA, m.shapeB, m.points[point].point, m.normal,
                                            rowImpactSpeed_[b * kLanes + lane]});
            }
    }

    StageTimer timer(w.profile, Stage::Integrate);
    fastBodies_ = std::any_of(enlarged_.begin(), enlarged_.end(), [](std::uint8_t f) { return (f & 2) != 0; });
    for (std::size_t i = 0; i < n; ++i) {
        if (!(enlarged_[i] & 1)) continue;
        const BodyData& b = w.bodies[sims_[i].body];
        // The Continuous stage may put this body back: its proxy moves after that stage, once (bit 2).
        if ((enlarged_[i] & 2) || b.detection != CollisionDetection::Discrete) enlarged_[i] |= 4;
        else w.moveProxies(b);
    }
}

void Solver::sortJointRows(bool wheelsInLanes) {
    const std::vector<std::uint32_t>& segments = graph_.jointSegmentStart;
    pinBlockStart_.assign(segments.size(), 0);
    wheelBlockStart_.assign(segments.size(), 0);
    otherJointStart_.assign(segments.size(), 0);
    pinRows_.clear();
    wheelRows_.clear();
    otherJointRows_.clear();
    inPlaceRows_.clear();
    sortedWheelsInLanes_ = wheelsInLanes;
    pinsPacked_ = false;
    for (std::size_t s = 0; s + 1 < segments.size(); ++s) {
        if (s % kSegments < kColours) {
            for (std::uint32_t r = segments[s]; r < segments[s + 1]; ++r) {
                const JointConstraint& row = graph_.jointConstraints[r];
                if (row.lanes == RowLanes::Pin) pinRows_.push_back(&row);
                else if (row.lanes == RowLanes::Wheel && wheelsInLanes) wheelRows_.push_back(&row);
                else otherJointRows_.push_back(r);
                if (row.lanes != RowLanes::Pin) inPlaceRows_.push_back(r);
            }
            // The colour's last blocks' free lanes.
            while (pinRows_.size() % kLanes != 0) pinRows_.push_back(nullptr);
            while (wheelRows_.size() % kLanes != 0) wheelRows_.push_back(nullptr);
        } else {
            for (std::uint32_t r = segments[s]; r < segments[s + 1]; ++r) inPlaceRows_.push_back(r);
        }
        pinBlockStart_[s + 1] = static_cast<std::uint32_t>(pinRows_.size() / kLanes);
        wheelBlockStart_[s + 1] = static_cast<std::uint32_t>(wheelRows_.size() / kLanes);
        otherJointStart_[s + 1] = static_cast<std::uint32_t>(otherJointRows_.size());
    }
    pinBlocks_.resize(pinRows_.size() / kLanes);  // each group packs its own (solveGroup)
    pinFrames_.resize(pinBlocks_.size());
    wheelBlocks_.resize(wheelRows_.size() / kLanes);
}

void Solver::startBody(WorldImpl& w, std::size_t i) {
    const BodyData& b = w.bodies[w.awake[i]];
    const bool dynamic = b.type == BodyType::Dynamic;
    SolverBody& s = states_[i];
    s.v = b.v;
    s.w = b.w;
    s.dAngle = 0.0;
    s.dp.setZero();
    s.dq = Rotation{};
    SolverBodySim& sim = sims_[i];
    sim.center0 = b.center;
    sim.q0 = b.xf.q;
    sim.angle0 = b.angle;
    sim.acceleration = dynamic ? Vec2(b.gravityFactor() * w.settings.gravity + b.invMass * b.force) : Vec2::Zero();
    sim.angularAcceleration = dynamic ? b.invInertia * b.torque : 0.0;
    sim.invMass = dynamic ? b.invMass : 0.0;
    sim.invInertia = dynamic ? b.invInertia : 0.0;
    sim.body = w.awake[i];
    sim.dynamic = dynamic;
    sim.turns = rowSide(b).turns;
}

void Solver::finishBody(WorldImpl& w, std::size_t i) {
    const SolverBody& s = states_[i];
    const SolverBodySim& sim = sims_[i];
    BodyData& b = w.bodies[sim.body];
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
    w.updateBoxes(b);
    if (w.settings.enableSleep && b.canSleep() && sim.dynamic && b.v.norm() <= w.settings.sleepLinearTolerance &&
        std::abs(b.w) <= w.settings.sleepAngularTolerance)
        b.sleepTime += w.dt;
    else
        b.sleepTime = 0.0;
    // Its proxy must move (bit 0); it moved far for its size this step (bit 1: the Continuous stage's).
    const double travel = s.dp.norm() + std::abs(s.dAngle) * b.extent;
    enlarged_[i] = static_cast<std::uint8_t>(
        (w.proxyOutgrown(b) ? 1 : 0) | (sim.dynamic && b.collides && travel > 0.5 * b.coreRadius ? 2 : 0));
}

std::size_t Solver::solveGroup(WorldImpl& w, std::size_t g, bool timed, int worker) {
    const int substeps = w.settings.substeps;
    const double h = w.dt / substeps;
    const std::uint32_t* const bodyList = graph_.groupBodies.data() + graph_.groupBodyStart[g];
    const std::size_t bodyCount = graph_.groupBodyStart[g + 1] - graph_.groupBodyStart[g];
    const std::uint32_t* const segments = graph_.blockStart.data() + g * kSegments;
    const bool anyRows = segments[kSegments] > segments[0] || graph_.groupJointStart[g + 1] > graph_.groupJointStart[g];
    SolverBody* const st = states_;
    // Block b of the group (numbered as blockRows) lies at blockAt(b) and coldAt(b), in the worker's region.
    const std::size_t firstBlock = segments[0], blockCount = segments[kSegments] - firstBlock;
    const std::size_t region = static_cast<std::size_t>(worker) * graph_.regionBlocks;
    auto blockAt = [&](std::size_t b) { return contactBlocks_.data() + region + (b - firstBlock); };
    auto coldAt = [&](std::size_t b) { return contactCold_.data() + region + (b - firstBlock); };
    auto endsAt = [&](std::size_t b) { return contactEnds_.data() + region + (b - firstBlock); };
    // Block b's surface-material terms; null (the loops without them) in a world that has never used them.
    const bool materials = w.surfaceMaterials;
    auto materialAt = [&](std::size_t b) {
        return materials ? contactMaterial_.data() + region + (b - firstBlock) : nullptr;
    };
    // On the calling thread's share of the step: a stage's time counts only where one group runs at a time.
    auto stage = [&](Stage s) { return timed ? std::optional<StageTimer>(std::in_place, w.profile, s) : std::nullopt; };
    auto forBodies = [&](auto&& f) {
        w.executor.parallelFor(bodyCount, kBodyGrain, [&](std::size_t begin, std::size_t end, int) {
            for (std::size_t k = begin; k < end; ++k) f(bodyList[k]);
        });
    };
    // The same over the bodies' records, asking for each whole record a few bodies ahead: a group lists its
    // bodies island by island, not in memory order.
    auto forRecords = [&](auto&& f) {
        w.executor.parallelFor(bodyCount, kBodyGrain, [&](std::size_t begin, std::size_t end, int) {
            for (std::size_t k = begin; k < end; ++k) {
                if (k + kPrefetchBodies < end)
                    prefetchLines(&w.bodies[w.awake[bodyList[k + kPrefetchBodies]]], sizeof(BodyData));
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
    const bool ordered = w.executor.ordersLoops() && graph_.halvesInOrder(g);
    // A half's head or rest of colour colours[k]: blocks [begin, end) of the group's.
    auto halfOf = [&](std::size_t k, int share, bool head) {
        const std::size_t col = colours[k], first = segments[col], end = segments[col + 1];
        const std::size_t mid = middleBlock(first, end), cut = graph_.shareHeads[(g * kColours + col) * 2 + share];
        return share == 0 ? (head ? std::make_pair(cut, mid) : std::make_pair(first, cut))
                          : (head ? std::make_pair(mid, cut) : std::make_pair(cut, end));
    };
    // Joint rows: colour by colour, each colour's pin blocks (pinsWork(begin, end)), wheel blocks (wheelsWork) and
    // other rows in parallel, then the joints' overflow row after row, then the chains (chainsWork(), which solve
    // passes give).
    auto jointPass = [&](auto&& pinsWork, auto&& wheelsWork, auto&& jointWork, auto&& chainsWork) {
        for (std::size_t col = 0; col < kColours; ++col) {
            const std::size_t s = g * kSegments + col;
            const std::size_t firstPin = pinBlockStart_[s], pins = pinBlockStart_[s + 1] - firstPin;
            const std::size_t firstWheel = wheelBlockStart_[s], wheels = wheelBlockStart_[s + 1] - firstWheel;
            const std::size_t firstOther = otherJointStart_[s], others = otherJointStart_[s + 1] - firstOther;
            const std::size_t blocks = pins + wheels;
            w.executor.parallelFor(blocks + others, kJointGrain, [&](std::size_t begin, std::size_t end, int) {
                if (begin < pins) pinsWork(firstPin + begin, firstPin + std::min(end, pins));
                if (begin < blocks && end > pins)
                    wheelsWork(firstWheel + std::max(begin, pins) - pins, firstWheel + std::min(end, blocks) - pins);
                for (std::size_t k = std::max(begin, blocks); k < end; ++k) {
                    JointConstraint& row = graph_.jointConstraints[otherJointRows_[firstOther + k - blocks]];
                    jointWork(row, w.joints[row.joint]);
                }
            });
        }
        const std::uint32_t* const overflow = graph_.jointSegmentStart.data() + g * kSegments + kColours;
        for (std::uint32_t j = overflow[0]; j < overflow[1]; ++j)
            jointWork(graph_.jointConstraints[j], w.joints[graph_.jointConstraints[j].joint]);
        chainsWork();
    };
    auto pass = [&](auto&& rowsWork, auto&& pinsWork, auto&& wheelsWork, auto&& jointWork, auto&& chainsWork) {
        jointPass(pinsWork, wheelsWork, jointWork, chainsWork);
        if (ordered) {
            w.executor.forLoopsInOrder(colourCount, [&](std::size_t loop, int share, bool head) {
                const auto [begin, end] = halfOf(loop, share, head);
                if (begin < end) rowsWork(begin, end);
            });
        } else {
            for (std::size_t k = 0; k < colourCount; ++k) {
                const std::size_t first = segments[colours[k]], count = segments[colours[k] + 1] - first;
                w.executor.parallelFor(count, kBlockGrain, [&](std::size_t begin, std::size_t end, int) {
                    rowsWork(first + begin, first + end);
                });
            }
        }
        rowsWork(segments[kColours], segments[kSegments]);
    };
    {
        auto timer = stage(Stage::Forces);
        forRecords([&](std::size_t i) { startBody(w, i); });
    }
    // A block is prepared in the step's first pass over the rows, just before its warm start, and its impulses
    // stored in the last, just after its relax: the thread that solves it in every pass (Team.hpp) writes it first
    // and reads it last, so it never moves to another core's cache for that.
    std::atomic<std::size_t> turningRows{0};
    std::atomic<bool> bounces{false};  // some row can bounce: only then is what the warm start gave kept (bounces)
    const double impactSpeed = w.settings.impactSpeedThreshold;
    auto storeBlocks = [&](std::size_t begin, std::size_t end) {
        for (std::size_t b = begin; b < end; ++b)
            for (std::uint32_t lane = 0; lane < graph_.blockRows[b].count; ++lane) {
                const ContactBlockCold& cold = *coldAt(b);
                const int k = static_cast<int>(lane);
                const std::uint32_t contact = cold.lanes[k].contact;
                storeImpulses(*blockAt(b), cold, k, w.contacts[contact], w.contactImpulses[contact]);
                const int point = impactPoint(cold, k, impactSpeed);
                rowImpact_[b * kLanes + lane] = static_cast<std::int8_t>(point);
                if (point >= 0) rowImpactSpeed_[b * kLanes + lane] = -cold.relativeVelocity[point][k];
            }
    };
    const bool storeInRelax = w.settings.relaxIterations > 0;
    // Block k's rows in `rows` (pinRows_, wheelRows_): kLanes, but for a colour's last block, whose free lanes hold
    // no row.
    auto laneRows = [&](const std::vector<const JointConstraint*>& rows, std::size_t k) {
        std::uint32_t count = 0;
        while (count < kLanes && rows[k * kLanes + count] != nullptr) ++count;
        return count;
    };
    // Pin blocks [b, e) for the step: from their rows, or made ready from the bodies where the layout is kept.
    const double pinArcStep = arcStep(w.settings, h);  // the rows' h (prepareJointRow)
    auto packPinBlocks = [&](std::size_t b, std::size_t e) {
        for (std::size_t k = b; k < e; ++k) {
            if (refreshPins_) {
                refreshPins(pinBlocks_[k], pinFrames_[k], sims_.data(), w.bodies, pinArcStep, 1.0 / h, rodSoftness_);
                continue;
            }
            const std::uint32_t count = laneRows(pinRows_, k);
            packPins(pinBlocks_[k], pinRows_.data() + k * kLanes, count, w.joints);
            framePins(pinFrames_[k], pinRows_.data() + k * kLanes, count, w.joints, w.bodies);
        }
    };
    ContactPass contactPass = contactPassSettings_;
    contactPass.pushes = pushVelocities_.data();
    contactPass.holdPushes = w.settings.relaxIterations > 0;  // the relax pass takes held push-out back
    // The warm start has two forms, on purpose. The step's first substep warm starts over the rows (their impulses
    // from the last step, through this step's J). After it, where bodiesWarmStart holds, it runs on the bodies
    // (integrateVelocity adds again what the rows gave each body over the substep before): the same impulses to
    // rounding, without a pass. One rule for both would change bits: the rows' form rounds per row, the bodies'
    // per body, and the first substep has no substep before it to take the bodies' form from. The rows' form stays
    // for joints (their J turns with the bodies), an effect acting between substeps and exact-continuous bullets: a
    // bullet can leave its rows' geometry metres and radians behind within a step, where even a rounding change can
    // decide whether a bounce keeps its energy.
    const bool bodiesWarmStart = !graph_.groupRowsWarmStart[g] && !w.effects.perSubstep();
    RowsBase* const base = rowsBase_.data();
    if (bodiesWarmStart) contactPass.rowsBase = base;
    // The bases are read by the warm start on the bodies and by bounces (recordWarmStart), which need contact rows.
    RowsBase* const keepBase = bodiesWarmStart || blockCount > 0 ? base : nullptr;
    WarmStartVelocity* const warm = warmStarts_.data();
    contactPass.warmStarts = warm;
    // The substep's last pass over the contact rows adds their impulses to the step's totals (ContactBlockCold).
    auto solvePass = [&](bool useBias, bool store, bool total) {
        contactPass.useBias = useBias;
        contactPass.total = total;
        pass([&](std::size_t b, std::size_t e) {
                 solveContacts(blockAt(b), blockAt(e), coldAt(b), st, contactPass, WideCode::Best, materialAt(b));
                 if (store) storeBlocks(b, e);
             },
             [&](std::size_t b, std::size_t e) {
                 solvePins(pinBlocks_.data() + b, pinBlocks_.data() + e, st, useBias);
                 if (store) storePins(pinBlocks_.data() + b, pinBlocks_.data() + e, w.joints);
             },
             [&](std::size_t b, std::size_t e) {
                 solveWheels(wheelBlocks_.data() + b, wheelBlocks_.data() + e, st, useBias);
                 if (store) storeWheels(wheelBlocks_.data() + b, wheelBlocks_.data() + e, w.joints);
             },
             [&](const JointConstraint& row, JointData& joint) {
                 if (!row.chained) solveJoint(row, joint, st, useBias);
             },
             [&] {
                 const PinChains& chains = graph_.chains;
                 for (std::uint32_t c = chains.groupChainStart[g]; c < chains.groupChainStart[g + 1]; ++c)
                     solveChain(chains.rows.data() + chains.chainStart[c], chains.chainStart[c + 1] - chains.chainStart[c],
                                graph_.jointConstraints.data(), w.joints, st, useBias,
                                chainScratch_[static_cast<std::size_t>(worker)]);
             });
    };

    // On two threads, a substep's solve passes, position integration and relax passes are one ordered sequence
    // (each pass's colours, the bodies' loop between), where no joint or overflow row needs a thread alone between
    // passes. Where the warm start after the first substep is the bodies' (no pass) and nothing acts between
    // substeps, the substeps after it join the sequence too, each from its velocity integration: one wait for the
    // step's substeps. Each loop gets its own copy of the passes' settings: the threads may be in different passes.
    const bool ledger = w.ledger.enabled;  // then each substep's stages run apart, for the ledger's marks
    const bool oneSequence = !ledger && ordered && colourCount > 0 && graph_.groupJointStart[g + 1] == graph_.groupJointStart[g] &&
                             segments[kSegments] == segments[kColours];
    const SubstepList stages = substepStages(w.settings.velocityIterations, w.settings.relaxIterations);
    auto solveInOrder = [&](int firstSub, int lastSub) {
        const std::size_t perSubstep = loopsOf(stages, 0, stages.size(), colourCount);
        const std::size_t skip = loopsThroughWarmStart(stages, colourCount);  // the first substep's are done
        const std::uint32_t* const halves = graph_.shareBodies.data() + graph_.groupBodyStart[g];
        const std::size_t headEnd = graph_.shareBodyCuts[g * 2] - graph_.groupBodyStart[g];
        const std::size_t secondStart = graph_.shareBodyCuts[g * 2 + 1] - graph_.groupBodyStart[g];
        WarmStartVelocity* const keepWarm = bounces.load(std::memory_order_relaxed) ? warm : nullptr;
        const std::size_t loops = static_cast<std::size_t>(lastSub - firstSub + 1) * perSubstep - skip;
        w.executor.forLoopsInOrder(loops, [&](std::size_t loop, int share, bool head) {
            const int sub = firstSub + static_cast<int>((loop + skip) / perSubstep);
            const OrderedLoop at = orderedLoop(stages, (loop + skip) % perSubstep, colourCount);
            if (at.stage == SubstepStage::Velocities || at.stage == SubstepStage::Positions) {
                // A bodies' loop: the first half's head, then each half's rest.
                if (share == 1 && head) return;
                const std::size_t begin = share == 0 ? (head ? 0 : headEnd) : secondStart;
                const std::size_t end = share == 0 ? (head ? headEnd : secondStart) : bodyCount;
                if (begin >= end) return;
                if (at.stage == SubstepStage::Velocities)
                    integrateVelocities(st, base, keepWarm, sims_.data(), halves + begin, end - begin, h, true);
                else
                    integratePositions(st, halves + begin, end - begin, h);
                return;
            }
            const bool relax = at.stage == SubstepStage::Relax;
            const auto [begin, end] = halfOf(at.colour, share, head);
            if (begin >= end) return;
            ContactPass rows = contactPass;
            rows.substep = sub;
            rows.useBias = !relax;
            rows.total = at.lastPass && (relax || !storeInRelax);
            solveContacts(blockAt(begin), blockAt(end), coldAt(begin), st, rows, WideCode::Best, materialAt(begin));
            if (relax && sub + 1 == substeps && at.lastPass) storeBlocks(begin, end);
        });
    };

    // The substeps' stages switch tens of times a step: one clock reading at each switch.
    StageClock clock(timed ? &w.profile : nullptr);
    for (int sub = 0; sub < substeps; ++sub) {
        contactPass.substep = sub;
        if (ledger) tally_.markStart(st, bodyList, bodyCount);
        if (w.effects.perSubstep()) w.effects.substep(w, h);  // then there is one group
        bool sequenced = false;  // solveInOrder ran the rest of the substep (and the substeps up to `sub`)
        for (const StagePasses& run : stages)
            for (int p = 0; p < run.passes && !sequenced; ++p) {
                const bool lastPass = p + 1 == run.passes;
                switch (run.stage) {
                    case SubstepStage::Velocities: {
                        clock.enter(Stage::Integrate);
                        WarmStartVelocity* const keepWarm = bounces.load(std::memory_order_relaxed) ? warm : nullptr;
                        w.executor.parallelFor(bodyCount, kBodyGrain, [&](std::size_t begin, std::size_t end, int) {
                            integrateVelocities(st, keepBase, keepWarm, sims_.data(), bodyList + begin, end - begin,
                                                h, bodiesWarmStart && sub > 0);
                        });
                        break;
                    }
                    case SubstepStage::WarmStart: {
                        const bool overRows = sub == 0 || !bodiesWarmStart;  // else integrateVelocities did it
                        if (!anyRows || !(overRows || oneSequence)) break;
                        clock.enter(Stage::Solve);
                        if (overRows) {
                            pass([&](std::size_t b, std::size_t e) {
                                     if (sub == 0) {
                                         const PreparedRows prepared = prepareContacts(
                                             blockAt(b), coldAt(b), graph_.blockRows.data() + b, e - b,
                                             graph_.rowContacts.data(), w.contacts.data(), sims_.data(),
                                             w.bodies.data(), WideCode::Best, w.contactCores.data(),
                                             w.shapes.data(), endsAt(b),
                                             roundedSides_.empty() ? nullptr : roundedSides_.data());
                                         if (materials)
                                             prepareMaterials(blockAt(b), coldAt(b), materialAt(b),
                                                              graph_.blockRows.data() + b, e - b,
                                                              w.contactSurfaces.data());
                                         turningRows += prepared.turning;  // one add per chunk
                                         if (prepared.bounce) bounces.store(true, std::memory_order_relaxed);
                                         if (prepared.rounded)
                                             roundedRows_.value.store(true, std::memory_order_relaxed);
                                     }
                                     warmStartContacts(blockAt(b), blockAt(e), st);
                                     if (materials && sub > 0) warmStartRolling(blockAt(b), blockAt(e), materialAt(b), st);
                                 },
                                 [&](std::size_t b, std::size_t e) {
                                     if (sub == 0) packPinBlocks(b, e);
                                     warmStartPins(pinBlocks_.data() + b, pinBlocks_.data() + e, st);
                                 },
                                 [&](std::size_t b, std::size_t e) {
                                     if (sub == 0)
                                         for (std::size_t k = b; k < e; ++k)
                                             packWheels(wheelBlocks_[k], wheelRows_.data() + k * kLanes,
                                                        laneRows(wheelRows_, k), w.joints);
                                     warmStartWheels(wheelBlocks_.data() + b, wheelBlocks_.data() + e, st);
                                 },
                                 [&](const JointConstraint& row, JointData& joint) { warmStartJoint(row, joint, st); },
                                 [] {});
                            if (bounces.load(std::memory_order_relaxed))
                                forBodies([&](std::size_t i) {
                                    if (sims_[i].dynamic) recordWarmStart(st[i], base[i], warm[i]);
                                });
                        }
                        if (oneSequence) {
                            const int last = bodiesWarmStart ? substeps - 1 : sub;
                            solveInOrder(sub, last);
                            sub = last;
                            sequenced = true;
                        }
                        break;
                    }
                    case SubstepStage::Solve:
                        if (anyRows) {
                            clock.enter(Stage::Solve);
                            solvePass(true, false, lastPass && !storeInRelax);
                        }
                        break;
                    case SubstepStage::Positions: {
                        clock.enter(Stage::Integrate);
                        w.executor.parallelFor(bodyCount, kBodyGrain, [&](std::size_t begin, std::size_t end, int) {
                            integratePositions(st, bodyList + begin, end - begin, h);
                        });
                        if (ledger) tally_.markMoved(st, bodyList, bodyCount);
                        break;
                    }
                    case SubstepStage::Relax:
                        if (anyRows) {
                            clock.enter(Stage::Solve);
                            solvePass(false, sub + 1 == substeps && lastPass, lastPass);
                        }
                        break;
                }
            }
        clock.stop();  // the ledger, the effects and the next substep's start count nowhere, as before
        if (ledger)
            tally_.closeSubstep(w, g, sims_.data(), st, bodyList, bodyCount, blockAt(firstBlock), coldAt(firstBlock),
                                graph_.blockRows.data(), firstBlock, blockCount,
                                graph_.jointConstraints.data() + graph_.groupJointStart[g],
                                graph_.groupJointStart[g + 1] - graph_.groupJointStart[g], h);
    }
    if (blockCount > 0 && !storeInRelax) {
        auto timer = stage(Stage::Solve);
        w.executor.parallelFor(blockCount, kBlockGrain, [&](std::size_t begin, std::size_t end, int) {
            storeBlocks(firstBlock + begin, firstBlock + end);
        });
    }
    if (!storeInRelax) {
        const std::size_t first = pinBlockStart_[g * kSegments], end = pinBlockStart_[(g + 1) * kSegments];
        storePins(pinBlocks_.data() + first, pinBlocks_.data() + end, w.joints);
        const std::size_t firstWheel = wheelBlockStart_[g * kSegments], endWheel = wheelBlockStart_[(g + 1) * kSegments];
        storeWheels(wheelBlocks_.data() + firstWheel, wheelBlocks_.data() + endWheel, w.joints);
    }
    {
        auto timer = stage(Stage::Integrate);
        forRecords([&](std::size_t i) { finishBody(w, i); });
    }
    return turningRows.load();
}

void Solver::moveDeferredProxies(WorldImpl& w) {
    deferredKeys_.clear();
    deferredBoxes_.clear();
    for (std::size_t i = 0; i < enlarged_.size(); ++i) {
        const BodyData& b = w.bodies[sims_[i].body];
        if (!(enlarged_[i] & 4) || !w.proxyOutgrown(b)) continue;
        const WorldImpl::StepTravel travel = w.stepTravel(b);
        w.forEachShape(b, [&](std::uint32_t, const ShapeData& shape) {
            deferredKeys_.push_back(shape.proxy);
            deferredBoxes_.push_back(w.proxyBox(b, travel, shape.aabb));
        });
    }
    w.broadPhase.moveProxies(deferredKeys_, deferredBoxes_);  // a crowd of fast bodies rebuilds the tree once
}

}  // namespace physim
