#pragma once

#include "physim/core/Math.hpp"

namespace physim {

/// How a contact combines its two shapes' coefficients a and b (friction or restitution): the arithmetic mean
/// (a + b) / 2, the geometric mean sqrt(a b), the smaller, the larger, or the product a b (docs/collision.md,
/// "Surface materials").
enum class MixingRule { Average, GeometricMean, Min, Max, Multiply };

struct WorldSettings {
    /// Bounds validate() holds: substeps in [1, maxSubsteps]; velocityIterations in [1, maxIterations] and
    /// relaxIterations in [0, maxIterations].
    static constexpr int maxSubsteps = 1000;
    static constexpr int maxIterations = 1000;

    Vec2 gravity{0.0, -9.81};         ///< m/s^2, y up
    int substeps = 8;                 ///< each step is this many substeps of dt / substeps (docs/dynamics.md)
    int velocityIterations = 1;       ///< solve passes (with the soft push-out) over all rows per substep
    int relaxIterations = 1;          ///< relax passes (no push-out) per substep: remove the push-out's velocity
    /// Contact stiffness: overlap is pushed out as a spring of this frequency (Hz), capped at a quarter of the
    /// substep rate for stability. A stack of N boxes sinks about N^2 g / (4 pi^2 hertz^2) in all.
    double contactHertz = 120.0;
    double contactDampingRatio = 10.0;   ///< of that spring; well above 1 so pushing out never overshoots
    double contactPushMaxVelocity = 3.0; ///< m/s: deep overlaps separate no faster than this
    double jointHertz = 120.0;           ///< joint stiffness, Hz (also capped at a quarter of the substep rate)
    double jointDampingRatio = 1.0;      ///< critical: stretch dies out without draining a swing
    /// Pins and welds aim their points where the anchors' arcs take them over a substep, not along straight lines
    /// (docs/dynamics.md, "Joints keep a swing's energy"): a frictionless pendulum keeps its energy to 1e-10 a
    /// second instead of losing 2e-5. Costs about 16% of a step on a grid of 10 000 pins (peer_bench joint_grid).
    bool jointArcs = true;
    /// A chain of pins (revolute joints without motor, limit or spring, each body pinned at most twice) whose
    /// bodies' masses differ by this factor or more is solved as one block, exactly, in every pass: a heavy weight
    /// on light links then stretches the chain by its top pin's give alone (docs/dynamics.md). >= 1; 1: every
    /// chain; infinity: none (each pin on its own, like other rows).
    double directChainMassRatio = 4.0;
    double linearSlop = 0.005;        ///< m: speculative contacts reach 4 slops; touching is within that
    /// m/s: below e = 1, slower approaches do not bounce, so resting bodies settle. e = 1 bounces at any speed.
    double restitutionThreshold = 1.0;
    double impactSpeedThreshold = 1.0;   ///< m/s: approach speed above which a contact reports an ImpactEvent
    /// Sleeping: an island of touching dynamic bodies whose speeds all stay below the tolerances for
    /// timeToSleep stops being simulated until something wakes it (docs/dynamics.md).
    bool enableSleep = true;
    double sleepLinearTolerance = 0.01;   ///< m/s
    double sleepAngularTolerance = 0.035; ///< rad/s (2 degrees per second)
    double timeToSleep = 0.5;             ///< s
    /// Worker threads for the step: 1 runs everything on the calling thread; 0 uses every hardware thread.
    /// Results are bit-identical for any value (docs/architecture.md).
    int threads = 1;
    /// How a contact mixes its shapes' friction coefficients (static and dynamic alike), and their restitutions.
    /// A change re-mixes the existing contacts.
    MixingRule frictionMixing = MixingRule::Average;
    MixingRule restitutionMixing = MixingRule::Min;
};

/// Throws std::invalid_argument naming the first bad field.
void validate(const WorldSettings& settings);

}  // namespace physim
