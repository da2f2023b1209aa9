#pragma once
// Narrow phase: contact manifolds between two placed geometries. Shared by the world's step and by the
// paper's CollisionShape API so both give the same answers.

#include "physim/core/Contact.hpp"
#include "physim/core/Geometry.hpp"

namespace physim {

/// Manifold of `a` placed by `xa` against `b` placed by `xb`; pointCount is 0 when they do not touch.
/// The normal points from a to b. Body ids are left null: the caller fills them in.
Manifold collide(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb);

}  // namespace physim
