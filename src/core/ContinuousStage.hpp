#pragma once
// The World's Continuous stage: time of impact for fast bodies, after the solve. Internal.
//
// Each candidate body is swept from its pose at the step's start to its pose at the end. Candidates:
//   - bodies asking for continuous detection (the paper's modes): against every body whose box the sweep
//     meets (exact: conservative advancement; sampled: the paper's ceil(1/precision) samples);
//   - any other dynamic body that moved more than half its core radius in the step (struck by a bullet, say):
//     against static bodies only, exactly, so nothing is knocked through a wall.
// Candidates come from the broad phase's trees (the swept box as the query), never from a loop over all bodies.
// A pair touching at the start (a resting contact, or one just placed by an impact) is the contacts' business,
// unless turning or approaching would carry it more than the linear slop into each other within the step (a
// continuous body), or a fast body's centroid would come within a small circle of a static shape it touches (pressed
// through a chain piece or a segment by a heavy neighbour).
// A body that hits something is put back at the pose of its first impact, with its velocity kept: the contact is
// then in the next step's manifold, and the solver answers it like every contact (restitution, friction, joints
// all consistent). Exact pairs against moving bodies are solved as one batch by the ContinuousSolver (the CPU,
// or the GPU through the CUDA layer).

#include "KernelBridge.hpp"

#include "physim/core/ContinuousBatch.hpp"
#include "physim/core/TimeOfImpact.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace physim {

struct WorldImpl;

class ContinuousStage {
public:
    void run(WorldImpl& w);
    /// Bodies put back at an impact by the last run.
    std::size_t impactCount() const { return impacts_; }
    void setSolver(std::shared_ptr<ContinuousSolver> solver) { solver_ = std::move(solver); }
    const std::shared_ptr<ContinuousSolver>& solver() const { return solver_; }

private:
    template <class> friend struct StateFields;  // the snapshot file's serializer (SnapshotFile.cpp)
    struct Candidate {
        std::uint32_t awakeIndex = 0;
        Sweep sweep;
        bool continuous = false;  // asked for continuous detection (else: fast, against static bodies only)
        double t = 1.0;           // earliest impact found so far
    };
    Sweep sweepOf(const WorldImpl& w, std::uint32_t slot) const;
    // Folds one pair's result into the candidate's earliest impact. Touching at the start is the contacts'
    // business, unless a continuous body's turning or approaching carries the pair more than the slop into each
    // other (deepening), which never stops a fast discrete body. A Failed pair stops the body where the pair was
    // last proven apart, without a contact.
    static void consider(Candidate& c, const ToiResult& r, const Geometry& mine, const Geometry& theirs,
                         const Sweep& theirSweep, double slop);
    // First sample time (fraction of the sweeps) before the shapes overlap by more than `slop` (m); 1 if never.
    static double deepening(const Geometry& a, const Sweep& sa, const Geometry& b, const Sweep& sb, double slop);

    std::vector<Candidate> candidates_;
    std::vector<std::uint32_t> found_;
    ContinuousBatch batch_;
    ContinuousBatchResult batchResult_;
    std::vector<std::uint32_t> pairCandidate_;
    std::vector<std::uint32_t> pairPartner_;          // per batch pair: the other body's slot
    std::vector<std::int32_t> pairPartnerCandidate_;  // per batch pair: the partner's candidate index, or -1
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairShapes_;  // per batch pair: the shape slots, mine first
    std::vector<std::int32_t> candidateOf_;           // per body slot: its exact candidate's index, or -1
    std::vector<std::int32_t> batchBody_;      // per shape slot: its entry (the shape on its body's sweep) this run
    std::vector<Sweep> sweeps_;                // per body slot: its sweep this run, where sweepMade_ says so
    std::vector<kernel::Motion> motions_;      // the same for the kernel
    std::vector<std::uint8_t> sweepMade_;
    std::uint64_t shapeTableRevision_ = 0;     // the World's shapeRevision the batch's shape table was built for
    std::shared_ptr<ContinuousSolver> solver_;
    std::size_t impacts_ = 0;
};

}  // namespace physim
