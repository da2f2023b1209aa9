// Polygon construction: boxes and general convex polygons, with their outward unit edge normals.

#include "PolygonCheck.hpp"

#include "physim/core/Geometry.hpp"
#include "physim/core/Validate.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace physim {
namespace {

[[noreturn]] void fail(const char* what, const std::string& problem) {
    throw std::invalid_argument(std::string("physim: ") + what + " " + problem);
}

void computeNormals(Polygon& p) {
    for (int i = 0; i < p.count; ++i) {
        const Vec2 edge = p.vertices[(i + 1) % p.count] - p.vertices[i];
        p.normals[i] = Vec2(edge.y(), -edge.x()) / std::hypot(edge.x(), edge.y());  // outward for CCW
    }
}

}  // namespace

std::string show(const Vec2& v) {
    std::ostringstream os;
    os.precision(17);
    os << "(" << v.x() << ", " << v.y() << ")";
    return os.str();
}

double signedArea(const Vec2* v, int count) {
    // Shoelace formula about the first vertex (smaller terms than about the origin, so less rounding).
    double twice = 0.0;
    for (int i = 1; i + 1 < count; ++i) twice += cross(v[i] - v[0], v[i + 1] - v[0]);
    return 0.5 * twice;
}

void checkConvexCounterClockwise(const Vec2* v, int count, const char* what) {
    if (count < 3 || count > Polygon::maxVertices)
        fail(what, "vertex count must be in [3, " + std::to_string(Polygon::maxVertices) + "], got " +
                       std::to_string(count));
    for (int i = 0; i < count; ++i)
        if (!std::isfinite(v[i].x()) || !std::isfinite(v[i].y()))
            fail(what, "vertex " + std::to_string(i) + " must be finite, got " + show(v[i]));

    Vec2 lower = v[0], upper = v[0];
    for (int i = 1; i < count; ++i) {
        lower = lower.cwiseMin(v[i]);
        upper = upper.cwiseMax(v[i]);
    }
    const double size = (upper - lower).norm();
    if (!std::isfinite(size))  // squared lengths overflow: every later check would see NaN
        fail(what, "is too large: its extent " + show(upper - lower) + " m overflows squared lengths");
    for (int i = 0; i < count; ++i)
        for (int j = i + 1; j < count; ++j)
            if ((v[i] - v[j]).norm() <= kCoincident * size)
                fail(what, "vertices " + std::to_string(i) + " and " + std::to_string(j) +
                               " must be distinct, got coincident points " + show(v[i]) + " and " + show(v[j]));

    double turning = 0.0;  // total exterior angle, rad: 2 pi for a boundary that winds once
    for (int i = 0; i < count; ++i) {
        const Vec2 prev = v[i] - v[(i + count - 1) % count];
        const Vec2 next = v[(i + 1) % count] - v[i];
        const double c = cross(prev, next);
        const double sine = c / (prev.norm() * next.norm());
        if (std::abs(sine) <= kCollinear)
            fail(what, "vertex " + std::to_string(i) + " " + show(v[i]) +
                           " is collinear with its neighbours (no corner there, or zero area)");
        if (sine < 0.0)
            fail(what, "must be convex and counter-clockwise, but turns right (a reflex corner) at vertex " +
                           std::to_string(i) + " " + show(v[i]));
        turning += std::atan2(c, prev.dot(next));
    }
    if (turning > 2.0 * M_PI + 1e-6)
        fail(what, "must not intersect itself, but its boundary winds " + std::to_string(turning / (2.0 * M_PI)) +
                       " times");
}

Polygon makeBox(double halfWidth, double halfHeight) {
    return makeBox(halfWidth, halfHeight, Vec2::Zero(), 0.0);
}

Polygon makeBox(double halfWidth, double halfHeight, const Vec2& center, double angle) {
    requirePositive("box half-width", halfWidth);
    requirePositive("box half-height", halfHeight);
    requireFinite("box center", center);
    requireFinite("box angle", angle);
    const Transform xf{center, Rotation::fromAngle(angle)};
    Polygon p;
    p.count = 4;
    const Vec2 corners[4] = {{-halfWidth, -halfHeight}, {halfWidth, -halfHeight}, {halfWidth, halfHeight},
                             {-halfWidth, halfHeight}};
    const Vec2 normals[4] = {{0.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}};
    for (int i = 0; i < 4; ++i) {
        p.vertices[i] = xf.apply(corners[i]);
        p.normals[i] = xf.q.apply(normals[i]);  // exact axes when angle == 0
    }
    return p;
}

Polygon makePolygon(const std::vector<Vec2>& points) {
    const int count = static_cast<int>(std::min<std::size_t>(points.size(), Polygon::maxVertices + 1));
    if (points.size() < 3 || points.size() > static_cast<std::size_t>(Polygon::maxVertices))
        fail("polygon", "vertex count must be in [3, " + std::to_string(Polygon::maxVertices) + "], got " +
                            std::to_string(points.size()));
    Polygon p;
    p.count = count;
    std::copy(points.begin(), points.end(), p.vertices.begin());
    for (int i = 0; i < count; ++i) requireFinite("polygon vertex", p.vertices[i]);
    // Clockwise input is reversed; the checks below then see every corner of a convex polygon turn left.
    if (signedArea(p.vertices.data(), count) < 0.0) std::reverse(p.vertices.begin(), p.vertices.begin() + count);
    checkConvexCounterClockwise(p.vertices.data(), count, "polygon");
    computeNormals(p);
    return p;
}

}  // namespace physim

namespace physim {

Polygon makeRoundedBox(double halfWidth, double halfHeight, double radius) {
    requirePositive("rounded box radius", radius);
    Polygon p = makeBox(halfWidth, halfHeight);
    p.radius = radius;
    return p;
}

Polygon makeRoundedPolygon(const std::vector<Vec2>& points, double radius) {
    requirePositive("rounded polygon radius", radius);
    Polygon p = makePolygon(points);
    p.radius = radius;
    return p;
}

}  // namespace physim
