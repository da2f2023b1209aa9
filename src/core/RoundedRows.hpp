#pragma once
// A rounded side's separation within the step (ContactSolver.cpp). Internal.
//
// The rows measure a point's separation from anchors that turn with their bodies. Where a rounded side (a circle,
// a capsule, a rounded polygon) rests on a straight side (a polygon's, a segment's, a chain piece's), its anchor on
// the contact point would turn away from the face as the side rolls, by r (1 - cos turn) (9 mm in a 40 Hz step at
// 10 rad/s), which reads as lifting off while its centre keeps its height; the speculative row then lets it
// approach, and its grip comes and goes. So there the anchors are the cores' points under the contact point: the
// rounded side's centre of curvature, and the face's point. Measured along the normal, a centre sees the face's
// line, which goes on past the face's ends; so the row keeps the face's ends, and once the centre has passed one,
// the separation is that end's distance from the centre less the roundings: the side leaves the face and pivots
// about its end as it would (onto the next piece of a chain, over a platform's edge) instead of running on along
// the face's line. Where neither core has a straight side there (two circles, a circle on a corner) the rows keep
// the contact points, which turn with a side that rolls about the other as a pivot does: measured along the
// normal between the centres, a disc rolling over a corner would seem to sink by r (1 - cos turn) and be pushed off.

#include "BodyLanes.hpp"
#include "ContactData.hpp"
#include "ContactSolver.hpp"

namespace physim {

/// How a side's surface goes on past one of its ends, as the rows follow it (RoundedRows.cpp, turnAt): the
/// direction as cosine and sine in the side's frame (along the side out of the end, along its outward normal).
struct Turn {
    double c = -1.0, s = 0.0;
};

/// A shape's straight core side that faces the other shape along the contact normal (outward n for A's, -n for
/// B's), if it has one: its ends in world metres, and the turns past them.
struct FacingSide {
    bool found = false;
    Vec2 end0 = Vec2::Zero(), end1 = Vec2::Zero();
    Turn turn0, turn1;
};

/// A contact's facing sides as prepareRounded last found them, with what they follow from: the shapes, the normal
/// and the poses of the bodies whose sides were asked for (compared bit for bit). A wheel on a terrain's piece
/// keeps all of them from step to step while it rolls over the piece's face; the solver keeps one per contact slot.
struct RoundedSides {
    bool kept = false;
    ShapeId shapeA, shapeB;
    Vec2 normal = Vec2::Zero();
    Transform xfA, xfB;
    FacingSide a, b;
};

/// Lane `lane` of a prepared block, whose contact has a rounded side and a side that may be straight
/// (cores.radiusA + cores.radiusB > 0, cores.facesA or facesB): where a core's straight side faces the other along
/// the normal, its points' separation anchors moved onto the cores and the side's ends kept in `ends` (beside the
/// block), which marks the block (ContactBlock::ends); else the lane is left as prepared. The lever arms, the
/// masses and the separation at the step's start are unchanged. a, b are the contact's bodies. `kept` (or null):
/// the contact's sides from the last call, used while what they follow from is the same, else found again.
void prepareRounded(ContactBlock& block, ContactBlockEnds& ends, int lane, const Manifold& manifold,
                    const ContactCores& cores, const ShapeData* shapes, const BodyData& a, const BodyData& b,
                    RoundedSides* kept = nullptr);

/// Point i's separation s (m, along the normal from its anchors), once the block's centres of curvature may
/// have passed their sides' ends (c.ends): past an end, the centre's distance from the surface that goes on there
/// (the end's corner, or the next side's line), less the roundings. Lanes whose centre is within its side's ends
/// (all lanes without ends: lo -inf, hi +inf) keep s's bits.
template <bool V, bool Turns>
[[gnu::always_inline]] inline Wide pastEnds(const Wide& s, const ContactBlock& c, const ContactBlockEnds& ends,
                                            int i, const WideSide& A, const WideSide& B) {
    const ContactBlock::Point& cp = c.points[i];
    const Wide tx = -c.ny, ty = c.nx;
    // The centre's travel along the face's tangent t = perp(n) relative to the face point under it since the step
    // began (t . R a = cos(turn) t . a + sin(turn) n . a, and t . a = -(a x n)).
    Wide u = mulAdd<V>(tx, B.dpx - A.dpx, ty * (B.dpy - A.dpy));
    if constexpr (Turns)
        u = u + (mulAdd<V>(B.qs, cp.ndB, -(B.qc * cp.rnB)) + mulAdd<V>(A.qs, cp.negNdA, -(A.qc * cp.negRnA)) +
                 (cp.rnB + cp.negRnA));
    const Wide zero{};
    const Wide beyondLow = ends.lo[i] - u, beyondHigh = u - ends.hi[i];
    const WideMask high = beyondHigh > 0.0;
    const Wide past = max(max(beyondLow, beyondHigh), zero);  // how far past an end, m
    if (!any(past > 0.0)) return s;  // most passes: every centre over its side
    const Wide c0 = high ? ends.hiCos[i] : ends.loCos[i], s0 = high ? ends.hiSin[i] : ends.loSin[i];
    // In (past, h) about the end, h the centre's height above the side's line: within the corner's wedge (before
    // the next side's normal; always at an open end) the distance is the end's, sqrt(h^2 + past^2), written without
    // cancellation; beyond it, the distance from the next side's line, h cos - past sin (the line's, at a flat joint).
    const Wide h = s + ends.rounding;
    const WideMask wedge = mulAdd<V>(past, c0, h * s0) <= 0.0;
    const Wide up = max(h, zero);
    const Wide pivot = s + past * past / (sqrtLanes<V>(mulAdd<V>(up, up, past * past)) + up);
    const Wide next = s + mulAdd<V>(h, c0 - 1.0, -(past * s0));
    return past > 0.0 ? (wedge ? pivot : next) : s;
}

}  // namespace physim
