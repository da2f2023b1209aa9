// Distance between convex shapes and conservative-advancement time of impact (both in the shared kernel,
// ContinuousKernel.hpp), the paper's sampled method and swept boxes. docs/ccd.md explains the choices and measures them.

#include "physim/core/TimeOfImpact.hpp"

#include "KernelBridge.hpp"

#include "physim/core/Collide.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace physim {

void checkPrecision(double precision) {
    if (!(precision > 0.0 && precision <= 1.0)) {  // NaN fails both comparisons
        std::ostringstream os;
        os.precision(17);
        os << "physim: collision detection precision must be in (0, 1] (a fraction of the step), got "
           << precision;
        throw std::invalid_argument(os.str());
    }
}

double boundingRadius(const Geometry& g) {
    if (const auto* c = std::get_if<Circle>(&g)) return std::hypot(c->center.x(), c->center.y()) + c->radius;
    const auto& p = std::get<Polygon>(g);
    double r = 0.0;
    for (int i = 0; i < p.count; ++i) r = std::max(r, std::hypot(p.vertices[i].x(), p.vertices[i].y()));
    return r;
}

double coreRadius(const Geometry& g) {
    if (const auto* c = std::get_if<Circle>(&g)) return c->radius;
    const auto& p = std::get<Polygon>(g);
    const Vec2 centroid = computeMassProperties(g).centroid;
    double r = std::numeric_limits<double>::infinity();
    for (int i = 0; i < p.count; ++i) r = std::min(r, p.normals[i].dot(p.vertices[i] - centroid));
    return r;
}

namespace {

Vec2 toVec2(const kernel::Vec& v) { return {v.x, v.y}; }

}  // namespace

// Both are the shared kernel's (ContinuousKernel.hpp), so the World, the batch and the GPU agree.
DistanceOutput shapeDistance(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
    const kernel::Distance d = kernel::shapeDistance(toKernel(a), toKernel(xa), toKernel(b), toKernel(xb));
    return {d.distance, toVec2(d.normal), toVec2(d.pointA), toVec2(d.pointB)};
}

ToiResult timeOfImpact(const Geometry& a, const Sweep& sa, const Geometry& b, const Sweep& sb, double tolerance,
                       int maxIterations) {
    const kernel::Toi r =
        kernel::timeOfImpact(toKernel(a), toKernel(sa), toKernel(b), toKernel(sb), tolerance, maxIterations);
    return {static_cast<ToiState>(r.state), r.t, r.iterations};
}

ToiResult sampledTimeOfImpact(const Geometry& a, const Sweep& sa, const Geometry& b, const Sweep& sb,
                              double precision) {
    // Spacing at most `precision`; the 1e-12 keeps 1/0.1 from rounding up to 11 samples. Capped at a million
    // intervals so a tiny precision cannot overflow the count.
    const double wanted = std::ceil((1.0 - 1e-12) / precision);
    const int n = wanted < 1.0 ? 1 : wanted > 1e6 ? 1000000 : static_cast<int>(wanted);
    ToiResult r;
    for (int k = 0; k <= n; ++k) {
        const double t = k == n ? 1.0 : static_cast<double>(k) / n;
        r.iterations = k + 1;
        if (collide(a, sa.at(t), b, sb.at(t)).pointCount > 0) {
            r.state = k == 0 ? ToiState::Touching : ToiState::Hit;
            r.t = t;
            return r;
        }
    }
    return r;
}

Aabb sweptAabb(const Geometry& g, const Sweep& s) {
    if (s.a0 == s.a1) return Aabb::merged(computeAabb(g, s.at(0.0)), computeAabb(g, s.at(1.0)));
    const Aabb path{s.p0.cwiseMin(s.p1), s.p0.cwiseMax(s.p1)};
    return path.fattened(boundingRadius(g));
}

}  // namespace physim
