#pragma once

#include "physim/core/Math.hpp"

namespace physim {

/// Axis-aligned bounding box in world metres. Invariant for a valid box: lower <= upper component-wise.
struct Aabb {
    Vec2 lower = Vec2::Zero();
    Vec2 upper = Vec2::Zero();

    /// The paper's AABB test (section 5.2.1): boxes that touch count as overlapping.
    bool overlaps(const Aabb& o) const {
        return lower.x() <= o.upper.x() && o.lower.x() <= upper.x() && lower.y() <= o.upper.y() &&
               o.lower.y() <= upper.y();
    }
    /// True when `o` lies inside this box (touching the boundary counts as inside).
    bool contains(const Aabb& o) const {
        return lower.x() <= o.lower.x() && lower.y() <= o.lower.y() && o.upper.x() <= upper.x() &&
               o.upper.y() <= upper.y();
    }
    Vec2 center() const { return 0.5 * (lower + upper); }
    Vec2 extents() const { return 0.5 * (upper - lower); }
    Aabb fattened(double margin) const { return {lower.array() - margin, upper.array() + margin}; }
    static Aabb merged(const Aabb& a, const Aabb& b) {
        return {a.lower.cwiseMin(b.lower), a.upper.cwiseMax(b.upper)};
    }
};

}  // namespace physim
