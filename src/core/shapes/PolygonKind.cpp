// The convex polygon's room: mass, radii, width, checks and outline (Polygon.cpp builds polygons).

#include "PolygonKind.hpp"

#include "PolygonCheck.hpp"

#include "../KernelBridge.hpp"

#include "physim/core/Validate.hpp"

#include <limits>
#include <stdexcept>

namespace physim {

namespace {

// Area, first and second moments of area (m^2, m^3, m^4) about a reference point, summed over pieces.
struct Moments {
    double area = 0.0;
    Vec2 first = Vec2::Zero();
    double second = 0.0;

    // A convex polygon through the points (relative to the reference), counter-clockwise: its triangles fanned
    // from the reference point.
    void addPolygon(const Vec2* v, int count) {
        for (int i = 0; i < count; ++i) {
            const Vec2& e1 = v[i];
            const Vec2& e2 = v[(i + 1) % count];
            const double a = 0.5 * cross(e1, e2);
            area += a;
            first += a * (e1 + e2) / 3.0;
            second += a / 6.0 * (e1.squaredNorm() + e1.dot(e2) + e2.squaredNorm());
        }
    }
    // The circular sector of radius r at apex v between the unit directions from and to (counter-clockwise, less
    // than pi apart): area theta r^2 / 2, centroid 4 r sin(theta / 2) / (3 theta) along the bisector, second moment
    // about the apex area r^2 / 2, moved to the reference point.
    void addSector(const Vec2& v, double r, const Vec2& from, const Vec2& to) {
        const double theta = std::atan2(cross(from, to), from.dot(to));
        if (theta <= 0.0) return;
        const double a = 0.5 * theta * r * r;
        const Vec2 offset = (4.0 * r * std::sin(0.5 * theta) / (3.0 * theta)) * (from + to).normalized();
        area += a;
        first += a * (v + offset);
        second += a * v.squaredNorm() + 2.0 * a * v.dot(offset) + 0.5 * a * r * r;
    }
};

// A rounded polygon: its core, a rectangle of depth radius on each edge and a sector at each corner (together a
// disc), all about the first vertex.
MassProperties roundedMass(const Polygon& p) {
    const Vec2 origin = p.vertices[0];
    const double r = p.radius;
    Vec2 v[Polygon::maxVertices];
    for (int i = 0; i < p.count; ++i) v[i] = p.vertices[i] - origin;
    Moments m;
    m.addPolygon(v, p.count);
    for (int i = 0; i < p.count; ++i) {
        const int next = (i + 1) % p.count;
        const Vec2 out = r * p.normals[i];
        const Vec2 rectangle[4] = {v[i], v[i] + out, v[next] + out, v[next]};  // counter-clockwise
        m.addPolygon(rectangle, 4);
        m.addSector(v[next], r, p.normals[i], p.normals[next]);
    }
    const Vec2 centroid = m.first / m.area;
    return {m.area, origin + centroid, m.second - m.area * centroid.squaredNorm()};
}

}  // namespace

// Decompose into triangles fanned from the first vertex; sum their areas, centroids and second moments.
MassProperties ShapeKind<Polygon>::mass(const Polygon& p) {
    if (p.radius > 0.0) return roundedMass(p);
    const Vec2 origin = p.vertices[0];
    double area = 0.0;
    Vec2 weighted = Vec2::Zero();
    double momentAboutOrigin = 0.0;  // second moment about `origin`
    for (int i = 1; i + 1 < p.count; ++i) {
        const Vec2 e1 = p.vertices[i] - origin;
        const Vec2 e2 = p.vertices[i + 1] - origin;
        const double a = 0.5 * cross(e1, e2);
        area += a;
        weighted += a * (e1 + e2) / 3.0;
        momentAboutOrigin += a / 6.0 * (e1.squaredNorm() + e1.dot(e2) + e2.squaredNorm());
    }
    const Vec2 centroidFromOrigin = weighted / area;
    const double aboutCentroid = momentAboutOrigin - area * centroidFromOrigin.squaredNorm();
    return {area, origin + centroidFromOrigin, aboutCentroid};
}

double ShapeKind<Polygon>::coreRadius(const Polygon& p) {
    const Vec2 centroid = mass(p).centroid;
    double r = std::numeric_limits<double>::infinity();
    for (int i = 0; i < p.count; ++i) r = std::min(r, p.normals[i].dot(p.vertices[i] - centroid));
    return r + p.radius;
}

double ShapeKind<Polygon>::extentAbout(const Polygon& p, const Vec2& center) {
    double r = 0.0;
    for (int i = 0; i < p.count; ++i) r = std::max(r, (p.vertices[i] - center).norm());
    return r + p.radius;
}

// Cauchy's formula: the mean width of a convex shape is its perimeter / pi (a rounded polygon's perimeter is its
// core's plus 2 pi radius).
double ShapeKind<Polygon>::meanWidth(const Polygon& p) {
    double perimeter = 0.0;
    for (int i = 0; i < p.count; ++i) perimeter += (p.vertices[(i + 1) % p.count] - p.vertices[i]).norm();
    return perimeter / M_PI + 2.0 * p.radius;
}

void ShapeKind<Polygon>::validate(const Polygon& p) {
    requireNonNegative("polygon radius", p.radius);
    if (p.count >= 3 && p.count <= Polygon::maxVertices && signedArea(p.vertices.data(), p.count) < 0.0)
        throw std::invalid_argument("physim: polygon vertices must be counter-clockwise, got clockwise "
                                    "(makePolygon accepts either winding)");
    checkConvexCounterClockwise(p.vertices.data(), p.count, "polygon");
    // The narrow phase trusts the normals: each must be its edge's outward unit normal. 1e-9 allows the
    // rounding of normalising a finite edge, nothing more.
    for (int i = 0; i < p.count; ++i) {
        const Vec2 edge = p.vertices[(i + 1) % p.count] - p.vertices[i];
        const Vec2 expected = Vec2(edge.y(), -edge.x()).normalized();
        if (!std::isfinite(p.normals[i].x()) || !std::isfinite(p.normals[i].y()) ||
            (p.normals[i] - expected).norm() > 1e-9)
            throw std::invalid_argument("physim: polygon normal " + std::to_string(i) +
                                        " must be the outward unit normal of edge " + std::to_string(i) + " (" +
                                        std::to_string(expected.x()) + ", " + std::to_string(expected.y()) +
                                        "), got (" + std::to_string(p.normals[i].x()) + ", " +
                                        std::to_string(p.normals[i].y()) + ")");
    }
}

std::vector<Vec2> ShapeKind<Polygon>::outline(const Polygon& p, const Transform& xf) {
    if (p.radius > 0.0) {
        // An arc at each corner from the previous edge's normal to the next one's, about 9 degrees a step.
        constexpr double kStep = 2.0 * M_PI / 40.0;
        std::vector<Vec2> points;
        for (int i = 0; i < p.count; ++i) {
            const Vec2& from = p.normals[(i + p.count - 1) % p.count];
            const Vec2& to = p.normals[i];
            const double start = std::atan2(from.y(), from.x());
            const double theta = std::atan2(cross(from, to), from.dot(to));
            const int steps = std::max(1, static_cast<int>(std::ceil(theta / kStep)));
            for (int k = 0; k <= steps; ++k) {
                const double angle = start + theta * k / steps;
                points.push_back(xf.apply(p.vertices[i] + p.radius * Vec2(std::cos(angle), std::sin(angle))));
            }
        }
        return points;
    }
    std::vector<Vec2> points(static_cast<std::size_t>(p.count));
    for (int i = 0; i < p.count; ++i) points[static_cast<std::size_t>(i)] = xf.apply(p.vertices[i]);
    return points;
}

Polygon ShapeKind<Polygon>::fromBatch(const ContinuousBatch::Shapes& s, std::size_t i) {
    const std::int32_t first = s.firstVertex[i];
    Polygon p;
    p.count = s.vertexCount[i];
    p.radius = s.radius[i];
    for (int k = 0; k < p.count; ++k) {
        p.vertices[k] = {s.vertexX[first + k], s.vertexY[first + k]};
        p.normals[k] = {s.normalX[first + k], s.normalY[first + k]};
    }
    return p;
}

// validate() allows normals 1e-9 off; the kernel's inside test may still refuse them.
std::string ShapeKind<Polygon>::kernelProblem(const Polygon& p) {
    ContinuousBatch one;
    one.addShape(p);
    return kernel::shapeHolds(viewOf(one), 0) ? "" : "a vertex lies on or outside another edge's line";
}

}  // namespace physim
