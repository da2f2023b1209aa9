#include "BroadPhase.hpp"

#include <algorithm>
#include <stdexcept>

namespace physim {

std::int32_t BroadPhase::createProxy(const Aabb& fatBox, std::uint32_t shape, bool isStatic) {
    const std::int32_t id = tree_[isStatic ? 1 : 0].createProxy(fatBox, shape);
    const std::int32_t k = key(id, isStatic);
    markMoved(k);
    boxesChanged();
    if (isStatic) ++staticRevision_;
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
    boxesChanged();
    if (isStatic(k)) ++staticRevision_;
}

void BroadPhase::moveProxy(std::int32_t k, const Aabb& fatBox) {
    treeOf(k).moveProxy(k >> 1, fatBox);
    markMoved(k);
    boxesChanged();
    if (isStatic(k)) ++staticRevision_;
}

void BroadPhase::moveProxies(const std::vector<std::int32_t>& keys, const std::vector<Aabb>& fatBoxes) {
    movedIds_.clear();
    for (const std::int32_t k : keys) {
        if (isStatic(k)) throw std::logic_error("BroadPhase::moveProxies: a static body's proxy");
        movedIds_.push_back(k >> 1);
    }
    tree_[0].moveProxies(movedIds_, fatBoxes);
    for (const std::int32_t k : keys) markMoved(k);
    if (!keys.empty()) boxesChanged();
}

void BroadPhase::boxesChanged() {
    ++boxRevision_;
    wide_.queries.store(0, std::memory_order_relaxed);
}

namespace {

// Building a wide tree costs about as much as a query per proxy over four (measured on piles of boxes): waiting that
// many queries on the same boxes bounds the cost of a build that is never used to what the queries took anyway.
bool wideTreePays(std::size_t queries, std::size_t proxies) { return queries >= 64 + proxies / 4; }

// Every proxy of `tree` as a leaf of `wide`, its data the proxy's shape or (byId) its id.
void addLeaves(WideBoxTree& wide, const DynamicTree& tree, bool byId) {
    for (std::size_t i = 0; i < tree.nodeCount(); ++i) {
        const auto id = static_cast<std::int32_t>(i);
        if (tree.isProxy(id)) wide.addLeaf(tree.fatAabb(id), byId ? static_cast<std::uint32_t>(id) : tree.userData(id));
    }
}

}  // namespace

const WideBoxTree* BroadPhase::wideTree() const {
    if (wide_.revision.load(std::memory_order_acquire) == boxRevision_) return &wide_.tree;
    const std::size_t proxies = tree_[0].proxyCount() + tree_[1].proxyCount();
    if (!wideTreePays(wide_.queries.fetch_add(1, std::memory_order_relaxed), proxies)) return nullptr;
    const std::unique_lock<std::mutex> lock(wide_.building, std::try_to_lock);
    if (!lock.owns_lock()) return nullptr;
    if (wide_.revision.load(std::memory_order_acquire) == boxRevision_) return &wide_.tree;
    wide_.tree.clear();
    for (const DynamicTree& tree : tree_) addLeaves(wide_.tree, tree, false);
    wide_.tree.build();
    wide_.revision.store(boxRevision_, std::memory_order_release);
    return &wide_.tree;
}

const WideBoxTree* BroadPhase::staticWideTree(std::size_t queries) {
    // A few static boxes (a ground, walls) are found as fast by the binary tree: no wide one for them.
    if (tree_[1].proxyCount() < kStaticWideAt) return nullptr;
    StaticWide& s = staticWide_;
    if (s.revision == staticRevision_) return &s.tree;
    if (s.counted != staticRevision_) {  // the boxes changed: count anew
        s.counted = staticRevision_;
        s.queries = 0;
    }
    s.queries += queries;
    if (!wideTreePays(s.queries, tree_[1].proxyCount())) return nullptr;
    s.tree.clear();
    addLeaves(s.tree, tree_[1], true);
    s.tree.build();
    s.revision = staticRevision_;
    return &s.tree;
}

void BroadPhase::markMoved(std::int32_t k) {
    const std::int32_t id = k >> 1;
    auto& flags = isMoved_[k & 1];
    if (flags.size() <= static_cast<std::size_t>(id)) flags.resize(static_cast<std::size_t>(id) + 1, 0);
    if (flags[id]) return;
    flags[id] = 1;
    moved_.push_back(k);
}

void BroadPhase::beginFind(int workerSlots) {
    perTask_.resize(static_cast<std::size_t>(workerSlots));
    declinedPerTask_.resize(perTask_.size());
    for (auto& buffer : perTask_) buffer.clear();
    for (auto& buffer : declinedPerTask_) buffer.clear();
}

void BroadPhase::endFind(std::vector<ShapePair>& pairs) {
    for (auto& buffer : perTask_) pairs.insert(pairs.end(), buffer.begin(), buffer.end());
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

    for (const std::int32_t k : moved_) isMoved_[k & 1][k >> 1] = 0;
    moved_.clear();
    for (const auto& buffer : declinedPerTask_)
        for (const std::int32_t k : buffer) markMoved(k);
}

}  // namespace physim
