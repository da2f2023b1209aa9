#pragma once
// The narrow phase's result and constants. Internal. The routines for each pair of shape kinds are in the kinds'
// rooms (src/core/shapes), and NarrowPhase.cpp dispatches to them by a table of kind pairs.
//
// Every routine returns the contact manifold (normal from the first shape to the second, up to two points
// midway between the surfaces, stable feature ids) and the signed distance between the shapes along that
// normal: negative when they overlap, where its magnitude is the penetration depth (the distance to move the
// second shape along the normal to separate them). `margin` (m, >= 0) makes the manifold speculative: points up
// to that far apart are kept too (positive separation), so the solver can stop the shapes before they meet.
// With margin 0, pointCount is 0 exactly when the shapes do not touch.

#include "physim/core/Contact.hpp"
#include "physim/core/Geometry.hpp"

namespace physim {

/// How long a routine's empty answer stays empty, from the routine's own tests: while the point `about` of the
/// second shape (in its body's frame) moves less than `distance` (m) relative to the first (`anyMargin`: at any
/// margin), or while the margin, at least kSpeculativeMargin, plus that move stays below `distance` (the shapes'
/// gap, less rounding's due). Zero: nothing known. The narrow phase then skips the routine and has the same answer
/// (Contacts.cpp).
struct StaysEmpty {
    double distance = 0.0;
    bool anyMargin = false;
    Vec2 about = Vec2::Zero();
    bool fragile = false;  // emptied by a rule on directions (a chain's joints): the answer is not kept at all
};

struct NarrowResult {
    Manifold manifold;
    double separation = 0.0;  ///< m along manifold.normal; only meaningful when manifold.pointCount > 0
    StaysEmpty empty;         ///< only meaningful when manifold.pointCount == 0
};

/// Dispatch on the pair of shape kinds (NarrowPhase.cpp); the normal points from a to b.
NarrowResult collideGeometries(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb,
                               double margin = 0.0);

/// Largest |separation difference| (m) for which polygon-polygon keeps the first shape's face as the reference
/// when the two candidate faces are almost antiparallel (a box resting on a box): rounding and solver jitter
/// then cannot swap the reference face between steps, which would change the feature ids and lose warm
/// starting. 50x below the default linear slop, so the penetration it reports is within this of the minimum.
constexpr double kReferenceFaceTolerance = 1e-4;

/// A polygon-polygon manifold keeps a clipped point up to this far (m) outside the reference face, when the
/// shapes touch. A box resting flat is tilted by solver rounding (1e-7 rad or so), lifting one corner by a
/// hair; dropping that point would leave a single point under the box, which then rocks. Far below the
/// default linear slop (5e-3 m), so a point kept this way holds a body no visible distance off the ground.
constexpr double kSpeculativeMargin = 5e-4;

}  // namespace physim
