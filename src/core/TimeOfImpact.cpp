// Distance between convex shapes, conservative-advancement time of impact, the paper's sampled method and
// swept boxes. docs/ccd.md explains the choices and measures them.

#include "physim/core/TimeOfImpact.hpp"

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

Vec2 closestOnSegment(const Vec2& point, const Vec2& a, const Vec2& b) {
    const Vec2 e = b - a;
    const double ee = e.squaredNorm();  // > 0: valid polygons have no coincident vertices
    const double s = std::clamp((point - a).dot(e) / ee, 0.0, 1.0);
    return a + s * e;
}

// Fills normal and distance from two closest points; distance 0 (touching) leaves the output zero.
DistanceOutput fromPoints(const Vec2& pa, const Vec2& pb) {
    DistanceOutput out;
    const Vec2 d = pb - pa;
    const double length = std::hypot(d.x(), d.y());
    if (!(length > 0.0)) return out;
    out.distance = length;
    out.normal = d / length;
    out.pointA = pa;
    out.pointB = pb;
    return out;
}

DistanceOutput circleCircle(const Circle& a, const Transform& xa, const Circle& b, const Transform& xb) {
    const Vec2 ca = xa.apply(a.center);
    const Vec2 cb = xb.apply(b.center);
    const Vec2 d = cb - ca;
    const double centres = std::hypot(d.x(), d.y());
    DistanceOutput out;
    if (!(centres > a.radius + b.radius)) return out;
    out.normal = d / centres;
    out.distance = centres - a.radius - b.radius;
    out.pointA = ca + a.radius * out.normal;
    out.pointB = cb - b.radius * out.normal;
    return out;
}

// In the polygon's frame: the centre is inside when no face has it in front; otherwise the closest boundary
// point is the nearest of the edges' closest points.
DistanceOutput polygonCircle(const Polygon& a, const Transform& xa, const Circle& b, const Transform& xb) {
    const Vec2 c = xa.applyInverse(xb.apply(b.center));
    double bestSq = std::numeric_limits<double>::infinity();
    Vec2 surface = Vec2::Zero();
    bool outside = false;
    for (int i = 0; i < a.count; ++i) {
        if (a.normals[i].dot(c - a.vertices[i]) > 0.0) outside = true;
        const Vec2 q = closestOnSegment(c, a.vertices[i], a.vertices[(i + 1) % a.count]);
        const double sq = (c - q).squaredNorm();
        if (sq < bestSq) {
            bestSq = sq;
            surface = q;
        }
    }
    DistanceOutput out;
    if (!outside) return out;
    const double toCentre = std::sqrt(bestSq);
    if (!(toCentre > b.radius)) return out;
    const Vec2 n = (c - surface) / toCentre;
    out.distance = toCentre - b.radius;
    out.normal = xa.q.apply(n);
    out.pointA = xa.apply(surface);
    out.pointB = xa.apply(c - b.radius * n);
    return out;
}

// In a's frame. Disjoint convex polygons (some face separates them, the SAT test over both polygons' faces) have
// their closest points at a vertex of one against an edge of the other, so the minimum over all vertex-edge
// pairs (at most 2 * 8 * 8) is the exact distance.
DistanceOutput polygonPolygon(const Polygon& a, const Transform& xa, const Polygon& b, const Transform& xb) {
    const Rotation q{xa.q.c * xb.q.c + xa.q.s * xb.q.s, xa.q.c * xb.q.s - xa.q.s * xb.q.c};  // qa^-1 qb
    const Transform relative{xa.q.applyInverse(xb.p - xa.p), q};
    std::array<Vec2, Polygon::maxVertices> vb{};
    std::array<Vec2, Polygon::maxVertices> nb{};
    for (int i = 0; i < b.count; ++i) {
        vb[i] = relative.apply(b.vertices[i]);
        nb[i] = q.apply(b.normals[i]);
    }
    bool separated = false;
    for (int i = 0; i < a.count && !separated; ++i) {
        double s = std::numeric_limits<double>::infinity();
        for (int j = 0; j < b.count; ++j) s = std::min(s, a.normals[i].dot(vb[j] - a.vertices[i]));
        separated = s > 0.0;
    }
    for (int j = 0; j < b.count && !separated; ++j) {
        double s = std::numeric_limits<double>::infinity();
        for (int i = 0; i < a.count; ++i) s = std::min(s, nb[j].dot(a.vertices[i] - vb[j]));
        separated = s > 0.0;
    }
    if (!separated) return {};

    double bestSq = std::numeric_limits<double>::infinity();
    Vec2 pa = Vec2::Zero(), pb = Vec2::Zero();
    for (int j = 0; j < b.count; ++j)  // b's vertices against a's edges
        for (int i = 0; i < a.count; ++i) {
            const Vec2 on = closestOnSegment(vb[j], a.vertices[i], a.vertices[(i + 1) % a.count]);
            const double sq = (vb[j] - on).squaredNorm();
            if (sq < bestSq) bestSq = sq, pa = on, pb = vb[j];
        }
    for (int i = 0; i < a.count; ++i)  // a's vertices against b's edges
        for (int j = 0; j < b.count; ++j) {
            const Vec2 on = closestOnSegment(a.vertices[i], vb[j], vb[(j + 1) % b.count]);
            const double sq = (a.vertices[i] - on).squaredNorm();
            if (sq < bestSq) bestSq = sq, pa = a.vertices[i], pb = on;
        }
    return fromPoints(xa.apply(pa), xa.apply(pb));
}

DistanceOutput swapped(DistanceOutput d) {
    std::swap(d.pointA, d.pointB);
    d.normal = -d.normal;
    return d;
}

}  // namespace

DistanceOutput shapeDistance(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
    const auto* ca = std::get_if<Circle>(&a);
    const auto* cb = std::get_if<Circle>(&b);
    if (ca && cb) return circleCircle(*ca, xa, *cb, xb);
    if (cb) return polygonCircle(std::get<Polygon>(a), xa, *cb, xb);
    if (ca) return swapped(polygonCircle(std::get<Polygon>(b), xb, *ca, xa));
    return polygonPolygon(std::get<Polygon>(a), xa, std::get<Polygon>(b), xb);
}

ToiResult timeOfImpact(const Geometry& a, const Sweep& sa, const Geometry& b, const Sweep& sb, double tolerance,
                       int maxIterations) {
    const Vec2 relativeMotion = (sa.p1 - sa.p0) - (sb.p1 - sb.p0);  // m per unit t
    const double turning = std::abs(sa.a1 - sa.a0) * boundingRadius(a) + std::abs(sb.a1 - sb.a0) * boundingRadius(b);
    ToiResult r;
    double t = 0.0;
    for (r.iterations = 1; r.iterations <= maxIterations; ++r.iterations) {
        const DistanceOutput d = shapeDistance(a, sa.at(t), b, sb.at(t));
        if (d.distance < tolerance) {
            r.state = t == 0.0 ? ToiState::Touching : ToiState::Hit;
            r.t = t;
            return r;
        }
        // Gap along the fixed axis d.normal is a lower bound on the distance and shrinks at most this fast.
        const double closing = relativeMotion.dot(d.normal) + turning;
        if (!(closing > 0.0)) break;  // the gap along this axis never shrinks: no contact
        // Aim half a tolerance short of contact, so rounding cannot carry the pose into overlap and the loop
        // ends with a gap in [tolerance / 2, tolerance).
        t += (d.distance - 0.5 * tolerance) / closing;
        if (t >= 1.0) break;
    }
    if (r.iterations > maxIterations) {  // not converged: t is still a safe (early) contact time
        r.iterations = maxIterations;
        r.state = ToiState::Hit;
        r.t = t;
        return r;
    }
    r.state = ToiState::Separated;
    r.t = 1.0;
    return r;
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
