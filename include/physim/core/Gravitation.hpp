#pragma once
// Newtonian gravitation between bodies: every attracting body pulls every other one (World::setAttracting).

#include <cstddef>

namespace physim {

/// Each pair of attracting bodies A, B pulls together with the softened inverse-square force
///   F on B = -G mA mB d / (|d|^2 + softening^2)^(3/2)   (N; d = centre of B - centre of A, m)
/// (Plummer softening: close passes stay finite; softening 0 is Newton's law exactly). Below `directBelow`
/// attracting bodies every pair is summed (O(n^2)); from there on a Barnes-Hut quadtree sums far groups as
/// one mass at their centre (O(n log n)): a cell of width s at distance r from a body counts as one when
/// s < theta r. The forces are evaluated every substep, from the substep's positions.
struct GravitationSettings {
    double G = 6.674e-11;          ///< N m^2 / kg^2, >= 0 (scenes in scaled units set their own)
    double softening = 0.0;        ///< m, >= 0
    double theta = 0.5;            ///< Barnes-Hut opening angle, in [0, 1]: 0 opens every cell (exact)
    std::size_t directBelow = 256; ///< attracting bodies below this are summed directly
};

/// Throws std::invalid_argument naming the first bad field.
void validate(const GravitationSettings& settings);

}  // namespace physim
