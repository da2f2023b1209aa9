#include "ContinuousStage.hpp"

#include "ContinuousCpu.hpp"
#include "Manifolds.hpp"
#include "WorldImpl.hpp"
#include "shapes/ShapeKinds.hpp"

#include "physim/core/Collide.hpp"

#include <algorithm>
#include <cmath>

namespace physim {
namespace {

// Deepest overlap (m, <= 0) of two placed shapes: the least separation of their manifold's points.
double deepest(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
    const Manifold m = collide(a, xa, b, xb);
    double separation = 0.0;
    for (int p = 0; p < m.pointCount; ++p) separation = std::min(separation, m.points[p].separation);
    return separation;
}

// How far the outline can move per radian the body turns about its origin, m (ShapeKind.hpp).
double turningRadius(const Geometry& g) {
    return withKind(g, [](auto kind, const auto& s) { return kind.turningRadius(s); });
}

// Whether the pre-solve hook lets an impact at time t of the sweeps stand (World::setPreSolve): it is asked about
// the contact the two shapes would make there, as the narrow phase builds one (shape slots in order, the normal
// from the first to the second, points within the speculative distance). A one-way platform is passed this way by
// bodies fast enough for this stage, as by the others in the narrow phase.
bool impactAllowed(const WorldImpl& w, std::uint32_t mine, const Sweep& mySweep, std::uint32_t theirs,
                   const Sweep& theirSweep, double t) {
    const bool mineFirst = mine < theirs;
    const std::uint32_t first = mineFirst ? mine : theirs, second = mineFirst ? theirs : mine;
    const Transform x1 = (mineFirst ? mySweep : theirSweep).at(t), x2 = (mineFirst ? theirSweep : mySweep).at(t);
    NarrowResult r = collideGeometries(w.shapes[first].geometry, x1, w.shapes[second].geometry, x2,
                                       w.speculativeDistance());
    Manifold& m = r.manifold;
    if (m.pointCount == 0) return true;  // not touching there: nothing to ask about
    const std::uint32_t a = w.shapes[first].body, b = w.shapes[second].body;
    m.bodyA = BodyId{a, w.bodies[a].generation};
    m.bodyB = BodyId{b, w.bodies[b].generation};
    m.shapeA = ShapeId{first, w.shapes[first].generation};
    m.shapeB = ShapeId{second, w.shapes[second].generation};
    return w.preSolve(m);
}

// Where a fast discrete body that starts touching a static shape must stop: before its centre comes within a small
// circle of that shape (1 if it does not). Pressed by a heavy neighbour, such a body can be carried past a thin
// shape's middle line (a chain piece, a segment) in one step; the contact's normal then flips and the body is pushed
// out behind. The time of impact of the shapes themselves says only Touching, so the circle of radius a quarter of
// the shape's core radius about its centroid (inside the shape), and at most half the centroid's gap so that it
// starts apart, is swept instead: stopped there, the body overlaps by at most three quarters of its core and its
// contact pushes it back out in front. A body sliding or rolling along keeps its centroid a core radius away. Under a
// crowd's lasting pressure (the spinner's, 20 g along its loop) the gap may halve step after step; the tolerance
// shrinks with it, so the centroid comes ever closer but never crosses (unless it starts on the shape).
double coreImpact(const ShapeData& mine, const Sweep& mySweep, const Geometry& theirs, const Sweep& theirSweep) {
    const Vec2& centroid = mine.unitMass.centroid;
    const double core = withKind(mine.geometry, [](auto kind, const auto& s) { return kind.coreRadius(s); });
    if (!(core > 0.0)) return 1.0;  // no area (a segment): no centre to keep out
    const Transform start = mySweep.at(0.0), ground = theirSweep.at(0.0);
    const DistanceOutput gap = shapeDistance(Circle{centroid, 0.0}, start, theirs, ground);  // centroid to shape
    const double radius = std::min(0.25 * core, 0.5 * gap.distance);
    if (!(radius > 0.0)) return 1.0;  // the centroid already lies on the shape: nothing to tell
    const double tolerance = std::min(kToiTolerance, 0.5 * radius);
    // The shape (convex, still) lies beyond the line through its closest point across gap.normal, so the circle
    // cannot come within the tolerance of it while the centroid's advance along the normal (its origin's, and at most
    // the centroid's distance from the origin per radian turned) stays under gap - radius - tolerance: most touching
    // pairs, a body sliding or rolling along among them, are done here without a time of impact.
    const double advance = std::max(0.0, (mySweep.p1 - mySweep.p0).dot(gap.normal)) +
                           std::abs(mySweep.a1 - mySweep.a0) * centroid.norm();
    if (advance < gap.distance - radius - tolerance) return 1.0;
    const ToiResult r = timeOfImpact(Circle{centroid, radius}, mySweep, theirs, theirSweep, tolerance);
    // Failed: proven apart only up to r.t, and no further (as consider).
    return r.state == ToiState::Hit || r.state == ToiState::Failed ? r.t : 1.0;
}

}  // namespace

Sweep ContinuousStage::sweepOf(const WorldImpl& w, std::uint32_t slot) const {
    const BodyData& b = w.bodies[slot];
    if (!b.awake()) return {b.xf.p, b.xf.p, b.angle, b.angle};
    const SolverBodySim& sim = w.solver.sim(static_cast<std::size_t>(b.awakeIndex));
    // The origin's start pose; its path is taken as straight (exact when the centre of mass is the origin).
    const Vec2 start = sim.center0 - sim.q0.apply(b.localCenter);
    return {start, b.xf.p, sim.angle0, b.angle};
}

double ContinuousStage::deepening(const Geometry& a, const Sweep& sa, const Geometry& b, const Sweep& sb,
                                  double slop) {
    // Shapes touching at the start can still be carried into each other within the step: by turning (a point at R
    // from its origin moves R per radian) or by approaching across the line that separates them at the start
    // (sliding along it cannot make convex shapes overlap). No overlap grows faster than `reach` over the sweep,
    // so samples half a slop apart in that measure cannot step over an overlap deeper than the slop.
    const Transform xa = sa.at(0.0), xb = sb.at(0.0);
    const Vec2 motion = (sa.p1 - sa.p0) - (sb.p1 - sb.p0);
    Vec2 n = Vec2::Zero();  // from a to b
    const DistanceOutput gap = shapeDistance(a, xa, b, xb);
    if (gap.distance > 0.0) {
        n = gap.normal;
    } else {
        const Manifold m = collide(a, xa, b, xb);
        if (m.pointCount > 0) n = m.normal;
    }
    const double approach = n.isZero() ? motion.norm() : std::max(0.0, motion.dot(n));
    const double reach = approach + std::abs(sa.a1 - sa.a0) * turningRadius(a) +
                         std::abs(sb.a1 - sb.a0) * turningRadius(b);
    if (!(reach > slop)) return 1.0;  // cannot overlap by more than the slop: the contacts' business
    // Deeper than the slop; or, for a pair that already starts deeper (spawned so, or pressed in: the contacts'
    // push-out is on it), half a slop deeper than it starts, so its own overlap never counts as an impact.
    const double start = deepest(a, xa, b, xb);
    const double limit = start > -slop ? -slop : start - 0.5 * slop;
    const int samples = static_cast<int>(std::min(4096.0, std::ceil(reach / (0.5 * slop))));
    for (int s = 1; s <= samples; ++s) {
        const double u = static_cast<double>(s) / samples;
        const Transform ua = sa.at(u), ub = sb.at(u);
        if (deepest(a, ua, b, ub) < limit) return static_cast<double>(s - 1) / samples;
        if (!(shapeDistance(a, ua, b, ub).distance > kToiTolerance)) continue;
        // Apart: the time of impact over the rest proves how long they stay so (no overlap at all), and the
        // sampling resumes from the last sample inside that time (a bullet leaving a wall it bounced off is done).
        const ToiResult rest =
            timeOfImpact(a, {ua.p, sa.p1, sa.angleAt(u), sa.a1}, b, {ub.p, sb.p1, sb.angleAt(u), sb.a1});
        if (rest.state == ToiState::Separated) return 1.0;
        const int proven = static_cast<int>(std::floor((u + rest.t * (1.0 - u)) * samples));
        s = std::max(s, std::min(proven, samples - 1));
    }
    return 1.0;
}

void ContinuousStage::consider(Candidate& c, const ToiResult& r, const Geometry& mine, const Geometry& theirs,
                               const Sweep& theirSweep, double slop) {
    if (r.state == ToiState::Hit) {
        c.t = std::min(c.t, r.t);
    } else if (r.state == ToiState::Failed) {
        // No contact proven, so none is made up (the velocity stays, no contact is added); but the pair is only
        // proven apart up to r.t, so the body goes no further than that: exact detection never tunnels.
        c.t = std::min(c.t, r.t);
    } else if (r.state == ToiState::Touching && c.continuous && c.t > 0.0) {
        c.t = std::min(c.t, deepening(mine, c.sweep, theirs, theirSweep, slop));
    }
}

void ContinuousStage::run(WorldImpl& w) {
    impacts_ = 0;
    const double slop = w.settings.linearSlop;
    candidates_.clear();
    // A fast discrete body meets only still bodies (static, sleeping or resting kinematic ones). While no movable
    // body is still, the static tree alone holds what it can meet; with no static shape either, it meets nothing
    // here (a cloud of debris in empty space). Asked once, at the first fast discrete body.
    enum class Still { Unknown, None, StaticOnly, Any } still = Still::Unknown;
    auto stillness = [&] {
        if (still == Still::Unknown) {
            const bool movable = std::any_of(w.bodies.begin(), w.bodies.end(), [](const BodyData& o) {
                return o.alive && o.type != BodyType::Static && !o.awake();
            });
            still = movable ? Still::Any : w.broadPhase.staticProxyCount() > 0 ? Still::StaticOnly : Still::None;
        }
        return still;
    };
    for (std::uint32_t i = 0; i < w.awake.size(); ++i) {
        const BodyData& b = w.bodies[w.awake[i]];
        if (b.type != BodyType::Dynamic || !b.collides || b.shapeHead == kNullIndex) continue;  // touches nothing
        const Sweep s = sweepOf(w, w.awake[i]);
        const bool continuous = b.detection != CollisionDetection::Discrete;
        const double travel = (s.p1 - s.p0).norm() + std::abs(s.a1 - s.a0) * b.extent;
        if (continuous || (travel > 0.5 * b.coreRadius && stillness() != Still::None))
            candidates_.push_back({i, s, continuous, 1.0});
    }
    if (candidates_.empty()) return;

    // Exact pairs go to the batch (the CPU, or the GPU through the CUDA layer); the paper's sampled method is
    // solved here, one pair at a time.
    // The batch's shape table is every shape slot's geometry, rebuilt only when shapes are created or destroyed: a GPU
    // solver keeps it on the device while shapesRevision stays the same. An entry of the batch is a shape on its
    // body's sweep.
    if (shapeTableRevision_ != w.shapeRevision) {
        batch_.clear();
        for (const ShapeData& shape : w.shapes) batch_.addShape(shape.geometry);
        shapeTableRevision_ = w.shapeRevision;
    } else {
        batch_.clearBodiesAndPairs();
    }
    batch_.shapesRevision = w.shapeRevision;
    batchBody_.assign(w.shapes.size(), -1);
    auto inBatch = [&](std::uint32_t shape, const Sweep& sweep) {
        std::int32_t& index = batchBody_[shape];
        if (index < 0) index = batch_.addBody(static_cast<std::int32_t>(shape), sweep);
        return index;
    };
    pairCandidate_.clear();
    pairPartner_.clear();
    pairPartnerCandidate_.clear();
    pairShapes_.clear();
    candidateOf_.assign(w.bodies.size(), -1);
    for (std::uint32_t k = 0; k < candidates_.size(); ++k)
        if (w.bodies[w.awake[candidates_[k].awakeIndex]].detection == CollisionDetection::ContinuousExact)
            candidateOf_[w.awake[candidates_[k].awakeIndex]] = static_cast<std::int32_t>(k);
    // Each body's sweep, made once per run: a body of a crowd is found by many queries.
    sweeps_.resize(w.bodies.size());
    motions_.resize(w.bodies.size());
    sweepMade_.assign(w.bodies.size(), 0);
    auto sweepFor = [&](std::uint32_t slot) -> const Sweep& {
        if (!sweepMade_[slot]) {
            sweeps_[slot] = sweepOf(w, slot);
            motions_[slot] = toKernel(sweeps_[slot]);
            sweepMade_[slot] = 1;
        }
        return sweeps_[slot];
    };
    const auto& radius = batch_.shapes.boundingRadius;  // per shape slot (the shape table's order), about the origin
    for (std::uint32_t k = 0; k < candidates_.size(); ++k) {
        Candidate& c = candidates_[k];
        const std::uint32_t slot = w.awake[c.awakeIndex];
        const BodyData& b = w.bodies[slot];
        const kernel::Motion mine = toKernel(c.sweep);
        w.forEachShape(b, [&](std::uint32_t mineShape, const ShapeData& shape) {
            if (shape.sensor) return;  // sensors stop nothing and are stopped by nothing
            const Geometry& myGeometry = shape.geometry;
            found_.clear();
            auto keep = [&](std::uint32_t other) {
                if (w.shapes[other].body != slot && !w.shapes[other].sensor) found_.push_back(other);
                return true;
            };
            if (c.continuous || stillness() == Still::Any) w.broadPhase.query(sweptAabb(myGeometry, c.sweep), keep);
            else w.broadPhase.queryStatic(sweptAabb(myGeometry, c.sweep), keep);
            for (const std::uint32_t otherShape : found_) {
                // Shapes that may not collide (Filter.hpp) pass through each other here too; a pair with a contact
                // was allowed when it was made, one without is asked.
                if (!shouldCollide(shape.filter, w.shapes[otherShape].filter)) continue;
                const std::uint32_t low = std::min(mineShape, otherShape), high = std::max(mineShape, otherShape);
                if (w.pairFilter && !w.contactExists(low, high) && !w.pairAllowed(mineShape, otherShape)) continue;
                const std::uint32_t other = w.shapes[otherShape].body;
                const BodyData& o = w.bodies[other];
                const Geometry& theirGeometry = w.shapes[otherShape].geometry;
                const bool still = !o.awake();
                if (!c.continuous && !still) continue;  // fast discrete bodies: static (and sleeping) bodies only
                if (const auto* piece = std::get_if<ChainSegment>(&theirGeometry)) {
                    // A chain is one-sided: a body that starts behind a piece passes through it, as in the narrow
                    // phase.
                    const Sweep& ground = sweepFor(other);
                    const double from = frontOffset(*piece, ground.at(0.0), myGeometry, c.sweep.at(0.0));
                    if (from < 0.0) continue;
                    // A body whose centre ends the step at least half its core radius in front of the piece's line
                    // has not passed it, and the contacts answer its overlap (a continuous body's only if it came
                    // no more than a quarter core radius closer to the line: it slides along, it does not strike).
                    // Rolling along a curved chain sweeps into the next piece's line at every concave joint: an
                    // impact there would put the body back with its speed kept and gain energy each step.
                    const double to = frontOffset(*piece, ground.at(1.0), myGeometry, c.sweep.at(1.0));
                    if (to >= 0.5 * b.coreRadius && (!c.continuous || from - to <= 0.25 * b.coreRadius)) continue;
                }
                if (b.detection == CollisionDetection::ContinuousSampled) {
                    const Sweep& theirs = sweepFor(other);
                    const double before = c.t;
                    consider(c, sampledTimeOfImpact(myGeometry, c.sweep, theirGeometry, theirs, b.precision),
                             myGeometry, theirGeometry, theirs, slop);
                    if (w.preSolve && c.t < before && !impactAllowed(w, mineShape, c.sweep, otherShape, theirs, c.t))
                        c.t = before;
                } else {
                    // Two exact candidates: one test serves both, asked by the one in the lower slot.
                    const std::int32_t partner = candidateOf_[other];
                    if (partner >= 0 && other < slot) continue;
                    // Most pairs of a crowd pass far apart: their answer (Separated) is known without the batch.
                    const Sweep& theirs = sweepFor(other);
                    if (kernel::boundsStayApart(mine, radius[mineShape], motions_[other], radius[otherShape],
                                                batch_.tolerance))
                        continue;
                    batch_.addPair(inBatch(mineShape, c.sweep), inBatch(otherShape, theirs));
                    pairCandidate_.push_back(k);
                    pairPartner_.push_back(other);
                    pairPartnerCandidate_.push_back(partner);
                    pairShapes_.emplace_back(mineShape, otherShape);
                }
            }
        });
    }
    if (batch_.pairCount() > 0) {
        if (solver_) solver_->solve(batch_, batchResult_);
        else solveOnCpu(batch_, batchResult_, w.executor);  // on the step's threads
        for (std::size_t p = 0; p < pairCandidate_.size(); ++p) {
            Candidate& c = candidates_[pairCandidate_[p]];
            const Geometry& mine = w.shapes[pairShapes_[p].first].geometry;
            const Geometry& theirs = w.shapes[pairShapes_[p].second].geometry;
            const ToiResult r = batchResult_.toi(p);
            const auto [mineShape, otherShape] = pairShapes_[p];
            const Sweep& theirSweep = sweeps_[pairPartner_[p]];
            const double before = c.t;
            consider(c, r, mine, theirs, theirSweep, slop);
            if (r.state == ToiState::Touching && !c.continuous && w.bodies[pairPartner_[p]].type == BodyType::Static)
                c.t = std::min(c.t, coreImpact(w.shapes[mineShape], c.sweep, theirs, theirSweep));
            if (w.preSolve && c.t < before && !impactAllowed(w, mineShape, c.sweep, otherShape, theirSweep, c.t))
                c.t = before;
            if (pairPartnerCandidate_[p] >= 0) {
                Candidate& d = candidates_[static_cast<std::size_t>(pairPartnerCandidate_[p])];
                const double partnerBefore = d.t;
                consider(d, r, theirs, mine, c.sweep, slop);
                if (w.preSolve && d.t < partnerBefore &&
                    !impactAllowed(w, otherShape, theirSweep, mineShape, c.sweep, d.t))
                    d.t = partnerBefore;
            }
        }
    }

    // Each body that meets something goes back to the pose of its first impact, its velocity kept: the next step's
    // contact answers the impact with the solver's rules.
    for (const Candidate& c : candidates_) {
        if (!(c.t < 1.0)) continue;
        ++impacts_;
        BodyData& b = w.bodies[w.awake[c.awakeIndex]];
        b.xf = c.sweep.at(c.t);
        b.angle = c.sweep.angleAt(c.t);
        b.center = b.xf.apply(b.localCenter);
        w.updateBoxes(b);
        if (w.proxyOutgrown(b)) w.solver.deferProxy(c.awakeIndex);  // moved once, after this stage
    }
}

}  // namespace physim
