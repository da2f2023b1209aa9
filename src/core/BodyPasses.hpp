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

}  // namespace physim
