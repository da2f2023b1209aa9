#pragma once
// The solver's passes over bodies (as ContactSolver.hpp's are over rows). Internal.

#include "SolverData.hpp"
#include "Wide.hpp"

#include <cstddef>
#include <cstdint>

namespace physim {

/// A substep's position integration (integratePosition) of the awake bodies list[0 .. count) (indices into
/// states, all different), four at a time; a lane's bits are integratePosition's for its body, in every build.
void integratePositions(SolverBody* states, const std::uint32_t* list, std::size_t count, double h,
                        WideCode code = WideCode::Best);

/// A substep's velocity integration (integrateVelocity: gravity and forces from sims, the rows' base unless null and
/// the warm start on the bodies with `again`, kept in warm if given) of the dynamic bodies among list[0 .. count),
/// four at a time; a lane's bits are integrateVelocity's for its body, in every build. The others are left as they
/// are.
void integrateVelocities(SolverBody* states, RowsBase* base, WarmStartVelocity* warm, const SolverBodySim* sims,
                         const std::uint32_t* list, std::size_t count, double h, bool again,
                         WideCode code = WideCode::Best);

}  // namespace physim
