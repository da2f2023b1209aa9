#pragma once
// Shape checks shared by makePolygon (which fixes the winding first) and validate(Geometry). Internal.

#include "physim/core/Geometry.hpp"

namespace physim {

/// Throws std::invalid_argument unless vertices[0..count) are a counter-clockwise, strictly convex polygon
/// that winds once, with finite, pairwise distinct vertices and no three consecutive ones collinear.
/// `what` names the value in the message (e.g. "polygon").
void checkConvexCounterClockwise(const Vec2* vertices, int count, const char* what);

/// Signed area (m^2) of the closed path through vertices[0..count): positive when counter-clockwise.
double signedArea(const Vec2* vertices, int count);

}  // namespace physim
