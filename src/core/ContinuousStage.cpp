#include "ContinuousStage.hpp"

#include "WorldImpl.hpp"

#include <algorithm>

namespace physim {

Sweep ContinuousStage::sweepOf(const WorldImpl& w, std::uint32_t slot) const {
    const BodyData& b = w.bodies[slot];
    if (!b.awake()) return {b.xf.p, b.xf.p, b.angle, b.angle};
    const SolverBodySim& sim = w.sims[static_cast<std::size_t>(b.awakeIndex)];
    // The origin's start pose; its path is taken as straight (exact when the centre of mass is the origin).
    const Vec2 start = sim.center0 - sim.q0.apply(b.localCenter);
    return {start, b.xf.p, sim.angle0, b.angle};
}

void ContinuousStage::run(WorldImpl& w) {
    impacts_ = 0;
    candidates_.clear();
    for (std::uint32_t i = 0; i < w.awake.size(); ++i) {
        const BodyData& b = w.bodies[w.awake[i]];
        if (b.type != BodyType::Dynamic) continue;
        const Sweep s = sweepOf(w, w.awake[i]);
        const bool continuous = b.detection != CollisionDetection::Discrete;
        const double travel = (s.p1 - s.p0).norm() + std::abs(s.a1 - s.a0) * b.extent;
        if (continuous || travel > 0.5 * coreRadius(b.shape)) candidates_.push_back({i, s, continuous, 1.0});
    }
    if (candidates_.empty()) return;

    // Exact pairs against moving bodies go to the batch; the rest are solved here, one pair at a time.
    batch_.clear();
    pairCandidate_.clear();
    for (std::uint32_t k = 0; k < candidates_.size(); ++k) {
        Candidate& c = candidates_[k];
        const std::uint32_t slot = w.awake[c.awakeIndex];
        const BodyData& b = w.bodies[slot];
        found_.clear();
        w.broadPhase.query(sweptAabb(b.shape, c.sweep), [&](std::uint32_t other) {
            if (other != slot) found_.push_back(other);
            return true;
        });
        std::sort(found_.begin(), found_.end());  // tree order depends on history; results must not
        std::int32_t mine = -1;
        for (const std::uint32_t other : found_) {
            const BodyData& o = w.bodies[other];
            const bool staticLike = !o.awake();
            if (!c.continuous && !staticLike) continue;
            const Sweep theirs = sweepOf(w, other);
            if (b.detection == CollisionDetection::ContinuousSampled) {
                const ToiResult r = sampledTimeOfImpact(b.shape, c.sweep, o.shape, theirs, b.precision);
                if (r.state == ToiState::Hit) c.t = std::min(c.t, r.t);
            } else if (staticLike && !c.continuous) {
                const ToiResult r = timeOfImpact(b.shape, c.sweep, o.shape, theirs);
                if (r.state == ToiState::Hit) c.t = std::min(c.t, r.t);
            } else {
                if (mine < 0) mine = batch_.addBody(batch_.addShape(b.shape), c.sweep);
                batch_.addPair(mine, batch_.addBody(batch_.addShape(o.shape), theirs));
                pairCandidate_.push_back(k);
            }
        }
    }
    if (batch_.pairCount() > 0) {
        if (solver_) solver_->solve(batch_, batchResult_);
        else solveOnCpu(batch_, batchResult_, 1);
        for (std::size_t p = 0; p < pairCandidate_.size(); ++p) {
            const ToiResult r = batchResult_.toi(p);
            Candidate& c = candidates_[pairCandidate_[p]];
            if (r.state == ToiState::Hit) c.t = std::min(c.t, r.t);
        }
    }

    for (const Candidate& c : candidates_) {
        if (!(c.t < 1.0)) continue;
        ++impacts_;
        const std::uint32_t slot = w.awake[c.awakeIndex];
        BodyData& b = w.bodies[slot];
        const Transform at = c.sweep.at(c.t);
        b.xf = at;
        b.angle = c.sweep.angleAt(c.t);
        b.center = at.apply(b.localCenter);
        b.aabb = computeAabb(b.shape, b.xf);
        if (w.proxyOutgrown(b)) w.moveProxy(b);
    }
}

}  // namespace physim
