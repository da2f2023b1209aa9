#pragma once
// The World's Continuous stage: time of impact for bodies that ask for continuous detection. Internal.
//
// It runs in every substep, after the contact solve and before positions are integrated, so each body's motion
// over the (sub)step (pose to pose + v dt, angle + w dt) is final. For every dynamic continuous body it:
//   1. tests its swept box against every other body's swept box (the paper's swept volume, 5.1.5), and runs the
//      costly test (exact or sampled, per body) only for the pairs whose boxes overlap. The first sweep of every
//      exact body is independent of the others' (each sweeps against the others' snapshot), so those pairs go to
//      the ContinuousSolver as one batch (the CPU, or the GPU through the CUDA layer);
//   2. at the earliest impact, moves the body there and applies a contact impulse (restitution as the solver:
//      min of the pair, none below the restitution threshold; no friction) to it and its partner;
//   3. sweeps the rest of the step with the new velocity in the same way (up to kMaxImpacts impacts), so the
//      body neither tunnels nor stops dead: it bounces or slides on for the remaining time.
// Pairs already touching at the start of a (sub-)step are left to the discrete contacts unless they would still
// close by more than kToiTolerance over the rest of the step (then they are an impact at once). The integrator then
// moves every body as usual, and placeBodies puts the bodies that hit something where step 3 ended them.

#include "BodyData.hpp"

#include "physim/core/ContinuousBatch.hpp"
#include "physim/core/WorldSettings.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace physim {

class ContinuousStage {
public:
    /// Impacts a body may meet in one step; after the last one it stays at that impact's pose for the rest of
    /// the step (a corner hit from both sides, for instance).
    static constexpr int kMaxImpacts = 4;

    /// Before integratePositions: finds impacts, applies their impulses and records end poses.
    void findImpacts(std::vector<BodyData>& bodies, double dt, const WorldSettings& settings);
    /// After integratePositions: puts the bodies that hit something at their recorded end poses, then forgets
    /// them (a step that skips the stage places nothing).
    void placeBodies(std::vector<BodyData>& bodies);
    /// Impacts found by the last findImpacts (for tests and profiles).
    std::size_t impactCount() const { return impacts_; }
    /// Who solves the first-sweep batch; null: this thread, on the CPU.
    void setSolver(std::shared_ptr<ContinuousSolver> solver) { solver_ = std::move(solver); }
    const std::shared_ptr<ContinuousSolver>& solver() const { return solver_; }

private:
    struct Motion {  // a body's snapshot at the start of the stage; dp, da are the whole step's motion
        Vec2 p = Vec2::Zero();
        Vec2 dp = Vec2::Zero();
        double angle = 0.0;
        double da = 0.0;
        Aabb swept;
    };
    struct Placement {
        std::uint32_t body = 0;
        Vec2 p = Vec2::Zero();
        double angle = 0.0;
    };
    // Step 1's batch: every exact body's first sweep against the bodies its swept box overlaps.
    void batchFirstSweeps(const std::vector<BodyData>& bodies);

    std::vector<Motion> motion_;
    std::vector<Placement> placements_;
    std::size_t impacts_ = 0;
    std::shared_ptr<ContinuousSolver> solver_;
    ContinuousBatch batch_;
    ContinuousBatchResult batchResult_;
    std::vector<std::int32_t> batchBody_;      // per body slot: its index in batch_, or -1
    std::vector<std::uint32_t> pairPartner_;   // per batch pair: the other body's slot
    std::vector<std::uint32_t> firstPair_;     // per body slot: its pairs are [firstPair_[i], endPair_[i])
    std::vector<std::uint32_t> endPair_;
};

}  // namespace physim
