#pragma once

#include "physim/core/Math.hpp"

namespace physim {

struct WorldSettings {
    Vec2 gravity{0.0, -9.81};         ///< m/s^2, y up
    int substeps = 4;                 ///< each step is this many substeps of dt / substeps (docs/dynamics.md)
    int velocityIterations = 6;       ///< sequential-impulse passes over all contacts per substep
    int positionIterations = 2;       ///< position-projection passes per substep (no velocity is added)
    double linearSlop = 0.005;        ///< m of overlap left alone, so resting contacts persist between steps
    double restitutionThreshold = 1.0;///< m/s: slower approaches do not bounce, so resting bodies settle
    /// Sleeping: an island of touching dynamic bodies whose speeds all stay below the tolerances for
    /// timeToSleep stops being simulated until something wakes it (docs/dynamics.md).
    bool enableSleep = true;
    double sleepLinearTolerance = 0.01;   ///< m/s
    double sleepAngularTolerance = 0.035; ///< rad/s (2 degrees per second)
    double timeToSleep = 0.5;             ///< s
    /// Worker threads for the step: 1 runs everything on the calling thread; 0 uses every hardware thread.
    /// Results are bit-identical for any value (docs/architecture.md).
    int threads = 1;
};

/// Throws std::invalid_argument naming the first bad field.
void validate(const WorldSettings& settings);

}  // namespace physim
