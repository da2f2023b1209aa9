#include "ContinuousStage.hpp"

#include "physim/core/Collide.hpp"
#include "physim/core/TimeOfImpact.hpp"

#include <algorithm>
#include <limits>

namespace physim {
namespace {

// Velocity impulse at an impact between a (the continuous body) and b, normal n from a to b, contact point c.
// One point, no friction: only the approaching normal velocity changes, so a body hitting a wall at a slant keeps
// its tangential speed and slides on. The solver's rules for restitution: the pair's min, and none below the
// threshold speed, so slow impacts do not bounce.
void applyImpulse(BodyData& a, BodyData& b, const Vec2& n, const Vec2& c, const WorldSettings& settings) {
    const Vec2 ra = c - a.xf.p, rb = c - b.xf.p;
    const Vec2 relative = (b.v + cross(b.w, rb)) - (a.v + cross(a.w, ra));
    const double vn = relative.dot(n);
    if (!(vn < 0.0)) return;  // already separating or sliding
    const double rna = cross(ra, n), rnb = cross(rb, n);
    const double k = a.invMass + b.invMass + a.invInertia * rna * rna + b.invInertia * rnb * rnb;
    if (!(k > 0.0)) return;
    const double e = -vn > settings.restitutionThreshold ? std::min(a.restitution, b.restitution) : 0.0;
    const double j = -(1.0 + e) * vn / k;  // N s along n
    a.v -= j * a.invMass * n;
    a.w -= j * a.invInertia * rna;
    b.v += j * b.invMass * n;
    b.w += j * b.invInertia * rnb;
}

// Normal (from a to b) and point of the contact between two placed shapes that touch or nearly touch: closest
// points when apart, the narrow phase's manifold when overlapping. False when neither gives one.
bool contactAt(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb, Vec2& normal,
               Vec2& point) {
    const DistanceOutput gap = shapeDistance(a, xa, b, xb);
    if (gap.distance > 0.0) {
        normal = gap.normal;
        point = 0.5 * (gap.pointA + gap.pointB);
        return true;
    }
    const Manifold m = collide(a, xa, b, xb);
    if (m.pointCount == 0) return false;
    normal = m.normal;
    point = m.points[0].point;
    return true;
}

// Normal speed (m/s) at which b approaches a at the contact point: > 0 when closing.
double closingSpeed(const BodyData& a, const BodyData& b, const Vec2& n, const Vec2& c, const Transform& xa,
                    const Transform& xb) {
    const Vec2 relative = (b.v + cross(b.w, c - xb.p)) - (a.v + cross(a.w, c - xa.p));
    return -relative.dot(n);
}

bool sweeps(const BodyData& b) {
    return b.alive && b.type == BodyType::Dynamic && b.detection != CollisionDetection::Discrete;
}

constexpr double kNever = std::numeric_limits<double>::infinity();

}  // namespace

Sweep ContinuousStage::sweepFrom(std::size_t k, double t) const {
    const Segment& s = segments_[k];
    return {s.positionAt(t), s.positionAt(1.0), s.angleAt(t), s.angleAt(1.0)};
}

void ContinuousStage::restartSegment(std::size_t k, const BodyData& b, double t, double dt) {
    Segment& s = segments_[k];
    s.p = s.positionAt(t);
    s.angle = s.angleAt(t);
    s.t0 = t;
    const bool stays = s.impacts >= kMaxImpacts;  // the last impact it may meet: it stays here
    s.dp = stays ? Vec2::Zero() : Vec2(dt * b.v);
    s.da = stays ? 0.0 : dt * b.w;
    s.swept = sweptAabb(b.shape, sweepFrom(k, t));
    s.changed = true;
}

ToiResult ContinuousStage::test(const std::vector<BodyData>& bodies, std::size_t k, std::size_t other,
                                double t) const {
    const BodyData& body = bodies[k];
    const Sweep mine = sweepFrom(k, t), theirs = sweepFrom(other, t);
    return body.detection == CollisionDetection::ContinuousExact
               ? timeOfImpact(body.shape, mine, bodies[other].shape, theirs)
               : sampledTimeOfImpact(body.shape, mine, bodies[other].shape, theirs, body.precision);
}

void ContinuousStage::consider(const std::vector<BodyData>& bodies, std::size_t k, std::size_t other, double t,
                               const ToiResult& r, double dt, Impact& best) const {
    const double rest = 1.0 - t;
    if (r.state == ToiState::Hit) {
        const double at = t + r.t * rest;
        if (at < best.t) best = {at, other};
    } else if (r.state == ToiState::Touching && best.t > t) {
        // Touching at the segment's start (the contact just met, or a resting one): the discrete contacts own it,
        // unless the bodies would close by more than the tolerance over the rest of the substep (the solve saw no
        // contact within that hair's gap): then it is an impact now.
        const Sweep mine = sweepFrom(k, t), theirs = sweepFrom(other, t);
        const Transform here = mine.at(0.0), there = theirs.at(0.0);
        Vec2 n = Vec2::Zero(), c = Vec2::Zero();
        const bool contact = contactAt(bodies[k].shape, here, bodies[other].shape, there, n, c);
        if (contact && closingSpeed(bodies[k], bodies[other], n, c, here, there) * rest * dt > kToiTolerance) {
            best = {t, other};
            return;
        }
        // Not closing where they touch, but turning can still carry another part through (a spinning plank that
        // just hit something). Then the impact is where they last overlapped by no more than the linear slop.
        const double deeper = deepening(bodies[k].shape, mine, bodies[other].shape, theirs, n, slop_);
        if (deeper < 1.0 && t + deeper * rest < best.t) best = {t + deeper * rest, other};
    }
}

double ContinuousStage::deepening(const Geometry& a, const Sweep& sa, const Geometry& b, const Sweep& sb,
                                  const Vec2& n, double slop) {
    // Touching convex shapes are separated by the line through the contact across n: sliding along it cannot
    // make them overlap, so only the approach along n and the turning (a point at R from its origin moves R per
    // radian) can, and no overlap grows faster than `reach` over the sweep. Sampling at half the slop's spacing
    // in that measure cannot step over an overlap deeper than the slop.
    // n zero (no contact normal was found): any approach counts.
    const Vec2 motion = (sa.p1 - sa.p0) - (sb.p1 - sb.p0);
    const double approach = n.isZero() ? motion.norm() : motion.dot(n);
    const double reach = std::max(0.0, approach) + std::abs(sa.a1 - sa.a0) * boundingRadius(a) +
                         std::abs(sb.a1 - sb.a0) * boundingRadius(b);
    if (!(reach > slop)) return 1.0;  // cannot overlap by more than the slop: the discrete contacts' business
    // Deeper than the slop; or, for a pair that already starts deeper (spawned so, or pressed in: the position
    // correction's business), half a slop deeper than it starts, so its own overlap never counts as an impact.
    auto deepest = [&](double u) {
        const Manifold m = collide(a, sa.at(u), b, sb.at(u));
        double separation = 0.0;
        for (int p = 0; p < m.pointCount; ++p) separation = std::min(separation, m.points[p].separation);
        return separation;
    };
    const double start = deepest(0.0);
    const double limit = start > -slop ? -slop : start - 0.5 * slop;
    const int samples = static_cast<int>(std::min(4096.0, std::ceil(reach / (0.5 * slop))));
    for (int s = 1; s <= samples; ++s)
        if (deepest(static_cast<double>(s) / samples) < limit) return static_cast<double>(s - 1) / samples;
    return 1.0;
}

ContinuousStage::Impact ContinuousStage::earliestImpact(const std::vector<BodyData>& bodies, std::size_t k, double t,
                                                        double dt) const {
    Impact best{kNever, bodies.size()};
    const Aabb& box = segments_[k].swept;  // covers [t0, 1], so [t, 1] too
    for (std::size_t m = 0; m < bodies.size(); ++m) {
        if (m == k || !bodies[m].alive || !box.overlaps(segments_[m].swept)) continue;  // swept-volume pre-check
        consider(bodies, k, m, t, test(bodies, k, m, t), dt, best);
    }
    return best;
}

void ContinuousStage::batchFirstImpacts(const std::vector<BodyData>& bodies, double dt) {
    batch_.clear();
    pairOwner_.clear();
    pairPartner_.clear();
    batchBody_.assign(bodies.size(), -1);
    auto inBatch = [&](std::size_t k) {
        if (batchBody_[k] < 0) batchBody_[k] = batch_.addBody(batch_.addShape(bodies[k].shape), sweepFrom(k, 0.0));
        return batchBody_[k];
    };
    for (const std::uint32_t i : sweepers_) {
        if (bodies[i].detection != CollisionDetection::ContinuousExact) continue;
        for (std::size_t j = 0; j < bodies.size(); ++j) {
            if (j == i || !bodies[j].alive || !segments_[i].swept.overlaps(segments_[j].swept)) continue;
            batch_.addPair(inBatch(i), inBatch(j));
            pairOwner_.push_back(i);
            pairPartner_.push_back(static_cast<std::uint32_t>(j));
        }
    }
    if (batch_.pairCount() == 0) return;
    // The World built the batch from validated bodies, so every pair passes the kernel's checks.
    if (solver_)
        solver_->solve(batch_, batchResult_);
    else
        solveOnCpu(batch_, batchResult_, 1);
    for (std::size_t k = 0; k < pairOwner_.size(); ++k) {
        // kInvalid cannot come from shapes validate(Geometry) accepted; if it ever does, the one-pair test answers.
        const ToiResult r = batchResult_.state[k] == kernel::kInvalid
                                ? test(bodies, pairOwner_[k], pairPartner_[k], 0.0)
                                : batchResult_.toi(k);
        consider(bodies, pairOwner_[k], pairPartner_[k], 0.0, r, dt, next_[pairOwner_[k]]);
    }
}

void ContinuousStage::answer(std::vector<BodyData>& bodies, std::size_t i, std::size_t j, double t, double dt,
                             const WorldSettings& settings) {
    ++impacts_;
    BodyData& a = bodies[i];
    BodyData& b = bodies[j];
    const Transform here{segments_[i].positionAt(t), Rotation::fromAngle(segments_[i].angleAt(t))};
    const Transform there{segments_[j].positionAt(t), Rotation::fromAngle(segments_[j].angleAt(t))};
    // The impulse's lever arms need the poses at the impact; the bodies' own poses are put back after it (the
    // integrator still moves them from the start of the substep, and placeBodies corrects the changed ones).
    const Transform aStart = a.xf, bStart = b.xf;
    a.xf = here;
    b.xf = there;
    Vec2 n, c;
    // Sampled hits overlap: contactAt then takes the narrow phase's normal and point.
    if (contactAt(a.shape, here, b.shape, there, n, c)) applyImpulse(a, b, n, c, settings);
    a.xf = aStart;
    b.xf = bStart;
    ++segments_[i].impacts;
    restartSegment(i, a, t, dt);
    if (b.type == BodyType::Dynamic) {  // its velocity changed: it goes on from here, swept like the rest
        b.awake = true;                  // a sleeper that is hit moves, so it must be integrated and swept
        b.sleepTime = 0.0;
        ++segments_[j].impacts;
        restartSegment(j, b, t, dt);
    }
}

void ContinuousStage::findImpacts(std::vector<BodyData>& bodies, double dt, const WorldSettings& settings) {
    slop_ = settings.linearSlop;
    placements_.clear();
    impacts_ = 0;
    segments_.resize(bodies.size());
    next_.assign(bodies.size(), Impact{kNever, bodies.size()});
    sweepers_.clear();
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const BodyData& b = bodies[i];
        if (!b.alive) continue;
        Segment& s = segments_[i];
        s = Segment{};
        s.p = b.xf.p;
        s.angle = b.angle;
        s.dp = b.movable() ? Vec2(dt * b.v) : Vec2::Zero();
        s.da = b.movable() ? dt * b.w : 0.0;
        s.swept = sweptAabb(b.shape, sweepFrom(i, 0.0));
        if (sweeps(b)) sweepers_.push_back(static_cast<std::uint32_t>(i));
    }
    batchFirstImpacts(bodies, dt);
    for (const std::uint32_t i : sweepers_)
        if (bodies[i].detection != CollisionDetection::ContinuousExact) next_[i] = earliestImpact(bodies, i, 0.0, dt);

    // Every impact gives its sweeper one more impact, and a sweeper with kMaxImpacts has no more: this ends.
    for (;;) {
        std::size_t i = bodies.size();
        for (const std::uint32_t k : sweepers_)
            if (next_[k].t < kNever && (i == bodies.size() || next_[k].t < next_[i].t)) i = k;
        if (i == bodies.size()) break;
        const Impact impact = next_[i];
        const std::size_t j = impact.partner;
        answer(bodies, i, j, impact.t, dt, settings);
        for (const std::uint32_t k : sweepers_) {
            if (segments_[k].impacts >= kMaxImpacts) {
                next_[k] = Impact{kNever, bodies.size()};
            } else if (k == i || k == j || next_[k].partner == i || next_[k].partner == j) {
                next_[k] = earliestImpact(bodies, k, impact.t, dt);
            } else {
                for (const std::size_t moved : {i, j})  // an earlier impact with a new segment?
                    if (segments_[moved].changed && segments_[k].swept.overlaps(segments_[moved].swept))
                        consider(bodies, k, moved, impact.t, test(bodies, k, moved, impact.t), dt, next_[k]);
            }
        }
    }
    for (std::size_t k = 0; k < bodies.size(); ++k)
        if (bodies[k].alive && segments_[k].changed)
            placements_.push_back({static_cast<std::uint32_t>(k), segments_[k].positionAt(1.0), segments_[k].angleAt(1.0)});
}

void ContinuousStage::placeBodies(std::vector<BodyData>& bodies) {
    placed_.assign(bodies.size(), 0);
    for (const Placement& pl : placements_) {
        placed_[pl.body] = 1;
        BodyData& b = bodies[pl.body];
        b.xf.p = pl.p;
        b.angle = pl.angle;
        b.xf.q = Rotation::fromAngle(pl.angle);
    }
    placements_.clear();
}

}  // namespace physim
