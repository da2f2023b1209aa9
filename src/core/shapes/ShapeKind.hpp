#pragma once
// What a shape kind provides. Internal.
//
// A kind is an alternative of Geometry (physim/core/Geometry.hpp) with a room of its own under src/core/shapes/:
// a header that specialises ShapeKind<S> and the sources behind it. ShapeKinds.hpp lists the rooms and is the one
// place that dispatches from a Geometry to its kind (the kernel aside). ShapeKind<S> holds, as static
// members (S is the kind's data, m in body-local coordinates unless a Transform places it):
//
//   name                         "circle": for messages
//   kernelKind                   the kind's code in the shared kernel (ContinuousKernel.hpp), equal to its index
//                                in Geometry
//   minVertices, maxVertices,    how the kind lays itself out in a ContinuousBatch: the vertex count range (and
//   vertexCounts                 its text for messages)
//   mass(s)                      MassProperties per unit density: area, centroid, second moment about the centroid
//   aabb(s, xf)                  world box of the placed shape
//   boundingRadius(s)            farthest point from the body origin, m
//   coreRadius(s)                largest circle about the centroid inside the shape, m
//   turningRadius(s)             how far the outline moves per radian the body turns about its origin, m
//   extentAbout(s, c)            farthest point from the point c, m
//   meanWidth(s)                 mean width over all directions (drag), m
//   validate(s)                  throws std::invalid_argument naming the problem
//   outline(s, xf)               world points around the boundary, counter-clockwise, for drawing
//   placed(s, xf)                the same kind with every point moved by xf (a part placed in a compound body)
//   toKernel(s, k)               fills the kernel's Shape but its bounding radius (kind, count, radius, vertices,
//                                normals)
//   fromBatch(shapes, i)         the shape from a ContinuousBatch's entry i, for validate(ContinuousBatch)'s messages,
//   radiusProblem(r),            with what is wrong with the entry's radius before validate(s) runs, and with the
//   kernelProblem(s)             shape that validate(s) accepts but the kernel refuses ("" when nothing)
//   collide(s, xs, t, xt, margin)  the narrow phase against every kind T up to and including this one in
//                                Geometry's order: the normal from s to t (the table in NarrowPhase.cpp reverses
//                                it for the other order)
//   rayCast(s, ray)              where a ray enters the shape (RayCast.hpp: no hit from inside), the shape's frame
//   containsPoint(s, p)          whether the point (the shape's frame) lies in the shape, boundary included

#include "RayCast.hpp"
#include "../Manifolds.hpp"
#include "../ContinuousKernel.hpp"

#include "physim/core/Aabb.hpp"
#include "physim/core/ContinuousBatch.hpp"
#include "physim/core/Geometry.hpp"

namespace physim {

template <class S>
struct ShapeKind;

}  // namespace physim
