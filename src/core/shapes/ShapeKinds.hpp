#pragma once
// The shape kinds' rooms, and the one dispatch from a Geometry to its kind. Internal.
//
// Every user of a shape's kind goes through withKind (or withKindCode, for a kernel code), which hands the caller's
// function the kind's ShapeKind<S> (ShapeKind.hpp lists what it holds) and the shape; the narrow phase's table of
// pairs (NarrowPhase.cpp) is built from the same list. A new kind is an alternative of Geometry, its room, and its
// include below (docs/architecture.md, "Adding a shape kind").

#include "CapsuleKind.hpp"
#include "ChainSegmentKind.hpp"
#include "CircleKind.hpp"
#include "PolygonKind.hpp"
#include "SegmentKind.hpp"

#include <cstddef>
#include <utility>
#include <variant>

namespace physim {

constexpr std::size_t kKindCount = std::variant_size_v<Geometry>;

template <std::size_t I>
using KindAt = std::variant_alternative_t<I, Geometry>;

namespace detail {

template <std::size_t... I>
constexpr bool kernelCodesAreIndices(std::index_sequence<I...>) {
    return ((ShapeKind<KindAt<I>>::kernelKind == static_cast<int>(I)) && ...);
}

}  // namespace detail

static_assert(detail::kernelCodesAreIndices(std::make_index_sequence<kKindCount>{}),
              "a kind's kernel code is its index in Geometry (ContinuousBatch::Shapes::kind relies on it)");

/// f(ShapeKind<S>{}, shape) for the kind S that g holds: a test of the index per kind, in Geometry's order.
template <std::size_t I = 0, class F>
decltype(auto) withKind(const Geometry& g, F&& f) {
    if constexpr (I + 1 == kKindCount) {
        return f(ShapeKind<KindAt<I>>{}, std::get<I>(g));
    } else {
        if (g.index() == I) return f(ShapeKind<KindAt<I>>{}, *std::get_if<I>(&g));
        return withKind<I + 1>(g, std::forward<F>(f));
    }
}

/// f(ShapeKind<S>{}) for the kind whose kernel code (its index in Geometry) is `code`; false when no kind has it.
template <std::size_t I = 0, class F>
bool withKindCode(std::int32_t code, F&& f) {
    if constexpr (I == kKindCount) {
        return false;
    } else {
        if (code == static_cast<std::int32_t>(I)) {
            f(ShapeKind<KindAt<I>>{});
            return true;
        }
        return withKindCode<I + 1>(code, std::forward<F>(f));
    }
}

}  // namespace physim
