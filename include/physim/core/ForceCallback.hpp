#pragma once
// User-written forces: a callback the world calls at the start of every step.

#include <cstdint>
#include <functional>
#include <limits>

namespace physim {

class World;

/// Called at the start of each World::step(dt) with the world and dt (s), before any stage, in the order the
/// callbacks were added. It may read the world and apply forces, torques and impulses (World::applyForce and
/// friends), which act during this step, exactly as if applied just before it; it may change the world as
/// between steps, but not step it or add or remove callbacks (std::logic_error).
using ForceCallback = std::function<void(World& world, double dt)>;

/// Handle to a force callback of one World.
struct ForceCallbackId {
    std::uint32_t value = std::numeric_limits<std::uint32_t>::max();
    bool isNull() const { return value == std::numeric_limits<std::uint32_t>::max(); }
    friend bool operator==(const ForceCallbackId& a, const ForceCallbackId& b) { return a.value == b.value; }
};

}  // namespace physim
