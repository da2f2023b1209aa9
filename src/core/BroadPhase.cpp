#include "BroadPhase.hpp"

#include "Executor.hpp"

#include <algorithm>

namespace physim {

std::int32_t BroadPhase::createProxy(const Aabb& fatBox, std::uint32_t body, bool isStatic) {
    const std::int32_t id = tree_[isStatic ? 1 : 0].createProxy(fatBox, body);
    const std::int32_t k = key(id, isStatic);
    markMoved(k);
    return k;
}

void BroadPhase::destroyProxy(std::int32_t k) {
    const std::int32_t id = k >> 1;
    auto& flags = isMoved_[k & 1];
    if (static_cast<std::size_t>(id) < flags.size() && flags[id]) {
        moved_.erase(std::find(moved_.begin(), moved_.end(), k));
        flags[id] = 0;
    }
    treeOf(k).destroyProxy(id);
}

void BroadPhase::moveProxy(std::int32_t k, const Aabb& fatBox) {
    treeOf(k).moveProxy(k >> 1, fatBox);
    markMoved(k);
}

const Aabb& BroadPhase::fatBox(std::int32_t k) const { return treeOf(k).fatAabb(k >> 1); }

void BroadPhase::markMoved(std::int32_t k) {
    const std::int32_t id = k >> 1;
    auto& flags = isMoved_[k & 1];
    if (flags.size() <= static_cast<std::size_t>(id)) flags.resize(static_cast<std::size_t>(id) + 1, 0);
    if (flags[id]) return;
    flags[id] = 1;
    moved_.push_back(k);
}

void BroadPhase::findNewPairs(std::vector<BodyPair>& pairs, const PairSet& known, const PairWanted& wanted,
                              Executor& executor) {
    pairs.clear();
    if (moved_.empty()) return;
    perTask_.resize(static_cast<std::size_t>(executor.workerSlots()));
    declinedPerTask_.resize(perTask_.size());
    for (auto& buffer : perTask_) buffer.clear();
    for (auto& buffer : declinedPerTask_) buffer.clear();

    // A moved movable proxy meets both trees; a moved static proxy meets only the movable tree (static bodies
    // never pair). A pair of two moved proxies is reported by the query of the smaller key only.
    executor.parallelFor(moved_.size(), 64, [&](std::size_t begin, std::size_t end, int worker) {
        std::vector<BodyPair>& out = perTask_[static_cast<std::size_t>(worker)];
        std::vector<std::int32_t>& declined = declinedPerTask_[static_cast<std::size_t>(worker)];
        for (std::size_t i = begin; i < end; ++i) {
            const std::int32_t k = moved_[i];
            bool declinedOne = false;
            const Aabb& box = fatBox(k);
            const std::uint32_t body = treeOf(k).userData(k >> 1);
            for (int t = 0; t < 2; ++t) {
                if (t == 1 && isStatic(k)) continue;
                const auto& flags = isMoved_[t];
                tree_[t].query(box, [&](std::int32_t id, std::uint32_t other) {
                    const std::int32_t otherKey = key(id, t == 1);
                    if (otherKey == k) return true;
                    const bool otherMoved = static_cast<std::size_t>(id) < flags.size() && flags[id];
                    if (otherMoved && otherKey < k) return true;
                    const std::uint32_t first = std::min(body, other), second = std::max(body, other);
                    // Most overlaps of a moving proxy are pairs it already has: only new ones go on to the sort.
                    if (known.contains(PairSet::key(first, second))) return true;
                    if (wanted(first, second)) out.emplace_back(first, second);
                    else declinedOne = true;
                    return true;
                });
            }
            if (declinedOne) declined.push_back(k);
        }
    });
    for (auto& buffer : perTask_) pairs.insert(pairs.end(), buffer.begin(), buffer.end());
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

    for (const std::int32_t k : moved_) isMoved_[k & 1][k >> 1] = 0;
    moved_.clear();
    for (const auto& buffer : declinedPerTask_)
        for (const std::int32_t k : buffer) markMoved(k);
}

}  // namespace physim
