#pragma once
// The changes a branch started from the window makes (Runner::startBranch, key B, the gallery's Branch box).
// Internal.

#include "physim/framework/Runner.hpp"

#include <functional>

namespace physim {

/// What `change` does to the branch's world, for Simulation::startBranch.
std::function<void(World&)> branchChangeFor(BranchChange change);

}  // namespace physim
