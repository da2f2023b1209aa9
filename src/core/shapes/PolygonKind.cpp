// The convex polygon's room: mass, radii, width, checks and outline (Polygon.cpp builds polygons).

#include "PolygonKind.hpp"

#include "PolygonCheck.hpp"

#include "../KernelBridge.hpp"

#include <limits>
#include <stdexcept>

namespace physim {

// Decompose into triangles fanned from the first vertex; sum their areas, centroids and second moments.
MassProperties ShapeKind<Polygon>::mass(const Polygon& p) {
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
    return r;
}

double ShapeKind<Polygon>::extentAbout(const Polygon& p, const Vec2& center) {
    double r = 0.0;
    for (int i = 0; i < p.count; ++i) r = std::max(r, (p.vertices[i] - center).norm());
    return r;
}

// Cauchy's formula: the mean width of a convex shape is its perimeter / pi.
double ShapeKind<Polygon>::meanWidth(const Polygon& p) {
    double perimeter = 0.0;
    for (int i = 0; i < p.count; ++i) perimeter += (p.vertices[(i + 1) % p.count] - p.vertices[i]).norm();
    return perimeter / M_PI;
}

void ShapeKind<Polygon>::validate(const Polygon& p) {
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
    std::vector<Vec2> points(static_cast<std::size_t>(p.count));
    for (int i = 0; i < p.count; ++i) points[static_cast<std::size_t>(i)] = xf.apply(p.vertices[i]);
    return points;
}

Polygon ShapeKind<Polygon>::fromBatch(const ContinuousBatch::Shapes& s, std::size_t i) {
    const std::int32_t first = s.firstVertex[i];
    Polygon p;
    p.count = s.vertexCount[i];
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
