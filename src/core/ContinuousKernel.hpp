#pragma once
// The geometry of continuous collision detection, written once for the CPU and the GPU: shape distance and
// time of impact by conservative advancement as __host__ __device__ functions over plain structs. g++ compiles
// it into the core (through KernelBridge.hpp), nvcc into the CUDA kernel (cuda/ContinuousKernel.cu),
// so both run the same arithmetic in the same order. The CUDA layer is built with --fmad=false (no fused
// multiply-add the host does not do); the only remaining difference is the last bit of cos and sin, which
// docs/cuda.md measures.
//
// Rules for this file: no Eigen, no std:: types or algorithms, no exceptions, no allocation, no globals. Inputs are
// valid (ContinuousBatch validate() or the Geometry factories checked them). SI units: metres, radians; time is
// the fraction t in [0, 1] of the motion. Internal (not installed): users reach it through TimeOfImpact.hpp and
// ContinuousBatch.hpp.

#include <cmath>
#include <cstdint>

#if defined(__CUDACC__)
#define PHYSIM_HOST_DEVICE __host__ __device__
#else
#define PHYSIM_HOST_DEVICE
#endif

namespace physim::kernel {

struct Vec {
    double x;
    double y;
};

PHYSIM_HOST_DEVICE inline Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y}; }
PHYSIM_HOST_DEVICE inline Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y}; }
PHYSIM_HOST_DEVICE inline Vec operator-(Vec a) { return {-a.x, -a.y}; }
PHYSIM_HOST_DEVICE inline Vec operator*(double s, Vec a) { return {s * a.x, s * a.y}; }
PHYSIM_HOST_DEVICE inline double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y; }
PHYSIM_HOST_DEVICE inline double lengthSquared(Vec a) { return a.x * a.x + a.y * a.y; }
PHYSIM_HOST_DEVICE inline double minOf(double a, double b) { return b < a ? b : a; }
PHYSIM_HOST_DEVICE inline double maxOf(double a, double b) { return a < b ? b : a; }
PHYSIM_HOST_DEVICE inline double clamp01(double s) { return s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s); }

/// Rotation as cosine and sine (the core's Rotation without Eigen).
struct Rot {
    double c;
    double s;
    PHYSIM_HOST_DEVICE Vec apply(Vec v) const { return {c * v.x - s * v.y, s * v.x + c * v.y}; }
    PHYSIM_HOST_DEVICE Vec applyInverse(Vec v) const { return {c * v.x + s * v.y, -s * v.x + c * v.y}; }
};

PHYSIM_HOST_DEVICE inline Rot rotation(double angle) { return {::cos(angle), ::sin(angle)}; }

struct Xf {
    Vec p;
    Rot q;
    PHYSIM_HOST_DEVICE Vec apply(Vec local) const { return q.apply(local) + p; }
    PHYSIM_HOST_DEVICE Vec applyInverse(Vec world) const { return q.applyInverse(world - p); }
};

/// The shape kinds, each coded by its index in the core's Geometry (src/core/shapes/ShapeKinds.hpp checks it; the
/// kind's room there converts it to a Shape). A kind appears in this file only in: its layout in Shape (below), its
/// distance to every kind in shapeDistance (circleCircle, polygonCircle, polygonPolygon: every kind but the circle
/// is a polygon there), turningReach, and its checks in shapeHolds.
enum ShapeKind : std::int32_t { kCircle = 0, kPolygon = 1, kSegment = 2, kCapsule = 3, kChainSegment = 4 };
constexpr int kMaxVertices = 8;

/// One shape in its body's frame. Circle: vertices[0] is the centre, count 1, radius > 0. Polygon: 3 to 8
/// counter-clockwise vertices with outward unit normals (normals[i] for the edge i -> i + 1), radius >= 0 (> 0: a
/// rounded polygon, its core grown by radius). Segment, capsule, chain segment: count 2, the two points (centres),
/// normals[0] = (dy, -dx) / length for the edge 0 -> 1 and normals[1] = -normals[0] (the two edges of a 2-vertex
/// polygon); radius the capsule's (> 0), 0 for the others. So every kind but the circle is a rounded polygon of 2
/// to 8 vertices: its core (the vertices' hull, a segment for 2) grown by radius. A chain segment is two-sided here
/// (conservative: it never tunnels); the core's continuous stage skips it for a body that starts behind it.
/// boundingRadius: the farthest point of the shape from the body origin (m), which bounds how fast rotation moves
/// any of its points.
struct Shape {
    std::int32_t kind;
    std::int32_t count;
    double radius;
    double boundingRadius;
    Vec vertices[kMaxVertices];
    Vec normals[kMaxVertices];
};

/// A body's motion over the interval: position and angle move linearly from (p0, a0) to (p1, a1).
struct Motion {
    Vec p0;
    Vec p1;
    double a0;
    double a1;
    PHYSIM_HOST_DEVICE Xf at(double t) const { return {p0 + t * (p1 - p0), rotation(a0 + t * (a1 - a0))}; }
};

/// Closest points of two placed shapes; distance 0 (and the rest zero) when they touch or overlap.
struct Distance {
    double distance;
    Vec normal;  ///< unit, from a to b
    Vec pointA;  ///< world
    Vec pointB;  ///< world
};

PHYSIM_HOST_DEVICE inline Distance noDistance() { return {0.0, {0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}}; }

PHYSIM_HOST_DEVICE inline Vec closestOnSegment(Vec point, Vec a, Vec b) {
    const Vec e = b - a;  // |e| > 0: valid polygons have no coincident vertices
    return a + clamp01(dot(point - a, e) / lengthSquared(e)) * e;
}

PHYSIM_HOST_DEVICE inline Distance fromPoints(Vec pa, Vec pb) {
    const Vec d = pb - pa;
    const double length = ::sqrt(lengthSquared(d));
    if (!(length > 0.0)) return noDistance();
    return {length, (1.0 / length) * d, pa, pb};
}

PHYSIM_HOST_DEVICE inline Distance circleCircle(const Shape& a, const Xf& xa, const Shape& b, const Xf& xb) {
    const Vec ca = xa.apply(a.vertices[0]);
    const Vec cb = xb.apply(b.vertices[0]);
    const Vec d = cb - ca;
    const double centres = ::sqrt(lengthSquared(d));
    if (!(centres > a.radius + b.radius)) return noDistance();
    const Vec n = (1.0 / centres) * d;
    return {centres - a.radius - b.radius, n, ca + a.radius * n, cb - b.radius * n};
}

// Every kind but the circle is a polygon here: its core (2 to 8 vertices) grown by its radius.

// In the polygon's frame: a core of 3 or more vertices holds the centre when no face has it in front; otherwise the
// closest core point is the nearest of the edges' closest points. A 2-vertex core (a segment) is searched as its one
// edge and holds the centre only on it, where the distance is 0. Both radii then come off.
PHYSIM_HOST_DEVICE inline Distance polygonCircle(const Shape& a, const Xf& xa, const Shape& b, const Xf& xb) {
    const Vec c = xa.applyInverse(xb.apply(b.vertices[0]));
    const int edges = a.count == 2 ? 1 : a.count;
    double bestSq = INFINITY;
    Vec surface{0.0, 0.0};
    bool outside = a.count == 2;
    for (int i = 0; i < edges; ++i) {
        if (dot(a.normals[i], c - a.vertices[i]) > 0.0) outside = true;
        const Vec q = closestOnSegment(c, a.vertices[i], a.vertices[i + 1 == a.count ? 0 : i + 1]);
        const double sq = lengthSquared(c - q);
        if (sq < bestSq) {
            bestSq = sq;
            surface = q;
        }
    }
    if (!outside) return noDistance();
    const double toCentre = ::sqrt(bestSq), radii = a.radius + b.radius;  // radii = b.radius exactly for radius 0
    if (!(toCentre > radii)) return noDistance();
    const Vec n = (1.0 / toCentre) * (c - surface);
    const Vec onA = a.radius == 0.0 ? surface : surface + a.radius * n;
    return {toCentre - radii, xa.q.apply(n), xa.apply(onA), xa.apply(c - b.radius * n)};
}

// In a's frame, on the cores. Disjoint convex polygons (some face separates them: SAT over both polygons' faces)
// have their closest points at a vertex of one against an edge of the other, so the minimum over all vertex-edge
// pairs (at most 2 * 8 * 8) is the exact distance; both radii then come off. A vertex outside a convex polygon is
// nearest to an edge that faces it (its outward normal has the vertex in front, or on the line), so edges facing
// away are skipped. A 2-vertex core is a segment whose two edges (0 -> 1 and back) are one: it is searched once and
// no vertex is skipped against it. Two segments on one line are separated by neither's normal, only along their
// direction, which is tested too. b's vertices and normals are moved into a's frame where they are used rather
// than stored in local arrays: the same arithmetic, and nvcc 13.0 at -O3 computed wrong distances from such
// arrays (docs/cuda.md).
PHYSIM_HOST_DEVICE inline Distance polygonPolygon(const Shape& a, const Xf& xa, const Shape& b, const Xf& xb) {
    const Rot q{xa.q.c * xb.q.c + xa.q.s * xb.q.s, xa.q.c * xb.q.s - xa.q.s * xb.q.c};  // qa^-1 qb
    const Xf relative{xa.q.applyInverse(xb.p - xa.p), q};
    bool separated = false;
    for (int i = 0; i < a.count && !separated; ++i) {
        double s = INFINITY;
        for (int j = 0; j < b.count; ++j) s = minOf(s, dot(a.normals[i], relative.apply(b.vertices[j]) - a.vertices[i]));
        separated = s > 0.0;
    }
    for (int j = 0; j < b.count && !separated; ++j) {
        const Vec nb = q.apply(b.normals[j]);
        const Vec vb = relative.apply(b.vertices[j]);
        double s = INFINITY;
        for (int i = 0; i < a.count; ++i) s = minOf(s, dot(nb, a.vertices[i] - vb));
        separated = s > 0.0;
    }
    if (!separated && a.count == 2 && b.count == 2) {
        const Vec e = a.vertices[1] - a.vertices[0];  // a spans [e.v0, e.v1] along e
        const double h0 = dot(e, relative.apply(b.vertices[0])), h1 = dot(e, relative.apply(b.vertices[1]));
        separated = minOf(h0, h1) > dot(e, a.vertices[1]) || maxOf(h0, h1) < dot(e, a.vertices[0]);
    }
    if (!separated) return noDistance();

    const int edgesA = a.count == 2 ? 1 : a.count, edgesB = b.count == 2 ? 1 : b.count;
    double bestSq = INFINITY;
    Vec pa{0.0, 0.0}, pb{0.0, 0.0};
    for (int j = 0; j < b.count; ++j) {  // b's vertices against a's edges
        const Vec vb = relative.apply(b.vertices[j]);
        for (int i = 0; i < edgesA; ++i) {
            if (a.count > 2 && dot(a.normals[i], vb - a.vertices[i]) < 0.0) continue;
            const Vec on = closestOnSegment(vb, a.vertices[i], a.vertices[i + 1 == a.count ? 0 : i + 1]);
            const double sq = lengthSquared(vb - on);
            if (sq < bestSq) {
                bestSq = sq;
                pa = on;
                pb = vb;
            }
        }
    }
    for (int j = 0; j < edgesB; ++j) {  // a's vertices against b's edges
        const Vec from = relative.apply(b.vertices[j]);
        const Vec to = relative.apply(b.vertices[j + 1 == b.count ? 0 : j + 1]);
        const Vec nb = q.apply(b.normals[j]);
        for (int i = 0; i < a.count; ++i) {
            if (b.count > 2 && dot(nb, a.vertices[i] - from) < 0.0) continue;
            const Vec on = closestOnSegment(a.vertices[i], from, to);
            const double sq = lengthSquared(a.vertices[i] - on);
            if (sq < bestSq) {
                bestSq = sq;
                pa = a.vertices[i];
                pb = on;
            }
        }
    }
    if (a.radius == 0.0 && b.radius == 0.0) return fromPoints(xa.apply(pa), xa.apply(pb));
    const double cores = ::sqrt(bestSq), radii = a.radius + b.radius;
    if (!(cores > radii)) return noDistance();
    const Vec n = (1.0 / cores) * (pb - pa);
    return {cores - radii, xa.q.apply(n), xa.apply(pa + a.radius * n), xa.apply(pb - b.radius * n)};
}

/// Exact Euclidean distance between two placed convex shapes.
PHYSIM_HOST_DEVICE inline Distance shapeDistance(const Shape& a, const Xf& xa, const Shape& b, const Xf& xb) {
    if (a.kind == kCircle && b.kind == kCircle) return circleCircle(a, xa, b, xb);
    if (b.kind == kCircle) return polygonCircle(a, xa, b, xb);
    if (a.kind == kCircle) {
        Distance d = polygonCircle(b, xb, a, xa);
        const Vec swap = d.pointA;
        d.pointA = d.pointB;
        d.pointB = swap;
        d.normal = -d.normal;
        return d;
    }
    return polygonPolygon(a, xa, b, xb);
}

/// kInvalid: the pair's entries failed the batch's checks (pairHolds) and were not solved. kFailed: the advancement
/// ran out of iterations before it proved either a contact or its absence (never a hit).
enum ToiState : std::int32_t { kInvalid = -1, kSeparated = 0, kHit = 1, kTouching = 2, kFailed = 3 };

/// First contact of two moving shapes. At a hit, gap/normal/point describe the two shapes at time t: the gap
/// (m, in [0, tolerance)), the normal from a to b and the midpoint of the closest points; all zero when the
/// shapes already overlap (gap 0 gives no direction). Separated: t = 1. Failed: t is how far the shapes were proven
/// apart, gap/normal/point zero.
struct Toi {
    std::int32_t state;
    std::int32_t iterations;
    double t;
    double gap;
    Vec normal;
    Vec point;
};

PHYSIM_HOST_DEVICE inline Vec perp(Vec v) { return {-v.y, v.x}; }

/// How far the points that bound a shape's core (a polygon's vertices, a circle's centre, a capsule's centres) lie
/// from the body origin (m): what turning the body moves them by per radian. A radius about the core turns onto
/// itself and moves no boundary point outward, so it does not count (safeAdvance adds it to the extents). A sharp
/// polygon's core reaches its bounding radius.
PHYSIM_HOST_DEVICE inline double turningReach(const Shape& s) {
    if (s.kind == kCircle || (s.kind == kPolygon && s.radius == 0.0))
        return s.kind == kCircle ? ::sqrt(lengthSquared(s.vertices[0])) : s.boundingRadius;
    double reach = 0.0;
    for (int i = 0; i < s.count; ++i) reach = maxOf(reach, ::sqrt(lengthSquared(s.vertices[i])));
    return reach;
}

/// Smallest s > 0 where e + b s - k s^2 / 2 falls to 0, for e > 0 and any k (k < 0 curves up); INFINITY when it
/// never does; 0 when e <= 0. Each branch is the cancellation-free form of the smaller root.
PHYSIM_HOST_DEVICE inline double firstRoot(double e, double b, double k) {
    if (!(e > 0.0)) return 0.0;
    const double disc = b * b + 2.0 * k * e;
    if (k > 0.0) return b < 0.0 ? 2.0 * e / (-b + ::sqrt(disc)) : (b + ::sqrt(disc)) / k;
    if (b < 0.0 && disc >= 0.0) return 2.0 * e / (-b + ::sqrt(disc));
    return INFINITY;
}

/// A safe advance for one gap g along a separating line: how long g - target stays positive, from its value
/// e = g - target > 0, slope b and curvature c now (per unit t), and bounds k on |g''| and j on |g'''| over the
/// interval. Everywhere g - target >= e + b s - k s^2 / 2, whose first root s0 is safe; up to S, g'' >= c - j S, so
/// g - target >= e + b s + (c - j S) s^2 / 2 there, which is tighter when the gap curves less than k allows (a
/// corner gliding along a face). Tried with S = 2 s0.
PHYSIM_HOST_DEVICE inline double gapAdvance(double e, double b, double c, double k, double j) {
    const double safe = firstRoot(e, b, k);
    const double reach = 2.0 * safe;
    if (!(reach < INFINITY)) return safe;
    return maxOf(safe, minOf(reach, firstRoot(e, b, j * reach - c)));
}

/// min(current, gapAdvance(...)), without its square roots when the bound of the second derivative alone already
/// keeps the gap above target until `current`.
PHYSIM_HOST_DEVICE inline double shorterAdvance(double current, double e, double b, double c, double k, double j) {
    if (current < INFINITY && e + (b - 0.5 * k * current) * current >= 0.0) return current;
    return minOf(current, gapAdvance(e, b, c, k, j));
}

/// What the advancement's bounds need of a pair's motion; the same at every step.
struct PairRates {
    Vec velocityA, velocityB;  ///< m per unit t
    double spinA, spinB;       ///< rad per unit t
    double reachA, reachB;     ///< m, turningReach
    double speed;              ///< m per unit t, |velocityB - velocityA|
    double apart;              ///< m, the origins' largest distance over the motion (at t = 0 or 1: they move on lines)
};

PHYSIM_HOST_DEVICE inline PairRates pairRates(const Shape& a, const Motion& ma, const Shape& b, const Motion& mb) {
    const Vec va = ma.p1 - ma.p0, vb = mb.p1 - mb.p0;
    return {va,
            vb,
            ma.a1 - ma.a0,
            mb.a1 - mb.a0,
            turningReach(a),
            turningReach(b),
            ::sqrt(lengthSquared(vb - va)),
            maxOf(::sqrt(lengthSquared(mb.p0 - ma.p0)), ::sqrt(lengthSquared(mb.p1 - ma.p1)))};
}

/// Velocity (m per unit t) of the material point at world point p of a body whose origin is at `origin`.
PHYSIM_HOST_DEVICE inline Vec pointVelocity(Vec velocity, double spin, Vec origin, Vec p) {
    return velocity + spin * perp(p - origin);
}

/// How long (in t) the shapes certainly stay more than `target` apart, given that at the current time they are
/// d.distance > target apart along the closest-point normal n; any advance of at least `remaining` (the rest of
/// the motion) is as good as another. Every bound follows a separating line carried along with the motion: the gap
/// across such a line never exceeds the distance, so while it stays above target nothing touches.
///   - First order (classic conservative advancement; best for long advances): the line fixed in the world, where
///     no point closes the gap faster than (motion_a - motion_b) . n + |turn_a| R_a + |turn_b| R_b per unit t.
///   - Second order, when something turns: the line turning with a (a's extent along it then fixed; best for a
///     face of a against b), and turning with b. The gap is then a minimum over the other shape's bounding points
///     of smooth functions of time, each advanced by gapAdvance.
/// Derivative bounds (w: turn per unit t, V = motion_b - motion_a, D = c_b - c_a between the origins, whose length
/// is largest at an end of the interval as they move on lines, r: a point's offset from its origin). Seen from a,
/// a point of b is at Rot(-w_a t) D(t) + Rot((w_b - w_a) t) r (up to constant rotations), so
///   g'' = n . (-w_a^2 D - 2 w_a perp(V) - (w_b - w_a)^2 r),   |g''| <= 2 |w_a| |V| + w_a^2 |D| + (w_b - w_a)^2 |r|,
///   |g'''| <= |w_a|^3 |D| + 3 w_a^2 |V| + |w_b - w_a|^3 |r|.
PHYSIM_HOST_DEVICE inline double safeAdvance(const Shape& a, const Xf& xa, const Shape& b, const Xf& xb,
                                             const PairRates& m, const Distance& d, double target, double remaining) {
    const Vec n = d.normal;
    const Vec v = m.velocityB - m.velocityA;
    const double wa = m.spinA, wb = m.spinB;

    const double closing = -dot(v, n) + ::fabs(wa) * m.reachA + ::fabs(wb) * m.reachB;
    double best = closing > 0.0 ? (d.distance - target) / closing : INFINITY;
    // Without turning, both second-order bounds are this one.
    if (best >= remaining || (wa == 0.0 && wb == 0.0)) return best;
    const double dw = wb - wa, wa2 = wa * wa, wb2 = wb * wb, dw2 = dw * dw;

    // Each shape's extent along n from its origin now: a's on its side towards b, b's on its side towards a.
    double extentA = -INFINITY;
    for (int i = 0; i < a.count; ++i) extentA = maxOf(extentA, dot(n, xa.q.apply(a.vertices[i])));
    extentA += a.radius;
    double extentB = INFINITY;
    for (int j = 0; j < b.count; ++j) extentB = minOf(extentB, dot(n, xb.q.apply(b.vertices[j])));
    extentB -= b.radius;

    // The line fixed in the world again, with no spin term: however a shape turns, its extent along the line stays
    // within its turning reach (plus radius) of its origin, and exactly as now if it does not turn. Far from
    // contact this advances further than the first-order bound, whose spin term counts against every step.
    const double boundA = wa == 0.0 ? extentA : m.reachA + a.radius;
    const double boundB = wb == 0.0 ? -extentB : m.reachB + b.radius;
    const double lineGap = dot(n, xb.p - xa.p) - boundA - boundB - target;
    if (lineGap > 0.0) best = maxOf(best, -dot(v, n) > 0.0 ? lineGap / -dot(v, n) : INFINITY);
    if (best >= remaining) return best;

    // Turning with a: each bounding point of b against a's extent along n (measured from a's origin).
    const double kA = 2.0 * ::fabs(wa) * m.speed + wa2 * m.apart + dw2 * m.reachB;
    const double jA = ::fabs(wa) * wa2 * m.apart + 3.0 * wa2 * m.speed + ::fabs(dw) * dw2 * m.reachB;
    const double cA = dot(n, -wa2 * (xb.p - xa.p) - (2.0 * wa) * perp(v));
    double frame = INFINITY;
    for (int j = 0; j < b.count && frame > best; ++j) {
        const Vec q = xb.apply(b.vertices[j]);
        const double e = dot(n, q - xa.p) - b.radius - extentA - target;
        const double c = cA - dw2 * dot(n, q - xb.p);
        const Vec relative = pointVelocity(m.velocityB, wb, xb.p, q) - pointVelocity(m.velocityA, wa, xa.p, q);
        frame = shorterAdvance(frame, e, dot(n, relative), c, kA, jA);
    }
    best = maxOf(best, frame);
    if (best >= remaining) return best;

    // Turning with b: each bounding point of a against b's extent along n; the gap is that extent minus the
    // point's height, so the roles swap and the signs of its derivatives flip.
    const double kB = 2.0 * ::fabs(wb) * m.speed + wb2 * m.apart + dw2 * m.reachA;
    const double jB = ::fabs(wb) * wb2 * m.apart + 3.0 * wb2 * m.speed + ::fabs(dw) * dw2 * m.reachA;
    const double cB = dot(n, -wb2 * (xb.p - xa.p) - (2.0 * wb) * perp(v));
    frame = INFINITY;
    for (int i = 0; i < a.count && frame > best; ++i) {
        const Vec p = xa.apply(a.vertices[i]);
        const double e = extentB - dot(n, p - xb.p) - a.radius - target;
        const double c = cB + dw2 * dot(n, p - xa.p);
        const Vec relative = pointVelocity(m.velocityB, wb, xb.p, p) - pointVelocity(m.velocityA, wa, xa.p, p);
        frame = shorterAdvance(frame, e, dot(n, relative), c, kB, jB);
    }
    return maxOf(best, frame);
}

/// Closest the origins come (m) when their separation moves linearly from d0 (t = 0) by v over t in [0, 1].
PHYSIM_HOST_DEVICE inline double closestApproach(Vec d0, Vec v) {
    const double vv = lengthSquared(v);
    const double t = vv > 0.0 ? minOf(1.0, maxOf(0.0, -dot(d0, v) / vv)) : 0.0;
    return ::sqrt(lengthSquared(d0 + t * v));
}

/// Whether two bodies stay at least `gap` (m) apart over their motions whatever they turn, from bounding radii
/// alone (m, about each origin): every point of a shape stays within its radius of its origin, and the origins,
/// moving on straight lines, never come within both radii plus the gap. No distance evaluation.
PHYSIM_HOST_DEVICE inline bool boundsStayApart(const Motion& ma, double radiusA, const Motion& mb, double radiusB,
                                               double gap) {
    return closestApproach(mb.p0 - ma.p0, (mb.p1 - mb.p0) - (ma.p1 - ma.p0)) > radiusA + radiusB + gap;
}

/// Time of impact by conservative advancement. First, without any distance evaluation (iterations 0): every point
/// of a shape stays within its bounding radius of its origin, so origins that never come within the two radii
/// plus the tolerance prove the pair Separated whatever the turning (most pairs of a crowd whose swept boxes
/// meet pass each other far apart in time). Then from t = 0, evaluate the distance; below the tolerance (m, > 0) it
/// is the contact (Touching at t = 0, else Hit); otherwise advance t by safeAdvance, aiming at half the tolerance so
/// that rounding cannot carry the pose into overlap (the last advance ends with a gap in [tolerance / 2,
/// tolerance) when the bounds are tight). Separated when the advance reaches t = 1. The shapes are never closer
/// than tolerance / 2 at any time before the t returned. Failed after maxIterations distance evaluations without
/// either: t is then how far the shapes were proven apart.
PHYSIM_HOST_DEVICE inline Toi timeOfImpact(const Shape& a, const Motion& ma, const Shape& b, const Motion& mb,
                                           double tolerance, int maxIterations) {
    Toi r{kSeparated, 0, 1.0, 0.0, {0.0, 0.0}, {0.0, 0.0}};
    const double target = 0.5 * tolerance;
    if (boundsStayApart(ma, a.boundingRadius, mb, b.boundingRadius, tolerance)) return r;
    const PairRates rates = pairRates(a, ma, b, mb);
    double t = 0.0;
    for (r.iterations = 1; r.iterations <= maxIterations; ++r.iterations) {
        const Xf xa = ma.at(t), xb = mb.at(t);
        const Distance d = shapeDistance(a, xa, b, xb);
        if (d.distance < tolerance) {
            r.state = t == 0.0 ? kTouching : kHit;
            r.t = t;
            r.gap = d.distance;
            r.normal = d.normal;
            r.point = 0.5 * (d.pointA + d.pointB);
            return r;
        }
        const double step = safeAdvance(a, xa, b, xb, rates, d, target, 1.0 - t);
        if (step >= 1.0 - t) return r;  // apart until the end
        if (!(step >= 0.0)) break;      // NaN: only from input so large that the bounds overflow; nothing proven
        t += step;
    }
    if (r.iterations > maxIterations) r.iterations = maxIterations;
    r.state = kFailed;
    r.t = t;
    return r;
}

/// Raw views of a ContinuousBatch's arrays (structure of arrays; see ContinuousBatch.hpp), host or device memory.
struct BatchView {
    // shapes
    const std::int32_t* kind;
    const std::int32_t* firstVertex;
    const std::int32_t* vertexCount;
    const double* radius;
    const double* boundingRadius;
    const double* vertexX;
    const double* vertexY;
    const double* normalX;
    const double* normalY;
    // bodies
    const std::int32_t* shape;
    const double* x0;
    const double* y0;
    const double* angle0;
    const double* x1;
    const double* y1;
    const double* angle1;
    // pairs
    const std::int32_t* pairA;
    const std::int32_t* pairB;
    std::int32_t pairCount;
    double tolerance;
    std::int32_t maxIterations;
    // entries in the shape, vertex and body arrays (each group's arrays have one size: checked on the host)
    std::int32_t shapeCount;
    std::int32_t vertexTotal;
    std::int32_t bodyCount;
};

/// Raw views of a ContinuousBatchResult's arrays, one entry per pair.
struct ResultView {
    std::int32_t* state;
    std::int32_t* iterations;
    double* t;
    double* gap;
    double* normalX;
    double* normalY;
    double* pointX;
    double* pointY;
};

PHYSIM_HOST_DEVICE inline Shape loadShape(const BatchView& v, std::int32_t s) {
    Shape shape;
    shape.kind = v.kind[s];
    shape.count = v.vertexCount[s];
    shape.radius = v.radius[s];
    shape.boundingRadius = v.boundingRadius[s];
    const std::int32_t first = v.firstVertex[s];
    for (int k = 0; k < shape.count; ++k) {
        shape.vertices[k] = {v.vertexX[first + k], v.vertexY[first + k]};
        shape.normals[k] = {v.normalX[first + k], v.normalY[first + k]};
    }
    return shape;
}

PHYSIM_HOST_DEVICE inline Motion loadMotion(const BatchView& v, std::int32_t body) {
    return {{v.x0[body], v.y0[body]}, {v.x1[body], v.y1[body]}, v.angle0[body], v.angle1[body]};
}

// --- The batch's checks, run for every pair where it is solved (so they cost a GPU batch no host time). Their
// failure is reported, not solved: ContinuousBatch.cpp's validate() then names the bad entry.

/// False for infinities and NaN (x - x is NaN for both).
PHYSIM_HOST_DEVICE inline bool finite(double x) { return x - x == 0.0; }

/// Each normal is its edge's outward unit normal (unit to 2e-9, square to the edge to 1e-9 rad, the bounds
/// validate(Geometry) allows) and every other vertex lies strictly inside every edge's line. Together these hold
/// exactly for strictly convex, counter-clockwise, simple polygons (a star, or a repeated, coincident or collinear
/// vertex, breaks the second). O(count^2) multiplications, no square roots or divisions. For 2 vertices (a segment:
/// edges 0 -> 1 and back) it asks two distinct finite points with normals[1] = -normals[0] square to them.
PHYSIM_HOST_DEVICE inline bool polygonHolds(const BatchView& v, std::int32_t first, std::int32_t count) {
    for (std::int32_t i = 0; i < count; ++i) {
        const std::int32_t a = first + i, next = i + 1 == count ? 0 : i + 1, b = first + next;
        const double ex = v.vertexX[b] - v.vertexX[a], ey = v.vertexY[b] - v.vertexY[a];
        const double nx = v.normalX[a], ny = v.normalY[a];
        const double lengthSq = ex * ex + ey * ey, unit = nx * nx + ny * ny - 1.0, along = nx * ex + ny * ey;
        if (!(lengthSq > 0.0 && finite(lengthSq))) return false;
        if (!(unit <= 4e-9 && unit >= -4e-9 && along * along <= 1e-18 * lengthSq && nx * ey - ny * ex > 0.0))
            return false;  // false for NaN too
        for (std::int32_t k = 0; k < count; ++k) {
            if (k == i || k == next) continue;
            const double inside = nx * (v.vertexX[first + k] - v.vertexX[a]) + ny * (v.vertexY[first + k] - v.vertexY[a]);
            if (!(inside < 0.0)) return false;
        }
    }
    return true;
}

/// boundingRadius[s] reaches every point of shape s (to 1e-12 relative: the host computes it with hypot).
PHYSIM_HOST_DEVICE inline bool radiusBounds(const BatchView& v, std::int32_t s) {
    const double reach = v.boundingRadius[s] - v.radius[s];  // what the vertices (a circle's centre) may reach
    if (!(reach >= 0.0 && finite(reach))) return false;
    const std::int32_t first = v.firstVertex[s];
    for (std::int32_t k = 0; k < v.vertexCount[s]; ++k) {
        const double x = v.vertexX[first + k], y = v.vertexY[first + k];
        if (!(x * x + y * y <= reach * reach * (1.0 + 4e-12))) return false;
    }
    return true;
}

/// Shape s is one the kernel can read and trust: a known kind, a vertex range inside the arrays, the geometry of
/// its kind, and a bounding radius that bounds it. Vertex counts: circle 1, polygon 3 to 8, the others 2. Radius:
/// circle and capsule > 0, polygon >= 0, segment and chain segment 0.
PHYSIM_HOST_DEVICE inline bool shapeHolds(const BatchView& v, std::int32_t s) {
    if (s < 0 || s >= v.shapeCount) return false;
    const std::int32_t kind = v.kind[s], first = v.firstVertex[s], count = v.vertexCount[s];
    if (kind < kCircle || kind > kChainSegment) return false;
    const bool circle = kind == kCircle, polygon = kind == kPolygon;
    if (count < (circle ? 1 : polygon ? 3 : 2) || count > (circle ? 1 : polygon ? kMaxVertices : 2)) return false;
    if (first < 0 || first > v.vertexTotal - count) return false;
    const double r = v.radius[s];
    const bool radius = circle || kind == kCapsule ? r > 0.0 && finite(r) : polygon ? r >= 0.0 && finite(r) : r == 0.0;
    const bool geometry = circle ? finite(v.vertexX[first]) && finite(v.vertexY[first]) : polygonHolds(v, first, count);
    return radius && geometry && radiusBounds(v, s);
}

PHYSIM_HOST_DEVICE inline bool bodyHolds(const BatchView& v, std::int32_t body) {
    return body >= 0 && body < v.bodyCount && shapeHolds(v, v.shape[body]) && finite(v.x0[body]) &&
           finite(v.y0[body]) && finite(v.angle0[body]) && finite(v.x1[body]) && finite(v.y1[body]) &&
           finite(v.angle1[body]);
}

PHYSIM_HOST_DEVICE inline bool pairHolds(const BatchView& v, std::int32_t i) {
    return v.pairA[i] != v.pairB[i] && bodyHolds(v, v.pairA[i]) && bodyHolds(v, v.pairB[i]);
}

/// Pair i of the batch: the unit of work of one CPU loop iteration or one GPU thread. A pair that fails its checks
/// gets state kInvalid and is not solved.
PHYSIM_HOST_DEVICE inline void solvePair(const BatchView& v, const ResultView& out, std::int32_t i) {
    if (!pairHolds(v, i)) {
        out.state[i] = kInvalid;
        out.iterations[i] = 0;
        out.t[i] = out.gap[i] = out.normalX[i] = out.normalY[i] = out.pointX[i] = out.pointY[i] = 0.0;
        return;
    }
    const std::int32_t a = v.pairA[i], b = v.pairB[i];
    const Shape sa = loadShape(v, v.shape[a]);
    const Shape sb = loadShape(v, v.shape[b]);
    const Toi r = timeOfImpact(sa, loadMotion(v, a), sb, loadMotion(v, b), v.tolerance, v.maxIterations);
    out.state[i] = r.state;
    out.iterations[i] = r.iterations;
    out.t[i] = r.t;
    out.gap[i] = r.gap;
    out.normalX[i] = r.normal.x;
    out.normalY[i] = r.normal.y;
    out.pointX[i] = r.point.x;
    out.pointY[i] = r.point.y;
}

}  // namespace physim::kernel
