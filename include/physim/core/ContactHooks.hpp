#pragma once
// The user's say over contacts: a pair filter (may two shapes collide at all) and a pre-solve hook (may this
// contact act in this step). Each costs nothing while unset (World::setPairFilter, World::setPreSolve).

#include "physim/core/Contact.hpp"
#include "physim/core/Shape.hpp"

#include <functional>

namespace physim {

/// Whether two shapes whose filters let them collide (Filter.hpp) may make a contact. Asked when a pair would become
/// a contact (the broad phase offers it: their enlarged boxes came to overlap), not every step, and by the
/// Continuous stage for a fast body's shapes that have no contact yet. Called on the stepping thread, in a fixed
/// order; it may read the world but not change it (std::logic_error). Shapes a and b belong to two bodies.
using PairFilterCallback = std::function<bool(ShapeId a, ShapeId b)>;

/// Called every step for each awake contact with points (its normal from A to B, its points and separations, the
/// impulses of the last step), after the narrow phase and before the solver, one contact after another in a fixed
/// order (deterministic). Returning false disables the contact for this step: it gives the solver nothing, does
/// not touch (a touching contact ends with an end event; contacts() omits it) and its impulses are dropped. The
/// Continuous stage asks it too about each impact it finds (the contact the two shapes would make at the impact
/// pose), so a fast body passes where a slow one would. It may read the world but not change it (std::logic_error).
using PreSolveCallback = std::function<bool(const Manifold& contact)>;

}  // namespace physim
