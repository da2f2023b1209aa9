#include "RoundedRows.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace physim {

namespace {

// A straight side of a shape's core, in world metres: its ends, and beyond each the far point of the side that
// goes on from it (the end itself where none does: an open end).
struct CoreSide {
    bool found = false;
    Vec2 end0 = Vec2::Zero(), end1 = Vec2::Zero();
    Vec2 beyond0 = Vec2::Zero(), beyond1 = Vec2::Zero();
};

// Cosine above which a side's outward normal is taken as the contact's: the narrow phase gives a face contact
// exactly the face's normal (to rounding), and near a corner the two measures agree, so the choice is not delicate.
constexpr double kFaceCosine = 1.0 - 1e-9;

// The straight side of the core of `g` (at pose xf) whose outward normal is `outward`, if it has one.
CoreSide coreSide(const Geometry& g, const Transform& xf, const Vec2& outward) {
    const Vec2 local = xf.q.applyInverse(outward);
    // Two-sided: a segment's, a capsule's core, a chain piece's (whose ghosts are its neighbours' far points).
    auto line = [&](const Vec2& p1, const Vec2& p2, const Vec2& g1, const Vec2& g2) {
        const Vec2 normal = perp(p2 - p1).normalized();
        if (std::abs(normal.dot(local)) < kFaceCosine) return CoreSide{};
        return CoreSide{true, xf.apply(p1), xf.apply(p2), xf.apply(g1), xf.apply(g2)};
    };
    if (const auto* p = std::get_if<Polygon>(&g)) {
        const int n = p->count;
        for (int k = 0; k < n; ++k)
            if (p->normals[k].dot(local) >= kFaceCosine)
                return {true, xf.apply(p->vertices[k]), xf.apply(p->vertices[(k + 1) % n]),
                        xf.apply(p->vertices[(k + n - 1) % n]), xf.apply(p->vertices[(k + 2) % n])};
        return {};
    }
    if (const auto* s = std::get_if<Segment>(&g)) return line(s->point1, s->point2, s->point1, s->point2);
    if (const auto* c = std::get_if<Capsule>(&g)) return line(c->center1, c->center2, c->center1, c->center2);
    if (const auto* c = std::get_if<ChainSegment>(&g))
        return line(c->segment.point1, c->segment.point2, c->ghost1, c->ghost2);
    return {};  // a circle's core is a point
}

// How the surface goes on past `end` (the other end `other`, the side's normal `outward`), as the rows follow it:
// the direction to `beyond` as cosine and sine in the side's frame (along the side out of the end, along the
// normal). A flat joint goes straight on, (1, 0), and a convex one (negative sine) turns away from the rounded side.
// At a concave joint the next side rises toward the rounded side, and the rows, whose normal is this side's for the
// whole step, would push along it against a slope and give energy: there the surface is taken to end, as at an open
// end, which folds straight back, (-1, 0), so the rounded side leaves this side by pivoting about its end.
Turn turnAt(const Vec2& end, const Vec2& other, const Vec2& beyond, const Vec2& outward) {
    constexpr double kFlatSine = 1e-9;  // a joint whose turn has a smaller sine is flat (as chains take it)
    if (beyond == end) return {};
    const Vec2 next = (beyond - end).normalized();
    const double sine = next.dot(outward);
    if (sine > kFlatSine) return {};
    if (sine >= -kFlatSine) return {1.0, 0.0};
    return {next.dot((end - other).normalized()), sine};
}

// Whether `point` is (to rounding) an end of `side`, along the tangent t.
bool atEnd(const FacingSide& side, const Vec2& point, const Vec2& t) {
    constexpr double kTolerance = 1e-9;  // m: a clipped point lies on its end to rounding
    return std::abs(t.dot(side.end0 - point)) < kTolerance || std::abs(t.dot(side.end1 - point)) < kTolerance;
}

// The side of `g` (at pose xf) facing along `outward`, with its turns.
FacingSide facingSide(const Geometry& g, const Transform& xf, const Vec2& outward) {
    const CoreSide side = coreSide(g, xf, outward);
    if (!side.found) return {};
    return {true, side.end0, side.end1, turnAt(side.end0, side.end1, side.beyond0, outward),
            turnAt(side.end1, side.end0, side.beyond1, outward)};
}

bool sameBits(double x, double y) {
    std::uint64_t u, v;
    std::memcpy(&u, &x, sizeof u);
    std::memcpy(&v, &y, sizeof v);
    return u == v;
}
bool sameBits(const Vec2& x, const Vec2& y) { return sameBits(x.x(), y.x()) && sameBits(x.y(), y.y()); }
bool sameBits(const Transform& x, const Transform& y) {
    return sameBits(x.p, y.p) && sameBits(x.q.c, y.q.c) && sameBits(x.q.s, y.q.s);
}

// Whether `kept` holds the sides prepareRounded would find now: found from the same shapes (a slot's generation
// names one shape for life), normal and poses of the bodies whose sides were asked for.
bool stillHolds(const RoundedSides& kept, const Manifold& manifold, const ContactCores& cores, const BodyData& a,
                const BodyData& b) {
    return kept.kept && kept.shapeA == manifold.shapeA && kept.shapeB == manifold.shapeB &&
           sameBits(kept.normal, manifold.normal) && (!cores.facesA || sameBits(kept.xfA, a.xf)) &&
           (!cores.facesB || sameBits(kept.xfB, b.xf));
}

}  // namespace

void prepareRounded(ContactBlock& block, ContactBlockEnds& ends, int lane, const Manifold& manifold,
                    const ContactCores& cores, const ShapeData* shapes, const BodyData& a, const BodyData& b,
                    RoundedSides* kept) {
    const Vec2 n = manifold.normal, t = perp(n);
    // A's straight side facing B (outward n), B's facing A (outward -n).
    RoundedSides fresh;
    RoundedSides& sides = kept ? *kept : fresh;
    if (!kept || !stillHolds(*kept, manifold, cores, a, b)) {
        sides.kept = true;
        sides.shapeA = manifold.shapeA;
        sides.shapeB = manifold.shapeB;
        sides.normal = n;
        sides.xfA = a.xf;
        sides.xfB = b.xf;
        sides.a = cores.facesA ? facingSide(shapes[manifold.shapeA.index].geometry, a.xf, n) : FacingSide{};
        sides.b = cores.facesB ? facingSide(shapes[manifold.shapeB.index].geometry, b.xf, -n) : FacingSide{};
    }
    const FacingSide& sideA = sides.a;
    const FacingSide& sideB = sides.b;
    if (!sideA.found && !sideB.found) return;  // a vertex on a vertex: the rows keep the contact points
    for (int i = 0; i < manifold.pointCount; ++i) {
        const ContactPoint& p = manifold.points[i];
        // The cores' points under the contact point (midway between the surfaces, p.separation apart).
        const double reachA = cores.radiusA + 0.5 * p.separation, reachB = cores.radiusB + 0.5 * p.separation;
        const Vec2 coreA = p.point - reachA * n, coreB = p.point + reachB * n;
        // The interval of u = t . (coreB - coreA) (0 now) within which the vertex is over the straight side: B's
        // vertex on A's side, unless B's point lies inside a straight side of B's (then it is A's vertex on B's).
        const bool onA = sideA.found && !(sideB.found && !atEnd(sideB, coreB, t));
        const FacingSide& side = onA ? sideA : sideB;
        // u at each end: B's vertex moves along t over A's side; A's vertex, -t over B's.
        const double e0 = onA ? t.dot(side.end0 - coreA) : -t.dot(side.end0 - coreB);
        const double e1 = onA ? t.dot(side.end1 - coreA) : -t.dot(side.end1 - coreB);
        const bool firstLow = e0 <= e1;
        const double lo = firstLow ? e0 : e1, hi = firstLow ? e1 : e0;
        const Turn& low = firstLow ? side.turn0 : side.turn1;
        const Turn& high = firstLow ? side.turn1 : side.turn0;
        // From the anchors (each side's surface point across a gap, the midway point in overlap: prepareContacts).
        const double inward = 0.5 * std::min(p.separation, 0.0);
        ContactBlock::Point& q = block.points[i];
        q.negNdA[lane] += cores.radiusA + inward;
        q.ndB[lane] += cores.radiusB + inward;
        q.baseSeparation[lane] -= (cores.radiusA + inward) + (cores.radiusB + inward);
        if (!block.ends) {  // the block's first lane with ends: the others measure along the normal
            constexpr double kInfinity = std::numeric_limits<double>::infinity();
            for (int j = 0; j < 2; ++j) {
                ends.lo[j] = splat(-kInfinity);
                ends.hi[j] = splat(kInfinity);
                ends.loCos[j] = ends.hiCos[j] = splat(-1.0);
                ends.loSin[j] = ends.hiSin[j] = splat(0.0);
            }
            ends.rounding = splat(0.0);
            block.ends = &ends;
        }
        ends.lo[i][lane] = lo;
        ends.hi[i][lane] = hi;
        ends.loCos[i][lane] = low.c;
        ends.loSin[i][lane] = low.s;
        ends.hiCos[i][lane] = high.c;
        ends.hiSin[i][lane] = high.s;
        ends.rounding[lane] = cores.radiusA + cores.radiusB;
    }
}

}  // namespace physim
