#pragma once

#include <array>
#include <cstddef>
#include <string_view>

namespace physim {

/// The stages of one fixed step, in the order the step runs them (docs/architecture.md, "The engine step"); the
/// force callbacks, which open the step before the broad phase, count in Forces. A stage the scene's content does
/// not call for is skipped before it does any work (StepProfile::ran tells which ran).
enum class Stage : std::size_t {
    BroadPhase,   ///< candidate pairs whose bounding boxes overlap
    NarrowPhase,  ///< contact manifolds of the candidate pairs
    Forces,       ///< gravity, accumulated forces and the force effects into velocities
    Solve,        ///< contact impulses
    Integrate,    ///< velocities into positions, position correction
    Continuous,   ///< time of impact for fast bodies
    Sensors,      ///< sensors' overlaps and their events (only while the world holds a sensor)
    Sleep,        ///< bodies at rest stop being simulated
    Count
};

std::string_view stageName(Stage s);

/// The force effects (docs/effects.md). Each runs, inside the Forces stage, only while the world holds something
/// that uses it: a body with drag, a spring joint, two attracting bodies, a force callback.
enum class Effect : std::size_t {
    Drag,         ///< air drag, every substep
    Springs,      ///< spring joints, every substep
    Gravitation,  ///< Newtonian gravitation between attracting bodies, every substep
    Callbacks,    ///< user force callbacks, at the start of the step
    Count
};

std::string_view effectName(Effect e);

/// Wall-clock cost of the last step, per stage.
struct StepProfile {
    static constexpr std::size_t stageCount = static_cast<std::size_t>(Stage::Count);
    std::array<double, stageCount> seconds{};
    std::array<bool, stageCount> ran{};
    static constexpr std::size_t effectCount = static_cast<std::size_t>(Effect::Count);
    std::array<double, effectCount> effectSeconds{};  ///< part of the Forces stage's seconds
    std::array<bool, effectCount> effectRan{};
    std::size_t candidatePairs = 0;
    std::size_t manifolds = 0;
    /// Contact rows solved with angular terms: those with a body that can turn. Rows between bodies whose rotation
    /// is locked (or immovable and not spinning) skip them, so a scene with every rotation locked has none.
    std::size_t turningRows = 0;
    /// The step coloured its constraint rows and sorted them into groups anew. A step whose awake bodies and
    /// contacts are those of the step before (the same ones, in the same order, each contact with points or without
    /// as before), with no joint created or destroyed and no type, detection or settings change (nor a joint setter
    /// moving a row into or out of lanes, nor a shape moving a body's centre of mass), keeps that step's layout
    /// instead: the same layout, so the same results, without the work.
    bool rowsLaidOut = false;
    /// On two threads, each colour of a large group's rows is cut in halves, one per thread (docs/architecture.md,
    /// "Two threads through the colours in order"): `halvedBlocks` counts the blocks of rows so cut, `headBlocks`
    /// those of them that touch a body the other half touches too. A thread runs its head of a colour first and
    /// waits only for the other's head of the colour before, so the fewer heads, the less the threads meet; a group
    /// whose heads are over half its blocks is solved colour by colour instead (and counts in neither). Both 0 on
    /// one thread.
    std::size_t halvedBlocks = 0;
    std::size_t headBlocks = 0;

    double& secondsOf(Stage s) { return seconds[static_cast<std::size_t>(s)]; }
    double secondsOf(Stage s) const { return seconds[static_cast<std::size_t>(s)]; }
    bool didRun(Stage s) const { return ran[static_cast<std::size_t>(s)]; }
    bool didRun(Effect e) const { return effectRan[static_cast<std::size_t>(e)]; }
    double secondsOf(Effect e) const { return effectSeconds[static_cast<std::size_t>(e)]; }
    double total() const;
};

}  // namespace physim
