#pragma once
// Which shapes may touch, and which shapes a query sees: category and mask bits and a group index per shape, with
// the semantics Box2D users know.

#include <cstdint>

namespace physim {

/// A shape's collision filter. Two shapes collide when each one's mask holds a category bit of the other, unless
/// they share a non-zero group: then a positive group always collides and a negative group never does.
struct Filter {
    std::uint64_t categoryBits = 1;              ///< what the shape is: usually one bit
    std::uint64_t maskBits = ~std::uint64_t{0};  ///< the categories it collides with
    std::int32_t groupIndex = 0;                 ///< 0: no group; a shared group overrides the bits

    friend bool operator==(const Filter& a, const Filter& b) {
        return a.categoryBits == b.categoryBits && a.maskBits == b.maskBits && a.groupIndex == b.groupIndex;
    }
    friend bool operator!=(const Filter& a, const Filter& b) { return !(a == b); }
};

/// Whether two shapes' filters let them collide (the one rule; World applies it to every new pair).
inline bool shouldCollide(const Filter& a, const Filter& b) {
    if (a.groupIndex == b.groupIndex && a.groupIndex != 0) return a.groupIndex > 0;
    return (a.maskBits & b.categoryBits) != 0 && (a.categoryBits & b.maskBits) != 0;
}

/// What a query (ray cast, shape cast, overlap) sees: shapes whose category is in maskBits and whose mask holds one
/// of categoryBits. The default sees every shape.
struct QueryFilter {
    std::uint64_t categoryBits = 1;
    std::uint64_t maskBits = ~std::uint64_t{0};
};

/// Whether a query with this filter sees a shape with that one.
inline bool shouldQuery(const QueryFilter& query, const Filter& shape) {
    return (query.maskBits & shape.categoryBits) != 0 && (query.categoryBits & shape.maskBits) != 0;
}

}  // namespace physim
