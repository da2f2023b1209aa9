// The public API of the queries (World.hpp, "queries"): rays, swept shapes and overlaps, answered through the broad
// phase's two trees and each kind's own geometry (shapes/RayCast.hpp, the kernel's distance and time of impact).
// Nothing here writes to the world.

#include "physim/core/World.hpp"

#include "KernelBridge.hpp"
#include "WorldImpl.hpp"
#include "shapes/ShapeKinds.hpp"

#include "physim/core/Validate.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace physim {
namespace {

std::string describe(const Vec2& v) {
    std::ostringstream os;
    os.precision(17);
    os << "(" << v.x() << ", " << v.y() << ")";
    return os.str();
}

void requireFiniteVector(const char* call, const char* name, const Vec2& v) {
    requireFinite(std::string("World::") + call + ": " + name, v);
}

void requireTranslation(const char* call, const Vec2& translation) {
    requireFiniteVector(call, "translation", translation);
    if (translation.x() == 0.0 && translation.y() == 0.0)
        throw std::invalid_argument(std::string("physim: World::") + call + ": translation must not be zero, got " +
                                    describe(translation));
}

void requireBox(const char* call, const Aabb& box) {
    requireFiniteVector(call, "box lower", box.lower);
    requireFiniteVector(call, "box upper", box.upper);
    if (box.lower.x() > box.upper.x() || box.lower.y() > box.upper.y())
        throw std::invalid_argument(std::string("physim: World::") + call + ": box lower " + describe(box.lower) +
                                    " exceeds upper " + describe(box.upper));
}

void requirePose(const char* call, const Geometry& geometry, const Transform& pose) {
    requireFiniteVector(call, "pose position", pose.p);
    const double unit = pose.q.c * pose.q.c + pose.q.s * pose.q.s;
    if (!(std::abs(unit - 1.0) <= 1e-6))  // NaN and infinite fail too
        throw std::invalid_argument(std::string("physim: World::") + call +
                                    ": pose rotation must be a unit (cos, sin), got " +
                                    describe(Vec2(pose.q.c, pose.q.s)));
    try {
        validate(geometry);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("physim: World::") + call + ": invalid geometry: " + e.what());
    }
}

// Whether a query with this filter sees the shape (sensors never).
bool seen(const ShapeData& shape, const QueryFilter& filter) {
    return !shape.sensor && shouldQuery(filter, shape.filter);
}

}  // namespace

namespace {

// The ray cast every form shares: onHit(hit) returns the new maxFraction as RayCallback does.
template <class OnHit>
void castRayImpl(const WorldImpl& w, const Vec2& origin, const Vec2& translation, const QueryFilter& filter,
                 OnHit&& onHit) {
    w.broadPhase.rayCast(origin, translation, 1.0, [&](std::uint32_t slot, double maxFraction) -> double {
        const ShapeData& shape = w.shapes[slot];
        if (!seen(shape, filter)) return maxFraction;
        const BodyData& body = w.bodies[shape.body];
        const LocalRayHit local = withKind(shape.geometry, [&](auto kind, const auto& s) {
            return kind.rayCast(s, toLocal(origin, translation, maxFraction, body.xf));
        });
        if (!local.hit) return maxFraction;
        const LocalRayHit h = toWorld(local, body.xf);
        const RayHit hit{ShapeId{slot, shape.generation}, BodyId{shape.body, body.generation}, h.point, h.normal,
                         h.fraction};
        const double value = onHit(hit);
        if (value < 0.0) return maxFraction;  // ignored
        return std::min(value, maxFraction);
    });
}

}  // namespace

std::optional<RayHit> World::castRayClosest(const Vec2& origin, const Vec2& translation,
                                            const QueryFilter& filter) const {
    impl_->requireNotStepping("castRayClosest");
    requireFiniteVector("castRayClosest", "origin", origin);
    requireTranslation("castRayClosest", translation);
    std::optional<RayHit> best;
    castRayImpl(*impl_, origin, translation, filter, [&](const RayHit& hit) {
        best = hit;
        return hit.fraction;
    });
    return best;
}

std::vector<RayHit> World::castRayAll(const Vec2& origin, const Vec2& translation, const QueryFilter& filter) const {
    impl_->requireNotStepping("castRayAll");
    requireFiniteVector("castRayAll", "origin", origin);
    requireTranslation("castRayAll", translation);
    std::vector<RayHit> hits;
    castRayImpl(*impl_, origin, translation, filter, [&](const RayHit& hit) {
        hits.push_back(hit);
        return 1.0;
    });
    // Nearest first; equal fractions by shape slot, so the order is the same on every run.
    std::sort(hits.begin(), hits.end(), [](const RayHit& a, const RayHit& b) {
        return a.fraction < b.fraction || (a.fraction == b.fraction && a.shape.index < b.shape.index);
    });
    return hits;
}

void World::castRay(const Vec2& origin, const Vec2& translation, const QueryFilter& filter,
                    const RayCallback& callback) const {
    impl_->requireNotStepping("castRay");
    requireFiniteVector("castRay", "origin", origin);
    requireTranslation("castRay", translation);
    if (!callback) throw std::invalid_argument("physim: World::castRay: callback is empty");
    castRayImpl(*impl_, origin, translation, filter, [&](const RayHit& hit) {
        const double value = callback(hit);
        return std::isnan(value) ? -1.0 : value;
    });
}

namespace {

// The swept shape against every shape its swept box meets: onHit as in castRayImpl.
template <class OnHit>
void castShapeImpl(const WorldImpl& w, const Geometry& geometry, const Transform& pose, const Vec2& translation,
                   const QueryFilter& filter, OnHit&& onHit) {
    const Aabb start = computeAabb(geometry, pose);
    const Aabb swept{start.lower.cwiseMin(start.lower + translation), start.upper.cwiseMax(start.upper + translation)};
    const kernel::Shape cast = toKernel(geometry);
    const double angle = pose.q.angle();
    double maxFraction = 1.0;
    w.broadPhase.queryOften(swept, [&](std::uint32_t slot) {
        const ShapeData& shape = w.shapes[slot];
        if (!seen(shape, filter) || !shape.aabb.overlaps(swept)) return true;
        const BodyData& body = w.bodies[shape.body];
        // A chain piece is met from its front only: a cast that starts behind it passes.
        if (const auto* piece = std::get_if<ChainSegment>(&shape.geometry))
            if (frontOffset(*piece, body.xf, geometry, pose) < 0.0) return true;
        const Vec2 end = pose.p + maxFraction * translation;
        const kernel::Motion motion{{pose.p.x(), pose.p.y()}, {end.x(), end.y()}, angle, angle};
        const kernel::Motion still{{body.xf.p.x(), body.xf.p.y()}, {body.xf.p.x(), body.xf.p.y()}, body.angle,
                                   body.angle};
        const kernel::Toi toi =
            kernel::timeOfImpact(cast, motion, toKernel(shape.geometry), still, kToiTolerance, 100);
        if (toi.state != kernel::kHit && toi.state != kernel::kTouching) return true;
        RayHit hit{ShapeId{slot, shape.generation}, BodyId{shape.body, body.generation},
                   Vec2(toi.point.x, toi.point.y), Vec2::Zero(), toi.t * maxFraction};
        if (toi.state == kernel::kHit && (toi.normal.x != 0.0 || toi.normal.y != 0.0))
            hit.normal = -Vec2(toi.normal.x, toi.normal.y);  // the kernel's is from the cast shape to the target
        if (toi.state == kernel::kTouching) hit.fraction = 0.0;
        const double value = onHit(hit);
        if (value < 0.0) return true;
        if (!(value > 0.0)) return false;
        maxFraction = std::min(value, maxFraction);
        return true;
    });
}

}  // namespace

std::optional<RayHit> World::castShape(const Geometry& geometry, const Transform& pose, const Vec2& translation,
                                       const QueryFilter& filter) const {
    impl_->requireNotStepping("castShape");
    requirePose("castShape", geometry, pose);
    requireTranslation("castShape", translation);
    std::optional<RayHit> best;
    castShapeImpl(*impl_, geometry, pose, translation, filter, [&](const RayHit& hit) {
        if (!best || hit.fraction < best->fraction) best = hit;
        return hit.fraction;
    });
    return best;
}

void World::castShape(const Geometry& geometry, const Transform& pose, const Vec2& translation,
                      const QueryFilter& filter, const RayCallback& callback) const {
    impl_->requireNotStepping("castShape");
    requirePose("castShape", geometry, pose);
    requireTranslation("castShape", translation);
    if (!callback) throw std::invalid_argument("physim: World::castShape: callback is empty");
    castShapeImpl(*impl_, geometry, pose, translation, filter, [&](const RayHit& hit) {
        const double value = callback(hit);
        return std::isnan(value) ? -1.0 : value;
    });
}

namespace {

// The shapes whose tight box meets `box`, to onShape(slot) (false stops). The tree's candidates are gathered a batch
// at a time with their records asked for from memory, then checked: each record's line then arrives while the walk
// goes on instead of stalling the check (a record is several lines, far apart from the next).
template <class OnShape>
void overlapAabbImpl(const WorldImpl& w, const Aabb& box, const QueryFilter& filter, OnShape&& onShape) {
    constexpr std::size_t kBatch = 32;
    std::uint32_t batch[kBatch];
    std::size_t count = 0;
    const auto flush = [&] {
        for (std::size_t i = 0; i < count; ++i) {
            const ShapeData& shape = w.shapes[batch[i]];
            if (shape.aabb.overlaps(box) && seen(shape, filter) && !onShape(batch[i])) return false;
        }
        count = 0;
        return true;
    };
    bool go = true;
    w.broadPhase.queryOften(box, [&](std::uint32_t slot) {
        __builtin_prefetch(&w.shapes[slot].aabb);
        __builtin_prefetch(&w.shapes[slot].filter);
        batch[count++] = slot;
        if (count == kBatch) go = flush();
        return go;
    });
    if (go) flush();
}

}  // namespace

void World::overlapAabb(const Aabb& box, const QueryFilter& filter, const OverlapCallback& callback) const {
    impl_->requireNotStepping("overlapAabb");
    requireBox("overlapAabb", box);
    if (!callback) throw std::invalid_argument("physim: World::overlapAabb: callback is empty");
    const WorldImpl& w = *impl_;
    overlapAabbImpl(w, box, filter,
                    [&](std::uint32_t slot) { return callback(ShapeId{slot, w.shapes[slot].generation}); });
}

std::vector<ShapeId> World::overlapAabb(const Aabb& box, const QueryFilter& filter) const {
    impl_->requireNotStepping("overlapAabb");
    requireBox("overlapAabb", box);
    const WorldImpl& w = *impl_;
    std::vector<ShapeId> found;
    overlapAabbImpl(w, box, filter, [&](std::uint32_t slot) {
        found.push_back(ShapeId{slot, w.shapes[slot].generation});
        return true;
    });
    return found;
}

std::vector<ShapeId> World::overlapPoint(const Vec2& point, const QueryFilter& filter) const {
    impl_->requireNotStepping("overlapPoint");
    requireFiniteVector("overlapPoint", "point", point);
    const WorldImpl& w = *impl_;
    std::vector<ShapeId> found;
    w.broadPhase.queryOften(Aabb{point, point}, [&](std::uint32_t slot) {
        const ShapeData& shape = w.shapes[slot];
        if (!seen(shape, filter) || !shape.aabb.overlaps(Aabb{point, point})) return true;
        const Vec2 local = w.bodies[shape.body].xf.applyInverse(point);
        const bool inside =
            withKind(shape.geometry, [&](auto kind, const auto& s) { return kind.containsPoint(s, local); });
        if (inside) found.push_back(ShapeId{slot, shape.generation});
        return true;
    });
    return found;
}

std::vector<ShapeId> World::overlapShape(const Geometry& geometry, const Transform& pose,
                                         const QueryFilter& filter) const {
    impl_->requireNotStepping("overlapShape");
    requirePose("overlapShape", geometry, pose);
    const WorldImpl& w = *impl_;
    const Aabb box = computeAabb(geometry, pose);
    const kernel::Shape query = toKernel(geometry);
    const kernel::Xf queryXf = toKernel(pose);
    std::vector<ShapeId> found;
    w.broadPhase.queryOften(box, [&](std::uint32_t slot) {
        const ShapeData& shape = w.shapes[slot];
        if (!seen(shape, filter) || !shape.aabb.overlaps(box)) return true;
        const kernel::Distance d =
            kernel::shapeDistance(query, queryXf, toKernel(shape.geometry), toKernel(w.bodies[shape.body].xf));
        if (d.distance == 0.0) found.push_back(ShapeId{slot, shape.generation});
        return true;
    });
    return found;
}

}  // namespace physim
