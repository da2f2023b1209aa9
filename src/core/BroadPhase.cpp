#include "BroadPhase.hpp"

#include <algorithm>

namespace physim {

// Sort and sweep on x: sort the boxes by their lower x bound; each box then meets only the boxes that start
// before it ends. Cost O(n log n + k) for k overlaps along x.
void findCandidatePairs(std::vector<BodyData>& bodies, std::vector<BodyPair>& pairs,
                        std::vector<std::uint32_t>& order) {
    pairs.clear();
    order.clear();
    for (std::uint32_t i = 0; i < bodies.size(); ++i) {
        BodyData& b = bodies[i];
        if (!b.alive) continue;
        b.aabb = computeAabb(b.shape, b.xf);
        order.push_back(i);
    }
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const double la = bodies[a].aabb.lower.x(), lb = bodies[b].aabb.lower.x();
        return la < lb || (la == lb && a < b);
    });
    for (std::size_t i = 0; i < order.size(); ++i) {
        const BodyData& a = bodies[order[i]];
        for (std::size_t j = i + 1; j < order.size(); ++j) {
            const BodyData& b = bodies[order[j]];
            if (b.aabb.lower.x() > a.aabb.upper.x()) break;
            if (!a.movable() && !b.movable()) continue;
            if (!a.aabb.overlaps(b.aabb)) continue;
            pairs.emplace_back(std::min(order[i], order[j]), std::max(order[i], order[j]));
        }
    }
    std::sort(pairs.begin(), pairs.end());  // creation order, independent of positions
}

}  // namespace physim
