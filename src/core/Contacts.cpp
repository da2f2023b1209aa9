// Persistent contacts: created from the broad phase's new pairs of shapes, updated once per step by the narrow
// phase, destroyed when their shapes' enlarged boxes part (or the pair is deferred: see `deferred`).

#include "Contacts.hpp"
#include "BodyLanes.hpp"
#include "ContinuousKernel.hpp"
#include "KernelBridge.hpp"
#include "Manifolds.hpp"
#include "Prefetch.hpp"
#include "Slots.hpp"
#include "WorldImpl.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace physim {
namespace {

// At least one body must be able to respond; two immovable bodies never make a contact.
bool shouldCollide(const BodyData& a, const BodyData& b) {
    return a.type == BodyType::Dynamic || b.type == BodyType::Dynamic;
}

// Whether a pair with a continuous body needs speculative points this step. Each shape stays inside the circle
// of its extent about its centre of mass however it turns, so centres that never come within both extents plus
// `gap` (m) at the present velocities keep the shapes apart, and a speculative point along a fixed normal would
// only stop bodies that pass each other. A continuous body's enlarged box covers its whole sweep, so in a crowd
// most pairs are such. Should a velocity change in the step make them meet after all, the Continuous stage
// stops the continuous body at the impact. Discrete pairs keep their points: nothing else would catch them.
[[gnu::always_inline]] inline bool bothDiscrete(const BodyData& A, const BodyData& B) {
    return A.detection == CollisionDetection::Discrete && B.detection == CollisionDetection::Discrete;
}
[[gnu::always_inline]] inline bool needsPoints(const BodyData& A, const BodyData& B, double gap, double dt) {
    if (bothDiscrete(A, B)) return true;
    // The centre's straight path over the step (the turn does not matter to a circle about the centre).
    auto path = [dt](const BodyData& b) {
        const Vec2 end = b.center + b.v * dt;
        return kernel::Motion{{b.center.x(), b.center.y()}, {end.x(), end.y()}, b.angle, b.angle};
    };
    return !kernel::boundsStayApart(path(A), A.extent, path(B), B.extent, gap);
}

// A shape in the kernel's terms about its body's centre of mass, about which the body turns: over a step at the
// present velocities the centre moves on a straight line, as a kernel Motion's origin does.
kernel::Shape aboutCenter(const Geometry& g, const Vec2& localCenter) {
    kernel::Shape s = toKernel(g);
    if (localCenter.isZero()) return s;
    double reach = 0.0;
    for (int i = 0; i < s.count; ++i) {
        s.vertices[i] = s.vertices[i] - kernel::Vec{localCenter.x(), localCenter.y()};
        reach = std::max(reach, std::sqrt(kernel::lengthSquared(s.vertices[i])));
    }
    s.boundingRadius = reach + s.radius;
    return s;
}

// Whether a pair may be asked turnsPastItsPoints: an exact continuous body (the Continuous stage sweeps dynamic
// bodies only) and something turning.
[[gnu::always_inline]] inline bool exactAndTurning(const BodyData& A, const BodyData& B) {
    auto exact = [](const BodyData& b) {
        return b.detection == CollisionDetection::ContinuousExact && b.type == BodyType::Dynamic;
    };
    return (exact(A) || exact(B)) && (A.w != 0.0 || B.w != 0.0);
}

// A body's centre of mass over the step at its present velocities: a straight line, and the body's turn about it.
kernel::Motion stepAhead(const BodyData& b, double dt) {
    const Vec2 end = b.center + b.v * dt;
    return {{b.center.x(), b.center.y()}, {end.x(), end.y()}, b.angle, b.angle + b.w * dt};
}

// Whether the speculative points of a turning pair with an exact continuous body are phantoms: the shapes, moved
// over the step at the present velocities with their true turn, stay apart (the bodies' extents, or conservative
// advancement, prove the gap stays above kToiTolerance / 2). A point's row predicts the approach along a normal
// fixed at the step's start with its anchors' linear speed, so a corner sweeping past a ball on an arc is taken to
// go through it and throws it. Should a velocity change in the step bring them together after all, the Continuous
// stage stops the continuous body at the impact. Kept as they are: points at most kToiTolerance apart (touching),
// points the centres' approach alone closes within the step (the linear prediction is a translation's, and right),
// and pairs that do not turn their outlines (a spinning circle's outline turns onto itself).
// Out of line: the narrow phase asks it only of the pairs exactAndTurning lets through.
[[gnu::noinline]] bool turnsPastItsPoints(const Manifold& m, const Geometry& shapeA, const BodyData& A,
                                          const Geometry& shapeB, const BodyData& B, double dt) {
    const double approach = -m.normal.dot(B.v - A.v) * dt;  // m the centres close along the normal in the step
    for (int p = 0; p < m.pointCount; ++p)
        if (!(m.points[p].separation > std::max(kToiTolerance, approach))) return false;
    const kernel::Motion ma = stepAhead(A, dt), mb = stepAhead(B, dt);
    if (kernel::boundsStayApart(ma, A.extent, mb, B.extent, kToiTolerance)) return true;
    const kernel::Shape a = aboutCenter(shapeA, A.localCenter), b = aboutCenter(shapeB, B.localCenter);
    if (A.w * kernel::turningReach(a) == 0.0 && B.w * kernel::turningReach(b) == 0.0) return false;
    return kernel::timeOfImpact(a, ma, b, mb, kToiTolerance, 100).state == kernel::kSeparated;
}

[[gnu::always_inline]] inline bool moving(const BodyData& b) {
    return b.awake() && (b.v.squaredNorm() > 0.0 || b.w != 0.0);
}

// A pair that needs no points while one of its bodies moves has no contact record: the broad phase offers it
// again next step (BroadPhase::requery), so it gets one the step it may meet. In a crowd of bullets, whose
// enlarged boxes overlap nearly all others, this keeps the contacts to the pairs that can touch. A pair at rest
// keeps its (empty) record instead of being asked every step.
[[gnu::always_inline]] inline bool deferred(const BodyData& A, const BodyData& B, double gap, double dt) {
    return !bothDiscrete(A, B) && (moving(A) || moving(B)) && !needsPoints(A, B, gap, dt);
}

void keep(ManifoldCache& k, const Manifold& m, const BodyData& A, const BodyData& B, double margin,
          const StaysEmpty& empty, double rounding) {
    k.margin = margin;
    k.quiet = m.pointCount == 0 ? empty.distance : 0.0;
    k.quietAtAnyMargin = empty.anyMargin;
    k.quietArm = 0.0f;
    if (k.quiet > 0.0) {
        const double arm = (empty.about - B.localCenter).norm();
        k.quietArm = static_cast<float>(arm);
        if (k.quietArm < arm) k.quietArm = std::nextafter(k.quietArm, std::numeric_limits<float>::infinity());
    }
    k.offset = A.xf.q.applyInverse(B.center - A.center);
    k.angle = B.angle - A.angle;
    k.normal = A.xf.q.applyInverse(m.normal);
    k.pointCount = m.pointCount;
    for (int p = 0; p < m.pointCount; ++p) {
        const ContactPoint& cp = m.points[p];
        const Vec2 half = 0.5 * cp.separation * m.normal;  // the point is midway between the two surfaces
        k.points[p].onA = A.xf.q.applyInverse(cp.point - half - A.center);
        k.points[p].onB = B.xf.q.applyInverse(cp.point + half - B.center);
        k.points[p].id = cp.id;
        k.points[p].rounding = static_cast<float>(rounding);
    }
    if (m.pointCount == 0) k.points[0].rounding = 0.0f;  // an empty answer has no point to slip
}

// The narrow phase's formulas on one pair (T = double) or on four (T = Wide, Wide.hpp), with the same operations
// in the same order, so that a lane's bits are the scalar's. V: the build has vector instructions (the AVX2 one).
template <class T>
struct PairSide {
    T cx, cy;   // centre of mass, m
    T vx, vy;   // m/s
    T w;        // rad/s
    T extent;   // m
    T turnReach;  // m (BodyData::turnReach)
    T qc, qs;   // rotation
    T angle;    // rad
};

[[gnu::always_inline]] inline PairSide<double> sideOf(const BodyData& b) {
    return {b.center.x(), b.center.y(), b.v.x(), b.v.y(), b.w, b.extent, b.turnReach, b.xf.q.c, b.xf.q.s, b.angle};
}

template <bool V>
[[gnu::always_inline]] inline double squareRoot(double x) {
    return std::sqrt(x);
}
template <bool V>
[[gnu::always_inline]] inline Wide squareRoot(Wide x) {
    return sqrtLanes<V>(x);
}
[[gnu::always_inline]] inline double magnitude(double x) { return std::abs(x); }
[[gnu::always_inline]] inline Wide magnitude(Wide x) { return abs(x); }
[[gnu::always_inline]] inline double larger(double a, double b) { return std::max(a, b); }
[[gnu::always_inline]] inline Wide larger(Wide a, Wide b) { return max(a, b); }
[[gnu::always_inline]] inline bool isNot(bool x) { return !x; }
[[gnu::always_inline]] inline WideMask isNot(WideMask x) { return ~x; }

// How far (m) the pair can close in a step at its present velocities, plus what gravity or forces add: the
// manifold keeps speculative points up to this far apart so the solver can stop the bodies at contact. A turn
// closes no more than its outline moves: a wheel spinning about its centre closes nothing by spinning.
template <bool V, class T>
[[gnu::always_inline]] inline T reach(const PairSide<T>& A, const PairSide<T>& B, double dt) {
    const T turn = magnitude(A.w) * A.turnReach + magnitude(B.w) * B.turnReach;
    const T dx = B.vx - A.vx, dy = B.vy - A.vy;
    return (squareRoot<V>(dx * dx + dy * dy) + turn) * dt;
}

// How B has moved in A's frame since the cache was made (its offset and angle): its centre's shift (m) and its
// turn (rad). A point of B at distance r from its centre has moved at most shift + turn r.
template <class T>
struct MovedSinceCache {
    T shift, turn;
    T reachingOut(const T& r) const { return shift + turn * r; }
};

// How far (m) a cached point on a round surface may have slipped back along it (the turn times the rounding) for
// the cache to hold: a rolling body's contact stays under its centre, and a point left behind gives the load a
// lever that drives the roll (a ball nudged on flat ground sped up to about 1 cm/s while the cache held).
constexpr double rollToleranceFor(double tolerance) { return 1e-3 * tolerance; }

template <bool V, class T>
[[gnu::always_inline]] inline MovedSinceCache<T> movedSinceCache(const T& offsetX, const T& offsetY, const T& angle,
                                                                 const PairSide<T>& A, const PairSide<T>& B) {
    const T dx = B.cx - A.cx, dy = B.cy - A.cy;
    const T x = A.qc * dx + A.qs * dy - offsetX, y = -A.qs * dx + A.qc * dy - offsetY;
    return {squareRoot<V>(x * x + y * y), magnitude(B.angle - A.angle - angle)};
}

// A cached point at the present poses: each surface point moves with its body, the contact point is midway, the
// separation is their distance along the normal (n, already turned with A).
template <class T>
[[gnu::always_inline]] inline void placePoint(const PairSide<T>& A, const PairSide<T>& B, const T& nx, const T& ny,
                                              const T& onAx, const T& onAy, const T& onBx, const T& onBy, T& px,
                                              T& py, T& separation) {
    const T ax = A.cx + (A.qc * onAx - A.qs * onAy), ay = A.cy + (A.qs * onAx + A.qc * onAy);
    const T bx = B.cx + (B.qc * onBx - B.qs * onBy), by = B.cy + (B.qs * onBx + B.qc * onBy);
    px = 0.5 * (ax + bx);
    py = 0.5 * (ay + by);
    separation = nx * (bx - ax) + ny * (by - ay);
}

// Whether a point is kept: a speculative one only if the pair approaches there fast enough to close it this step.
template <class T>
[[gnu::always_inline]] inline auto keepsPoint(const PairSide<T>& A, const PairSide<T>& B, const T& nx, const T& ny,
                                              const T& px, const T& py, const T& separation, double speculative,
                                              double dt) {
    const T rAx = px - A.cx, rAy = py - A.cy, rBx = px - B.cx, rBy = py - B.cy;
    const T vx = B.vx + -B.w * rBy - A.vx - -A.w * rAy, vy = B.vy + B.w * rBx - A.vy - A.w * rAx;
    const T vn = nx * vx + ny * vy, zero{};
    return isNot(separation > speculative + larger(zero, -vn) * dt);
}

// The pair's manifold with every point up to `margin` (m) apart, from the shapes collided again: with 2 tolerances
// to spare, so a pair at rest keeps its cache though its closing speed, and so its margin, jitters.
// The whole result, so that it is returned in place (a manifold is 160 bytes).
NarrowResult collide(ManifoldCache& k, const Geometry& shapeA, const BodyData& A, const Geometry& shapeB,
                     const BodyData& B, double margin, double tolerance) {
    const double wider = margin + 2.0 * tolerance;
    NarrowResult r = collideGeometries(shapeA, A.xf, shapeB, B.xf, wider);
    keep(k, r.manifold, A, B, wider, r.empty, std::max(rollingRadius(shapeA), rollingRadius(shapeB)));
    if (r.empty.fragile) k.margin = -1.0;  // not kept: collided again next step
    return r;
}

// Whether a cache holds an empty answer with a promise (StaysEmpty); 0 promises nothing, even to a pair at rest.
[[gnu::always_inline]] inline bool promisesEmpty(const ManifoldCache& k) { return k.pointCount == 0 && k.quiet > 0.0; }
// Whether that promise still holds: the routine, asked with `margin` (m) now, would answer empty again, its point
// (the arm from B's centre) having moved as `sinceCache` says.
[[gnu::always_inline]] inline bool staysEmpty(const ManifoldCache& k, double margin,
                                              const MovedSinceCache<double>& sinceCache) {
    const double moved = sinceCache.reachingOut(double{k.quietArm});
    if (k.quietAtAnyMargin) return moved < k.quiet;
    return std::max(margin, kSpeculativeMargin) + moved < k.quiet;
}

// What a manifold's points held before the narrow phase placed them anew.
struct KeptImpulses {
    struct Point {
        std::uint32_t id;
        double normal, tangent;
    } points[2];
    int count = 0;
    explicit KeptImpulses(const Manifold& m) : count(m.pointCount) {
        for (int q = 0; q < count; ++q)
            points[q] = {m.points[q].id, m.points[q].normalImpulse, m.points[q].tangentImpulse};
    }
};

// A point at the present poses, and whether it is kept. Field by field: a vector load of what was just stored as
// two scalars would wait for both.
struct PlacedPoint {
    double x = 0.0, y = 0.0, separation = 0.0;  // m
    std::uint32_t id = 0;
    bool keeps = false;
};

// Writes the `found` placed points that are kept into `m`, in order, each with the impulses it had (warm
// starting). Returns whether the pair touches.
[[gnu::always_inline]] inline bool keepPoints(Manifold& m, const KeptImpulses& kept, const PlacedPoint (&placed)[2],
                                              int found, double speculative) {
    int count = 0;
    bool touching = false;
    for (int p = 0; p < found; ++p) {
        const PlacedPoint& q = placed[p];
        if (!q.keeps) continue;
        ContactPoint& cp = m.points[count++];
        cp.point.x() = q.x;
        cp.point.y() = q.y;
        cp.separation = q.separation;
        cp.id = q.id;
        touching = touching || q.separation < speculative;
        cp.normalImpulse = cp.tangentImpulse = 0.0;
        for (int k = 0; k < kept.count; ++k)
            if (kept.points[k].id == q.id) {
                cp.normalImpulse = kept.points[k].normal;
                cp.tangentImpulse = kept.points[k].tangent;
            }
    }
    m.pointCount = count;
    return touching;
}

// The manifold at the present poses from the cache (`reuse`) or from the shapes collided again with `margin`, each
// point keeping the impulses it had; a speculative point only where the pair closes on it fast enough to touch
// this step. Returns whether the pair touches.
template <class Side>
[[gnu::always_inline]] inline bool placePoints(ContactData& c, const ShapeData* shapes, const BodyData& A,
                                               const BodyData& B, const Side& a, const Side& b, double margin,
                                               bool reuse, double speculative, double tolerance, double dt) {
    Manifold& m = c.manifold;
    ManifoldCache& k = c.cache;
    const KeptImpulses kept(m);
    PlacedPoint placed[2];
    int found = 0;
    if (reuse) {
        m.normal = A.xf.q.apply(k.normal);
        found = k.pointCount;
        for (int p = 0; p < found; ++p) {
            const ManifoldCache::Point& cached = k.points[p];
            placePoint(a, b, m.normal.x(), m.normal.y(), cached.onA.x(), cached.onA.y(), cached.onB.x(),
                       cached.onB.y(), placed[p].x, placed[p].y, placed[p].separation);
            placed[p].id = cached.id;
        }
    } else {
        const NarrowResult result =
            collide(k, shapes[c.shapeA()].geometry, A, shapes[c.shapeB()].geometry, B, margin, tolerance);
        const Manifold& fresh = result.manifold;
        m.normal = fresh.normal;
        found = std::min(fresh.pointCount, 2);  // always: said so that the compiler sees `placed` is large enough
        for (int p = 0; p < found; ++p) {
            const ContactPoint& cp = fresh.points[p];
            placed[p] = {cp.point.x(), cp.point.y(), cp.separation, cp.id, false};
        }
    }
    for (int p = 0; p < found; ++p)
        placed[p].keeps = keepsPoint(a, b, m.normal.x(), m.normal.y(), placed[p].x, placed[p].y,
                                     placed[p].separation, speculative, dt);
    return keepPoints(m, kept, placed, found, speculative);
}

// The manifold at the present poses. The shapes are collided again only when B has moved more than `tolerance` (m)
// in A's frame since the last collision, or when the margin grew past what that collision covered. Returns whether
// the pair touches.
template <bool V>
[[gnu::always_inline]] inline bool refreshManifold(ContactData& c, const ShapeData* shapes, const BodyData& A,
                                                   const BodyData& B, double speculative, double tolerance,
                                                   double dt) {
    if (!needsPoints(A, B, speculative, dt)) {
        c.manifold.pointCount = 0;
        return false;
    }
    const PairSide<double> a = sideOf(A), b = sideOf(B);
    const ManifoldCache& k = c.cache;
    const double margin = speculative + reach<V>(a, b, dt);
    bool reuse = false;
    if (k.margin >= 0.0) {
        const MovedSinceCache<double> moved = movedSinceCache<V>(k.offset.x(), k.offset.y(), k.angle, a, b);
        const double motion = moved.reachingOut(b.extent);  // of any point of B
        reuse = (motion <= tolerance && margin + motion <= k.margin &&
                 moved.turn * k.points[0].rounding <= rollToleranceFor(tolerance)) ||
                (promisesEmpty(k) && staysEmpty(k, margin + 2.0 * tolerance, moved));
    }
    const bool touching = placePoints(c, shapes, A, B, a, b, margin, reuse, speculative, tolerance, dt);
    if (c.manifold.pointCount > 0 && exactAndTurning(A, B) &&
        turnsPastItsPoints(c.manifold, shapes[c.shapeA()].geometry, A, shapes[c.shapeB()].geometry, B, dt)) {
        c.manifold.pointCount = 0;
        return false;
    }
    return touching;
}

// Records what the refresh of contact i changed: its flag, and whether it gained its first point or lost its last.
[[gnu::always_inline]] inline void noteChange(const RefreshPass& p, std::size_t i, ContactData& c, bool hadPoints,
                                              bool touching) {
    if (hadPoints != (c.manifold.pointCount > 0)) {
        p.pointsChanged->store(true, std::memory_order_relaxed);
        if (p.hasPoints) p.hasPoints[i] = c.manifold.pointCount > 0 ? 1 : 0;
    }
    if (touching != c.touching) p.flags[i] = touching ? kBegan : kEnded;
    else if (!hadPoints && c.manifold.pointCount > 0) p.flags[i] = kReached;  // speculative points, not touching
    c.touching = touching;
}

// A large scene's contacts and bodies are no longer in the cache, and the contacts name their bodies in no order a
// hardware prefetcher follows: ask for a contact's record twice as far ahead as its bodies' records. A small
// scene's are in the cache, and asking costs more than it saves.
constexpr std::size_t kAhead = 4;
[[gnu::always_inline]] inline void askAhead(const RefreshPass& p, std::size_t i, std::size_t end) {
    if (i + 2 * kAhead < end) prefetchLines(&p.contacts[p.awakeContacts[i + 2 * kAhead]], sizeof(ContactData));
    if (i + kAhead < end) {
        const ContactData& ahead = p.contacts[p.awakeContacts[i + kAhead]];
        prefetchLines(&p.bodies[ahead.a()], sizeof(BodyData));
        prefetchLines(&p.bodies[ahead.b()], sizeof(BodyData));
    }
}

// Whether contact i's enlarged boxes parted (then flagged): a pair that no longer overlaps is destroyed.
[[gnu::always_inline]] inline bool parted(const RefreshPass& p, std::size_t i, const ContactData& c) {
    if (p.overlapsKnown || p.broadPhase->fatBox(c.proxyA).overlaps(p.broadPhase->fatBox(c.proxyB))) return false;
    p.flags[i] = kParted;
    return true;
}

// Contact i of the pass, one at a time.
template <bool V>
[[gnu::always_inline]] inline void refreshOne(const RefreshPass& p, std::size_t i) {
    ContactData& c = p.contacts[p.awakeContacts[i]];
    const BodyData& A = p.bodies[c.a()];
    const BodyData& B = p.bodies[c.b()];
    if (parted(p, i, c)) return;
    if (deferred(A, B, p.speculative, p.dt)) {
        p.flags[i] = kDeferred;
        return;
    }
    const bool hadPoints = c.manifold.pointCount > 0;
    noteChange(p, i, c, hadPoints, refreshManifold<V>(c, p.shapes, A, B, p.speculative, p.tolerance, p.dt));
}

// Four records' 32 bytes from byte `offset` on, transposed: the j-th double of record k in lane k of values[j].
template <class Record>
[[gnu::always_inline]] inline void fourLanes(const Record* const (&records)[kLanes], std::size_t offset,
                                             Wide (&values)[4]) {
    for (int k = 0; k < kLanes; ++k)
        values[k] = reinterpret_cast<const RecordHalf*>(reinterpret_cast<const char*>(records[k]) + offset)->values;
    transpose(values[0], values[1], values[2], values[3]);
}

// A body's motion as three 32-byte runs of its record, from its rotation on: (q.c, q.s, center), (angle, -, v),
// (w, extent, -, -).
constexpr std::size_t kRotationAt = offsetof(BodyData, xf) + offsetof(Transform, q);
static_assert(offsetof(BodyData, center) == kRotationAt + 16 && offsetof(BodyData, angle) == kRotationAt + 32 &&
                  offsetof(BodyData, v) == kRotationAt + 48 && offsetof(BodyData, w) == kRotationAt + 64 &&
                  offsetof(BodyData, extent) == kRotationAt + 72 && kRotationAt + 96 <= sizeof(BodyData),
              "the motion fields sidesOf reads");
[[gnu::always_inline]] inline PairSide<Wide> sidesOf(const BodyData* const (&b)[kLanes]) {
    Wide pose[4], motion[4], spin[4];
    fourLanes(b, kRotationAt, pose);
    fourLanes(b, kRotationAt + 32, motion);
    fourLanes(b, kRotationAt + 64, spin);
    Wide turnReach;
    for (int k = 0; k < kLanes; ++k) turnReach[k] = b[k]->turnReach;
    return {pose[2], pose[3], motion[2], motion[3], spin[0], spin[1], turnReach, pose[0], pose[1], motion[0]};
}

// A cache as four 32-byte runs: (margin, -, offset), (angle, -, normal), and each point's (onA, onB).
constexpr std::size_t kCacheAt = offsetof(ContactData, cache);
static_assert(offsetof(ManifoldCache, margin) == 0 && offsetof(ManifoldCache, offset) == 16 &&
                  offsetof(ManifoldCache, angle) == 32 && offsetof(ManifoldCache, normal) == 48 &&
                  offsetof(ManifoldCache, points) == 64 && offsetof(ManifoldCache::Point, onB) == 16 &&
                  sizeof(ManifoldCache::Point) == 48 && kCacheAt + 64 + 48 + 32 <= sizeof(ContactData),
              "the cache fields refreshFour reads");

// Contacts [i, i + kLanes) of the pass. The common case, two discrete bodies with a cached manifold, is worked out
// four contacts at once, lane by lane with refreshManifold's formulas; any other contact takes refreshOne. The same
// bits either way. The lanes pay for their gathers where points are placed: four contacts none of which holds a
// face (a pile of circles: one point or none) take refreshOne too.
template <bool V>
[[gnu::always_inline]] inline void refreshFour(const RefreshPass& p, std::size_t i) {
    const ContactData* c[kLanes];
    const BodyData *A[kLanes], *B[kLanes];
    unsigned lanes = 0;  // a bit per contact that takes the lanes' way
    bool faces = false;  // some contact holds a face (two points), where the lanes save most
    for (int k = 0; k < kLanes; ++k) {
        c[k] = &p.contacts[p.awakeContacts[i + k]];
        A[k] = &p.bodies[c[k]->a()];
        B[k] = &p.bodies[c[k]->b()];
        if (bothDiscrete(*A[k], *B[k]) && c[k]->cache.margin >= 0.0) lanes |= 1u << k;
        faces = faces || c[k]->cache.pointCount == 2;
    }
    if (lanes == 0 || !faces) {
        for (int k = 0; k < kLanes; ++k) refreshOne<V>(p, i + k);
        return;
    }
    const PairSide<Wide> a = sidesOf(A), b = sidesOf(B);
    Wide head[4], turn[4];
    fourLanes(c, kCacheAt, head);
    fourLanes(c, kCacheAt + 32, turn);
    const Wide margin = p.speculative + reach<V>(a, b, p.dt);
    const MovedSinceCache<Wide> moved = movedSinceCache<V>(head[2], head[3], turn[0], a, b);
    const Wide motion = moved.reachingOut(b.extent);
    Wide rounding;
    for (int k = 0; k < kLanes; ++k) rounding[k] = c[k]->cache.points[0].rounding;
    const WideMask reuse = (motion <= p.tolerance) & (margin + motion <= head[0]) &
                           (moved.turn * rounding <= rollToleranceFor(p.tolerance));
    unsigned reused = 0;  // a bit per contact whose cache holds
    int points = 0;       // the most points a kept manifold has: many pairs in a pile have none
    for (int k = 0; k < kLanes; ++k)
        if ((lanes >> k & 1u) &&
            (reuse[k] != 0 || (promisesEmpty(c[k]->cache) && staysEmpty(c[k]->cache, margin[k] + 2.0 * p.tolerance,
                                                                          {moved.shift[k], moved.turn[k]})))) {
            reused |= 1u << k;
            points = std::max(points, int{c[k]->cache.pointCount});
        }
    const Wide nx = a.qc * turn[2] - a.qs * turn[3], ny = a.qs * turn[2] + a.qc * turn[3];
    Wide px[2], py[2], separation[2];
    WideMask keeps[2];
    for (int q = 0; q < points; ++q) {
        Wide on[4];  // onA.x, onA.y, onB.x, onB.y
        fourLanes(c, kCacheAt + offsetof(ManifoldCache, points) + q * sizeof(ManifoldCache::Point), on);
        placePoint(a, b, nx, ny, on[0], on[1], on[2], on[3], px[q], py[q], separation[q]);
        keeps[q] = keepsPoint(a, b, nx, ny, px[q], py[q], separation[q], p.speculative, p.dt);
    }
    // Each contact's manifold from its lanes, from its shapes collided again with the lanes' margin, or all of
    // refreshOne where the lanes took no part.
    for (int k = 0; k < kLanes; ++k) {
        if (!(lanes >> k & 1u)) {
            refreshOne<V>(p, i + k);
            continue;
        }
        ContactData& contact = p.contacts[p.awakeContacts[i + k]];
        if (parted(p, i + k, contact)) continue;
        const bool hadPoints = contact.manifold.pointCount > 0;
        bool touching;
        if (reused >> k & 1u) {
            Manifold& m = contact.manifold;
            const KeptImpulses kept(m);
            const ManifoldCache& cache = contact.cache;
            m.normal = {nx[k], ny[k]};
            PlacedPoint placed[2];
            for (int q = 0; q < cache.pointCount; ++q)
                placed[q] = {px[q][k], py[q][k], separation[q][k], cache.points[q].id, keeps[q][k] != 0};
            touching = keepPoints(m, kept, placed, cache.pointCount, p.speculative);
        } else {
            touching = placePoints(contact, p.shapes, *A[k], *B[k], sideOf(*A[k]), sideOf(*B[k]), margin[k], false,
                                   p.speculative, p.tolerance, p.dt);
        }
        noteChange(p, i + k, contact, hadPoints, touching);
    }
}

// The narrow phase's loop over awake contacts [begin, end), built twice (refreshContacts picks): for baseline
// x86-64, and for AVX2 without FMA, whose three-operand VEX forms spare the copies SSE2's two-operand forms need.
// With no fused multiply-add in either build, each operation is the same IEEE one: the same bits.
template <bool V>
[[gnu::always_inline]] inline void refreshLoop(const RefreshPass& p, std::size_t begin, std::size_t end) {
    std::size_t i = begin;
    for (; i + kLanes <= end; i += kLanes) {
        if (p.prefetch)
            for (std::size_t k = 0; k < kLanes; ++k) askAhead(p, i + k, end);
        refreshFour<V>(p, i);
    }
    for (; i < end; ++i) {
        if (p.prefetch) askAhead(p, i, end);
        refreshOne<V>(p, i);
    }
}

void refreshBaseline(const RefreshPass& p, std::size_t begin, std::size_t end) { refreshLoop<false>(p, begin, end); }
#if PHYSIM_HAS_AVX2_CODE
__attribute__((target("avx2"))) void refreshAvx2(const RefreshPass& p, std::size_t begin, std::size_t end) {
    refreshLoop<true>(p, begin, end);
}
#endif

}  // namespace

void refreshContacts(const RefreshPass& pass, std::size_t begin, std::size_t end, WideCode code) {
#if PHYSIM_HAS_AVX2_CODE
    if (code == WideCode::Avx2 || code == WideCode::Avx512 || (code == WideCode::Best && avx2CodeRuns()))
        return refreshAvx2(pass, begin, end);
#endif
    refreshBaseline(pass, begin, end);
}

bool WorldImpl::contactExists(std::uint32_t shapeA, std::uint32_t shapeB) const {
    return contactPairs.contains(PairSet::key(shapeA, shapeB));
}

void WorldImpl::createContact(std::uint32_t shapeA, std::uint32_t shapeB) {
    const std::uint32_t index = takeSlot(contacts, freeContacts);
    ContactData& c = contacts[index];
    const std::uint32_t a = shapes[shapeA].body, b = shapes[shapeB].body;
    contactPairs.insert(PairSet::key(shapeA, shapeB));
    c.manifold.bodyA = BodyId{a, bodies[a].generation};
    c.manifold.bodyB = BodyId{b, bodies[b].generation};
    c.manifold.shapeA = ShapeId{shapeA, shapes[shapeA].generation};
    c.manifold.shapeB = ShapeId{shapeB, shapes[shapeB].generation};
    mixContact(index);
    if (contactImpulses.size() <= index) contactImpulses.resize(contacts.size());
    contactImpulses[index] = StepImpulses{};  // a slot's last pair's totals are not this one's
    c.proxyA = shapes[shapeA].proxy;
    c.proxyB = shapes[shapeB].proxy;
    const std::uint32_t ends[2] = {a, b};
    for (int side = 0; side < 2; ++side) {
        BodyData& body = bodies[ends[side]];
        const std::int32_t key = static_cast<std::int32_t>(index) * 2 + side;
        c.prev[side] = kNullIndex;
        c.next[side] = body.contactHead;
        if (body.contactHead != kNullIndex) {
            ContactData& head = contacts[static_cast<std::size_t>(body.contactHead >> 1)];
            head.prev[body.contactHead & 1] = key;
        }
        body.contactHead = key;
        ++body.contactCount;
    }
    if (bodies[a].awake() || bodies[b].awake()) addAwakeContact(index);
}

void WorldImpl::destroyContact(std::uint32_t index, bool wakeBodies) {
    ContactData& c = contacts[index];
    contactPairs.erase(PairSet::key(c.shapeA(), c.shapeB()));
    const bool dynamicPair = bodies[c.a()].type == BodyType::Dynamic && bodies[c.b()].type == BodyType::Dynamic;
    if (c.touching && dynamicPair) unlinkBodies(c.a(), c.b());
    if (c.awakeIndex != kNullIndex) removeAwakeContact(index);
    const std::uint32_t ends[2] = {c.a(), c.b()};
    for (int side = 0; side < 2; ++side) {
        BodyData& body = bodies[ends[side]];
        if (c.prev[side] != kNullIndex)
            contacts[static_cast<std::size_t>(c.prev[side] >> 1)].next[c.prev[side] & 1] = c.next[side];
        else
            body.contactHead = c.next[side];
        if (c.next[side] != kNullIndex)
            contacts[static_cast<std::size_t>(c.next[side] >> 1)].prev[c.next[side] & 1] = c.prev[side];
        --body.contactCount;
    }
    if (wakeBodies) {
        wakeBody(c.a());
        wakeBody(c.b());
    }
    c.alive = false;
    freeContacts.push_back(index);
}

// The rows' layout depends on the awake contacts that have points, in the awake list's order (ConstraintGraph):
// a contact without points joining at the end, or leaving with another without points moved into its place,
// leaves that sequence as it was. A contact entering with no points gets a row, later, only by gaining one, which
// the narrow phase reports (RefreshPass::pointsChanged). Chains and crowds add and drop such contacts nearly
// every step as bodies move past neighbouring shapes.
void WorldImpl::addAwakeContact(std::uint32_t index) {
    contacts[index].awakeIndex = static_cast<std::int32_t>(awakeContacts.size());
    awakeContacts.push_back(index);
    awakeHasPoints.push_back(contacts[index].manifold.pointCount > 0 ? 1 : 0);
    if (contacts[index].manifold.pointCount > 0) solver.layoutChanged();
    awakeContactsChanged = true;
}

void WorldImpl::removeAwakeContact(std::uint32_t index) {
    const std::int32_t at = contacts[index].awakeIndex;
    const std::uint32_t last = awakeContacts.back();
    if (contacts[index].manifold.pointCount > 0 || (last != index && contacts[last].manifold.pointCount > 0))
        solver.layoutChanged();
    awakeContacts[static_cast<std::size_t>(at)] = last;
    awakeHasPoints[static_cast<std::size_t>(at)] = awakeHasPoints.back();
    contacts[last].awakeIndex = at;
    awakeContacts.pop_back();
    awakeHasPoints.pop_back();
    contacts[index].awakeIndex = kNullIndex;
    awakeContactsChanged = true;
}

void WorldImpl::updatePairs() {
    const double speculative = speculativeDistance();
    // Pairs that never make a contact (two immovable bodies, a sensor: the Sensors stage finds its overlaps itself;
    // shapes whose filters refuse each other) are taken and dropped here: declined pairs are asked about again every
    // step. The filters are read last, for the deferred pairs only: the others are taken anyway and meet them below.
    // Two shapes of one body, and bodies joined by a joint without collideConnected (they meet only through it), are
    // passed by: a wheel's pair with its chassis is met at every move of either. Removing that joint asks their
    // proxies again (WorldImpl::removeJoint).
    const bool joints = jointCount > 0;
    const auto wanted = [&](std::uint32_t a, std::uint32_t b) {
        const std::uint32_t bodyA = shapes[a].body, bodyB = shapes[b].body;
        if (bodyA == bodyB || (joints && jointKeepsApart(bodyA, bodyB))) return Offer::PassBy;
        const BodyData& A = bodies[bodyA];
        const BodyData& B = bodies[bodyB];
        return offerOf(!shouldCollide(A, B) || shapes[a].sensor || shapes[b].sensor ||
                       !deferred(A, B, speculative, dt) || !shouldCollide(shapes[a].filter, shapes[b].filter));
    };
    // A pair the filters or the pair filter refuse is taken and dropped (asked here, serially, once per offer).
    broadPhase.findNewPairs(newPairs, contactPairs, wanted, executor);
    for (const auto& [a, b] : newPairs) {
        const std::uint32_t bodyA = shapes[a].body, bodyB = shapes[b].body;
        if (shouldCollide(bodies[bodyA], bodies[bodyB]) && !shapes[a].sensor && !shapes[b].sensor && pairAllowed(a, b))
            createContact(a, b);
    }
}

void WorldImpl::updateContacts() {
    const double speculative = speculativeDistance();
    // A manifold kept while the pair moves less than this in its own frame is off by at most this (m) along the
    // surfaces; the separations, which the solver needs exactly, are measured at the present poses anyway.
    const double reuseTolerance = 0.1 * settings.linearSlop;
    const std::size_t n = awakeContacts.size();
    contactFlags.assign(n, kNone);
    std::atomic<bool> pointsChanged{false};  // a contact gained its first point or lost its last: it has a row or not
    // No box and no awake contact changed since the last narrow phase, which found every awake contact's proxies
    // overlapping (else it destroyed the contact): they still overlap, and the test would only miss the cache.
    const bool overlapsKnown = !awakeContactsChanged && broadPhase.boxRevision() == checkedBoxRevision;
    awakeContactsChanged = false;
    checkedBoxRevision = broadPhase.boxRevision();
    constexpr std::size_t kPrefetchFromContacts = 8192;
    const RefreshPass pass{contacts.data(), awakeContacts.data(), bodies.data(), shapes.data(), &broadPhase,
                           contactFlags.data(), awakeHasPoints.data(),
                           speculative, reuseTolerance, dt, overlapsKnown, n >= kPrefetchFromContacts,
                           &pointsChanged};
    executor.parallelFor(n, 64, [&](std::size_t begin, std::size_t end, int) { refreshContacts(pass, begin, end); });

    if (preSolve) runPreSolve();
    if (pointsChanged.load()) solver.layoutChanged();

    // Changes in a fixed order (the awake list's), serially: they link islands, wake sleepers and destroy.
    changedContacts.clear();
    for (std::size_t i = 0; i < n; ++i)
        if (contactFlags[i] != kNone) changedContacts.emplace_back(awakeContacts[i], contactFlags[i]);
    for (const auto& [index, flag] : changedContacts) {
        ContactData& c = contacts[index];
        const ContactEvent event{c.manifold.bodyA, c.manifold.bodyB, c.manifold.shapeA, c.manifold.shapeB};
        const bool dynamicPair = bodies[c.a()].type == BodyType::Dynamic && bodies[c.b()].type == BodyType::Dynamic;
        if (flag == kParted || flag == kDeferred) {
            if (c.touching) events.end.push_back(event);
            if (flag == kDeferred) broadPhase.requery(c.proxyA);
            destroyContact(index, false);
        } else if (flag == kBegan) {
            events.begin.push_back(event);
            if (dynamicPair) linkBodies(c.a(), c.b());
            // Touching a sleeper wakes its island (its contacts join the awake list for the next step).
            if (!bodies[c.a()].awake() && bodies[c.a()].type == BodyType::Dynamic) wakeBody(c.a());
            if (!bodies[c.b()].awake() && bodies[c.b()].type == BodyType::Dynamic) wakeBody(c.b());
        } else if (flag == kEnded) {
            events.end.push_back(event);
            if (dynamicPair) unlinkBodies(c.a(), c.b());
        } else if (flag == kReached) {
            // Speculative points reach a sleeper before the pair touches: it wakes now, so this step's rows move
            // it (asleep, it would stand as immovable and stop whatever comes at it, however heavy).
            if (!bodies[c.a()].awake() && bodies[c.a()].type == BodyType::Dynamic) wakeBody(c.a());
            if (!bodies[c.b()].awake() && bodies[c.b()].type == BodyType::Dynamic) wakeBody(c.b());
        }
    }
}

}  // namespace physim
