// The Sensors stage (Sensors.hpp): each sensor's visitors, and the times within the step at which they came and went.

#include "Sensors.hpp"
#include "WorldImpl.hpp"

#include "physim/core/Filter.hpp"
#include "physim/core/TimeOfImpact.hpp"

#include <algorithm>
#include <cmath>

namespace physim {
namespace {

// A body's path over the step as a function of the fraction s in [0, 1]: its centre of mass and angle move along
// the chord from the start to the end plus s (s - 1) times the bend, the bend being half the step's change of
// velocity times dt. Under a constant force that is the parabola through every substep's pose of the solver's
// semi-implicit Euler, exactly; otherwise a curve through both ends that follows the velocities' change.
struct Path {
    Vec2 c0 = Vec2::Zero(), c1 = Vec2::Zero(), bend = Vec2::Zero();  // m
    double a0 = 0.0, a1 = 0.0, turnBend = 0.0;                      // rad
    Vec2 localCenter = Vec2::Zero();
    Transform end;
    double reach = 0.0;  // m per unit fraction: no point of the body moves faster along the path

    Transform at(double s) const {
        if (s >= 1.0) return end;
        const double b = s * (s - 1.0);
        const Vec2 c = c0 + s * (c1 - c0) + b * bend;
        const Rotation q = Rotation::fromAngle(a0 + s * (a1 - a0) + b * turnBend);
        return {c - q.apply(localCenter), q};
    }
};

// The box holding every pose of the shape along the path, from its box at the end: the end box moved back along
// the chord, both grown by how far the turn and the bend (at most a quarter of each) carry a point off the chord.
Aabb sweptBox(const Aabb& end, const Path& p, double extent) {
    const Vec2 back = p.c0 - p.c1;
    const double grow =
        (std::abs(p.a1 - p.a0) + 0.25 * std::abs(p.turnBend)) * extent + 0.25 * p.bend.norm();
    const Aabb start{end.lower + back, end.upper + back};
    return Aabb::merged(end, start).fattened(grow);
}

double gapAt(const Geometry& a, const Path& pa, const Geometry& b, const Path& pb, double s) {
    return shapeDistance(a, pa.at(s), b, pb.at(s)).distance;
}

// The first fraction at which the shapes come within kSensorTolerance, walking from the step's start (forward) or
// from its end; -1 when they never do. Conservative advancement: the gap closes no faster than the two reaches
// together, so the walk never steps past a touch. A walk that has not settled after its last try returns where it
// stands (early) when `touches` says the far end touches, else -1.
double firstTouch(const Geometry& a, const Path& pa, const Geometry& b, const Path& pb, bool forward, bool touches) {
    constexpr int kTries = 100;
    const double reach = pa.reach + pb.reach;
    double walked = 0.0;
    for (int i = 0; i < kTries; ++i) {
        const double s = forward ? walked : 1.0 - walked;
        const double gap = gapAt(a, pa, b, pb, s);
        if (gap < kSensorTolerance) return s;
        if (!(reach > 0.0)) return -1.0;
        walked += gap / reach;
        if (walked > 1.0) return -1.0;
    }
    return touches ? (forward ? walked : 1.0 - walked) : -1.0;
}

}  // namespace

std::vector<SensorStage::Sensor>::iterator SensorStage::find(std::uint32_t shape) {
    return std::lower_bound(sensors_.begin(), sensors_.end(), shape,
                            [](const Sensor& s, std::uint32_t slot) { return s.shape < slot; });
}

void SensorStage::add(std::uint32_t shape) {
    const auto at = find(shape);
    if (at != sensors_.end() && at->shape == shape) return;
    sensors_.insert(at, Sensor{shape, {}});
}

void SensorStage::remove(std::uint32_t shape) {
    const auto at = find(shape);
    if (at != sensors_.end() && at->shape == shape) sensors_.erase(at);
}

const std::vector<SensorStage::Visitor>* SensorStage::overlaps(std::uint32_t shape) const {
    const auto at = const_cast<SensorStage*>(this)->find(shape);
    return at != sensors_.end() && at->shape == shape ? &at->overlaps : nullptr;
}

void SensorStage::recordStarts(const WorldImpl& w) {
    if (starts_.size() < w.bodies.size()) starts_.resize(w.bodies.size());
    for (const std::uint32_t slot : w.awake) {
        const BodyData& b = w.bodies[slot];
        starts_[slot] = {b.center, b.v, b.angle, b.w, w.stepCount};
    }
}

void SensorStage::run(WorldImpl& w) {
    const std::uint64_t now = w.stepCount;
    const double dt = w.dt;
    auto pathOf = [&](std::uint32_t slot) {
        const BodyData& b = w.bodies[slot];
        Path p;
        p.c1 = b.center;
        p.a1 = b.angle;
        p.localCenter = b.localCenter;
        p.end = b.xf;
        if (slot < starts_.size() && starts_[slot].step == now) {
            const Start& s = starts_[slot];
            p.c0 = s.center;
            p.a0 = s.angle;
            p.bend = 0.5 * dt * (b.v - s.v);
            p.turnBend = 0.5 * dt * (b.w - s.w);
        } else {  // it did not move in this step
            p.c0 = p.c1;
            p.a0 = p.a1;
        }
        // |dc/ds| <= |c1 - c0| + |bend| over s in [0, 1]; likewise the angle, which moves a point by extent per rad.
        p.reach = (p.c1 - p.c0).norm() + p.bend.norm() +
                  (std::abs(p.a1 - p.a0) + std::abs(p.turnBend)) * b.extent;
        return p;
    };

    // A proxy's box holds its shape's whole path over the step unless the step gave it a new box (it left the old
    // one: the box holds the path ahead, and the turn, from where it was then). A sensor finds the first by querying
    // the trees with its swept box; the others, in the broad phase's move buffer (the step's moved proxies), are
    // listed here with their swept boxes, so a scene at rest or slow adds nothing to the list.
    movers_.clear();
    for (const std::int32_t key : w.broadPhase.movedProxies()) {
        const std::uint32_t shape = w.broadPhase.shapeOf(key);
        const ShapeData& d = w.shapes[shape];
        if (d.sensor) continue;
        const BodyData& b = w.bodies[d.body];
        movers_.push_back({shape, sweptBox(d.aabb, pathOf(d.body), b.extent)});
    }

    for (Sensor& sensor : sensors_) {
        const ShapeData& S = w.shapes[sensor.shape];
        const BodyData& SB = w.bodies[S.body];
        const Path ps = pathOf(S.body);
        candidates_.clear();
        if (S.proxy != kNullIndex) {  // a sensor on a body that collides with nothing sees nothing
            const Aabb swept = sweptBox(S.aabb, ps, SB.extent);
            w.broadPhase.query(swept, [&](std::uint32_t other) {
                candidates_.push_back(other);
                return true;
            });
            for (const Mover& m : movers_)
                if (m.swept.overlaps(swept)) candidates_.push_back(m.shape);
        }
        for (const Visitor& o : sensor.overlaps) candidates_.push_back(o.shape);
        std::sort(candidates_.begin(), candidates_.end());
        candidates_.erase(std::unique(candidates_.begin(), candidates_.end()), candidates_.end());

        next_.clear();
        auto old = sensor.overlaps.cbegin();
        for (const std::uint32_t v : candidates_) {
            while (old != sensor.overlaps.cend() && old->shape < v) ++old;
            const ShapeData& V = w.shapes[v];
            const bool wasIn = old != sensor.overlaps.cend() && old->shape == v && V.alive &&
                               old->generation == V.generation;
            if (!V.alive) continue;  // destroyed: its overlap ends silently
            const BodyData& VB = w.bodies[V.body];
            auto event = [&](double fraction) {
                return SensorEvent{ShapeId{sensor.shape, S.generation}, ShapeId{v, V.generation},
                                   BodyId{S.body, SB.generation}, BodyId{V.body, VB.generation}, fraction,
                                   fraction * dt};
            };
            const bool seen = V.body != S.body && !V.sensor && V.proxy != kNullIndex && S.proxy != kNullIndex &&
                              (SB.type != BodyType::Static || VB.type != BodyType::Static) &&
                              shouldCollide(S.filter, V.filter);
            if (!seen) {
                if (wasIn) events_.end.push_back(event(0.0));
                continue;
            }
            const Path pv = pathOf(V.body);
            const bool endIn = gapAt(S.geometry, ps, V.geometry, pv, 1.0) < kSensorTolerance;
            if (endIn) next_.push_back({v, V.generation});
            if (wasIn == endIn) {
                if (wasIn) continue;
                // Outside at both ends: a crossing within the step, or nothing.
                const double in = firstTouch(S.geometry, ps, V.geometry, pv, true, false);
                if (in < 0.0) continue;
                const double out = firstTouch(S.geometry, ps, V.geometry, pv, false, true);
                events_.begin.push_back(event(in));
                events_.end.push_back(event(std::max(in, out)));
            } else if (endIn) {
                // A walk that steps past the end found the gap there below the tolerance only just: it came at the end.
                const double in = firstTouch(S.geometry, ps, V.geometry, pv, true, true);
                events_.begin.push_back(event(in < 0.0 ? 1.0 : in));
            } else {
                // Not touching at the start either: it stopped being seen there (moved away between steps).
                const double out = firstTouch(S.geometry, ps, V.geometry, pv, false, true);
                events_.end.push_back(event(std::max(0.0, out)));
            }
        }
        sensor.overlaps.swap(next_);
    }
}

}  // namespace physim
