#pragma once
// The energy ledger's bookkeeping inside the step, while World::setEnergyLedger is on (physim/core/EnergyLedger.hpp
// says what each part measures). The solver marks each substep's start, each force effect's end and the move, and
// closes each substep of each group; a group's parts are its own, summed in group order (any thread count gives
// the same bits). Off, none of it runs. Internal.

#include "SolverData.hpp"

#include "physim/core/EnergyLedger.hpp"
#include "physim/core/Math.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace physim {

struct WorldImpl;
struct ContactBlock;
struct ContactBlockCold;
struct BlockRows;
struct JointConstraint;

/// The force effects whose impulses the ledger tells apart (Effects::substep's order).
enum class LedgerEffect : std::uint8_t { Gravitation, Springs, Drag };

/// A body's motion: m/s and rad/s.
struct LedgerMotion {
    Vec2 v = Vec2::Zero();
    double w = 0.0;
};

/// A spring's damping impulse in one substep (N s on B; -P on A) and where it acts: its work goes to `soft`.
struct LedgerDamping {
    Vec2 impulse = Vec2::Zero();
    Vec2 rA = Vec2::Zero(), rB = Vec2::Zero();  // anchors from the centres of mass, m
    std::int32_t indexA = -1, indexB = -1;      // awake indices; -1: not moved by the solver
};

class EnergyTally {
public:
    /// A step starts: `bodies` awake bodies, `groups` groups, `blocks` contact blocks.
    void startStep(std::size_t bodies, std::size_t groups, std::size_t blocks);
    /// The listed bodies' velocities now start a substep (before the force effects and the kick).
    void markStart(const SolverBody* st, const std::uint32_t* list, std::size_t count);
    /// Effect e has just acted on every awake body (0 .. count): what it changed since the last mark is its impulse
    /// (kept for drag, whose work the ledger counts).
    void markEffect(LedgerEffect e, const SolverBody* st, std::size_t count);
    /// The listed bodies have moved: their velocities now are the ones the move used.
    void markMoved(const SolverBody* st, const std::uint32_t* list, std::size_t count);
    /// A spring's damping impulse in this substep (SpringEffect::apply, while the ledger is on).
    void addDamping(const LedgerDamping& d) { damping_.push_back(d); }
    /// Closes a substep of group g: its bodies (list), its contact blocks [first, first + count) found at
    /// blocks[b - first] and cold[b - first] (b numbered as rows[b]), h the substep (s).
    void closeSubstep(const WorldImpl& w, std::size_t g, const SolverBodySim* sims, const SolverBody* st,
                      const std::uint32_t* list, std::size_t count, const ContactBlock* blocks,
                      const ContactBlockCold* cold, const BlockRows* rows, std::size_t first, std::size_t blockCount,
                      const JointConstraint* joints, std::size_t jointCount, double h);
    /// The step's parts so far, groups summed in order (residue left zero: the world fills it in).
    EnergyParts stepParts() const;

private:
    std::vector<LedgerMotion> start_, cursor_, moved_;
    std::vector<LedgerMotion> drag_;  // per awake body: drag's change of its motion in this substep (the effects
                                      // before it only move the cursor, their work is the residue's)
    // Per block lane, at the last close: the step's normal totals of its two points and its tangent total (the
    // substep's impulses are what they grew by).
    std::vector<double> totals_;
    std::vector<EnergyParts> groups_;
    std::vector<LedgerDamping> damping_;
};

/// The last all-pairs sum of gravitation's potential energy (J) and what it was summed over: a step's start, where
/// nothing moved since the last step's end, reuses it.
struct GravitationPotential {
    std::vector<double> x, y, m;  // the attracting bodies' centres (m) and masses (kg), in member order
    double G = 0.0, eps2 = 0.0;
    double value = 0.0;
};

/// J: kinetic energy of every body; the ledger's potential energy (EnergyLedger.hpp), from the bodies' records.
double kineticEnergyOf(const WorldImpl& w);
double potentialEnergyOf(const WorldImpl& w, GravitationPotential* cache = nullptr);

}  // namespace physim
