#pragma once
// The shared kernel's shapes of every kind built by hand (src/core/ContinuousKernel.hpp's layout, as the kinds'
// rooms lay them out), and fast pairs of the kinds beyond the circle and the sharp polygon: capsules, rounded
// boxes, segments, chain segments and rounded polygons. Shared by the core's and the CUDA layer's tests.

#include "ContinuousKernel.hpp"

#include "physim/core/ContinuousBatch.hpp"
#include "physim/core/Math.hpp"
#include "physim/core/TimeOfImpact.hpp"
#include "support/RandomBatch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace physim::testing {

/// A circle of radius r about c.
inline kernel::Shape kernelCircle(double r, Vec2 c = Vec2::Zero()) {
    kernel::Shape s{};
    s.kind = kernel::kCircle;
    s.count = 1;
    s.radius = r;
    s.vertices[0] = {c.x(), c.y()};
    s.boundingRadius = c.norm() + r;
    return s;
}

/// A polygon core (counter-clockwise, or 2 points) grown by radius, of the given kind: outward unit normals for
/// each edge i -> i + 1 (for 2 points the edge there and back), bounding radius the farthest vertex plus radius.
inline kernel::Shape kernelRounded(kernel::ShapeKind kind, const std::vector<Vec2>& core, double radius) {
    kernel::Shape s{};
    s.kind = kind;
    s.count = static_cast<std::int32_t>(core.size());
    s.radius = radius;
    double reach = 0.0;
    for (int i = 0; i < s.count; ++i) {
        const Vec2 e = core[(i + 1) % s.count] - core[i];
        s.vertices[i] = {core[i].x(), core[i].y()};
        s.normals[i] = {e.y() / e.norm(), -e.x() / e.norm()};
        reach = std::max(reach, std::hypot(core[i].x(), core[i].y()));
    }
    s.boundingRadius = reach + radius;
    return s;
}

inline kernel::Shape kernelSegment(Vec2 p1, Vec2 p2) { return kernelRounded(kernel::kSegment, {p1, p2}, 0.0); }
inline kernel::Shape kernelChainSegment(Vec2 p1, Vec2 p2) {
    return kernelRounded(kernel::kChainSegment, {p1, p2}, 0.0);
}
inline kernel::Shape kernelCapsule(Vec2 c1, Vec2 c2, double r) { return kernelRounded(kernel::kCapsule, {c1, c2}, r); }
/// A box of half extents hw, hh about the origin grown by radius (0: a sharp box).
inline kernel::Shape kernelBox(double hw, double hh, double radius = 0.0) {
    return kernelRounded(kernel::kPolygon, {{-hw, -hh}, {hw, -hh}, {hw, hh}, {-hw, hh}}, radius);
}

inline kernel::Motion kernelMotion(const Sweep& s) { return {{s.p0.x(), s.p0.y()}, {s.p1.x(), s.p1.y()}, s.a0, s.a1}; }

/// Appends a kernel shape to the batch's shape arrays, as ContinuousBatch::addShape lays out a Geometry.
inline std::int32_t appendShape(ContinuousBatch& batch, const kernel::Shape& k) {
    auto& s = batch.shapes;
    const auto index = static_cast<std::int32_t>(s.kind.size());
    s.kind.push_back(k.kind);
    s.firstVertex.push_back(static_cast<std::int32_t>(s.vertexX.size()));
    s.vertexCount.push_back(k.count);
    s.radius.push_back(k.radius);
    s.boundingRadius.push_back(k.boundingRadius);
    for (int i = 0; i < k.count; ++i) {
        s.vertexX.push_back(k.vertices[i].x);
        s.vertexY.push_back(k.vertices[i].y);
        s.normalX.push_back(k.normals[i].x);
        s.normalY.push_back(k.normals[i].y);
    }
    return index;
}

/// One moving pair of kernel shapes: a sweeps across b.
using KernelPair = MovingPair<kernel::Shape>;

/// Fast movers (circle, sharp box, capsule, rounded box; 2 to 20 cm) shot at thin obstacles near the origin (a
/// segment, a capsule 1 cm thick, a rounded pentagon, a chain segment; 0.5 to 2 m long), every mover against every
/// obstacle in turn. The mover starts 0.3 to 3 m away, travels 1 to 20 m, aimed within 0.6 m of the centre, and
/// turns up to 6 rad either way; the obstacle drifts up to 0.1 m and turns up to 0.5 rad, or in every other run of
/// 16 pairs (every mover against every obstacle) spins like a propeller, up to 17 rad. Without continuous
/// detection most of these tunnel: a segment has no thickness at all. Pairs may start touching.
inline std::vector<KernelPair> roundedKindsPairs(int count, unsigned seed) {
    PairDraws draw(seed);
    auto in = [&](double lo, double hi) { return draw.in(lo, hi); };
    std::vector<KernelPair> pairs;
    for (int i = 0; i < count; ++i) {
        KernelPair p;
        const double size = in(0.02, 0.2), aspect = in(0.2, 1.0);
        switch (i % 4) {
            case 0: p.a = kernelCircle(size); break;
            case 1: p.a = kernelBox(size, aspect * size); break;
            case 2: p.a = kernelCapsule({-size, 0.0}, {size, 0.0}, aspect * 0.5 * size); break;
            default: p.a = kernelBox(0.6 * size, 0.6 * aspect * size, 0.4 * size);
        }
        const double length = in(0.5, 2.0);
        switch ((i / 4) % 4) {
            case 0: p.b = kernelSegment({-0.5 * length, 0.0}, {0.5 * length, 0.0}); break;
            case 1: p.b = kernelCapsule({-0.5 * length, 0.0}, {0.5 * length, 0.0}, 0.005); break;
            case 2: {
                std::vector<Vec2> pentagon;
                for (int k = 0; k < 5; ++k)
                    pentagon.emplace_back(0.3 * length * std::cos(2.0 * M_PI * k / 5.0),
                                          0.1 * length * std::sin(2.0 * M_PI * k / 5.0));
                p.b = kernelRounded(kernel::kPolygon, pentagon, 0.02);
                break;
            }
            default: p.b = kernelChainSegment({0.5 * length, 0.1}, {-0.5 * length, -0.1});
        }
        p.sa = draw.aimedSweep(0.3, 3.0, 0.6, 20.0, 6.0);
        const double b0 = in(-M_PI, M_PI), drift = in(-0.1, 0.1);
        const double spin = (i / 16) % 2 == 0 ? in(-0.5, 0.5) : in(-17.0, 17.0);
        p.sb = Sweep{Vec2::Zero(), Vec2(drift, -drift), b0, b0 + spin};
        pairs.push_back(p);
    }
    return pairs;
}

/// The pairs as a batch: each body its own shape, pair i = bodies 2i (a) and 2i + 1 (b).
inline ContinuousBatch kernelBatch(const std::vector<KernelPair>& pairs) {
    ContinuousBatch batch;
    for (const KernelPair& p : pairs) {
        const std::int32_t a = batch.addBody(appendShape(batch, p.a), p.sa);
        const std::int32_t b = batch.addBody(appendShape(batch, p.b), p.sb);
        batch.addPair(a, b);
    }
    return batch;
}

}  // namespace physim::testing
