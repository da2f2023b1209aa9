// Persistent contacts: created from the broad phase's new pairs, updated once per step by the narrow phase,
// destroyed when their bodies' enlarged boxes part (or the pair is deferred: see `deferred`).

#include "Contacts.hpp"
#include "Manifolds.hpp"
#include "Prefetch.hpp"
#include "Slots.hpp"
#include "WorldImpl.hpp"
#include "physim/core/ContinuousKernel.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace physim {
namespace {

// At least one body must be able to respond; two immovable bodies never make a contact.
bool shouldCollide(const BodyData& a, const BodyData& b) {
    return a.type == BodyType::Dynamic || b.type == BodyType::Dynamic;
}

// How far (m) the pair can close in a step at its present velocities, plus what gravity or forces add: the
// manifold keeps speculative points up to this far apart so the solver can stop the bodies at contact.
[[gnu::always_inline]] inline double reach(const BodyData& A, const BodyData& B, double dt) {
    const double turn = std::abs(A.w) * A.extent + std::abs(B.w) * B.extent;
    return ((B.v - A.v).norm() + turn) * dt;
}

// Whether a pair with a continuous body needs speculative points this step. Each shape stays inside the circle
// of its extent about its centre of mass however it turns, so centres that never come within both extents plus
// `gap` (m) at the present velocities keep the shapes apart, and a speculative point along a fixed normal would
// only stop bodies that pass each other. A continuous body's enlarged box covers its whole sweep, so in a crowd
// most pairs are such. Should a velocity change in the step make them meet after all, the Continuous stage
// stops the continuous body at the impact. Discrete pairs keep their points: nothing else would catch them.
[[gnu::always_inline]] inline bool needsPoints(const BodyData& A, const BodyData& B, double gap, double dt) {
    if (A.detection == CollisionDetection::Discrete && B.detection == CollisionDetection::Discrete) return true;
    // The centre's straight path over the step (the turn does not matter to a circle about the centre).
    auto path = [dt](const BodyData& b) {
        const Vec2 end = b.center + b.v * dt;
        return kernel::Motion{{b.center.x(), b.center.y()}, {end.x(), end.y()}, b.angle, b.angle};
    };
    return !kernel::boundsStayApart(path(A), A.extent, path(B), B.extent, gap);
}

[[gnu::always_inline]] inline bool moving(const BodyData& b) {
    return b.awake() && (b.v.squaredNorm() > 0.0 || b.w != 0.0);
}

// A pair that needs no points while one of its bodies moves has no contact record: the broad phase offers it
// again next step (BroadPhase::requery), so it gets one the step it may meet. In a crowd of bullets, whose
// enlarged boxes overlap nearly all others, this keeps the contacts to the pairs that can touch. A pair at rest
// keeps its (empty) record instead of being asked every step.
[[gnu::always_inline]] inline bool deferred(const BodyData& A, const BodyData& B, double gap, double dt) {
    return (moving(A) || moving(B)) && !needsPoints(A, B, gap, dt);
}

// How far (m) any point of B can have moved in A's frame since the cache was made: the shift of B's centre plus
// the turn times B's extent.
[[gnu::always_inline]] inline double motionSinceCache(const ManifoldCache& k, const BodyData& A, const BodyData& B) {
    const Vec2 offset = A.xf.q.applyInverse(B.center - A.center);
    return (offset - k.offset).norm() + std::abs(B.angle - A.angle - k.angle) * B.extent;
}

void keep(ManifoldCache& k, const Manifold& m, const BodyData& A, const BodyData& B, double margin) {
    k.margin = margin;
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
    }
}

// The manifold at the present poses from the cache: each surface point moves with its body, the separation is
// their distance along the normal, which turns with A.
[[gnu::always_inline]] inline void rebuild(const ManifoldCache& k, const BodyData& A, const BodyData& B, Manifold& m) {
    m.normal = A.xf.q.apply(k.normal);
    m.pointCount = k.pointCount;
    for (int p = 0; p < k.pointCount; ++p) {
        const Vec2 onA = A.center + A.xf.q.apply(k.points[p].onA);
        const Vec2 onB = B.center + B.xf.q.apply(k.points[p].onB);
        ContactPoint& cp = m.points[p];
        cp.point = 0.5 * (onA + onB);
        cp.separation = m.normal.dot(onB - onA);
        cp.id = k.points[p].id;
    }
}

// The pair's manifold with every point up to `margin` (m) apart, into `m` (its impulses untouched). The shapes are
// collided again only when B has moved more than `tolerance` (m) in A's frame since the last collision, or when
// the margin grew past what that collision covered; they are collided with 2 tolerances to spare, so a pair at
// rest keeps its cache though its closing speed, and so its margin, jitters.
[[gnu::always_inline]] inline void collideOrReuse(ManifoldCache& k, const BodyData& A, const BodyData& B,
                                                  double margin, double tolerance, Manifold& m) {
    if (k.margin >= 0.0) {
        const double motion = motionSinceCache(k, A, B);
        if (motion <= tolerance && margin + motion <= k.margin) return rebuild(k, A, B, m);
    }
    const double wider = margin + 2.0 * tolerance;
    const NarrowResult r = collideGeometries(A.shape, A.xf, B.shape, B.xf, wider);
    keep(k, r.manifold, A, B, wider);
    m.normal = r.manifold.normal;
    m.pointCount = r.manifold.pointCount;
    for (int p = 0; p < m.pointCount; ++p) {
        m.points[p].point = r.manifold.points[p].point;
        m.points[p].separation = r.manifold.points[p].separation;
        m.points[p].id = r.manifold.points[p].id;
    }
}

// The manifold at the present poses, each point keeping the impulses it had (warm starting); a speculative point
// only where the pair closes on it fast enough to touch this step. Returns whether the pair touches.
[[gnu::always_inline]] inline bool refreshManifold(ContactData& c, const BodyData& A, const BodyData& B,
                                                   double speculative, double tolerance, double dt) {
    Manifold& m = c.manifold;
    if (!needsPoints(A, B, speculative, dt)) {
        m.pointCount = 0;
        return false;
    }
    struct Impulses {
        std::uint32_t id;
        double normal, tangent;
    } kept[2];
    const int keptCount = m.pointCount;
    for (int q = 0; q < keptCount; ++q)
        kept[q] = {m.points[q].id, m.points[q].normalImpulse, m.points[q].tangentImpulse};
    collideOrReuse(c.cache, A, B, speculative + reach(A, B, dt), tolerance, m);
    const int found = m.pointCount;
    m.pointCount = 0;
    bool touching = false;
    for (int p = 0; p < found; ++p) {
        ContactPoint& cp = m.points[m.pointCount];
        cp = m.points[p];
        // Keep a speculative point only if the pair approaches there fast enough to close it this step.
        const Vec2 rA = cp.point - A.center, rB = cp.point - B.center;
        const double vn = m.normal.dot(B.v + cross(B.w, rB) - A.v - cross(A.w, rA));
        if (cp.separation > speculative + std::max(0.0, -vn) * dt) continue;
        touching = touching || cp.separation < speculative;
        cp.normalImpulse = cp.tangentImpulse = 0.0;
        for (int q = 0; q < keptCount; ++q)
            if (kept[q].id == cp.id) {
                cp.normalImpulse = kept[q].normal;
                cp.tangentImpulse = kept[q].tangent;
            }
        ++m.pointCount;
    }
    return touching;
}

// The narrow phase's loop over awake contacts [begin, end), built twice (refreshContacts picks): for baseline
// x86-64, and for AVX2 without FMA, whose three-operand VEX forms spare the copies SSE2's two-operand forms need.
// With no fused multiply-add in either build, each operation is the same IEEE one: the same bits.
[[gnu::always_inline]] inline void refreshLoop(const RefreshPass& p, std::size_t begin, std::size_t end) {
    // A large scene's contacts and bodies are no longer in the cache, and the contacts name their bodies in no order
    // a hardware prefetcher follows: ask for a contact's record twice as far ahead as its bodies' records. A small
    // scene's are in the cache, and asking costs more than it saves (docs/performance.md, "Tenth measurement").
    constexpr std::size_t kAhead = 4;
    for (std::size_t i = begin; i < end; ++i) {
        if (p.prefetch && i + 2 * kAhead < end)
            prefetchLines(&p.contacts[p.awakeContacts[i + 2 * kAhead]], sizeof(ContactData));
        if (p.prefetch && i + kAhead < end) {
            const ContactData& ahead = p.contacts[p.awakeContacts[i + kAhead]];
            prefetchLines(&p.bodies[ahead.a], sizeof(BodyData));
            prefetchLines(&p.bodies[ahead.b], sizeof(BodyData));
        }
        ContactData& c = p.contacts[p.awakeContacts[i]];
        const BodyData& A = p.bodies[c.a];
        const BodyData& B = p.bodies[c.b];
        if (!p.overlapsKnown && !p.broadPhase->fatBox(A.proxy).overlaps(p.broadPhase->fatBox(B.proxy))) {
            p.flags[i] = kParted;
            continue;
        }
        if (deferred(A, B, p.speculative, p.dt)) {
            p.flags[i] = kDeferred;
            continue;
        }
        const bool hadPoints = c.manifold.pointCount > 0;
        const bool touching = refreshManifold(c, A, B, p.speculative, p.tolerance, p.dt);
        if (hadPoints != (c.manifold.pointCount > 0)) p.pointsChanged->store(true, std::memory_order_relaxed);
        if (touching != c.touching) p.flags[i] = touching ? kBegan : kEnded;
        c.touching = touching;
    }
}

void refreshBaseline(const RefreshPass& p, std::size_t begin, std::size_t end) { refreshLoop(p, begin, end); }
#if PHYSIM_HAS_AVX2_CODE
__attribute__((target("avx2"))) void refreshAvx2(const RefreshPass& p, std::size_t begin, std::size_t end) {
    refreshLoop(p, begin, end);
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

bool WorldImpl::contactExists(std::uint32_t a, std::uint32_t b) const {
    return contactPairs.contains(PairSet::key(a, b));
}

void WorldImpl::createContact(std::uint32_t a, std::uint32_t b) {
    const std::uint32_t index = takeSlot(contacts, freeContacts);
    ContactData& c = contacts[index];
    c.a = a;
    c.b = b;
    contactPairs.insert(PairSet::key(a, b));
    c.manifold.bodyA = BodyId{a, bodies[a].generation};
    c.manifold.bodyB = BodyId{b, bodies[b].generation};
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
    contactPairs.erase(PairSet::key(c.a, c.b));
    const bool dynamicPair = bodies[c.a].type == BodyType::Dynamic && bodies[c.b].type == BodyType::Dynamic;
    if (c.touching && dynamicPair) unlinkBodies(c.a, c.b);
    if (c.awakeIndex != kNullIndex) removeAwakeContact(index);
    const std::uint32_t ends[2] = {c.a, c.b};
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
        wakeBody(c.a);
        wakeBody(c.b);
    }
    c.alive = false;
    freeContacts.push_back(index);
}

void WorldImpl::addAwakeContact(std::uint32_t index) {
    contacts[index].awakeIndex = static_cast<std::int32_t>(awakeContacts.size());
    awakeContacts.push_back(index);
    rowsStale = awakeContactsChanged = true;
}

void WorldImpl::removeAwakeContact(std::uint32_t index) {
    const std::int32_t at = contacts[index].awakeIndex;
    const std::uint32_t last = awakeContacts.back();
    awakeContacts[static_cast<std::size_t>(at)] = last;
    contacts[last].awakeIndex = at;
    awakeContacts.pop_back();
    contacts[index].awakeIndex = kNullIndex;
    rowsStale = awakeContactsChanged = true;
}

void WorldImpl::updatePairs() {
    const double speculative = 4.0 * settings.linearSlop;
    const auto wanted = [&](std::uint32_t a, std::uint32_t b) {
        const BodyData& A = bodies[a];
        const BodyData& B = bodies[b];
        return !shouldCollide(A, B) || !deferred(A, B, speculative, dt);
    };
    broadPhase.findNewPairs(newPairs, contactPairs, wanted, executor);
    for (const auto& [a, b] : newPairs)
        if (shouldCollide(bodies[a], bodies[b])) createContact(a, b);
}

void WorldImpl::updateContacts() {
    const double speculative = 4.0 * settings.linearSlop;
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
    const RefreshPass pass{contacts.data(), awakeContacts.data(), bodies.data(), &broadPhase, contactFlags.data(),
                           speculative, reuseTolerance, dt, overlapsKnown, n >= kPrefetchFromContacts,
                           &pointsChanged};
    executor.parallelFor(n, 64, [&](std::size_t begin, std::size_t end, int) { refreshContacts(pass, begin, end); });

    if (pointsChanged.load()) rowsStale = true;

    // Changes in a fixed order (the awake list's), serially: they link islands, wake sleepers and destroy.
    changedContacts.clear();
    for (std::size_t i = 0; i < n; ++i)
        if (contactFlags[i] != kNone) changedContacts.emplace_back(awakeContacts[i], contactFlags[i]);
    for (const auto& [index, flag] : changedContacts) {
        ContactData& c = contacts[index];
        const ContactEvent event{c.manifold.bodyA, c.manifold.bodyB};
        const bool dynamicPair = bodies[c.a].type == BodyType::Dynamic && bodies[c.b].type == BodyType::Dynamic;
        if (flag == kParted || flag == kDeferred) {
            if (c.touching) events.end.push_back(event);
            if (flag == kDeferred) broadPhase.requery(bodies[c.a].proxy);
            destroyContact(index, false);
        } else if (flag == kBegan) {
            events.begin.push_back(event);
            if (dynamicPair) linkBodies(c.a, c.b);
            // Touching a sleeper wakes its island (its contacts join the awake list for the next step).
            if (!bodies[c.a].awake() && bodies[c.a].type == BodyType::Dynamic) wakeBody(c.a);
            if (!bodies[c.b].awake() && bodies[c.b].type == BodyType::Dynamic) wakeBody(c.b);
        } else if (flag == kEnded) {
            events.end.push_back(event);
            if (dynamicPair) unlinkBodies(c.a, c.b);
        }
    }
}

}  // namespace physim
