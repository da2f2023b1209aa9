// The public queries on a Geometry, each handed to the shape's kind (src/core/shapes).

#include "physim/core/Geometry.hpp"

#include "shapes/ShapeKinds.hpp"

namespace physim {

MassProperties computeMassProperties(const Geometry& g) {
    return withKind(g, [](auto kind, const auto& s) { return kind.mass(s); });
}

Aabb computeAabb(const Geometry& g, const Transform& xf) {
    return withKind(g, [&](auto kind, const auto& s) { return kind.aabb(s, xf); });
}

std::vector<Vec2> outline(const Geometry& g, const Transform& xf) {
    return withKind(g, [&](auto kind, const auto& s) { return kind.outline(s, xf); });
}

Geometry transformed(const Geometry& g, const Transform& xf) {
    return withKind(g, [&](auto kind, const auto& s) { return Geometry(kind.placed(s, xf)); });
}

void validate(const Geometry& g) {
    withKind(g, [](auto kind, const auto& s) { kind.validate(s); });
}

}  // namespace physim
