#pragma once
// Broad phase: which shapes may touch. Two dynamic AABB trees of enlarged boxes, one for static bodies' shapes and
// one for those of the bodies that can move. A proxy's box is the shape's box enlarged by a margin and by the motion
// its body is expected to make over the next step, so it is touched only when the shape leaves that box; the pairs
// of such moved proxies are the only new candidate pairs. A scene at rest costs nothing here. Internal.

#include "DynamicTree.hpp"
#include "Executor.hpp"
#include "PairSet.hpp"
#include "WideBoxTree.hpp"

#include "physim/core/Aabb.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <utility>
#include <vector>

namespace physim {

using ShapePair = std::pair<std::uint32_t, std::uint32_t>;  // shape slots, first < second

/// What findNewPairs' `wanted` answers for a pair it is offered: take it (a new pair), decline it (offered again by
/// the next call), or pass it by (offered again only when a proxy of the pair moves or is asked again: a pair that
/// can never make a contact while it stays as it is). `wanted` may also answer a bool: take or decline.
enum class Offer : std::uint8_t { Decline, Take, PassBy };
inline Offer offerOf(bool take) { return take ? Offer::Take : Offer::Decline; }
inline Offer offerOf(Offer offer) { return offer; }

class BroadPhase {
public:
    /// A proxy key: the tree (bit 0: 1 = static) and the proxy id in that tree.
    static std::int32_t key(std::int32_t id, bool isStatic) { return id * 2 + (isStatic ? 1 : 0); }

    std::int32_t createProxy(const Aabb& fatBox, std::uint32_t shape, bool isStatic);
    void destroyProxy(std::int32_t key);
    /// A new box (the shape left its old one, or was moved by the user); the proxy joins the move buffer.
    void moveProxy(std::int32_t key, const Aabb& fatBox);
    /// New boxes for many proxies of movable shapes at once (DynamicTree::moveProxies: a large share rebuilds the
    /// tree); each joins the move buffer.
    void moveProxies(const std::vector<std::int32_t>& keys, const std::vector<Aabb>& fatBoxes);
    const Aabb& fatBox(std::int32_t key) const { return treeOf(key).fatAabb(key >> 1); }
    bool isStatic(std::int32_t key) const { return (key & 1) != 0; }

    /// The shape pairs (first < second, sorted, each once) whose boxes overlap, at least one of which moved since
    /// the last call (or was asked again), which `known` does not hold (pairs that have a contact already) and
    /// which `wanted(first, second)` takes; empties the move buffer. Queries run on the executor's threads, and so
    /// does `wanted`. A pair it declines is offered again by the next call, whether or not its proxies move.
    template <class Wanted>
    void findNewPairs(std::vector<ShapePair>& pairs, const PairSet& known, const Wanted& wanted, Executor& executor);
    /// The next findNewPairs queries this proxy again although it did not move: its pairs are offered again.
    void requery(std::int32_t key) { markMoved(key); }

    std::size_t moveCount() const { return moved_.size(); }
    /// The move buffer: proxy keys given a new box since the last findNewPairs (the Sensors stage's fast shapes).
    const std::vector<std::int32_t>& movedProxies() const { return moved_; }
    std::uint32_t shapeOf(std::int32_t key) const { return treeOf(key).userData(key >> 1); }
    /// Changes whenever a proxy is created, destroyed or given a new box: while it stays the same, so do all boxes.
    std::uint64_t boxRevision() const { return boxRevision_; }
    /// Shapes whose boxes overlap `box` (both trees).
    template <class Callback>
    void query(const Aabb& box, Callback&& callback) const {
        auto forward = [&](std::int32_t, std::uint32_t shape) { return callback(shape); };
        tree_[0].query(box, forward);
        tree_[1].query(box, forward);
    }

    std::size_t staticProxyCount() const { return tree_[1].proxyCount(); }
    /// Shapes of static bodies whose boxes overlap `box` (the static tree alone, in query's order).
    template <class Callback>
    void queryStatic(const Aabb& box, Callback&& callback) const {
        tree_[1].query(box, [&](std::int32_t, std::uint32_t shape) { return callback(shape); });
    }

    /// Shapes whose boxes overlap `box`, for the world's public queries: as query, until many of them have met the
    /// same boxes; from then on through a four-wide tree built once over both trees' boxes (WideBoxTree), which
    /// takes about a third less time per query, in that tree's order. Steps use query, whose order is fixed.
    template <class Callback>
    void queryOften(const Aabb& box, Callback&& callback) const {
        if (const WideBoxTree* wide = wideTree()) wide->query(box, callback);
        else query(box, callback);
    }

    /// Both trees' proxies along a ray (DynamicTree::rayCast), the movable tree first, the clip carried from one to
    /// the other: callback(shape, maxFraction) returns the new maxFraction (<= 0 stops).
    template <class Callback>
    void rayCast(const Vec2& origin, const Vec2& translation, double maxFraction, Callback&& callback) const {
        auto forward = [&](std::int32_t, std::uint32_t shape, double fraction) { return callback(shape, fraction); };
        maxFraction = tree_[0].rayCast(origin, translation, maxFraction, forward);
        if (maxFraction > 0.0) tree_[1].rayCast(origin, translation, maxFraction, forward);
    }

private:
    template <class> friend struct StateFields;  // the snapshot file's serializer (SnapshotFile.cpp)
    DynamicTree& treeOf(std::int32_t key) { return tree_[key & 1]; }
    const DynamicTree& treeOf(std::int32_t key) const { return tree_[key & 1]; }
    void markMoved(std::int32_t key);
    void boxesChanged();
    const WideBoxTree* wideTree() const;  // null until queryOften has been asked often enough since boxesChanged
    const WideBoxTree* staticWideTree(std::size_t queries);  // null until findNewPairs has asked enough since
    void beginFind(int workerSlots);
    void endFind(std::vector<ShapePair>& pairs);  // merges, sorts, empties the move buffer, re-queues declined

    DynamicTree tree_[2];                 // [0] shapes of movable bodies, [1] of static bodies
    std::vector<std::int32_t> moved_;     // proxy keys in the move buffer
    std::uint64_t boxRevision_ = 0;
    // queryOften's tree and what decides when to build it. Const queries may run on several threads at once: the
    // one that builds holds `building`, the others go on through the two trees meanwhile. A copy starts without
    // one, and so does a broad phase assigned another's boxes (a restore): its revision counter may come to equal
    // the one the old tree was built at with other boxes.
    struct WideCache {
        WideCache() = default;
        WideCache(const WideCache&) {}
        WideCache& operator=(const WideCache&) {
            revision.store(~std::uint64_t{0}, std::memory_order_relaxed);
            queries.store(0, std::memory_order_relaxed);
            return *this;
        }
        WideBoxTree tree;
        std::atomic<std::uint64_t> revision{~std::uint64_t{0}};  // the boxRevision_ it was built for
        std::atomic<std::uint64_t> queries{0};                    // queryOften calls since boxesChanged
        std::mutex building;
    };
    mutable WideCache wide_;
    // findNewPairs' four-wide tree over the static tree's boxes, built once they stayed the same for about as many
    // queries as the build costs (as queryOften's). A copy or an assigned broad phase starts without one.
    struct StaticWide {
        StaticWide() = default;
        StaticWide(const StaticWide&) {}
        StaticWide& operator=(const StaticWide&) {
            revision = counted = ~std::uint64_t{0};
            queries = 0;
            return *this;
        }
        WideBoxTree tree;
        std::uint64_t revision = ~std::uint64_t{0};  // the staticRevision_ it was built for
        std::uint64_t counted = ~std::uint64_t{0};   // the staticRevision_ `queries` counts for
        std::size_t queries = 0;                     // queries of the static tree at that revision
    };
    StaticWide staticWide_;
    static constexpr std::size_t kStaticWideAt = 32;  // static proxies, at least, for staticWideTree to build one
    std::uint64_t staticRevision_ = 0;  // changes whenever a static proxy is created, destroyed or moved
    std::vector<std::uint8_t> isMoved_[2];  // per proxy id of each tree: 1 while in the move buffer
    std::vector<std::int32_t> movedIds_;  // moveProxies' tree ids
    std::vector<std::vector<ShapePair>> perTask_;
    std::vector<std::vector<std::int32_t>> declinedPerTask_;  // proxies whose query met a declined pair
};

template <class Wanted>
void BroadPhase::findNewPairs(std::vector<ShapePair>& pairs, const PairSet& known, const Wanted& wanted,
                              Executor& executor) {
    pairs.clear();
    if (moved_.empty()) return;
    beginFind(executor.workerSlots());
    const WideBoxTree* const staticWide = staticWideTree(moved_.size());
    // A moved movable proxy meets both trees; a moved static proxy meets only the movable tree (static bodies
    // never pair). Two shapes of one body do pair here: `wanted` takes them, the caller drops them. A pair of two
    // moved proxies is reported by the query of the smaller key only.
    executor.parallelFor(moved_.size(), 64, [&](std::size_t begin, std::size_t end, int worker) {
        std::vector<ShapePair>& out = perTask_[static_cast<std::size_t>(worker)];
        std::vector<std::int32_t>& declined = declinedPerTask_[static_cast<std::size_t>(worker)];
        for (std::size_t i = begin; i < end; ++i) {
            const std::int32_t k = moved_[i];
            bool declinedOne = false;
            const Aabb& box = fatBox(k);
            const std::uint32_t shape = treeOf(k).userData(k >> 1);
            for (int t = 0; t < 2; ++t) {
                if (t == 1 && isStatic(k)) continue;
                const auto& flags = isMoved_[t];
                const auto meet = [&](std::int32_t id, std::uint32_t other) {
                    const std::int32_t otherKey = key(id, t == 1);
                    if (otherKey == k) return true;
                    const bool otherMoved = static_cast<std::size_t>(id) < flags.size() && flags[id];
                    if (otherMoved && otherKey < k) return true;
                    const std::uint32_t first = std::min(shape, other), second = std::max(shape, other);
                    // Most overlaps of a moving proxy are pairs it already has: only new ones go on to the sort.
                    if (known.contains(PairSet::key(first, second))) return true;
                    const Offer offer = offerOf(wanted(first, second));
                    if (offer == Offer::Take) out.emplace_back(first, second);
                    else if (offer == Offer::Decline) declinedOne = true;
                    return true;
                };
                if (t == 0 || !staticWide) {
                    tree_[t].query(box, meet);
                    continue;
                }
                // The same leaves as the static tree's query (each checked exactly: the wide tree's floats may
                // report one that misses by their rounding), in another order: the pairs are sorted after.
                staticWide->query(box, [&](std::uint32_t data) {
                    const auto id = static_cast<std::int32_t>(data);
                    return !tree_[1].fatAabb(id).overlaps(box) || meet(id, tree_[1].userData(id));
                });
            }
            if (declinedOne) declined.push_back(k);
        }
    });
    endFind(pairs);
}

}  // namespace physim
