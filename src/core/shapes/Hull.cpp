// Convex hull of a point cloud (Andrew's monotone chain), handed to makePolygon so hulls and hand-ordered
// polygons share one rule for normals and checks.

#include "physim/core/Geometry.hpp"
#include "physim/core/Validate.hpp"

#include "PolygonCheck.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace physim {
namespace {

// makePolygon's tolerances (PolygonCheck.hpp), relative to the hull's extent (its bounding-box diagonal): corners
// closer than kWeld * extent are one corner, and a corner whose turn has a sine below kStraight is no corner.
constexpr double kWeld = kCoincident;
constexpr double kStraight = kCollinear;

[[noreturn]] void fail(const std::string& problem) { throw std::invalid_argument("physim: convex hull " + problem); }

double extentOf(const std::vector<Vec2>& v) {
    Vec2 lower = v[0], upper = v[0];
    for (const Vec2& p : v) {
        lower = lower.cwiseMin(p);
        upper = upper.cwiseMax(p);
    }
    return (upper - lower).norm();
}

// Drops corners makePolygon would reject as coincident or collinear: each removal keeps the polygon convex and
// moves its boundary by at most kWeld (or kStraight) times the extent. The extent is the points' (the hull keeps
// their extreme points) and only shrinks as corners go, so what is left passes makePolygon's checks. The corners
// form a ring; after a removal its two neighbours are looked at again, so the pass is linear.
void weldAndStraighten(std::vector<Vec2>& h) {
    const double size = extentOf(h);
    const std::size_t n = h.size();
    std::vector<std::size_t> prev(n), next(n);
    for (std::size_t i = 0; i < n; ++i) {
        prev[i] = (i + n - 1) % n;
        next[i] = (i + 1) % n;
    }
    std::size_t alive = n, i = 0, keptInARow = 0;
    while (alive >= 3 && keptInARow < alive) {
        const Vec2 in = h[i] - h[prev[i]], out = h[next[i]] - h[i];
        const bool weld = out.norm() <= kWeld * size;
        const bool straight = !weld && std::abs(cross(in, out) / (in.norm() * out.norm())) <= kStraight;
        if (!weld && !straight) {
            i = next[i];
            ++keptInARow;
            continue;
        }
        const std::size_t gone = weld ? next[i] : i;
        next[prev[gone]] = next[gone];
        prev[next[gone]] = prev[gone];
        --alive;
        keptInARow = 0;
        i = prev[gone];  // its next corner changed; the one after it (its prev changed) comes next
    }
    std::vector<Vec2> ring;
    ring.reserve(alive);
    for (std::size_t k = 0; k < alive; ++k, i = next[i]) ring.push_back(h[i]);
    // Start where the chain started (its leftmost, lowest corner), as makePolygon keeps the order given.
    std::rotate(ring.begin(), std::min_element(ring.begin(), ring.end(), [](const Vec2& a, const Vec2& b) {
                    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
                }), ring.end());
    h = std::move(ring);
}

}  // namespace

std::vector<Vec2> convexHullCorners(std::vector<Vec2> p) {
    if (p.empty()) return p;
    std::sort(p.begin(), p.end(), [](const Vec2& a, const Vec2& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    std::vector<Vec2> hull;
    hull.reserve(p.size() + 1);
    const auto sweep = [&](auto first, auto last, std::size_t floor) {
        for (auto it = first; it != last; ++it) {
            // Pop the last corner while it does not turn left on the way to *it.
            while (hull.size() > floor &&
                   cross(hull.back() - hull[hull.size() - 2], *it - hull[hull.size() - 2]) <= 0.0)
                hull.pop_back();
            hull.push_back(*it);
        }
    };
    sweep(p.begin(), p.end(), 1);                  // lower chain, left to right
    sweep(p.rbegin() + 1, p.rend(), hull.size());  // upper chain, right to left, back to the start
    hull.pop_back();                               // the start again
    return hull;
}

Polygon computeHull(const std::vector<Vec2>& points) {
    if (points.size() < 3) fail("needs at least 3 points, got " + std::to_string(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!std::isfinite(points[i].x()) || !std::isfinite(points[i].y()))
            fail("point " + std::to_string(i) + " must be finite, got " + show(points[i]));
    const double extent = extentOf(points);
    if (!std::isfinite(extent))
        fail("points are too far apart: their extent overflows squared lengths");
    if (extent == 0.0) fail("points all coincide at " + show(points[0]) + ": no area");

    std::vector<Vec2> hull = convexHullCorners(points);
    weldAndStraighten(hull);
    if (hull.size() < 3)
        fail("points are all collinear (within " + std::to_string(kStraight) + " of their extent " +
             std::to_string(extent) + " m, repeated points welded): no area");
    if (hull.size() > static_cast<std::size_t>(Polygon::maxVertices))
        fail("has " + std::to_string(hull.size()) + " vertices, more than Polygon::maxVertices (" +
             std::to_string(Polygon::maxVertices) + "); use fewer points or several shapes");
    return makePolygon(hull);
}

Polygon computeHull(const std::vector<Vec2>& points, double radius) {
    requireNonNegative("convex hull radius", radius);
    Polygon p = computeHull(points);
    p.radius = radius;
    return p;
}

}  // namespace physim
