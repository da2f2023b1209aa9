#pragma once
// Narrow phase: contact manifolds between two placed geometries. Shared by the world's step and by the
// paper's CollisionShape API so both give the same answers.

#include "physim/core/Colliding.hpp"
#include "physim/core/Contact.hpp"
#include "physim/core/Geometry.hpp"

namespace physim {

/// Manifold of `a` placed by `xa` against `b` placed by `xb`; pointCount is 0 when they do not touch.
/// The normal points from a to b. Body ids are left null: the caller fills them in.
/// Works for every pair of finite transforms and valid geometries whose world coordinates stay below about
/// 1e150 m (so squared lengths do not overflow); it never returns NaN there. Algorithms: docs/collision.md.
Manifold collide(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb);

/// The same collision as the paper's Colliding (what CollisionShape::satCollision returns): the manifold's
/// normal and points plus the penetration depth of the pair (Colliding.hpp says what each field means).
Colliding computeColliding(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb);

}  // namespace physim
