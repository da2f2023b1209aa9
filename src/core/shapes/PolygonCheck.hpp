#pragma once
// Shape checks shared by makePolygon (which fixes the winding first) and validate(Geometry). Internal.

#include "physim/core/Geometry.hpp"

#include <string>
#include <vector>

namespace physim {

/// makePolygon's tolerances, as fractions of the polygon's size, so the checks mean the same for a 1 mm and a 10 m
/// shape: points closer than kCoincident * size are one point; a turn whose sine is below kCollinear is no turn.
/// Both are far above rounding (1e-16) and far below any shape worth simulating. computeHull cleans its corners with
/// the same numbers, so makePolygon accepts what it leaves.
constexpr double kCoincident = 1e-6;
constexpr double kCollinear = 1e-6;

/// The convex hull's corners, counter-clockwise from the lowest-x (then lowest-y) point, of any number of points
/// (Andrew's monotone chain, Hull.cpp). Points strictly inside and points on an edge (repeats included) are left out.
std::vector<Vec2> convexHullCorners(std::vector<Vec2> points);

/// "(x, y)" with every digit, for the shape checks' messages.
std::string show(const Vec2& v);

/// Throws std::invalid_argument unless vertices[0..count) are a counter-clockwise, strictly convex polygon
/// that winds once, with finite, pairwise distinct vertices and no three consecutive ones collinear.
/// `what` names the value in the message (e.g. "polygon").
void checkConvexCounterClockwise(const Vec2* vertices, int count, const char* what);

/// Signed area (m^2) of the closed path through vertices[0..count): positive when counter-clockwise.
double signedArea(const Vec2* vertices, int count);

}  // namespace physim
