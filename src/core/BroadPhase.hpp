#pragma once
// Broad phase: candidate pairs whose world bounding boxes overlap, each pair once, never static-static.

#include "BodyData.hpp"

#include <cstdint>
#include <utility>
#include <vector>

namespace physim {

using BodyPair = std::pair<std::uint32_t, std::uint32_t>;

/// Refreshes every live body's aabb and writes the overlapping pairs of slot indices (first < second),
/// sorted, so the order is deterministic. `scratch` belongs to the broad phase between calls: it keeps last
/// call's order (so a step repairs it instead of sorting from scratch) and working tables. Pass the same
/// vector every step, untouched, for that fast path; any other content (an empty vector) is still correct
/// and costs a full sort.
void findCandidatePairs(std::vector<BodyData>& bodies, std::vector<BodyPair>& pairs,
                        std::vector<std::uint32_t>& scratch);

}  // namespace physim
