// Distance between convex shapes and conservative-advancement time of impact (both in the shared kernel,
// ContinuousKernel.hpp), the paper's sampled method and swept boxes. docs/ccd.md explains the choices.

#include "physim/core/TimeOfImpact.hpp"

#include "KernelBridge.hpp"
#include "shapes/ShapeKinds.hpp"

#include "physim/core/Collide.hpp"

#include <cmath>
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
    return withKind(g, [](auto kind, const auto& s) { return kind.boundingRadius(s); });
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
