#pragma once
// The World's Continuous stage: time of impact for bodies that ask for continuous detection. Internal.
//
// It runs in every substep, after the contact solve and before positions are integrated, so each body's motion
// over the substep (pose to pose + v h, angle + w h) is final. Every body moves along a segment: from its pose at
// time t0 (a fraction of the substep) with constant velocity to t = 1. Impacts are found and answered in time
// order, so no body ever moves along a path nobody checked:
//   1. each dynamic continuous body's earliest impact: its swept box against every other body's (the paper's swept
//      volume, 5.1.5), then the costly test (exact or sampled, per body) only where the boxes overlap. At t = 0 the
//      exact bodies' tests are independent of each other, so they go to the ContinuousSolver as one batch (the
//      CPU, or the GPU through the CUDA layer);
//   2. the earliest impact of all is answered: a contact impulse (restitution as the solver: min of the pair, none
//      below the restitution threshold; no friction) to both bodies, and both start new segments there with their
//      new velocities, a dynamic partner too (discrete or not), so it neither tunnels with a velocity nobody
//      swept nor jumps back to where its old segment started;
//   3. the impacts that changed are found again: those of the two bodies, of bodies whose impact was with one of
//      them, and any earlier impact with their new segments. Back to 2 until no impact is left in the substep.
// A body that meets kMaxImpacts impacts in a substep stays where the last one left it (velocity kept) for the rest
// of the substep. Pairs touching at the start of a segment are left to the discrete contacts unless they would
// still close by more than kToiTolerance over the rest of the substep (then they are an impact at once) or, not
// closing where they touch, turn or slide into an overlap deeper than the linear slop (an impact where they last
// overlapped less, found by sampling finely enough that no point moves more than half the slop between samples). The
// integrator then moves every body as usual, and placeBodies puts the bodies whose segments changed at their ends.

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
    /// Impacts a body may meet in one substep; after the last one it stays at that impact's pose for the rest of
    /// the substep (a corner hit from both sides, for instance).
    static constexpr int kMaxImpacts = 4;

    /// Before integratePositions: finds impacts, applies their impulses and records end poses.
    void findImpacts(std::vector<BodyData>& bodies, double dt, const WorldSettings& settings);
    /// After integratePositions: puts the bodies whose segments an impact changed at their ends, then forgets
    /// them (a step that skips the stage places nothing).
    void placeBodies(std::vector<BodyData>& bodies);
    /// Per body slot, 1 for the bodies the last placeBodies moved. Their contacts from the start of the substep
    /// describe poses they have left, so the position correction must not use them.
    const std::vector<std::uint8_t>& placed() const { return placed_; }
    /// Impacts found by the last findImpacts (for tests and profiles).
    std::size_t impactCount() const { return impacts_; }
    /// Who solves the first-sweep batch; null: this thread, on the CPU.
    void setSolver(std::shared_ptr<ContinuousSolver> solver) { solver_ = std::move(solver); }
    const std::shared_ptr<ContinuousSolver>& solver() const { return solver_; }

private:
    // A body's path through the substep from t0 on: pose (p, angle) at t0, moving by (dp, da) per whole substep.
    struct Segment {
        double t0 = 0.0;
        Vec2 p = Vec2::Zero();
        double angle = 0.0;
        Vec2 dp = Vec2::Zero();
        double da = 0.0;
        Aabb swept;           // covers the segment from t0 to 1
        int impacts = 0;
        bool changed = false;  // an impact gave it a new segment: placeBodies puts it at the end
        Vec2 positionAt(double t) const { return p + (t - t0) * dp; }
        double angleAt(double t) const { return angle + (t - t0) * da; }
    };
    struct Impact {
        double t = 1.0;  // >= 1: none in this substep
        std::size_t partner = 0;
    };
    struct Placement {
        std::uint32_t body = 0;
        Vec2 p = Vec2::Zero();
        double angle = 0.0;
    };

    Sweep sweepFrom(std::size_t k, double t) const;
    void restartSegment(std::size_t k, const BodyData& b, double t, double dt);
    // Folds the result of body k's test against `other` from time t (r: over the rest of the substep) into best.
    void consider(const std::vector<BodyData>& bodies, std::size_t k, std::size_t other, double t, const ToiResult& r,
                  double dt, Impact& best) const;
    // First sample time (fraction of the sweeps) before the shapes, touching at the start with normal n (a to b;
    // zero if none was found), overlap by more than `slop` (m); 1 when they never do. Samples so dense that no
    // overlap grows by more than slop / 2 between them (at most 4096: past that, a little more).
    static double deepening(const Geometry& a, const Sweep& sa, const Geometry& b, const Sweep& sb, const Vec2& n,
                            double slop);
    ToiResult test(const std::vector<BodyData>& bodies, std::size_t k, std::size_t other, double t) const;
    Impact earliestImpact(const std::vector<BodyData>& bodies, std::size_t k, double t, double dt) const;
    void batchFirstImpacts(const std::vector<BodyData>& bodies, double dt);
    void answer(std::vector<BodyData>& bodies, std::size_t i, std::size_t j, double t, double dt,
                const WorldSettings& settings);

    std::vector<Segment> segments_;
    std::vector<Impact> next_;               // per body slot: its earliest impact from the current time
    std::vector<std::uint32_t> sweepers_;    // the dynamic continuous bodies
    std::vector<Placement> placements_;
    std::vector<std::uint8_t> placed_;
    std::size_t impacts_ = 0;
    double slop_ = 0.0;  // the World's linear slop, m
    std::shared_ptr<ContinuousSolver> solver_;
    ContinuousBatch batch_;
    ContinuousBatchResult batchResult_;
    std::vector<std::int32_t> batchBody_;      // per body slot: its index in batch_, or -1
    std::vector<std::uint32_t> pairOwner_;     // per batch pair: the sweeping body's slot
    std::vector<std::uint32_t> pairPartner_;   // per batch pair: the other body's slot
};

}  // namespace physim
