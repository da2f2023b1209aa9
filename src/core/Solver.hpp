#pragma once
// The soft step's solver: the Forces, Solve and Integrate stages over the awake bodies, and its scratch, kept
// between steps so a running scene allocates nothing. Internal.
//
// Per step: gather the awake bodies into contiguous arrays, lay the rows out in the constraint graph (colours,
// groups, blocks; ConstraintGraph.hpp), then per group the substeps of integrate velocities -> warm start -> solve
// -> integrate positions -> relax, and finalize (poses, boxes, sleep timers, proxies that left their boxes).

#include "ConstraintGraph.hpp"
#include "ContactSolver.hpp"
#include "EnergyTally.hpp"
#include "RoundedRows.hpp"
#include "SolverData.hpp"
#include "joints/PinLanes.hpp"
#include "joints/WheelLanes.hpp"

#include "physim/core/Aabb.hpp"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace physim {

struct WorldImpl;

class Solver {
public:
    /// The Forces, Solve and Integrate stages over w.awake.
    void solve(WorldImpl& w);
    /// After the Continuous stage: the proxies of bodies it may have put back.
    void moveDeferredProxies(WorldImpl& w);

    /// Something the rows' layout depends on changed (ConstraintGraph::stale): the next step lays them out anew.
    void layoutChanged() { graph_.stale = true; }
    /// The world's state was replaced (a restore): the contacts' kept sides may name another history's shapes.
    void forgetRoundedSides() { roundedSides_.clear(); }
    /// The contact rows of the last layout.
    std::size_t rowCount() const { return graph_.rowContacts.size(); }

    /// While the step runs: awake body i's state (states()[i]; states()[-1] is the still body) and what the
    /// substeps read of its record.
    SolverBody* states() const { return states_; }
    const SolverBodySim& sim(std::size_t i) const { return sims_[i]; }
    /// A dynamic body moved far for its size this step: the Continuous stage has work.
    bool fastBodies() const { return fastBodies_; }
    /// The energy ledger's bookkeeping (read and marked only while it is on).
    EnergyTally& tally() { return tally_; }
    /// The Continuous stage put awake body i back and its proxy must move: it does once, after that stage.
    void deferProxy(std::size_t i) { enlarged_[i] |= 4; }

private:
    void startBody(WorldImpl& w, std::size_t i);   // awake body i's solver state and sims from its record
    void finishBody(WorldImpl& w, std::size_t i);  // its record from the solver's state: pose, box, sleep, enlarged
    /// A group's rows, substeps and impulses, its blocks in `worker`'s region; returns its turning rows.
    std::size_t solveGroup(WorldImpl& w, std::size_t g, bool timed, int worker);

    /// This step's split of each joint colour into pins solved in lanes and the other rows (Solver.cpp).
    void sortJointRows(bool wheelsInLanes);

    ConstraintGraph graph_;
    EnergyTally tally_;
    std::vector<SolverBody> solverBodies_;       // a still body, then one per awake body
    SolverBody* states_ = nullptr;               // &solverBodies_[1]: states_[i] is awake body i, states_[-1] still
    std::vector<SolverBodySim> sims_;
    std::vector<PushVelocity> pushVelocities_;   // per awake body: the solve passes' push-out (ContactSolver)
    std::vector<RowsBase> rowsBase_;             // per awake body: velocity before the substep's rows
    std::vector<WarmStartVelocity> warmStarts_;  // per awake body: what the substep's warm start gave it (bounces)
    // The rows, kLanes to a block (an overflow row alone), and the rest of each block's rows: a group's blocks live
    // only while it is solved, in its worker's region (ConstraintGraph::regionBlocks), reused group after group.
    std::vector<ContactBlock> contactBlocks_;
    std::vector<ContactBlockCold> contactCold_;
    std::vector<ContactBlockMaterial> contactMaterial_;  // beside contactCold_, only once the world uses materials
    std::vector<ContactBlockEnds> contactEnds_;  // beside contactCold_; a block's written only where it has ends
    // Per contact slot, its rounded rows' straight sides as last found (RoundedRows.hpp): kept from the step after
    // the first that prepared such a row (roundedRows_), so that a world without them holds none.
    std::vector<RoundedSides> roundedSides_;
    struct SetOnce {  // set by any chunk of a parallel preparation; copied with the state (a snapshot)
        std::atomic<bool> value{false};
        SetOnce() = default;
        SetOnce(const SetOnce& other) : value(other.value.load(std::memory_order_relaxed)) {}
        SetOnce& operator=(const SetOnce& other) {
            value.store(other.value.load(std::memory_order_relaxed), std::memory_order_relaxed);
            return *this;
        }
    } roundedRows_;
    std::vector<std::int8_t> rowImpact_;         // per block lane in use: its impact event's point; -1: none
    std::vector<double> rowImpactSpeed_;         // per block lane with an impact: how fast it met, m/s
    ContactPass contactPassSettings_;            // this step's pass constants
    // Each joint colour's rows this step (sortJointRows): its pins and its wheels, kLanes to a block, and its other
    // rows. Segment s (as ConstraintGraph numbers them) has pin blocks [pinBlockStart_[s], pinBlockStart_[s + 1]),
    // wheel blocks likewise, and other rows otherJointRows_[otherJointStart_[s] ...] (indices into
    // graph_.jointConstraints); the overflow has none here.
    std::vector<PinBlock> pinBlocks_;
    std::vector<const JointConstraint*> pinRows_;  // block b's rows: pinRows_[kLanes b ...], pinBlocks_[b].count
    std::vector<std::uint32_t> pinBlockStart_;
    std::vector<WheelBlock> wheelBlocks_;
    std::vector<const JointConstraint*> wheelRows_;  // as pinRows_
    std::vector<std::uint32_t> wheelBlockStart_;
    std::vector<std::uint32_t> otherJointRows_;
    std::vector<std::uint32_t> otherJointStart_;
    std::vector<PinFrame> pinFrames_;         // per pin block: what refreshPins needs beyond it
    std::vector<std::uint32_t> inPlaceRows_;  // joint rows in no pin block: prepared in their places
    bool sortedWheelsInLanes_ = false;        // sortJointRows' wheelsInLanes
    bool pinsPacked_ = false;                 // the pin blocks hold the last step's rows (since sortJointRows)
    bool refreshPins_ = false;                // this step makes them ready from the bodies (refreshPins)
    Softness rodSoftness_;                    // this step's joint softness
    std::vector<ChainScratch> chainScratch_;  // per worker: solveChain's scratch
    std::vector<std::uint8_t> enlarged_;  // per awake body (solver order): proxy outgrown (bit 0), fast (bit 1),
                                          // proxy to move after the Continuous stage (bit 2)
    bool fastBodies_ = false;             // a dynamic body moved more than half its core radius
    std::vector<std::int32_t> deferredKeys_;  // moveDeferredProxies' proxies and their new boxes
    std::vector<Aabb> deferredBoxes_;
};

}  // namespace physim
