#pragma once
// Dynamic bounding-volume tree over axis-aligned boxes, for a broad phase that touches only what moves.
// Internal: not installed.
//
// Leaves are proxies holding the caller's (already enlarged) box and a user value; internal nodes hold the union
// of their two children's boxes. Insertion picks the sibling that adds the least total perimeter to the tree
// (the surface-area heuristic in 2D, searched exactly by branch and bound) and then walks up refitting boxes and
// applying tree rotations that lower the perimeter. docs/collision.md ("Dynamic tree") has the design.
//
// Deterministic: the same calls in the same order give the same nodes, bit for bit. const members (query above
// all) only read, so several threads may query one tree at once while nobody modifies it.

#include "physim/core/Aabb.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <type_traits>
#include <vector>

namespace physim {

class DynamicTree {
public:
    static constexpr std::int32_t kNull = -1;
    static constexpr std::int32_t kFree = -1;  ///< Node::height of a free slot

    /// One slot of the node array. A proxy id is the index of its leaf and stays valid until destroyProxy.
    struct alignas(64) Node {
        Aabb box;                      // leaf: the caller's box; internal: the union of its children's boxes
        std::int32_t parent = kNull;   // free node: the next free node
        std::int32_t child1 = kNull;   // kNull for a leaf (and a free node)
        std::int32_t child2 = kNull;
        std::int32_t height = kFree;   // leaf 0, internal 1 + max(children), kFree for a free node
        std::uint32_t userData = 0;

        bool isLeaf() const { return child1 == kNull; }
    };

    /// Adds a proxy for `fatBox` (the caller enlarges it); returns its id. Throws std::invalid_argument for a
    /// box with a NaN or infinite coordinate or lower > upper, leaving the tree untouched.
    std::int32_t createProxy(const Aabb& fatBox, std::uint32_t userData);
    /// Removes a proxy; its id may be handed out again. Throws std::invalid_argument if `proxy` is not live.
    void destroyProxy(std::int32_t proxy);
    /// Gives a proxy a new box (the id stays): refitted in place if it overlaps the old box, else reinserted.
    /// Throws like createProxy and destroyProxy, before touching anything.
    void moveProxy(std::int32_t proxy, const Aabb& fatBox);
    /// Gives proxies[i] the box boxes[i], for every i. When they are a quarter of the tree or more (and at least
    /// kRebuildAtLeast), the boxes are set in place and the tree rebuilt; otherwise each moves as by moveProxy.
    /// Throws like moveProxy (or for lists of different sizes) before touching anything.
    void moveProxies(const std::vector<std::int32_t>& proxies, const std::vector<Aabb>& boxes);
    static constexpr std::size_t kRebuildAtLeast = 16;

    const Aabb& fatAabb(std::int32_t proxy) const {
        assert(isProxy(proxy));
        return nodes_[static_cast<std::size_t>(proxy)].box;
    }
    std::uint32_t userData(std::int32_t proxy) const {
        assert(isProxy(proxy));
        return nodes_[static_cast<std::size_t>(proxy)].userData;
    }
    /// True when `proxy` is the id of a live proxy.
    bool isProxy(std::int32_t proxy) const {
        return proxy >= 0 && static_cast<std::size_t>(proxy) < nodes_.size() &&
               nodes_[static_cast<std::size_t>(proxy)].height == 0;
    }

    /// Calls callback(proxy, userData) for each proxy whose box overlaps `box` (touching counts, as
    /// Aabb::overlaps), in tree order. A callback returning bool stops the query by returning false.
    /// Allocates nothing unless the tree is deeper than kQueryStack - 1 levels; a NaN box meets nothing.
    template <class Callback>
    void query(const Aabb& box, Callback&& callback) const;

    /// The ray origin + f * translation, f in [0, maxFraction] (m): calls callback(proxy, userData, maxFraction) for
    /// each proxy whose box the ray's remaining part meets, and takes its answer as the new maxFraction (clipping
    /// the ray there: later boxes beyond it are skipped); an answer <= 0 stops, one above maxFraction is ignored.
    /// Returns the final maxFraction. Allocates as query does.
    template <class Callback>
    double rayCast(const Vec2& origin, const Vec2& translation, double maxFraction, Callback&& callback) const;

    std::size_t proxyCount() const { return proxyCount_; }
    /// Levels below the root: 0 for one proxy (and for none).
    int height() const { return root_ == kNull ? 0 : nodes_[static_cast<std::size_t>(root_)].height; }
    /// Sum of the perimeters of the internal nodes (the root included) over the root's perimeter: the tree's
    /// expected query cost up to a constant, lower is better. 0 with fewer than two proxies.
    double areaRatio() const;
    /// Rebuilds every internal node top-down by the binned surface-area heuristic; proxy ids stay.
    void rebuild();
    /// Checks every invariant (links, heights, boxes, counts, free list); throws std::logic_error naming the first
    /// one broken.
    void validate() const;

    /// Removes every proxy (keeps the memory).
    void clear();

    // Read access to the raw structure, for tests and tools.
    std::int32_t root() const { return root_; }
    std::int32_t freeList() const { return freeList_; }
    std::size_t nodeCount() const { return nodes_.size(); }  ///< slots in the node array, free ones included
    const Node& node(std::int32_t index) const { return nodes_.at(static_cast<std::size_t>(index)); }

    /// query's fixed stack, in node ids: enough for any tree of height < kQueryStack.
    static constexpr std::size_t kQueryStack = 128;

private:
    template <class> friend struct StateFields;  // the snapshot file's serializer (SnapshotFile.cpp)
    friend struct DynamicTreeTestAccess;  // tests break invariants on purpose to check validate()

    // The node ids a query or ray cast has yet to visit: `entries` of them, in place for trees of height below
    // kQueryStack, on the heap only for deeper ones. Not copyable (it points into itself).
    class TraversalStack {
    public:
        explicit TraversalStack(std::size_t entries) {
            if (entries > kQueryStack) {
                deep_.resize(entries);
                data_ = deep_.data();
            }
        }
        TraversalStack(const TraversalStack&) = delete;
        TraversalStack& operator=(const TraversalStack&) = delete;
        std::int32_t* data() { return data_; }

    private:
        std::int32_t fixed_[kQueryStack];
        std::vector<std::int32_t> deep_;
        std::int32_t* data_ = fixed_;
    };

    // An internal node on insertion's branch-and-bound frontier, waiting to have its children looked at.
    struct Candidate {
        double bound;          // least cost of pairing the new leaf with anything below this node
        double inherited;      // perimeter this node's ancestors and the node itself gain from the new leaf
        std::int32_t height;   // the node's height: equal bounds are opened lowest first
        std::int32_t node;
    };

    std::int32_t allocateNode();
    void freeNode(std::int32_t index);
    void replaceChild(std::int32_t parent, std::int32_t from, std::int32_t to);  // parent kNull: the root
    void insertLeaf(std::int32_t leaf);
    void reinsert(std::int32_t proxy, const Aabb& fatBox);  // checked already: refit in place, or out and back in
    void removeLeaf(std::int32_t leaf);
    std::int32_t findBestSibling(const Aabb& box);
    void refitNode(std::int32_t index);  // box and height from the children
    void refitOnly(std::int32_t index);    // boxes from index up until one is unchanged; no rotations
    void refitUpward(std::int32_t index);
    bool rotate(std::int32_t index);  // true if it rotated
    void checkProxy(std::int32_t proxy, const char* call) const;

    Node& at(std::int32_t index) { return nodes_[static_cast<std::size_t>(index)]; }
    const Node& at(std::int32_t index) const { return nodes_[static_cast<std::size_t>(index)]; }

    std::vector<Node> nodes_;
    std::int32_t root_ = kNull;
    std::int32_t freeList_ = kNull;
    std::size_t proxyCount_ = 0;
    std::vector<Candidate> frontier_;  // insertion's search heap, kept to avoid allocating per insertion
    // rebuild's work lists, kept for the same reason.
    struct RebuildTask {
        std::size_t begin, end;
        std::int32_t parent;
    };
    std::vector<std::int32_t> rebuildLeaves_;
    std::vector<RebuildTask> rebuildTasks_;
    std::vector<std::int32_t> rebuildCreated_;
};

template <class Callback>
void DynamicTree::query(const Aabb& box, Callback&& callback) const {
    if (root_ == kNull) return;
    // As Aabb::overlaps (touching counts), with one branch for the four comparisons: which way it goes is hard to
    // predict, so one misprediction instead of up to four.
    const auto meets = [&box](const Aabb& b) {
        return (b.lower.x() <= box.upper.x()) & (box.lower.x() <= b.upper.x()) & (b.lower.y() <= box.upper.y()) &
               (box.lower.y() <= b.upper.y());
    };
    // false: the callback stopped the query.
    const auto report = [&callback](std::int32_t id, const Node& leaf) {
        if constexpr (std::is_void_v<std::invoke_result_t<Callback&, std::int32_t, std::uint32_t>>) {
            callback(id, leaf.userData);
            return true;
        } else {
            return static_cast<bool>(callback(id, leaf.userData));
        }
    };
    const Node& root = at(root_);
    if (!meets(root.box)) return;
    if (root.isLeaf()) {
        report(root_, root);
        return;
    }
    // Depth-first, child1's subtree before child2's (the order callbacks come in). A child is tested before it is
    // pushed, and a leaf that meets the box is reported at once unless child1's subtree must come first: the stack
    // holds at most one pending sibling per level plus two children, so height + 1 entries suffice.
    TraversalStack traversal(static_cast<std::size_t>(root.height) + 1);
    std::int32_t* const stack = traversal.data();
    std::size_t top = 0;
    stack[top++] = root_;
    while (top > 0) {
        const Node& n = at(stack[--top]);  // an internal node that meets the box
        const Node& c1 = at(n.child1);
        const Node& c2 = at(n.child2);
        bool first = meets(c1.box);
        const bool second = meets(c2.box);
        if (first && c1.isLeaf()) {
            if (!report(n.child1, c1)) return;
            first = false;
        }
        // The children of a pushed node are tested when it is popped: ask for their lines now, so the memory works
        // while the traversal goes on.
        if (second) {
            if (!c2.isLeaf()) {
                stack[top++] = n.child2;
                __builtin_prefetch(&at(c2.child1)), __builtin_prefetch(&at(c2.child2));
            } else if (first) {
                stack[top++] = n.child2;  // a leaf, after child1's subtree (popped as a leaf below)
            } else if (!report(n.child2, c2)) {
                return;
            }
        }
        if (first) {
            stack[top++] = n.child1;
            __builtin_prefetch(&at(c1.child1)), __builtin_prefetch(&at(c1.child2));
        }
        // A leaf left on the stack (child2 waiting for child1's subtree) is reported when it comes up.
        while (top > 0 && at(stack[top - 1]).isLeaf()) {
            const std::int32_t id = stack[--top];
            if (!report(id, at(id))) return;
        }
    }
}

template <class Callback>
double DynamicTree::rayCast(const Vec2& origin, const Vec2& translation, double maxFraction,
                            Callback&& callback) const {
    if (root_ == kNull) return maxFraction;
    const double ox = origin.x(), oy = origin.y(), dx = translation.x(), dy = translation.y();
    // A box is skipped when the ray's line misses it (the line's unit normal separates them) or when the box of the
    // ray's remaining part misses it; the second test tightens as the ray is clipped.
    const double length = std::sqrt(dx * dx + dy * dy);
    const double nx = -dy / length, ny = dx / length;
    const double anx = std::abs(nx), any = std::abs(ny);
    double ex = ox + maxFraction * dx, ey = oy + maxFraction * dy;
    double lowX = std::min(ox, ex), lowY = std::min(oy, ey), highX = std::max(ox, ex), highY = std::max(oy, ey);

    TraversalStack traversal(static_cast<std::size_t>(at(root_).height) + 1);
    std::int32_t* const stack = traversal.data();
    std::size_t top = 0;
    stack[top++] = root_;
    while (top > 0) {
        const std::int32_t id = stack[--top];
        const Node& n = at(id);
        const double bx0 = n.box.lower.x(), by0 = n.box.lower.y(), bx1 = n.box.upper.x(), by1 = n.box.upper.y();
        if (bx0 > highX || lowX > bx1 || by0 > highY || lowY > by1) continue;
        const double cx = 0.5 * (bx0 + bx1) - ox, cy = 0.5 * (by0 + by1) - oy;
        if (std::abs(nx * cx + ny * cy) > 0.5 * (anx * (bx1 - bx0) + any * (by1 - by0))) continue;
        if (!n.isLeaf()) {
            // The child whose centre lies nearer along the ray goes first: its hits clip the ray for the other.
            const Aabb& b1 = at(n.child1).box;
            const Aabb& b2 = at(n.child2).box;
            const double s1 = (b1.lower.x() + b1.upper.x()) * dx + (b1.lower.y() + b1.upper.y()) * dy;
            const double s2 = (b2.lower.x() + b2.upper.x()) * dx + (b2.lower.y() + b2.upper.y()) * dy;
            const bool firstIsNearer = s1 <= s2;
            stack[top++] = firstIsNearer ? n.child2 : n.child1;
            stack[top++] = firstIsNearer ? n.child1 : n.child2;
            continue;
        }
        const double value = callback(id, n.userData, maxFraction);
        if (!(value > 0.0)) return 0.0;
        if (value < maxFraction) {
            maxFraction = value;
            ex = ox + maxFraction * dx;
            ey = oy + maxFraction * dy;
            lowX = std::min(ox, ex), lowY = std::min(oy, ey), highX = std::max(ox, ex), highY = std::max(oy, ey);
        }
    }
    return maxFraction;
}

}  // namespace physim
