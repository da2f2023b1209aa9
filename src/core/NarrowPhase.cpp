// Narrow-phase dispatch on the pair of shape kinds, and the paper's Colliding built from the result.

#include "Manifolds.hpp"
#include "shapes/ShapeKinds.hpp"

#include "physim/core/Collide.hpp"

#include <algorithm>
#include <array>

namespace physim {
namespace {

NarrowResult swapped(NarrowResult r) {
    // The routine ran with the shapes swapped: the same points, the normal reversed to run from a to b. Its
    // StaysEmpty measured a's motion relative to b, which the narrow phase does not track: nothing known, but a
    // fragile answer stays fragile.
    r.manifold.normal = -r.manifold.normal;
    const bool fragile = r.empty.fragile;
    r.empty = {};
    r.empty.fragile = fragile;
    return r;
}

using PairFunction = NarrowResult (*)(const Geometry&, const Transform&, const Geometry&, const Transform&, double);

// Kinds I and J: the later kind's room collides it with every earlier kind (ShapeKind.hpp); the other order is
// that result swapped.
template <std::size_t I, std::size_t J>
NarrowResult collidePair(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb,
                         double margin) {
    if constexpr (I >= J)
        return ShapeKind<KindAt<I>>::collide(*std::get_if<I>(&a), xa, *std::get_if<J>(&b), xb, margin);
    else
        return swapped(ShapeKind<KindAt<J>>::collide(*std::get_if<J>(&b), xb, *std::get_if<I>(&a), xa, margin));
}

template <std::size_t... P>
constexpr std::array<PairFunction, sizeof...(P)> pairTable(std::index_sequence<P...>) {
    return {&collidePair<P / kKindCount, P % kKindCount>...};
}

// Entry a.index() * kKindCount + b.index().
constexpr auto kPairs = pairTable(std::make_index_sequence<kKindCount * kKindCount>{});

}  // namespace

NarrowResult collideGeometries(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb,
                               double margin) {
    return kPairs[a.index() * kKindCount + b.index()](a, xa, b, xb, margin);
}
Manifold collide(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
    return collideGeometries(a, xa, b, xb).manifold;
}

Colliding computeColliding(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
    const NarrowResult r = collideGeometries(a, xa, b, xb);
    const Manifold& m = r.manifold;
    Colliding c;
    if (m.pointCount == 0) return c;
    c.collision = true;
    c.normal = m.normal;
    c.penetration = std::max(-r.separation, 0.0);
    double shallowest = -m.points[0].separation;
    for (int i = 1; i < m.pointCount; ++i) shallowest = std::min(shallowest, -m.points[i].separation);
    c.overlap = std::max(shallowest, 0.0);
    c.collidingPoints.contactCount = m.pointCount;
    c.collidingPoints.pointA = m.points[0].point;
    if (m.pointCount > 1) c.collidingPoints.pointB = m.points[1].point;
    return c;
}

}  // namespace physim
