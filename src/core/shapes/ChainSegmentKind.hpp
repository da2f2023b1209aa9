#pragma once
// The chain segment's room: everything a piece of a chain provides (ShapeKind.hpp lists what a kind must).
// Internal. ChainSegmentKind.cpp holds its checks, outline and narrow phase: the segment's (CollideRounded.cpp),
// one-sided and smoothed across the joints by the ghost points (the rule is written there).

#include "SegmentKind.hpp"

namespace physim {

/// The signed distance (m) of the centre of b's core (b placed by xb) from the line of the piece placed by xa,
/// positive in front (< 0: behind, right of point1 -> point2; one-sided, the narrow phase gives no contact); infinite for another chain piece, which it never touches. The
/// Continuous stage skips a piece a body starts behind, as the narrow phase does, or stays well in front of.
double frontOffset(const ChainSegment& a, const Transform& xa, const Geometry& b, const Transform& xb);

/// The manifold of a chain piece (a) and a rounded core b (body-local, placed by xb); normal from a to b.
NarrowResult collideChainSegment(const ChainSegment& a, const Transform& xa, const RoundedCore& b,
                                 const Transform& xb, double margin);

/// Whether collideChainSegment surely gives the circle b no contact because its centre lies clearly beyond an end of
/// the piece where the neighbour answers for it, decided in a few products without the routines, and for how long:
/// -1 where it does not; else how far (m) the circle's centre may move relative to the piece with it still so
/// (StaysEmpty, at any margin; 0: below rounding's due).
double circleLeftToNeighbour(const ChainSegment& a, const Transform& xa, const Circle& b, const Transform& xb);

/// collideChainSegment for a circle: empty at once where circleLeftToNeighbour says so, the routine otherwise, with
/// the circle placed in the piece's frame once for both.
NarrowResult collideChainCircle(const ChainSegment& a, const Transform& xa, const Circle& b, const Transform& xb,
                                double margin);

template <>
struct ShapeKind<ChainSegment> {
    static constexpr const char* name = "chain segment";
    static constexpr kernel::ShapeKind kernelKind = kernel::kChainSegment;
    static constexpr int minVertices = 2, maxVertices = 2;
    static constexpr const char* vertexCounts = "2 (its end points)";

    static MassProperties mass(const ChainSegment& c) { return ShapeKind<Segment>::mass(c.segment); }
    static Aabb aabb(const ChainSegment& c, const Transform& xf) { return ShapeKind<Segment>::aabb(c.segment, xf); }
    static double boundingRadius(const ChainSegment& c) { return ShapeKind<Segment>::boundingRadius(c.segment); }
    static double coreRadius(const ChainSegment&) { return 0.0; }
    static double turningRadius(const ChainSegment& c) { return ShapeKind<Segment>::turningRadius(c.segment); }
    static double extentAbout(const ChainSegment& c, const Vec2& p) {
        return ShapeKind<Segment>::extentAbout(c.segment, p);
    }
    static double meanWidth(const ChainSegment& c) { return ShapeKind<Segment>::meanWidth(c.segment); }
    static void validate(const ChainSegment& c);
    static std::vector<Vec2> outline(const ChainSegment& c, const Transform& xf) {
        return ShapeKind<Segment>::outline(c.segment, xf);
    }
    static ChainSegment placed(const ChainSegment& c, const Transform& xf) {
        return {xf.apply(c.ghost1), ShapeKind<Segment>::placed(c.segment, xf), xf.apply(c.ghost2)};
    }

    // One-sided, as its collisions: a ray from in front (moving against the left normal) hits; one from behind
    // passes through, so a ray cast out of a chain loop's inside leaves it.
    static LocalRayHit rayCast(const ChainSegment& c, const LocalRay& ray) {
        const Vec2 left = perp(c.segment.point2 - c.segment.point1);
        if (!(left.dot(ray.translation) < 0.0)) return {};
        return rayCastSegment(ray, c.segment.point1, c.segment.point2);
    }
    static bool containsPoint(const ChainSegment&, const Vec2&) { return false; }  // no area

    // The kernel sees a two-sided segment (never tunnels); the batch does not carry the ghosts.
    static void toKernel(const ChainSegment& c, kernel::Shape& k) {
        TwoPoints::toKernel(kernelKind, c.segment.point1, c.segment.point2, 0.0, k);
    }
    static ChainSegment fromBatch(const ContinuousBatch::Shapes& s, std::size_t i) {
        const Segment segment = ShapeKind<Segment>::fromBatch(s, i);
        return ChainSegment{segment.point1, segment, segment.point2};
    }
    static std::string radiusProblem(double radius) { return radius != 0.0 ? "a chain segment has radius 0" : ""; }
    static std::string kernelProblem(const ChainSegment&) { return {}; }

    // Ground against ground (another chain piece or a segment): no contact.
    static NarrowResult collide(const ChainSegment&, const Transform&, const Segment&, const Transform&, double) {
        return {};
    }
    static NarrowResult collide(const ChainSegment&, const Transform&, const ChainSegment&, const Transform&,
                                double) {
        return {};
    }
    // A wheel rolling on a chain meets its piece's neighbours within the margin: most are left to the neighbour.
    static NarrowResult collide(const ChainSegment& a, const Transform& xa, const Circle& b, const Transform& xb,
                                double margin) {
        return collideChainCircle(a, xa, b, xb, margin);
    }
    template <class T>
    static NarrowResult collide(const ChainSegment& a, const Transform& xa, const T& b, const Transform& xb,
                                double margin) {
        return collideChainSegment(a, xa, coreOf(b), xb, margin);
    }
};

}  // namespace physim
