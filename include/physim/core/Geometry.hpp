#pragma once
// Collision geometry as plain data in body-local metres, relative to the body origin (BodyDef::position). The
// factories below build shapes centred on the local origin unless an offset is asked for; makePolygon keeps the
// coordinates it is given. Wherever the shape lies, the body turns about its centre of mass (the shape's
// centroid) and its inertia is taken about that point (MassData.hpp, the one rule before and after a body joins
// a world).

#include "physim/core/Aabb.hpp"
#include "physim/core/Math.hpp"

#include <array>
#include <variant>
#include <vector>

namespace physim {

struct Circle {
    Vec2 center = Vec2::Zero();  ///< local position of the centre, m
    double radius = 0.0;         ///< m, > 0
};

/// Convex polygon, counter-clockwise, at most maxVertices vertices, with outward unit edge normals:
/// normals[i] is the normal of the edge vertices[i] -> vertices[(i + 1) % count]. Build one with makeBox or
/// makePolygon; validate() checks a hand-filled one. With radius > 0 it is a rounded polygon: every point within
/// radius of the core polygon the vertices describe (makeRoundedBox, makeRoundedPolygon).
struct Polygon {
    static constexpr int maxVertices = 8;
    std::array<Vec2, maxVertices> vertices{};
    std::array<Vec2, maxVertices> normals{};
    int count = 0;
    double radius = 0.0;  ///< m, >= 0
};

/// A line between two points, zero thickness and two-sided: ground and walls (zero area, so a body made only of
/// segments must be static or kinematic).
struct Segment {
    Vec2 point1 = Vec2::Zero();  ///< m, local
    Vec2 point2 = Vec2::Zero();  ///< m, local, apart from point1
};

/// Every point within `radius` of the segment center1-center2: a stadium.
struct Capsule {
    Vec2 center1 = Vec2::Zero();  ///< m, local
    Vec2 center2 = Vec2::Zero();  ///< m, local, apart from center1
    double radius = 0.0;          ///< m, > 0
};

/// One piece of a chain (a polyline of ground): a segment that collides only from its left side, whose normal is
/// point2 - point1 turned 90 degrees counter-clockwise (ground listed left to right is solid below; a
/// counter-clockwise loop holds bodies inside). ghost1 and ghost2 are the chain's points before point1 and after
/// point2: with them a body crossing the joint between two pieces feels no bump. An open chain's end piece has its
/// ghost equal to its own end point (no neighbour: the end is a real corner).
struct ChainSegment {
    Vec2 ghost1 = Vec2::Zero();  ///< m, local
    Segment segment;
    Vec2 ghost2 = Vec2::Zero();  ///< m, local
};

/// The kinds, in this order (the kernel's codes, src/core/ContinuousKernel.hpp, are these indices).
using Geometry = std::variant<Circle, Polygon, Segment, Capsule, ChainSegment>;

/// A circle of the given radius (m) centred at `center`. Throws std::invalid_argument for radius <= 0 or NaN.
Circle makeCircle(double radius, const Vec2& center = Vec2::Zero());

/// A rectangle of half-extents (m) centred on the local origin. Throws for non-positive or non-finite sizes.
Polygon makeBox(double halfWidth, double halfHeight);

/// A rectangle of half-extents (m) centred at `center` (m, local) and rotated by `angle` (rad, CCW) in the
/// body frame. Throws std::invalid_argument for bad sizes or a non-finite centre or angle.
Polygon makeBox(double halfWidth, double halfHeight, const Vec2& center, double angle);

/// A convex polygon through `points` (m, body-local), given in order around the boundary in either winding;
/// the result is counter-clockwise and keeps the coordinates as given (no recentring, see the file comment).
/// Throws std::invalid_argument naming the problem: fewer than 3 or more than Polygon::maxVertices points,
/// a non-finite coordinate, coincident points, three consecutive collinear points (or zero area), a reflex
/// vertex (non-convex) or a boundary that winds more than once (self-intersecting).
Polygon makePolygon(const std::vector<Vec2>& points);

/// The segment from p1 to p2 (m, local). Throws std::invalid_argument for a non-finite point or p1 == p2.
Segment makeSegment(const Vec2& p1, const Vec2& p2);

/// The pieces of a chain through `points` (m, local), each with its neighbours as ghosts: an open chain of n points
/// gives n - 1 pieces (its two end pieces' outer ghosts are their own end points), a loop gives n, the last joining
/// the last point to the first. Bodies collide with the left side of the direction of travel (ChainSegment).
/// Throws std::invalid_argument naming the problem: fewer than 2 points (3 for a loop), a non-finite point, or two
/// consecutive points that coincide (a zero-length piece; for a loop, a last point repeating the first included).
std::vector<ChainSegment> makeChain(const std::vector<Vec2>& points, bool loop = false);

/// The capsule around the segment c1-c2 (m, local) with the given radius (m). Throws std::invalid_argument for a
/// non-finite centre, c1 == c2 (use a circle) or a radius <= 0 or NaN.
Capsule makeCapsule(const Vec2& c1, const Vec2& c2, double radius);

/// makeBox(halfWidth, halfHeight) grown by `radius` (m) all round: outer half-extents halfWidth + radius and
/// halfHeight + radius, with round corners. Throws std::invalid_argument for bad sizes or a radius <= 0 or NaN.
Polygon makeRoundedBox(double halfWidth, double halfHeight, double radius);

/// makePolygon(points) grown by `radius` (m) all round. Throws as makePolygon does, and for a radius <= 0 or NaN.
Polygon makeRoundedPolygon(const std::vector<Vec2>& points, double radius);

/// The convex hull of `points` (m, body-local, any order), counter-clockwise, built through makePolygon. Points
/// strictly inside and points on the hull's edges are dropped; corners closer than 1e-6 of the points' extent
/// (bounding-box diagonal) are welded into one, and a corner turning by less than 1e-6 rad is dropped (both as
/// makePolygon would reject them), so every point lies inside the hull or a few millionths of the extent outside.
/// Throws std::invalid_argument naming the problem: fewer than 3 points, a non-finite coordinate (its index and
/// value), all points coincident or collinear, or a hull of more than Polygon::maxVertices corners (how many).
Polygon computeHull(const std::vector<Vec2>& points);

/// computeHull(points) grown by `radius` (m, finite and >= 0; 0 gives the plain hull): a rounded polygon.
Polygon computeHull(const std::vector<Vec2>& points, double radius);

/// Mass properties per unit density (kg/m^2): area (m^2), centroid (m, local) and the second moment of area
/// about the centroid (m^4). Multiply area and secondMoment by a density to get mass and inertia.
struct MassProperties {
    double area = 0.0;
    Vec2 centroid = Vec2::Zero();
    double secondMoment = 0.0;
};

MassProperties computeMassProperties(const Geometry& g);

/// World-space bounding box of a geometry placed by `xf`.
Aabb computeAabb(const Geometry& g, const Transform& xf);

/// World points (m) around the boundary of a geometry placed by `xf`, counter-clockwise, for drawing it as a filled
/// convex polygon: a polygon's vertices, 40 points on a circle, arcs at a capsule's ends and a rounded polygon's
/// corners, a segment's two points.
std::vector<Vec2> outline(const Geometry& g, const Transform& xf);

/// The same shape with every point moved by `xf` (m, rad): a part placed in a body of several shapes.
Geometry transformed(const Geometry& g, const Transform& xf);

}  // namespace physim

namespace physim {

/// Throws std::invalid_argument naming the problem: non-positive or non-finite radius (a polygon's may be 0), a
/// polygon with fewer than 3 or more than Polygon::maxVertices vertices, non-finite coordinates, or a polygon that
/// makePolygon would reject (coincident, collinear, clockwise, non-convex), or whose normals are not its outward unit
/// edge normals; a segment, capsule or chain segment whose two points coincide.
void validate(const Geometry& g);

}  // namespace physim
