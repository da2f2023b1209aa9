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

bool exactContinuous(const BodyData& b) {
    return b.alive && b.type == BodyType::Dynamic && b.detection == CollisionDetection::ContinuousExact;
}

}  // namespace

void ContinuousStage::batchFirstSweeps(const std::vector<BodyData>& bodies) {
    batch_.clear();
    pairPartner_.clear();
    batchBody_.assign(bodies.size(), -1);
    firstPair_.assign(bodies.size(), 0);
    endPair_.assign(bodies.size(), 0);
    auto inBatch = [&](std::size_t k) {
        if (batchBody_[k] < 0) {
            const Motion& m = motion_[k];
            batchBody_[k] = batch_.addBody(batch_.addShape(bodies[k].shape),
                                           Sweep{m.p, m.p + m.dp, m.angle, m.angle + m.da});
        }
        return batchBody_[k];
    };
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        if (!exactContinuous(bodies[i])) continue;
        firstPair_[i] = static_cast<std::uint32_t>(pairPartner_.size());
        for (std::size_t j = 0; j < bodies.size(); ++j) {
            if (j == i || !bodies[j].alive || !motion_[i].swept.overlaps(motion_[j].swept)) continue;
            batch_.addPair(inBatch(i), inBatch(j));
            pairPartner_.push_back(static_cast<std::uint32_t>(j));
        }
        endPair_[i] = static_cast<std::uint32_t>(pairPartner_.size());
    }
    if (batch_.pairCount() == 0) return;
    // The World built the batch from validated bodies, so every pair passes the kernel's checks.
    if (solver_)
        solver_->solve(batch_, batchResult_);
    else
        solveOnCpu(batch_, batchResult_, 1);
}

void ContinuousStage::findImpacts(std::vector<BodyData>& bodies, double dt, const WorldSettings& settings) {
    placements_.clear();
    impacts_ = 0;
    motion_.resize(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const BodyData& b = bodies[i];
        if (!b.alive) continue;
        Motion& m = motion_[i];
        m.p = b.xf.p;
        m.angle = b.angle;
        m.dp = b.movable() ? Vec2(dt * b.v) : Vec2::Zero();
        m.da = b.movable() ? dt * b.w : 0.0;
        m.swept = sweptAabb(b.shape, Sweep{m.p, m.p + m.dp, m.angle, m.angle + m.da});
    }
    batchFirstSweeps(bodies);

    for (std::size_t i = 0; i < bodies.size(); ++i) {
        BodyData& body = bodies[i];
        if (!body.alive || body.type != BodyType::Dynamic || body.detection == CollisionDetection::Discrete)
            continue;
        // The body's state on the step's clock: at time t (fraction of the step) it is at (p, angle) and moves
        // by (dp, da) per whole step.
        double t = 0.0;
        Vec2 p = motion_[i].p, dp = motion_[i].dp;
        double angle = motion_[i].angle, da = motion_[i].da;
        int impacts = 0;
        bool hitSomething = false;
        for (;;) {
            const double rest = 1.0 - t;
            const Sweep mine{p, p + rest * dp, angle, angle + rest * da};  // u in [0, 1] is time t + u * rest
            auto theirs = [&](std::size_t j) {
                const Motion& o = motion_[j];
                return Sweep{o.p + t * o.dp, o.p + o.dp, o.angle + t * o.da, o.angle + o.da};
            };
            double first = std::numeric_limits<double>::infinity();
            std::size_t partner = bodies.size();
            auto consider = [&](std::size_t j, const ToiResult& r) {
                if (r.state == ToiState::Hit && r.t < first) {
                    first = r.t;
                    partner = j;
                } else if (r.state == ToiState::Touching && first > 0.0) {
                    // Touching at the start (the contact just met, or a resting one): the discrete contacts own
                    // it, unless the bodies would close by more than the tolerance over the rest of the step
                    // (the solve saw no contact within that hair's gap): then it is an impact now.
                    Vec2 n, c;
                    const Transform there = theirs(j).at(0.0);
                    if (contactAt(body.shape, mine.at(0.0), bodies[j].shape, there, n, c) &&
                        closingSpeed(body, bodies[j], n, c, mine.at(0.0), there) * rest * dt > kToiTolerance) {
                        first = 0.0;
                        partner = j;
                    }
                }
            };
            if (impacts == 0 && body.detection == CollisionDetection::ContinuousExact) {
                for (std::uint32_t k = firstPair_[i]; k < endPair_[i]; ++k) consider(pairPartner_[k], batchResult_.toi(k));
            } else {
                const Aabb box = sweptAabb(body.shape, mine);
                for (std::size_t j = 0; j < bodies.size(); ++j) {
                    if (j == i || !bodies[j].alive) continue;
                    if (!box.overlaps(motion_[j].swept)) continue;  // swept-volume pre-check: no costly test
                    consider(j, body.detection == CollisionDetection::ContinuousExact
                                    ? timeOfImpact(body.shape, mine, bodies[j].shape, theirs(j))
                                    : sampledTimeOfImpact(body.shape, mine, bodies[j].shape, theirs(j),
                                                          body.precision));
                }
            }
            if (partner == bodies.size()) {  // free for the rest of the step
                p += rest * dp;
                angle += rest * da;
                break;
            }
            // Move to the impact and answer it with an impulse.
            hitSomething = true;
            ++impacts;
            ++impacts_;
            const Transform here = mine.at(first);
            angle = mine.angleAt(first);
            p = here.p;
            t += first * rest;
            BodyData& other = bodies[partner];
            const Motion& o = motion_[partner];
            const Transform there{o.p + t * o.dp, Rotation::fromAngle(o.angle + t * o.da)};
            // The impulse's lever arms need the poses at the impact time; the bodies' own poses are put back
            // after it (the integrator still moves them from the start of the step).
            const Transform bodyStart = body.xf, otherStart = other.xf;
            body.xf = here;
            other.xf = there;
            // Sampled hits overlap: contactAt then takes the narrow phase's normal and point.
            Vec2 n, c;
            if (contactAt(body.shape, here, other.shape, there, n, c)) applyImpulse(body, other, n, c, settings);
            body.xf = bodyStart;
            other.xf = otherStart;
            dp = dt * body.v;
            da = dt * body.w;
            if (impacts == kMaxImpacts || t >= 1.0) break;  // stay at the last impact for the rest of the step
        }
        if (hitSomething) placements_.push_back({static_cast<std::uint32_t>(i), p, angle});
    }
}

void ContinuousStage::placeBodies(std::vector<BodyData>& bodies) {
    for (const Placement& pl : placements_) {
        BodyData& b = bodies[pl.body];
        b.xf.p = pl.p;
        b.angle = pl.angle;
        b.xf.q = Rotation::fromAngle(pl.angle);
    }
    placements_.clear();
}

}  // namespace physim
