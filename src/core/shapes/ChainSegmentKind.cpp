// The chain segment's room: its checks and its narrow phase.
//
// A chain piece is its segment (CollideRounded.cpp) made one-sided and smooth across its joints:
// - a body whose core centre lies behind the piece's line (right of point1 -> point2) gets no contact;
// - a manifold along the piece's face normal (its left normal) stands;
// - any other normal comes from one end of the piece (the end it leans towards). An open end (ghost equal to the
//   end point) is a real corner: the manifold stands. At a convex joint (the chain turns right there) the normals
//   between the two pieces' face normals belong to the corner and stand; beyond the neighbour's normal the
//   neighbour's face answers, so this piece drops the manifold. At a flat or concave joint the neighbour's face
//   covers everything past the end, so this piece answers with its own face only: the manifold along its face
//   normal with the body's points clipped to the piece's span.
// So a body crossing a flat joint meets two faces with the same normal and never the corner between them.

#include "ChainSegmentKind.hpp"
#include "Faces.hpp"

#include "physim/core/Validate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace physim {
namespace {

// A joint whose turn has a smaller sine is flat.
constexpr double kFlatSine = 1e-9;

// The piece's face: the 2-vertex core's face 1 (edge point2 -> point1), whose normal is the left normal.
constexpr int kFace = 1;

// Where a core's vertices sit in the piece's frame, without placing the whole core: their mean (the centre for the
// one-sided test and the bounding circle) and the greatest squared distance of one from it, m^2. The arithmetic is
// relativeCore's, so the tests below see the same numbers as the manifold routines.
struct Spread {
    Vec2 centre;
    double reachSquared;
};

Spread spreadOf(const RoundedCore& b, const Transform& relative) {
    if (b.count == 1) return {Vec2::Zero() + relative.apply(b.vertices[0]), 0.0};  // the loops' bits, unrolled
    std::array<Vec2, Polygon::maxVertices> placed;
    Vec2 centre = Vec2::Zero();
    for (int i = 0; i < b.count; ++i) {
        placed[i] = relative.apply(b.vertices[i]);
        centre += placed[i];
    }
    centre /= b.count;
    double reach = 0.0;
    for (int i = 0; i < b.count; ++i) reach = std::max(reach, (placed[i] - centre).squaredNorm());
    return {centre, reach};
}

// Signed distance (m) of p from the piece's line, positive on its open side (the left of point1 -> point2).
double offsetFromLine(const ChainSegment& a, const Vec2& p) {
    const Vec2 along = a.segment.point2 - a.segment.point1;
    return perp(along).dot(p - a.segment.point1) / along.norm();
}

// The gap (m) between the segment p1-p2 and the bounding circle of a core of this spread and radius.
double gapTo(const Vec2& p1, const Vec2& p2, const Spread& b, double radius) {
    const Vec2 e = p2 - p1;
    const double t = std::clamp(e.dot(b.centre - p1) / e.squaredNorm(), 0.0, 1.0);
    const double distance = (b.centre - (p1 + t * e)).norm();
    const double reach = b.reachSquared > 0.0 ? std::sqrt(b.reachSquared) : 0.0;  // a circle's is 0: no root
    return distance - reach - radius;
}

// Whether a core of this spread and radius lies farther from the segment p1-p2 than any kept point may: its bounding
// circle is apart by more than the margin (points are kept up to max(margin, kSpeculativeMargin), Manifolds.hpp).
// Most pieces near a body are such; the routines below would find nothing.
bool apart(const Vec2& p1, const Vec2& p2, const Spread& b, double radius, double margin) {
    return gapTo(p1, p2, b, radius) > std::max(margin, kSpeculativeMargin);
}

// What StaysEmpty keeps back from a distance for rounding: the slack clearlyApart allows its own tests (a
// micrometre, and 1e-12 of the coordinates), far above the few units of 1e-16 of the coordinates that any of
// these tests, or the narrow phase's measure of the motion, can be off by.
double roundingDue(const Vec2& p1, const Vec2& p2, const Vec2& centre) {
    return 1e-6 + 1e-12 * std::max({p1.cwiseAbs().maxCoeff(), p2.cwiseAbs().maxCoeff(), centre.cwiseAbs().maxCoeff()});
}

// An answer the rules on directions emptied (a corner dropped beyond the neighbour's normal, a face manifold clipped
// to nothing) is fragile: a move far below any gap can bring the point back, so it promises nothing (StaysEmpty).
NarrowResult fragileIfEmpty(NarrowResult r) {
    r.empty.fragile = r.manifold.pointCount == 0;
    return r;
}

// An empty answer that stays empty while the core's centre moves less than `distance` (anyMargin), or while the
// margin plus that move stays below it: the allowance less rounding's due, never negative.
NarrowResult emptyFor(const RoundedCore& b, double distance, bool anyMargin, double due) {
    Vec2 centre = Vec2::Zero();  // the spread's centre in b's body frame
    for (int i = 0; i < b.count; ++i) centre += b.vertices[i];
    NarrowResult r;
    r.empty = {std::max(distance - due, 0.0), anyMargin, centre / b.count};
    return r;
}

// apart's answer where it is plain, without its division and square roots: the centre's squared distance from the
// segment beyond the squared reach by a slack (a micrometre, and 1e-12 of the coordinates) far above either
// computation's rounding, a few units of 1e-16 of the coordinates. Near that line, apart decides.
bool clearlyApart(const Vec2& p1, const Vec2& p2, const Spread& b, double radius, double margin) {
    const Vec2 e = p2 - p1, c = b.centre - p1;
    const double along = e.dot(c), length2 = e.squaredNorm();
    const double size = std::max({p1.cwiseAbs().maxCoeff(), p2.cwiseAbs().maxCoeff(), b.centre.cwiseAbs().maxCoeff()});
    double squared;  // the centre's squared distance from the segment, times length2 inside its span
    double reach = radius + std::max(margin, kSpeculativeMargin) + 1e-6 + 1e-12 * size;
    if (b.reachSquared > 0.0) reach += std::sqrt(b.reachSquared);
    double bound = reach * reach;
    if (along <= 0.0) {
        squared = c.squaredNorm();
    } else if (along >= length2) {
        squared = (b.centre - p2).squaredNorm();
    } else {
        squared = cross(e, c) * cross(e, c);
        bound *= length2;
    }
    return squared > bound;
}

// A circle whose centre lies clearly beyond an end of the piece, where a neighbour goes on: the rule below finds
// that end's vertex closest, a normal off the face normal (sine > 1e-3) leaning towards that end, and keeps no
// contact where the chain goes on flat or bends left (the neighbour's face answers; collideWithFace keeps nothing
// outside the span), nor where it bends right and the normal lies beyond the neighbour's face normal. This finds
// that empty answer without the routines. "Clearly": each side of each test by more than 1e-3 of the lengths
// involved, far above any rounding of the rule's own tests; a turn >= 0 is never the convex case.
// Returns -1 where the rule does not apply; else how far (m) the centre may move with each test still passing
// (StaysEmpty), 0 where that is below rounding's due. Each test is a distance h beyond a line through the end
// (along the piece, or the neighbour's normal) greater than 1e-3 of the centre's distance d from the end; a move
// by x changes both by at most x, so the test holds while x < (h - 1e-3 d) / (1 + 1e-3).
double leftToNeighbour(const ChainSegment& a, const Vec2& centre) {
    const Vec2& p1 = a.segment.point1;
    const Vec2& p2 = a.segment.point2;
    const Vec2 along = p2 - p1;
    const double u = (centre - p1).dot(along), length2 = along.squaredNorm();
    // Past `end` by `beyondEnd` (along . (centre - end)), the neighbour's direction along the chain, `atStart`.
    auto past = [&](const Vec2& end, double beyondEnd, const Vec2& neighbour, bool atStart) {
        const Vec2 toCentre = centre - end;
        const double distance2 = toCentre.squaredNorm();
        if (!(beyondEnd * beyondEnd > 1e-6 * length2 * distance2)) return -1.0;
        const double d = std::sqrt(distance2);
        auto allowance = [d](double h) { return (h - 1e-3 * d) / (1.0 + 1e-3); };
        double still = allowance(std::abs(beyondEnd) / std::sqrt(length2));
        const double turn = atStart ? cross(neighbour, along) : cross(along, neighbour);  // < 0: bends right
        if (turn < 0.0) {
            const double side = atStart ? cross(perp(neighbour), toCentre) : cross(toCentre, perp(neighbour));
            if (!(side > 0.0 && side * side > 1e-6 * neighbour.squaredNorm() * distance2)) return -1.0;
            still = std::min(still, allowance(side / neighbour.norm()));
        }
        return std::max(still - roundingDue(p1, p2, centre), 0.0);
    };
    if (u < 0.0) return a.ghost1 != p1 ? past(p1, u, Vec2(p1 - a.ghost1), true) : -1.0;
    if (u > length2) return a.ghost2 != p2 ? past(p2, u - length2, Vec2(a.ghost2 - p2), false) : -1.0;
    return -1.0;
}

// A circle's core placed in the piece's frame: relativeCore's vertex, without its copies of the unused entries.
RoundedCore pointCore(const Vec2& centre, double radius) {
    RoundedCore k;
    k.vertices[0] = centre;
    k.normals[0] = Vec2::Zero();
    k.count = 1;
    k.radius = radius;
    return k;
}

// collideCores' answer for the piece and a point core (a circle, centre c in the piece's frame) whose closest
// feature is the piece's face, from its open side: the same operations on the few numbers that take part, without
// building the cores (a wheel on a terrain meets a piece so every step). False where collideCores must decide
// (the centre beyond an end, or not clearly on the open side).
bool pointOnFace(const Vec2& p1, const Vec2& p2, const Vec2& c, double radius, double margin, LocalManifold& m) {
    const Vec2 e = p2 - p1;
    const double u = (c - p1).dot(e);  // closestToEdges' test of the span
    if (!(u >= 0.0 && u <= e.squaredNorm())) return false;
    const Vec2 n0 = Vec2(e.y(), -e.x()) / e.norm();  // coreOf's normals[0]; the face's, normals[1], is -n0
    const double s0 = n0.dot(c - p1);
    if (!(s0 < 0.0)) return false;
    const Vec2 n = -n0;
    const double s1 = n.dot(c - p2);
    const double sat = s1 > s0 ? s1 : s0;  // maxSeparation over the piece's two faces
    if (sat - radius > margin) {
        m.separation = sat - radius;
        return true;
    }
    const double separation = -s0 - radius;  // the closest features: the centre over face 1
    m.separation = separation;
    if (separation > margin) return true;
    // clip() with face 1 as the reference and the point as the incident core: one point.
    const double onFace = s1 - radius;
    m.normal = n;
    m.pointCount = 1;
    const bool kept = onFace <= std::max(margin, kSpeculativeMargin);
    m.separations[0] = kept ? onFace : deepestSeparation(onFace, separation);
    m.points[0] = midwayPoint(c, n, 0.0, radius, radius, onFace);
    m.ids[0] = featureId(false, kFace, 0);
    return true;
}

// collideChainSegment with b's placement in the piece's frame (relativeTransform(xa, xb)) already worked out.
NarrowResult collideRelative(const ChainSegment& a, const Transform& xa, const RoundedCore& b, const Transform& xb,
                             const Transform& relative, double margin) {
    const Vec2& p1 = a.segment.point1;
    const Vec2& p2 = a.segment.point2;
    // The cheap rejections first: most pieces near a body are out of its reach or behind it.
    const Spread spread = spreadOf(b, relative);
    const bool clearly = clearlyApart(p1, p2, spread, b.radius, margin);
    const double offset = clearly ? 0.0 : offsetFromLine(a, spread.centre);
    if (clearly || apart(p1, p2, spread, b.radius, margin)) {
        // Apart until the gap closes to the margin; behind as well, until the centre crosses the line.
        const double due = roundingDue(p1, p2, spread.centre), gap = gapTo(p1, p2, spread, b.radius);
        if (offset < 0.0 && -offset > gap - std::max(margin, kSpeculativeMargin))
            return emptyFor(b, -offset, true, due);
        return emptyFor(b, gap, false, due);
    }
    if (offset < 0.0) return emptyFor(b, -offset, true, roundingDue(p1, p2, spread.centre));  // behind: one-sided

    if (LocalManifold m; b.count == 1 && pointOnFace(p1, p2, relative.apply(b.vertices[0]), b.radius, margin, m))
        return placed(m, xa);
    const RoundedCore piece = coreOf(p1, p2, 0.0);
    const RoundedCore local = b.count == 1 ? pointCore(relative.apply(b.vertices[0]), b.radius) : relativeCore(b, xa, xb);
    const Vec2 face = piece.normals[kFace];

    const LocalManifold m = collideCores(piece, local, margin);
    // Only the face's own normal stands as it is. Any other, however close (a body turned by a hair meeting the
    // piece's end with its own face), leans towards an end and follows that end's rule below: at a flat joint a
    // body then never takes a push along the ground from the corner.
    if (m.pointCount == 0 || m.normal == face) return placed(m, xa);
    if (m.normal.dot(face) <= 0.0) return fragileIfEmpty(placed(collideWithFace(piece, kFace, local, margin), xa));

    const Vec2 along = p2 - p1;
    const bool atStart = m.normal.dot(along) < 0.0;
    const Vec2& end = atStart ? p1 : p2;
    const Vec2& ghost = atStart ? a.ghost1 : a.ghost2;
    if (ghost == end) return placed(m, xa);  // an open chain's end: a real corner

    const Vec2 neighbour = atStart ? Vec2(p1 - ghost) : Vec2(ghost - p2);  // the neighbour's direction along the chain
    const double turn = atStart ? cross(neighbour, along) : cross(along, neighbour);  // < 0: turns right, convex
    if (turn < -kFlatSine * neighbour.norm() * along.norm()) {
        const Vec2 neighbourNormal = perp(neighbour).normalized();
        const bool beyond = atStart ? cross(neighbourNormal, m.normal) > 0.0 : cross(m.normal, neighbourNormal) > 0.0;
        return beyond ? fragileIfEmpty(NarrowResult{}) : placed(m, xa);
    }
    return fragileIfEmpty(placed(collideWithFace(piece, kFace, local, margin), xa));
}

}  // namespace

void ShapeKind<ChainSegment>::validate(const ChainSegment& c) {
    requireTwoPoints("chain segment", "point1", c.segment.point1, "point2", c.segment.point2);
    requireFinite("chain segment ghost1", c.ghost1);
    requireFinite("chain segment ghost2", c.ghost2);
}

double frontOffset(const ChainSegment& a, const Transform& xa, const Geometry& b, const Transform& xb) {
    if (std::holds_alternative<ChainSegment>(b)) return std::numeric_limits<double>::infinity();
    const RoundedCore core = std::visit(
        [](const auto& s) -> RoundedCore {
            if constexpr (std::is_same_v<std::decay_t<decltype(s)>, ChainSegment>) return {};
            else return coreOf(s);
        },
        b);
    return offsetFromLine(a, spreadOf(core, relativeTransform(xa, xb)).centre);
}

NarrowResult collideChainSegment(const ChainSegment& a, const Transform& xa, const RoundedCore& b, const Transform& xb,
                                 double margin) {
    return collideRelative(a, xa, b, xb, relativeTransform(xa, xb), margin);
}

double circleLeftToNeighbour(const ChainSegment& a, const Transform& xa, const Circle& b, const Transform& xb) {
    return leftToNeighbour(a, relativeTransform(xa, xb).apply(b.center));
}

NarrowResult collideChainCircle(const ChainSegment& a, const Transform& xa, const Circle& b, const Transform& xb,
                                double margin) {
    const Transform relative = relativeTransform(xa, xb);
    if (const double still = leftToNeighbour(a, relative.apply(b.center)); still >= 0.0) {
        NarrowResult r;
        r.empty = {still, true, b.center};
        return r;
    }
    return collideRelative(a, xa, coreOf(b), xb, relative, margin);
}

}  // namespace physim
