#pragma once
// A read-only tree of boxes four children wide, built top-down in one go by the surface-area heuristic, for answering
// many box queries while the boxes stay the same. Each node holds its four children's boxes side by side in floats:
// one comparison tests all four, and the children that meet are pushed without a branch each, where a binary tree
// takes a hard-to-predict branch per child tested (most of a query's time). Floats are rounded outwards from the
// doubles, so a query may report a few leaves that miss by a float's rounding but never misses one that meets: the
// caller checks each leaf exactly. Internal.

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "physim/core/Aabb.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace physim {

class WideBoxTree {
public:
    /// Drops the tree and its leaves.
    void clear();
    /// Adds a leaf for the next build.
    void addLeaf(const Aabb& box, std::uint32_t userData);
    /// Builds the tree over the leaves added since clear. Throws nothing the vectors' allocation would not.
    void build();
    /// Levels of nodes: 0 for no leaves; under 64 whatever the boxes (query's stack relies on it).
    int height() const { return height_; }

    /// Calls callback(userData) for each leaf whose box (rounded outwards to floats) meets `box`, in an order the
    /// tree fixes; a callback returning bool stops the query by returning false. A NaN box meets nothing.
    template <class Callback>
    void query(const Aabb& box, Callback&& callback) const;

    using Float4 = float __attribute__((vector_size(16)));  // GCC vector extensions, which Clang has too
    using Int4 = std::int32_t __attribute__((vector_size(16)));
    // A box in floats, rounded outwards from the caller's doubles: lower x, lower y and the upper corner negated,
    // so that the box holding two is their lane-wise least.
    using Box = Float4;

private:
    // child[i] >= 0: an internal node's index; < 0: the leaf ~child[i] of leafData_. A missing child has an empty
    // box (lower above upper), which meets nothing.
    struct alignas(16) Node {
        Float4 lowerX, lowerY, upperX, upperY;
        Int4 child;
    };

    // Bit i: lane i's sign bit (set for a true comparison, and for a leaf's child index).
    static unsigned signBits(Int4 v) {
#if defined(__SSE2__)
        return static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(reinterpret_cast<__m128i>(v))));
#else
        return (v[0] < 0 ? 1u : 0u) | (v[1] < 0 ? 2u : 0u) | (v[2] < 0 ? 4u : 0u) | (v[3] < 0 ? 8u : 0u);
#endif
    }

    struct Leaf {
        Box box;
        float centreX, centreY;
        std::uint32_t userData;
    };
    struct Range {
        std::size_t begin, end;  // in leaves_
        Box box;
    };

    std::size_t split(const Range& range, int depth, Range& left, Range& right);
    std::int32_t buildNode(const Range& range, int depth);

    std::vector<Leaf> leaves_;             // reordered by the build
    std::vector<std::uint8_t> bin_;        // the build's bin of each leaf, by position in leaves_
    std::vector<Node> nodes_;              // nodes_[0] is the root
    std::vector<std::uint32_t> leafData_;  // userData by leaf index
    int height_ = 0;
};

template <class Callback>
void WideBoxTree::query(const Aabb& box, Callback&& callback) const {
    if (nodes_.empty()) return;
    const auto report = [&callback](std::uint32_t data) {
        if constexpr (std::is_void_v<std::invoke_result_t<Callback&, std::uint32_t>>) {
            callback(data);
            return true;
        } else {
            return static_cast<bool>(callback(data));
        }
    };
    // The query box rounded to the nearest floats: rounding keeps order, so a leaf whose double box meets the query
    // still does in floats (its own box having been rounded outwards).
    const float qx0 = static_cast<float>(box.lower.x()), qy0 = static_cast<float>(box.lower.y());
    const float qx1 = static_cast<float>(box.upper.x()), qy1 = static_cast<float>(box.upper.y());
    const Float4 lowX = {qx0, qx0, qx0, qx0}, lowY = {qy0, qy0, qy0, qy0};
    const Float4 highX = {qx1, qx1, qx1, qx1}, highY = {qy1, qy1, qy1, qy1};
    // Each level leaves at most three siblings waiting; the build keeps the height under 64 (WideBoxTree.cpp). Four
    // spare entries: every child is written and the top moves only past those that meet.
    std::int32_t stack[4 * 64 + 4];
    std::size_t top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[static_cast<std::size_t>(stack[--top])];
        const Int4 meets = (n.lowerX <= highX) & (lowX <= n.upperX) & (n.lowerY <= highY) & (lowY <= n.upperY);
        const unsigned hits = signBits(meets), leaves = signBits(n.child);
        // Inner children pushed without a branch each (whether one meets is hard to predict); leaves reported.
        const unsigned inner = hits & ~leaves;
        for (unsigned i = 0; i < 4; ++i) {
            stack[top] = n.child[i];
            top += (inner >> i) & 1u;
        }
        for (unsigned met = hits & leaves; met != 0; met &= met - 1) {
            const std::int32_t c = n.child[__builtin_ctz(met)];
            if (!report(leafData_[static_cast<std::size_t>(~c)])) return;
        }
    }
}

}  // namespace physim
