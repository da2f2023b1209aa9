#pragma once
// The force effects a world can hold (docs/effects.md), each its own class with one task, run in the Forces
// stage only while something in the world uses it: decided from the counts each keeps as bodies and joints are
// created, changed and destroyed, never by looking at every body. Internal.
//
//   ForceCallbacks (ForceCallbacks.hpp)  the user's forces, at the start of the step
//   Gravitation    (Gravitation.hpp)     Newtonian gravitation between attracting bodies, every substep
//   Springs        (Springs.hpp)         spring joints, every substep
//   Drag           (Drag.hpp)            air drag, every substep, last (it is implicit in the velocity)

#include "Drag.hpp"
#include "ForceCallbacks.hpp"
#include "Gravitation.hpp"
#include "Springs.hpp"

#include "physim/core/Math.hpp"
#include "physim/core/StepProfile.hpp"

#include <cstdint>

namespace physim {

struct WorldImpl;

/// A body's motion now, in the middle of a step: the solver's arrays for an awake body, else its record.
struct BodyNow {
    Vec2 center = Vec2::Zero();  // centre of mass, m
    Rotation q{};
    Vec2 v = Vec2::Zero();
    double w = 0.0;
    std::int32_t index = -1;     // awake index (states, sims), or -1
    double invMass = 0.0;        // 0 unless dynamic and awake: who an effect may push
    double invInertia = 0.0;
};
BodyNow bodyNow(const WorldImpl& w, std::uint32_t slot);

struct Effects {
    ForceCallbacks callbacks;
    GravitationEffect gravitation;
    SpringEffect springs;
    DragEffect drag;

    /// Any effect to run in each substep.
    bool perSubstep() const { return gravitation.active() || springs.active() || drag.active(); }
    /// Runs the active per-substep effects at the substep's start, before its velocity kick (so they see the
    /// substep's starting velocities); timed into the profile.
    void substep(WorldImpl& w, double h);
    /// A body is gone: it leaves every effect (its joints, springs included, went before).
    void bodyDestroyed(std::uint32_t slot);
};

/// Adds the seconds since `start` to the Forces stage and to the effect, and marks both as run.
void recordEffect(StepProfile& profile, Effect e, double seconds);

}  // namespace physim
