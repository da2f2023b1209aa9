#include "ContactSolver.hpp"

#include "BodyLanes.hpp"
#include "ContactData.hpp"
#include "Impulse.hpp"
#include "Prefetch.hpp"
#include "RoundedRows.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>

namespace physim {

namespace {

// A normal impulse on one row (the bounce path and push records), with the moments prepared once per step. Row: a
// ContactConstraint, or a PushRow where only push-out is recorded; Point: its points' type.
template <class Row, class Point>
void pushNormal(const Row& c, MotionSide& A, MotionSide& B, const Point& p, double lambda) {
    const Vec2 P = lambda * c.normal;
    A.v -= c.invMassA * P;
    B.v += c.invMassB * P;
    A.w -= c.invIA * lambda * p.rnA;
    B.w += c.invIB * lambda * p.rnB;
}

inline double normalSpeed(const ContactConstraint& c, const MotionSide& A, const MotionSide& B,
                          const ContactConstraintPoint& p) {
    return c.normal.dot(B.v - A.v) + B.w * p.rnB - A.w * p.rnA;
}

}  // namespace

namespace {

// What preparation reads of a side: the solver's copy of an awake body (index >= 0), or, for a static or sleeping
// one, `still` filled from its record in the same shape: immovable (rowSide), no acceleration.
[[gnu::always_inline]] inline const SolverBodySim* rowBody(std::int32_t index, const SolverBodySim* sims,
                                                           const BodyData& record, SolverBodySim& still) {
    if (index != kNullIndex) return &sims[index];
    const RowSide side = rowSide(record);
    still.dynamic = side.moves;
    still.turns = side.turns;
    still.invMass = side.invMass;
    still.invInertia = side.invI;
    still.center0 = record.center;
    still.acceleration = Vec2::Zero();
    return &still;
}

// The rules every lane of a block keeps, and the block's marks, from its lanes' fields: a point past its row's
// pointCount has zero fields (no mass, no impulse), a frictionless row holds no tangent impulse, and the rows write
// a side with mass. `turns` and `holdsPush` are the caller's to set.
[[gnu::always_inline]] inline void markBlock(ContactBlock& b, const ContactBlockCold& cold) {
    const Wide zero = splat(0.0);
    Wide count;
    bool keepsPushes = false, twoPoints = false;
    unsigned writes = 0;
    for (int k = 0; k < kLanes; ++k) {
        count[k] = cold.lanes[k].pointCount;
        twoPoints = twoPoints || cold.lanes[k].pointCount == 2;
        keepsPushes = keepsPushes || cold.lanes[k].keepsPush;
        writes |= (b.negInvMassA[k] != 0.0 ? 1u << k : 0u) | (b.invMassB[k] != 0.0 ? 1u << (k + kLanes) : 0u);
    }
    for (int i = 0; i < 2; ++i) {
        const WideMask used = count > static_cast<double>(i);
        ContactBlock::Point& q = b.points[i];
        q.negRnA = used ? q.negRnA : -zero;
        q.rnB = used ? q.rnB : zero;
        q.negNdA = used ? q.negNdA : -zero;
        q.ndB = used ? q.ndB : zero;
        q.baseSeparation = used ? q.baseSeparation : zero;
        q.normalImpulse = used ? q.normalImpulse : zero;
        q.negNormalMass = used ? q.negNormalMass : -zero;
    }
    const WideMask rubs = (b.staticFriction > 0.0) | (b.dynamicFriction > 0.0);
    b.tangentImpulse = rubs ? b.tangentImpulse : zero;
    b.friction = any(rubs);
    b.keepsPushes = keepsPushes;
    b.twoPoints = twoPoints;
    b.writes = static_cast<std::uint8_t>(writes);
}

// One block's inputs, lane by lane (an empty lane all zero), for prepareLoop's four-lane arithmetic.
struct alignas(64) BlockInputs {
    Wide nx, ny;
    Wide centerAx, centerAy, centerBx, centerBy;  // centres of mass, m
    Wide accelerationNormal;                      // B's minus A's acceleration along the normal, m/s^2
    Wide invMassA, invIA, invMassB, invIB;
    Wide restitution, staticFriction, dynamicFriction;  // the contact's material (ContactData.hpp)
    Wide pointX[2], pointY[2], separation[2], normalImpulse[2], tangentImpulse[2];
    Wide pointCount, sliding;
};

// A field of the four lanes, from lane k's value f(k), each read from its record straight into the vector.
template <class Field>
[[gnu::always_inline]] inline Wide lanesOf(const Field& f) {
    return Wide{f(0), f(1), f(2), f(3)};
}

// Gathers a block's contacts and their sides (the scalar part of preparation) field by field, and writes what needs
// no arithmetic. Lane k's contact is contact[k], its sides A[k] and B[k]. Returns the lanes whose bodies turn.
[[gnu::always_inline]] inline int gatherLanes(BlockInputs& in, ContactBlock& block, ContactBlockCold& cold,
                                              const ContactData* const (&contact)[kLanes],
                                              const SolverBodySim* const (&A)[kLanes],
                                              const SolverBodySim* const (&B)[kLanes]) {
    auto manifold = [&](int k) -> const Manifold& { return contact[k]->manifold; };
    in.nx = lanesOf([&](int k) { return manifold(k).normal.x(); });
    in.ny = lanesOf([&](int k) { return manifold(k).normal.y(); });
    in.centerAx = lanesOf([&](int k) { return A[k]->center0.x(); });
    in.centerAy = lanesOf([&](int k) { return A[k]->center0.y(); });
    in.centerBx = lanesOf([&](int k) { return B[k]->center0.x(); });
    in.centerBy = lanesOf([&](int k) { return B[k]->center0.y(); });
    in.accelerationNormal =
        lanesOf([&](int k) { return manifold(k).normal.dot(B[k]->acceleration - A[k]->acceleration); });
    in.invMassA = lanesOf([&](int k) { return A[k]->invMass; });
    in.invIA = lanesOf([&](int k) { return A[k]->invInertia; });
    in.invMassB = lanesOf([&](int k) { return B[k]->invMass; });
    in.invIB = lanesOf([&](int k) { return B[k]->invInertia; });
    in.restitution = lanesOf([&](int k) { return contact[k]->material.restitution; });
    in.staticFriction = lanesOf([&](int k) { return contact[k]->material.staticFriction; });
    in.dynamicFriction = lanesOf([&](int k) { return contact[k]->material.dynamicFriction; });
    bool two = false;
    for (int k = 0; k < kLanes; ++k) two = two || manifold(k).pointCount == 2;
    for (int i = 0; i < (two ? 2 : 1); ++i) {  // an unused point's values are stale: markBlock keeps them out
        in.pointX[i] = lanesOf([&](int k) { return manifold(k).points[i].point.x(); });
        in.pointY[i] = lanesOf([&](int k) { return manifold(k).points[i].point.y(); });
        in.separation[i] = lanesOf([&](int k) { return manifold(k).points[i].separation; });
        in.normalImpulse[i] = lanesOf([&](int k) { return manifold(k).points[i].normalImpulse; });
        in.tangentImpulse[i] = lanesOf([&](int k) { return manifold(k).points[i].tangentImpulse; });
    }
    in.pointCount = lanesOf([&](int k) { return static_cast<double>(manifold(k).pointCount); });
    in.sliding = lanesOf([&](int k) { return contact[k]->sliding ? 1.0 : 0.0; });
    int turning = 0;
    for (int k = 0; k < kLanes; ++k) {
        ContactBlockCold::Lane& lane = cold.lanes[k];
        lane.pointCount = manifold(k).pointCount;
        lane.keepsPush = contact[k]->keepsPush;
        turning += A[k]->turns || B[k]->turns ? 1 : 0;
    }
    block.turns = turning > 0;
    block.twoPoints = two;
    return turning;
}

// A row's inverse effective mass along a direction at moments ra, rb (lever arm x direction), lane by lane:
// mA^-1 + mB^-1 + IA^-1 ra^2 + IB^-1 rb^2.
[[gnu::always_inline]] inline Wide inverseMass(const BlockInputs& in, const Wide& ra, const Wide& rb) {
    return in.invMassA + in.invMassB + in.invIA * ra * ra + in.invIB * rb * rb;
}

// 1 / k where k > 0, else 0 (an immovable direction takes no impulse), lane by lane.
[[gnu::always_inline]] inline Wide inverseOrZero(const Wide& k) { return k > 0.0 ? 1.0 / k : splat(0.0); }

// The rows' effective masses, Jacobians and separations, four lanes at once (each operation the scalar one on each
// lane, Wide.hpp, so a lane's bits never depend on the others). markBlock then zeroes an unused point's fields.
// Two: some lane has a second point; else the second point's fields are left to markBlock, which zeroes them.
template <bool Two>
[[gnu::always_inline]] inline void prepareLanes(const BlockInputs& in, ContactBlock& block, ContactBlockCold& cold) {
    const Wide zero = splat(0.0);
    const Wide nx = in.nx, ny = in.ny;
    block.nx = nx;
    block.ny = ny;
    block.negInvMassA = -in.invMassA;
    block.invIA = in.invIA;
    block.invMassB = in.invMassB;
    block.invIB = in.invIB;
    Wide sumAx = zero, sumAy = zero, sumBx = zero, sumBy = zero, tangentImpulse = zero;
    Wide rnA[2] = {}, rnB[2] = {}, kNormal[2] = {};  // per point: moments about the centres, inverse effective mass
    for (int i = 0; i < 2; ++i) {
        if (!Two && i == 1) {
            cold.anchorAx[i] = cold.anchorAy[i] = cold.anchorBx[i] = cold.anchorBy[i] = zero;
            cold.relativeVelocity[i] = cold.push[i] = zero;
            for (int lane = 0; lane < kLanes; ++lane) cold.lanes[lane].engaged[i] = false;
            continue;
        }
        const WideMask used = in.pointCount > static_cast<double>(i);
        // Across a gap each body's anchor is its own surface point (the manifold's point is midway between the
        // surfaces): once the gap closes, that is where each is touched, and the anchors stay put relative to the
        // centres all step. Overlapping, the midway point.
        const Wide gap = max(in.separation[i], zero);
        const Wide hx = 0.5 * gap * nx, hy = 0.5 * gap * ny;
        const Wide ax = used ? in.pointX[i] - hx - in.centerAx : zero;
        const Wide ay = used ? in.pointY[i] - hy - in.centerAy : zero;
        const Wide bx = used ? in.pointX[i] + hx - in.centerBx : zero;
        const Wide by = used ? in.pointY[i] + hy - in.centerBy : zero;
        rnA[i] = ax * ny - ay * nx;  // anchor x n
        rnB[i] = bx * ny - by * nx;
        ContactBlock::Point& q = block.points[i];
        q.negRnA = -rnA[i];
        q.rnB = rnB[i];
        q.negNdA = -(nx * ax + ny * ay);
        q.ndB = nx * bx + ny * by;
        q.baseSeparation = in.separation[i] - (nx * (bx - ax) + ny * (by - ay));
        q.normalImpulse = in.normalImpulse[i];
        kNormal[i] = inverseMass(in, rnA[i], rnB[i]);
        q.negNormalMass = -inverseOrZero(kNormal[i]);
        tangentImpulse = used ? tangentImpulse + in.tangentImpulse[i] : tangentImpulse;
        sumAx = used ? sumAx + ax : sumAx;
        sumAy = used ? sumAy + ay : sumAy;
        sumBx = used ? sumBx + bx : sumBx;
        sumBy = used ? sumBy + by : sumBy;
        cold.anchorAx[i] = ax;
        cold.anchorAy[i] = ay;
        cold.anchorBx[i] = bx;
        cold.anchorBy[i] = by;
        cold.relativeVelocity[i] = zero;
        cold.push[i] = zero;
        for (int lane = 0; lane < kLanes; ++lane) cold.lanes[lane].engaged[i] = false;
    }
    // Two points: their 2x2 normal mass matrix, for a bounce of both at once (the passes take one point at a time);
    // invDet 0 where nearly singular (coincident points).
    const WideMask two = in.pointCount == 2.0;
    const Wide k11 = kNormal[0], k22 = kNormal[1];
    const Wide k12 = in.invMassA + in.invMassB + in.invIA * rnA[0] * rnA[1] + in.invIB * rnB[0] * rnB[1];
    const Wide det = k11 * k22 - k12 * k12;
    const Wide k11Two = two ? k11 : zero, k12Two = two ? k12 : zero, k22Two = two ? k22 : zero;
    const Wide invDet = (two & (k11 * k11 < 1000.0 * det)) ? 1.0 / det : zero;
    cold.k11 = k11Two;
    cold.k12 = k12Two;
    cold.k22 = k22Two;
    cold.invDet = invDet;
    // Friction: one row at the manifold's centre, along the tangent t = perp(n).
    const Wide share = in.pointCount > 0.0 ? 1.0 / in.pointCount : zero;
    const Wide fax = share * sumAx, fay = share * sumAy, fbx = share * sumBx, fby = share * sumBy;
    const Wide tx = -ny, ty = nx;
    const Wide rtA = fax * ty - fay * tx, rtB = fbx * ty - fby * tx;
    block.negRtA = -rtA;
    block.rtB = rtB;
    block.tangentMass = inverseOrZero(inverseMass(in, rtA, rtB));
    block.tangentImpulse = tangentImpulse;
    block.staticFriction = in.staticFriction;
    block.dynamicFriction = in.dynamicFriction;
    block.sliding = in.sliding;
    cold.restitution = in.restitution;
    cold.normalAcceleration = in.accelerationNormal;
    cold.totalNormal[0] = cold.totalNormal[1] = block.totalTangent = zero;  // the step's totals start from nothing
    markBlock(block, cold);
}

// A block's surface-material terms from its `lanes` rows' contacts' (the other lanes' are zero) and its prepared
// masses.
inline void prepareMaterial(ContactBlockMaterial& m, const ContactBlockCold& cold, int lanes,
                            const ContactSurface* surfaces, const ContactBlock& block) {
    auto surface = [&](int k) { return k < lanes ? surfaces[cold.lanes[k].contact] : ContactSurface{}; };
    m.tangentSpeed = lanesOf([&](int k) { return surface(k).tangentSpeed; });
    m.rolling = lanesOf([&](int k) { return surface(k).rolling; });
    m.rollingMass = inverseOrZero(block.invIA + block.invIB);
    m.rollingImpulse = splat(0.0);
}

// What an empty lane is prepared from: no points, no bodies (immovable sides that do not turn).
const ContactData kEmptyContact{};
const SolverBodySim kNoBody{};

// Preparing a block asks for the contacts of the block this far ahead: far enough to hide a miss, near enough that
// the lines are still there.
constexpr std::size_t kPrefetchBlocks = 2;
static_assert(offsetof(ContactData, cache) <= 3 * kCacheLine && alignof(ContactData) == kCacheLine,
              "what preparation reads of a contact is three lines");

// Prepares blocks [0, count): block j holds rows refs[rows[j].first ..] (rows[j].count of them).
[[gnu::always_inline]] inline PreparedRows prepareLoop(ContactBlock* blocks, ContactBlockCold* cold,
                                                       const BlockRows* rows, std::size_t count, const RowRef* refs,
                                                       const ContactData* contacts, const SolverBodySim* sims,
                                                       const BodyData* bodies, const ContactCores* cores,
                                                       const ShapeData* shapes, ContactBlockEnds* ends,
                                                       RoundedSides* sides) {
    PreparedRows prepared;
    SolverBodySim still[2][kLanes];  // the lanes' static or sleeping sides, A and B (rowBody)
    for (std::size_t j = 0; j < count; ++j) {
        // Rows visit contacts in colour order, which no hardware prefetcher follows, and a large scene's contacts
        // are no longer in the cache by now: ask for the part preparation reads, a few blocks ahead.
        if (j + kPrefetchBlocks < count)
            for (std::uint32_t r = 0; r < rows[j + kPrefetchBlocks].count; ++r) {
                const std::uint32_t ahead = refs[rows[j + kPrefetchBlocks].first + r].contact;
                prefetchLines(&contacts[ahead], offsetof(ContactData, cache));
                if (cores) prefetchLines(&cores[ahead], sizeof(ContactCores));
            }
        ContactBlock& block = blocks[j];
        block.holdsPush = false;
        block.ends = nullptr;
        const int lanes = static_cast<int>(rows[j].count);
        const ContactData* contact[kLanes];
        const SolverBodySim *A[kLanes], *B[kLanes];
        for (int k = 0; k < kLanes; ++k) {
            if (k >= lanes) {  // an empty row: no bodies, no points
                contact[k] = &kEmptyContact;
                A[k] = B[k] = &kNoBody;
                block.indexA[k] = block.indexB[k] = kNullIndex;
                cold[j].lanes[k].contact = 0;
                continue;
            }
            const RowRef& ref = refs[rows[j].first + static_cast<std::uint32_t>(k)];
            const ContactData& c = contacts[ref.contact];
            const BodyData &a = bodies[c.a()], &b = bodies[c.b()];
            contact[k] = &c;
            A[k] = rowBody(ref.indexA, sims, a, still[0][k]);
            B[k] = rowBody(ref.indexB, sims, b, still[1][k]);
            block.indexA[k] = ref.indexA != kNullIndex ? ref.indexA : a.awakeIndex;  // rowSide's index
            block.indexB[k] = ref.indexB != kNullIndex ? ref.indexB : b.awakeIndex;
            cold[j].lanes[k].contact = ref.contact;
        }
        BlockInputs in;  // every field written by gatherLanes
        prepared.turning += static_cast<std::size_t>(gatherLanes(in, block, cold[j], contact, A, B));
        if (block.twoPoints) prepareLanes<true>(in, block, cold[j]);
        else prepareLanes<false>(in, block, cold[j]);
        if (cores && ends)
            for (int k = 0; k < lanes; ++k) {
                const std::uint32_t index = cold[j].lanes[k].contact;
                const ContactCores& rounding = cores[index];
                if (rounding.radiusA + rounding.radiusB > 0.0 && (rounding.facesA || rounding.facesB)) {
                    const ContactData& c = contacts[index];
                    prepareRounded(block, ends[j], k, c.manifold, rounding, shapes, bodies[c.a()], bodies[c.b()],
                                   sides ? &sides[index] : nullptr);
                    prepared.rounded = true;
                }
            }
        for (int k = 0; k < lanes; ++k) prepared.bounce = prepared.bounce || cold[j].restitution[k] > 0.0;
    }
    return prepared;
}

}  // namespace

namespace {

// A point that starts to push (it had no impulse): remember how it met; if it meets fast enough, it bounces now.
// It leaves at e times the meeting speed, placed so that for e = 1 semi-implicit Euler retraces the fall exactly
// (no energy gained or lost):
//   met in the solve pass (positions not yet moved this substep): the separation at the substep's end becomes e
//   times the gap it had at the substep's start, as if it had reflected off the surface on time;
//   met in the relax pass (positions already moved): the reflection of the next substep's fall leaves at the
//   speed before that substep's gravity.
// Bouncing at once, not after the substep, lets a struck body pass the blow on within the same pass (a cradle's
// balls, one in and one out). The bounce is not part of the accumulated impulse, so no later pass (relax) can take
// it back; a point that separates and meets again (a ball between a wall and another ball) bounces again.
// What a point owes when it bounces: the normal speed to reach (m/s) and the gap to open now (m).
struct Bounce {
    bool active = false;
    double target = 0.0;  // normal speed to leave at, m/s
    double gap = 0.0;     // separation to open now, m
};

Bounce planBounce(ContactConstraint& c, ContactConstraintPoint& cp, double vn, double separation,
                  const ContactPass& pass) {
    vn += 0.0;  // an exact zero reads +0, whether the lane's block summed turning terms into it or not
    cp.relativeVelocity = cp.engaged ? std::min(cp.relativeVelocity, vn) : vn;  // the fastest meeting, for events
    cp.engaged = true;
    const double e = c.restitution;
    const double limit = e < 1.0 ? -pass.restitutionThreshold : 0.0;  // e = 1 bounces at any speed
    if (!(e > 0.0 && vn < limit)) return {};
    const double speed = -vn - (pass.useBias ? 0.0 : pass.h * c.normalAcceleration);
    const double target = e * speed;
    if (!pass.useBias) return {true, target, 0.0};
    // Met in the solve pass, a gap s before contact: open the gap now so that after this substep's move
    // (target h) the separation is e s, the mirror of the approach (an exact retrace for e = 1).
    const double s = std::max(separation, 0.0);
    return {true, target, (e - 1.0) * s - target * pass.h};
}

// Moves the bodies apart along the normal at the point as a position "impulse" q (kg m) would.
void shift(const ContactConstraint& c, const ContactConstraintPoint& cp, MotionSide& A, MotionSide& B, double q) {
    const Vec2 P = q * c.normal;
    const Vec2 rA = A.dq.apply(cp.anchorA), rB = B.dq.apply(cp.anchorB);
    const double turnA = -c.invIA * cross(rA, P), turnB = c.invIB * cross(rB, P);
    A.dp -= c.invMassA * P;
    B.dp += c.invMassB * P;
    A.dq = compose(rotationBy(turnA), A.dq);
    B.dq = compose(rotationBy(turnB), B.dq);
    A.dAngle += turnA;
    B.dAngle += turnB;
}

// Applies the bounces of a row one of whose points bounces, as one blow on the whole row. First everything this
// pass gave the row's points is taken back (`delta`, N s per point), so the bodies move as they met (`vn`: each
// point's normal speed then, m/s, less what the substep gave the bodies provisionally). Then impulses x >= 0, one
// per point, bring each point to at least its target speed, exactly where x > 0, a 2x2 complementarity problem
// on the row's mass matrix: a bouncing point's target is its bounce's; any other point may not approach faster
// than it separated (target -vn), and one that approached is stopped (target 0). The kinetic energy changes by
// sum x (vn + v') / 2, so each point's share is zero (a bounce with e = 1, a separating point held at the mirror
// of its speed) or a loss, whatever the coupling between the points. Both points of a face bounce together (a
// box landing flat stays level); point by point, or keeping the pass's impulse at a point the blow then leaves
// alone, gained energy (a thin box spinning into a wall, one corner approaching and one leaving: docs/dynamics.md).
// A bounce is a blow, not a lasting push: nothing of it is warm-started into the next substep. Taking back the
// pass's impulse includes what it gave a point to push an overlap apart: the pair leaves at e times its meeting
// speed, not at the push-out speed (an overlapping pair that met slowly would otherwise keep that speed); later
// passes push the overlap out as usual. What the substep gave the bodies provisionally (`provisional`, along each
// point's normal: the warm start and other contacts' push-out) is left out of the speeds the blow answers, for the
// same reason: it stays on the bodies, and the rows that gave it keep or take it back in later passes. A blow that
// answered a warm start reflected a guess at this substep's impulses: when the guess was then taken back, the
// bodies kept the reflection's energy (a thin box spinning fast, stopped by one wall's rows and warm-started into
// another wall, gained energy: docs/dynamics.md).
// The blows' velocities alone are added to `blowA` and `blowB` (given at zero), and the blows, N s per point, are
// written to `blows`.
void applyBounces(ContactConstraint& c, MotionSide& A, MotionSide& B, const Bounce (&bounce)[2],
                  const double (&vn)[2], const double (&delta)[2], const double (&provisional)[2], MotionSide& blowA,
                  MotionSide& blowB, double (&blows)[2]) {
    for (int i = 0; i < c.pointCount; ++i) {
        if (delta[i] != 0.0) pushNormal(c, A, B, c.points[i], -delta[i]);
        c.points[i].normalImpulse -= delta[i];
    }
    auto speedAt = [&](int i) { return normalSpeed(c, A, B, c.points[i]) - provisional[i]; };
    auto target = [&](int i) { return bounce[i].active ? bounce[i].target : std::min(-vn[i], 0.0); };
    double x[2] = {0.0, 0.0}, q[2] = {0.0, 0.0};
    if (c.pointCount == 2) {
        const double d1 = target(0) - speedAt(0), d2 = target(1) - speedAt(1);
        const double g1 = bounce[0].gap, g2 = bounce[1].gap;  // zero for a point that does not bounce
        const double y1 = (c.k22 * d1 - c.k12 * d2) * c.invDet, y2 = (c.k11 * d2 - c.k12 * d1) * c.invDet;
        if (c.invDet > 0.0 && y1 >= 0.0 && y2 >= 0.0) {
            x[0] = y1, x[1] = y2;
            q[0] = (c.k22 * g1 - c.k12 * g2) * c.invDet, q[1] = (c.k11 * g2 - c.k12 * g1) * c.invDet;
        } else if (d1 > 0.0 && d2 - c.k12 * d1 / c.k11 <= 0.0) {
            x[0] = d1 / c.k11, q[0] = g1 / c.k11;  // the first gets the blow; the second then leaves fast enough
        } else if (d2 > 0.0 && d1 - c.k12 * d2 / c.k22 <= 0.0) {
            x[1] = d2 / c.k22, q[1] = g2 / c.k22;
        } else if (d1 > 0.0 || d2 > 0.0) {
            // Degenerate face (the points' rows nearly equal): one blow, at the point that needs more.
            const int i = d1 / c.k11 >= d2 / c.k22 ? 0 : 1;
            x[i] = (i == 0 ? d1 : d2) / (i == 0 ? c.k11 : c.k22);
            q[i] = (i == 0 ? g1 : g2) / (i == 0 ? c.k11 : c.k22);
        }
    } else if (c.pointCount == 1) {
        x[0] = std::max(c.points[0].normalMass * (target(0) - speedAt(0)), 0.0);
        q[0] = bounce[0].gap * c.points[0].normalMass;
    }
    for (int i = 0; i < c.pointCount; ++i) {
        if (x[i] != 0.0) {
            pushNormal(c, A, B, c.points[i], x[i]);
            pushNormal(c, blowA, blowB, c.points[i], x[i]);
        }
        if (q[i] != 0.0) shift(c, c.points[i], A, B, q[i]);
        blows[i] = x[i];
    }
}

}  // namespace

namespace {

// What the solve passes' push-out has given a body in the present substep, as a velocity (zero for an immovable
// side, or none yet).
MotionSide pushedSide(const ContactPass& pass, std::int32_t index) {
    MotionSide side;
    if (pass.pushes && index != kNullIndex && pass.pushes[index].substep == pass.substep) {
        side.v = pass.pushes[index].v;
        side.w = pass.pushes[index].w;
    }
    return side;
}

// What the present substep has given a side provisionally, as a velocity: the push-out its rows still hold, and in
// a solve pass, for a row that can bounce, its warm start (zero for a side the row cannot move: no row changes its
// velocity). A row that cannot bounce plans only its meeting speed for events, which stays as the push-out alone
// leaves it. By the relax pass every row has answered the warm start in the solve pass, so it is no longer a guess;
// the push-out is, until the row that holds it relaxes (releasePushes). In the relax pass a row that cannot bounce
// leaves nothing out (its bodies' other rows need not keep their push).
MotionSide provisionalSide(const ContactPass& pass, const ContactConstraint& c, std::int32_t index, double invMass) {
    if (!pass.useBias && !(pass.holdPushes && c.restitution > 0.0)) return {};
    MotionSide side = pushedSide(pass, index);
    if (pass.useBias && pass.warmStarts && c.restitution > 0.0 && rowMoves(index, invMass)) {
        side.v += pass.warmStarts[index].v;
        side.w += pass.warmStarts[index].w;
    }
    return side;
}

void addVelocity(RowsBase& base, const MotionSide& change) {
    base.v += change.v;
    base.w += change.w;
}

// Adds a point's push impulse (N s along the normal) to what its bodies have been given by push-out this substep.
// Only sides the row can move are written (a kinematic body is read by many rows of one colour).
template <class Row, class Point>
void recordPush(const ContactPass& pass, const Row& c, const Point& cp, double impulse) {
    if (!pass.pushes) return;
    MotionSide A = pushedSide(pass, c.indexA), B = pushedSide(pass, c.indexB);
    pushNormal(c, A, B, cp, impulse);
    if (rowMoves(c.indexA, c.invMassA)) pass.pushes[c.indexA] = {A.v, A.w, pass.substep};
    if (rowMoves(c.indexB, c.invMassB)) pass.pushes[c.indexB] = {B.v, B.w, pass.substep};
}

// B's speed relative to A along (dx, dy) at lever-arm moments -negArmA, armB (A's kept negated, as in the block),
// and an impulse d along it (B +, A -): the rule every pass applies, in the lanes. Turns false leaves the angular
// terms out (no body of the block turns).
// V: the build runs mulAdd as one instruction (the AVX builds; the bits are the same either way). Both are written
// for few operations and a short dependency chain: the speed sums its linear and angular parts apart, and the
// impulse's factors that do not wait for d (mass times direction) are multiplied first, so d reaches a velocity in
// one fused multiply-add.
template <bool V, bool Turns>
[[gnu::always_inline]] inline Wide speedAlong(const WideSide& A, const WideSide& B, const Wide& dx, const Wide& dy,
                                              const Wide& negArmA, const Wide& armB) {
    if constexpr (Turns) return mulAdd<V>(dx, B.vx - A.vx, dy * (B.vy - A.vy)) + mulAdd<V>(B.w, armB, A.w * negArmA);
    else return mulAdd<V>(dx, B.vx - A.vx, dy * (B.vy - A.vy));
}

template <bool V, bool Turns>
[[gnu::always_inline]] inline void applyAlong(const ContactBlock& c, WideSide& A, WideSide& B, const Wide& d,
                                              const Wide& dx, const Wide& dy, const Wide& negArmA, const Wide& armB) {
    A.vx = mulAdd<V>(d, c.negInvMassA * dx, A.vx);
    A.vy = mulAdd<V>(d, c.negInvMassA * dy, A.vy);
    B.vx = mulAdd<V>(d, c.invMassB * dx, B.vx);
    B.vy = mulAdd<V>(d, c.invMassB * dy, B.vy);
    if constexpr (Turns) {
        A.w = mulAdd<V>(d, c.invIA * negArmA, A.w);
        B.w = mulAdd<V>(d, c.invIB * armB, B.w);
    }
}

// A friction row's bound (N s): mu_s times the load while its face sticks, mu_d while it slides (0 for a
// frictionless lane). The solve pass clamps the warm start to it, the relax pass the solved impulse.
[[gnu::always_inline]] inline Wide frictionBound(const ContactBlock& c, const Wide& totalNormal) {
    return (c.sliding != 0.0 ? c.dynamicFriction : c.staticFriction) * totalNormal;
}

template <bool V, bool Turns>
[[gnu::always_inline]] inline void warmStartBlock(const ContactBlock& c, SolverBody* states) {
    WideSide A = gather<false>(c.indexA, states), B = gather<false>(c.indexB, states);
    for (int i = 0; i < (c.twoPoints ? 2 : 1); ++i) {
        const ContactBlock::Point& cp = c.points[i];
        applyAlong<V, Turns>(c, A, B, cp.normalImpulse, c.nx, c.ny, cp.negRnA, cp.rnB);
    }
    applyAlong<V, Turns>(c, A, B, c.tangentImpulse, -c.ny, c.nx, c.negRtA, c.rtB);
    scatter(c.indexA, c.writes, A, states);
    scatter(c.indexB, c.writes >> kLanes, B, states);
}

// What a point that started to push in this pass brings to the bounce path: per point, whether it started, its
// normal speed before this pass's impulses on the row, its separation, this pass's impulse, and the part of it that
// pushes an overlap out.
struct Start {
    bool started[2] = {false, false};
    double before[2] = {0.0, 0.0}, separation[2] = {0.0, 0.0}, delta[2] = {0.0, 0.0}, push[2] = {0.0, 0.0};
};

// What lane k's motion needs, field for field as row() gives it: enough to apply and record a normal impulse (the
// start path's meeting speed and push-out, the push records). completeRow adds the rest, which only a bounce reads.
ContactConstraint rowMotion(const ContactBlock& b, const ContactBlockCold& cold, int k) {
    const ContactBlockCold::Lane& lane = cold.lanes[k];
    ContactConstraint c;
    c.contact = lane.contact;
    c.indexA = b.indexA[k];
    c.indexB = b.indexB[k];
    c.normal = {b.nx[k], b.ny[k]};
    c.invMassA = -b.negInvMassA[k];
    c.invIA = b.invIA[k];
    c.invMassB = b.invMassB[k];
    c.invIB = b.invIB[k];
    c.restitution = cold.restitution[k];
    c.normalAcceleration = cold.normalAcceleration[k];
    c.turns = b.turns;
    c.keepsPush = lane.keepsPush;
    c.pointCount = lane.pointCount;
    for (int i = 0; i < 2; ++i) {
        const ContactBlock::Point& q = b.points[i];
        ContactConstraintPoint& p = c.points[i];
        p.rnA = -q.negRnA[k];
        p.rnB = q.rnB[k];
        p.normalImpulse = q.normalImpulse[k];
        p.relativeVelocity = cold.relativeVelocity[i][k];
        p.engaged = lane.engaged[i];
    }
    return c;
}

// What lane k's push-out records need (pushNormal, recordPush, storeSide), named as in ContactConstraint: the
// passes that only move held push-out read these few lanes of the block instead of the whole row.
struct PushRow {
    std::int32_t indexA, indexB;
    Vec2 normal;
    double invMassA, invIA, invMassB, invIB;
    struct Point {
        double rnA, rnB;
    } points[2];
};

PushRow pushRow(const ContactBlock& b, int k) {
    return {b.indexA[k],
            b.indexB[k],
            {b.nx[k], b.ny[k]},
            -b.negInvMassA[k],
            b.invIA[k],
            b.invMassB[k],
            b.invIB[k],
            {{-b.points[0].negRnA[k], b.points[0].rnB[k]}, {-b.points[1].negRnA[k], b.points[1].rnB[k]}}};
}

void completeRow(ContactConstraint& c, const ContactBlock& b, const ContactBlockCold& cold, int k) {
    c.staticFriction = b.staticFriction[k];
    c.dynamicFriction = b.dynamicFriction[k];
    c.rtA = -b.negRtA[k];
    c.rtB = b.rtB[k];
    c.tangentMass = b.tangentMass[k];
    c.tangentImpulse = b.tangentImpulse[k];
    c.sliding = b.sliding[k] != 0.0;
    for (int i = 0; i < 2; ++i) {
        const ContactBlock::Point& q = b.points[i];
        ContactConstraintPoint& p = c.points[i];
        p.anchorA = {cold.anchorAx[i][k], cold.anchorAy[i][k]};
        p.anchorB = {cold.anchorBx[i][k], cold.anchorBy[i][k]};
        p.ndA = -q.negNdA[k];
        p.ndB = q.ndB[k];
        p.baseSeparation = q.baseSeparation[k];
        p.normalMass = -q.negNormalMass[k];
    }
    c.k11 = cold.k11[k];
    c.k12 = cold.k12[k];
    c.k22 = cold.k22[k];
    c.invDet = cold.invDet[k];
}

// Lane k, one of whose points started to push (it had no impulse): the bounce path, on the lane as a scalar row.
// Returns the lane's total normal impulse after it.
double startLane(ContactBlock& block, ContactBlockCold& cold, int k, WideSide& wa, WideSide& wb, SolverBody* states,
                 const Start& start, const ContactPass& pass) {
    ContactConstraint c = rowMotion(block, cold, k);  // most starts record a meeting and no bounce
    const int count = c.pointCount;
    // Along each point's normal, what the substep gave the pair provisionally: push-out and warm start.
    double provisional[2] = {0.0, 0.0};
    {
        const MotionSide givenA = provisionalSide(pass, c, c.indexA, c.invMassA);
        const MotionSide givenB = provisionalSide(pass, c, c.indexB, c.invMassB);
        for (int i = 0; i < count; ++i) provisional[i] = normalSpeed(c, givenA, givenB, c.points[i]);
    }
    Bounce bounce[2];
    for (int i = 0; i < count; ++i)
        if (start.started[i])
            bounce[i] = planBounce(c, c.points[i], start.before[i] - provisional[i], start.separation[i], pass);
    if (!bounce[0].active && !bounce[1].active) {
        // A push that stays is remembered on both bodies for their other contacts, until this row relaxes.
        for (int i = 0; i < count; ++i)
            if (start.push[i] > 0.0) {
                recordPush(pass, c, c.points[i], start.push[i]);
                if (pass.holdPushes && c.keepsPush) {
                    cold.push[i][k] += start.push[i];
                    block.holdsPush = true;
                }
            }
    } else {
        completeRow(c, block, cold, k);
        auto side = [&](std::int32_t index, const WideSide& g) {
            MotionSide m;
            if (index != kNullIndex) m = loadSide(states, index);
            m.v = {g.vx[k], g.vy[k]};
            m.w = g.w[k];
            return m;
        };
        MotionSide A = side(c.indexA, wa), B = side(c.indexB, wb);
        const double met[2] = {start.before[0] - provisional[0], start.before[1] - provisional[1]};
        MotionSide blowA, blowB;
        double blows[2] = {0.0, 0.0};
        applyBounces(c, A, B, bounce, met, start.delta, provisional, blowA, blowB, blows);
        // A blow is momentum the contact passed, though no row's accumulated impulse: the step's total has it.
        for (int i = 0; i < count; ++i) cold.totalNormal[i][k] += blows[i];
        if (pass.rowsBase) {  // a blow is no impulse of the rows: the next substep's warm start leaves it out
            if (rowMoves(c.indexA, c.invMassA)) addVelocity(pass.rowsBase[c.indexA], blowA);
            if (rowMoves(c.indexB, c.invMassB)) addVelocity(pass.rowsBase[c.indexB], blowB);
        }
        storeSideWithPose(states, c.indexA, c.invMassA, A);
        storeSideWithPose(states, c.indexB, c.invMassB, B);
        wa.vx[k] = A.v.x(), wa.vy[k] = A.v.y(), wa.w[k] = A.w, wa.dAngle[k] = A.dAngle;
        wb.vx[k] = B.v.x(), wb.vy[k] = B.v.y(), wb.w[k] = B.w, wb.dAngle[k] = B.dAngle;
    }
    for (int i = 0; i < count; ++i) {
        block.points[i].normalImpulse[k] = c.points[i].normalImpulse;
        cold.relativeVelocity[i][k] = c.points[i].relativeVelocity;
        cold.lanes[k].engaged[i] = c.points[i].engaged;
    }
    return c.points[0].normalImpulse + (count == 2 ? c.points[1].normalImpulse : 0.0);
}

// A block's rows relax: each point first takes back the push-out it holds (the relax pass would: it solves for the
// accumulated impulse, so starting it from the impulse less the push gives the same answer), so that push is no
// longer on the bodies when another row bounces off them later in this pass, nor in their push record.
void releasePushes(ContactBlock& block, ContactBlockCold& cold, SolverBody* states, const ContactPass& pass) {
    for (int k = 0; k < kLanes; ++k) {
        if (cold.push[0][k] == 0.0 && cold.push[1][k] == 0.0) continue;
        const PushRow c = pushRow(block, k);
        MotionSide A = loadSide(states, c.indexA), B = loadSide(states, c.indexB);
        for (int i = 0; i < 2; ++i) {
            const double held = cold.push[i][k];
            if (held == 0.0) continue;
            const double impulse = block.points[i].normalImpulse[k];  // clang binds no reference to a lane
            const double back = std::min(held, impulse);
            pushNormal(c, A, B, c.points[i], -back);
            block.points[i].normalImpulse[k] = impulse - back;
            recordPush(pass, c, c.points[i], -held);
            cold.push[i][k] = 0.0;
        }
        storeSide(states, c.indexA, c.invMassA, A);
        storeSide(states, c.indexB, c.invMassB, B);
    }
    block.holdsPush = false;
}

// A solve pass over rows that keep their push-out: each point that did not start in this pass (startLane records
// those) holds as push-out the part of its impulse its bias gave, at most all of it (`held`, worked out in the
// lanes); where that changed (`changed`), its bodies' push record follows, lane by lane.
void updateHeldPushes(ContactBlock& block, ContactBlockCold& cold, const ContactPass& pass, const Wide (&held)[2],
                      const WideMask (&changed)[2]) {
    for (int k = 0; k < kLanes; ++k)
        for (int i = 0; i < 2; ++i) {
            if (!changed[i][k]) continue;
            const PushRow c = pushRow(block, k);
            recordPush(pass, c, c.points[i], held[i][k] - cold.push[i][k]);
            cold.push[i][k] = held[i][k];
            if (held[i][k] != 0.0) block.holdsPush = true;
        }
}

// One pass over a block's rows. Turns is false for a block none of whose bodies can turn (rotation locked, or
// immovable and not spinning; the preparation decides once per step): the same rule with its angular terms left
// out, so a scene whose bodies all have rotation locked does no rotation work in its hottest loop. Bias is the
// pass's useBias: the relax pass (false) has no soft scaling to apply, and compiles without it.
// Material: the relax pass adds the block's surface-material terms (ContactBlockMaterial, at `material`).
template <bool V, bool Turns, bool Bias, bool Two, bool Material = false>
[[gnu::always_inline]] inline void solveBlock(ContactBlock& c, ContactBlockCold& cold, SolverBody* states,
                                              const ContactPass& pass, ContactBlockMaterial* material = nullptr) {
    if constexpr (!Bias)
        if (c.holdsPush) releasePushes(c, cold, states, pass);
    WideSide A = gather<true>(c.indexA, states), B = gather<true>(c.indexB, states);
    const Wide zero{}, one = splat(1.0);
    const Wide nx = c.nx, ny = c.ny;
    const Wide normalShift = mulAdd<V>(nx, B.dpx - A.dpx, ny * (B.dpy - A.dpy));
    constexpr int kPoints = Two ? 2 : 1;
    Wide separation[2] = {}, bias[2] = {}, massScale[2] = {}, leak[2] = {}, before[2] = {};
    for (int i = 0; i < kPoints; ++i) {
        const ContactBlock::Point& cp = c.points[i];
        // Separation now: the start's, moved by the bodies' displacement and turn since the step began
        // (n . R a = cos(turn) n . a + sin(turn) a x n for an anchor a turned by R).
        Wide s;
        if constexpr (Turns)
            s = normalShift + mulAdd<V>(B.qc, cp.ndB, B.qs * cp.rnB) + mulAdd<V>(A.qc, cp.negNdA, A.qs * cp.negRnA) +
                cp.baseSeparation;
        else
            s = normalShift + cp.ndB + cp.negNdA + cp.baseSeparation;
        if (c.ends) s = pastEnds<V, Turns>(s, c, *c.ends, i, A, B);  // a rounded side past its face's end
        separation[i] = s;
        // Speculative (apart): close the gap in this substep, no further. Overlapping: the solve pass pushes out
        // softly, the relax pass not at all.
        const WideMask apart = s > 0.0;
        if constexpr (Bias) {
            bias[i] = apart ? s * pass.invH : max(pass.softness.biasRate * s, splat(-pass.maxPushVelocity));
            massScale[i] = apart ? one : splat(pass.softness.massScale);
            leak[i] = apart ? zero : splat(pass.softness.impulseScale);
        } else {
            bias[i] = apart ? s * pass.invH : zero;
            massScale[i] = one;
            leak[i] = zero;
        }
        before[i] = speedAlong<V, Turns>(A, B, nx, ny, cp.negRnA, cp.rnB);
    }
    // One point at a time (Gauss-Seidel): the second sees the first's impulse. Odd substeps take the second point
    // first, so neither leads on average: a lead always to one side would tip a symmetric column over time.
    const bool secondFirst = (pass.substep & 1) != 0;
    // Each point's normal speed before any of this pass's impulses on the row: what a bounce answers, since it takes
    // all of them back.
    const Wide met[2] = {before[0], before[1]};
    WideMask started[2] = {};
    Wide deltas[2] = {};  // each point's impulse change in this pass
    Wide totalNormal = zero;
    // Point i, compile-time (a runtime index would keep these arrays on the stack); `follows`: the other point went
    // first in this pass, so its speed is measured again.
    const auto solvePoint = [&](auto index, bool follows) __attribute__((always_inline)) {
        constexpr int i = decltype(index)::value;
        ContactBlock::Point& cp = c.points[i];
        const Wide x = cp.normalImpulse;
        if (follows) before[i] = speedAlong<V, Turns>(A, B, nx, ny, cp.negRnA, cp.rnB);
        // The soft impulse -massScale m (v + bias) - leak x, clamped so that the accumulated impulse only pushes (the
        // relax pass's is the rigid one: massScale 1, no leak). An unused point has zero mass and takes none.
        Wide delta;
        if constexpr (Bias)
            delta = max(mulAdd<V>(cp.negNormalMass * massScale[i], before[i] + bias[i], x - leak[i] * x), zero) - x;
        else
            delta = max(mulAdd<V>(cp.negNormalMass, before[i] + bias[i], x), zero) - x;
        applyAlong<V, Turns>(c, A, B, delta, nx, ny, cp.negRnA, cp.rnB);
        started[i] = (x == 0.0) & (delta > 0.0);
        deltas[i] = delta;
        cp.normalImpulse = x + delta;
        totalNormal += cp.normalImpulse;
    };
    constexpr std::integral_constant<int, 0> first{};
    constexpr std::integral_constant<int, 1> second{};
    if constexpr (!Two) {
        solvePoint(first, false);
    } else if (secondFirst) {
        solvePoint(second, false);
        solvePoint(first, true);
    } else {
        solvePoint(first, false);
        solvePoint(second, true);
    }
    if constexpr (Bias) {
        if (pass.holdPushes && c.keepsPushes) {
            WideMask keeps;
            for (int k = 0; k < kLanes; ++k) keeps[k] = cold.lanes[k].keepsPush ? -1 : 0;
            Wide held[2];
            WideMask changed[2];
            for (int i = 0; i < 2; ++i) {
                const Wide push = bias[i] < 0.0 ? c.points[i].negNormalMass * massScale[i] * bias[i] : zero;
                const Wide x = c.points[i].normalImpulse;
                held[i] = x < push ? x : push;  // std::min(push, x)
                changed[i] = keeps & ~started[i] & (held[i] != cold.push[i]);
            }
            if (any(changed[0] | changed[1])) updateHeldPushes(c, cold, pass, held, changed);
        }
    }
    if (any(started[0] | started[1])) {
        Wide push[2];  // of a starting point's impulse, what pushes an overlap apart (bias < 0)
        for (int i = 0; i < 2; ++i)
            push[i] = (started[i] & (bias[i] < 0.0))
                          ? clamp(c.points[i].negNormalMass * massScale[i] * bias[i], zero, deltas[i])
                          : zero;
        for (int k = 0; k < kLanes; ++k) {
            if (!started[0][k] && !started[1][k]) continue;
            Start start;
            for (int i = 0; i < 2; ++i) {
                start.started[i] = started[i][k] != 0;
                start.before[i] = met[i][k];
                start.separation[i] = separation[i][k];
                start.delta[i] = deltas[i][k];
                start.push[i] = push[i][k];
            }
            totalNormal[k] = startLane(c, cold, k, A, B, states, start, pass);
        }
    }
    // Friction the load no longer bears is taken back here, before the rows after this one in the pass: the warm
    // start gave the last substep's friction, and the relax pass would take the excess back only after every normal
    // row has run, too late for those that the excess drove into a surface (a spinning ball landing against a wall
    // was thrown off it). Only ever less friction: the bound here includes the push-out the relax pass removes.
    if constexpr (Bias) {
        if (c.friction) {
            const Wide bound = frictionBound(c, totalNormal);
            const Wide tangent = clamp(c.tangentImpulse, zero - bound, bound);
            if (any(tangent != c.tangentImpulse)) {
                applyAlong<V, Turns>(c, A, B, tangent - c.tangentImpulse, -ny, nx, c.negRtA, c.rtB);
                c.tangentImpulse = tangent;
            }
        }
    }
    if constexpr (!Bias && Material && Turns) {
        // Rolling resistance: before friction, so that friction, the pass's last word, leaves a rolling body's face
        // rolling without slip on what the rolling row left it. The bound is clamped like friction's (0 - bound).
        const Wide bound = material->rolling * totalNormal;
        const Wide old = material->rollingImpulse;
        const Wide next = clamp(mulAdd<V>(-material->rollingMass, B.w - A.w, old), zero - bound, bound);
        const Wide d = next - old;
        A.w = mulAdd<V>(d, -c.invIA, A.w);
        B.w = mulAdd<V>(d, c.invIB, B.w);
        material->rollingImpulse = next;
    }
    // Friction in the relax pass only, after the normal rows, so its bound sees the load without the solve pass's
    // push-out (friction bounded by a push the relax pass then takes back would hold faces the load does not). A
    // sticking face holds up to mu_s times its load, a sliding one mu_d times. The relax pass, the substep's last
    // word, also decides which it is for the next substep: sliding when even the bound leaves the faces moving
    // against each other faster than slipSpeed (a transient of one pass does not break a face loose). A frictionless
    // lane has a zero bound: no impulse.
    if constexpr (!Bias) {
        if (c.friction) {
            const Wide tx = -ny, ty = nx;
            Wide vt = speedAlong<V, Turns>(A, B, tx, ty, c.negRtA, c.rtB);
            if constexpr (Material) vt = vt + material->tangentSpeed;  // the belt's: rest is vt = -tangentSpeed
            const Wide bound = frictionBound(c, totalNormal);
            // 0 - bound, not -bound: a zero bound (a frictionless lane, or no load) clamps to +0, never -0, so a
            // lane's bits do not depend on whether a neighbour's friction made the block run this path.
            const Wide tangent = clamp(mulAdd<V>(-c.tangentMass, vt, c.tangentImpulse), zero - bound, bound);
            applyAlong<V, Turns>(c, A, B, tangent - c.tangentImpulse, tx, ty, c.negRtA, c.rtB);
            c.tangentImpulse = tangent;
            // The faces' speed against each other once the bound is applied, measured (no division in the loop).
            Wide after = speedAlong<V, Turns>(A, B, tx, ty, c.negRtA, c.rtB);
            if constexpr (Material) after = after + material->tangentSpeed;
            const WideMask slides = (c.tangentMass > 0.0) & (abs(after) > pass.slipSpeed);
            const WideMask rubs = (c.staticFriction > 0.0) | (c.dynamicFriction > 0.0);
            c.sliding = rubs ? (slides ? one : zero) : c.sliding;
        }
    }
    // The substep's last pass: what the rows now hold is what they gave the bodies over the substep (the warm start
    // applied the last substep's, this substep's passes changed it to this).
    if (pass.total) {
        cold.totalNormal[0] += c.points[0].normalImpulse;
        if constexpr (Two) cold.totalNormal[1] += c.points[1].normalImpulse;
        c.totalTangent += c.tangentImpulse;
    }
    scatter(c.indexA, c.writes, A, states);
    scatter(c.indexB, c.writes >> kLanes, B, states);
}

template <bool V>
[[gnu::always_inline]] inline void warmStartLoop(ContactBlock* begin, ContactBlock* end, SolverBody* states) {
    for (ContactBlock* c = begin; c != end; ++c) {
        if (c->turns) warmStartBlock<V, true>(*c, states);
        else warmStartBlock<V, false>(*c, states);
    }
}

template <bool V, bool Bias>
[[gnu::always_inline]] inline void solveLoopWith(ContactBlock* begin, ContactBlock* end, ContactBlockCold* cold,
                                                 SolverBody* states, const ContactPass& pass) {
    for (ContactBlock* c = begin; c != end; ++c, ++cold) {
        if (c->twoPoints) {
            if (c->turns) solveBlock<V, true, Bias, true>(*c, *cold, states, pass);
            else solveBlock<V, false, Bias, true>(*c, *cold, states, pass);
        } else {
            if (c->turns) solveBlock<V, true, Bias, false>(*c, *cold, states, pass);
            else solveBlock<V, false, Bias, false>(*c, *cold, states, pass);
        }
    }
}

// The relax pass with the blocks' surface-material terms (material[i] belongs to begin[i]).
template <bool V>
[[gnu::always_inline]] inline void relaxLoopMaterial(ContactBlock* begin, ContactBlock* end, ContactBlockCold* cold,
                                                     SolverBody* states, const ContactPass& pass,
                                                     ContactBlockMaterial* material) {
    for (ContactBlock* c = begin; c != end; ++c, ++cold, ++material) {
        if (c->twoPoints) {
            if (c->turns) solveBlock<V, true, false, true, true>(*c, *cold, states, pass, material);
            else solveBlock<V, false, false, true, true>(*c, *cold, states, pass, material);
        } else {
            if (c->turns) solveBlock<V, true, false, false, true>(*c, *cold, states, pass, material);
            else solveBlock<V, false, false, false, true>(*c, *cold, states, pass, material);
        }
    }
}

template <bool V>
[[gnu::always_inline]] inline void solveLoop(ContactBlock* begin, ContactBlock* end, ContactBlockCold* cold,
                                             SolverBody* states, const ContactPass& pass) {
    if (pass.useBias) solveLoopWith<V, true>(begin, end, cold, states, pass);
    else solveLoopWith<V, false>(begin, end, cold, states, pass);
}

// The loops, each built for baseline x86-64, AVX2 and AVX-512 (Wide.hpp, runWide).
struct PrepareContacts {
    template <bool>
    [[gnu::always_inline]] static PreparedRows run(ContactBlock* blocks, ContactBlockCold* cold, const BlockRows* rows,
                                                   std::size_t count, const RowRef* refs, const ContactData* contacts,
                                                   const SolverBodySim* sims, const BodyData* bodies,
                                                   const ContactCores* cores, const ShapeData* shapes,
                                                   ContactBlockEnds* ends, RoundedSides* sides) {
        return prepareLoop(blocks, cold, rows, count, refs, contacts, sims, bodies, cores, shapes, ends, sides);
    }
};
struct WarmStartContacts {
    template <bool V>
    [[gnu::always_inline]] static void run(ContactBlock* begin, ContactBlock* end, SolverBody* states) {
        warmStartLoop<V>(begin, end, states);
    }
};
struct SolveContacts {
    template <bool V>
    [[gnu::always_inline]] static void run(ContactBlock* begin, ContactBlock* end, ContactBlockCold* cold,
                                           SolverBody* states, const ContactPass& pass) {
        solveLoop<V>(begin, end, cold, states, pass);
    }
};
// The relax pass with surface-material terms: a loop of its own, so the loops above stay as they were.
struct RelaxMaterial {
    template <bool V>
    [[gnu::always_inline]] static void run(ContactBlock* begin, ContactBlock* end, ContactBlockCold* cold,
                                           SolverBody* states, const ContactPass& pass,
                                           ContactBlockMaterial* material) {
        relaxLoopMaterial<V>(begin, end, cold, states, pass, material);
    }
};

}  // namespace

PreparedRows prepareContacts(ContactBlock* blocks, ContactBlockCold* cold, const BlockRows* rows, std::size_t count,
                             const RowRef* refs, const ContactData* contacts, const SolverBodySim* sims,
                             const BodyData* bodies, WideCode code, const ContactCores* cores,
                             const ShapeData* shapes, ContactBlockEnds* ends, RoundedSides* sides) {
    return runWide<PrepareContacts>(code, blocks, cold, rows, count, refs, contacts, sims, bodies, cores, shapes,
                                    ends, sides);
}

void prepareMaterials(const ContactBlock* blocks, const ContactBlockCold* cold, ContactBlockMaterial* material,
                      const BlockRows* rows, std::size_t count, const ContactSurface* surfaces) {
    for (std::size_t j = 0; j < count; ++j)
        prepareMaterial(material[j], cold[j], static_cast<int>(rows[j].count), surfaces, blocks[j]);
}

void warmStartContacts(ContactBlock* begin, ContactBlock* end, SolverBody* states, WideCode code) {
    runWide<WarmStartContacts>(code, begin, end, states);
}

void solveContacts(ContactBlock* begin, ContactBlock* end, ContactBlockCold* cold, SolverBody* states,
                   const ContactPass& pass, WideCode code, ContactBlockMaterial* material) {
    // The material terms act in the relax pass only (friction's pass): the solve pass is the same without them.
    if (material && !pass.useBias) return runWide<RelaxMaterial>(code, begin, end, cold, states, pass, material);
    runWide<SolveContacts>(code, begin, end, cold, states, pass);
}

void warmStartRolling(const ContactBlock* begin, const ContactBlock* end, const ContactBlockMaterial* material,
                      SolverBody* states) {
    for (const ContactBlock* c = begin; c != end; ++c, ++material)
        for (int k = 0; k < kLanes; ++k) {
            const double impulse = material->rollingImpulse[k];
            if (impulse == 0.0) continue;
            if (c->writes & (1u << k)) states[c->indexA[k]].w -= c->invIA[k] * impulse;
            if (c->writes & (1u << (k + kLanes))) states[c->indexB[k]].w += c->invIB[k] * impulse;
        }
}

void startBlock(ContactBlock& block, ContactBlockCold& cold, int lanes) {
    ContactConstraint empty;
    empty.turns = false;
    for (int k = lanes; k < kLanes; ++k) setRow(block, cold, k, empty);
    block.turns = block.friction = block.keepsPushes = block.holdsPush = false;
    block.ends = nullptr;
}

void setRow(ContactBlock& b, ContactBlockCold& cold, int k, const ContactConstraint& c) {
    ContactBlockCold::Lane& lane = cold.lanes[k];
    b.indexA[k] = c.indexA;
    b.indexB[k] = c.indexB;
    b.nx[k] = c.normal.x();
    b.ny[k] = c.normal.y();
    b.negInvMassA[k] = -c.invMassA;
    b.invIA[k] = c.invIA;
    b.invMassB[k] = c.invMassB;
    b.invIB[k] = c.invIB;
    for (int i = 0; i < 2; ++i) {
        const ContactConstraintPoint& p = c.points[i];
        ContactBlock::Point& q = b.points[i];
        q.negRnA[k] = -p.rnA;
        q.rnB[k] = p.rnB;
        q.negNdA[k] = -p.ndA;
        q.ndB[k] = p.ndB;
        q.baseSeparation[k] = p.baseSeparation;
        q.normalImpulse[k] = p.normalImpulse;
        q.negNormalMass[k] = -p.normalMass;
        cold.anchorAx[i][k] = p.anchorA.x();
        cold.anchorAy[i][k] = p.anchorA.y();
        cold.anchorBx[i][k] = p.anchorB.x();
        cold.anchorBy[i][k] = p.anchorB.y();
        cold.relativeVelocity[i][k] = p.relativeVelocity;
        lane.engaged[i] = p.engaged;
        cold.push[i][k] = 0.0;
        cold.totalNormal[i][k] = 0.0;
    }
    b.totalTangent[k] = 0.0;
    cold.k11[k] = c.k11;
    cold.k12[k] = c.k12;
    cold.k22[k] = c.k22;
    cold.invDet[k] = c.invDet;
    b.negRtA[k] = -c.rtA;
    b.rtB[k] = c.rtB;
    b.tangentMass[k] = c.tangentMass;
    b.tangentImpulse[k] = c.tangentImpulse;
    b.staticFriction[k] = c.staticFriction;
    b.dynamicFriction[k] = c.dynamicFriction;
    b.sliding[k] = c.sliding ? 1.0 : 0.0;
    b.turns = b.turns || c.turns;
    lane.keepsPush = c.keepsPush;
    cold.restitution[k] = c.restitution;
    cold.normalAcceleration[k] = c.normalAcceleration;
    lane.contact = c.contact;
    lane.pointCount = c.pointCount;
    markBlock(b, cold);
}

ContactConstraint row(const ContactBlock& b, const ContactBlockCold& cold, int k) {
    ContactConstraint c = rowMotion(b, cold, k);
    completeRow(c, b, cold, k);
    return c;
}

void storeImpulses(const ContactBlock& block, const ContactBlockCold& cold, int lane, ContactData& contact,
                   StepImpulses& totals) {
    contact.sliding = block.sliding[lane] != 0.0;
    Manifold& m = contact.manifold;
    const int count = cold.lanes[lane].pointCount;
    const double share = count > 0 ? block.tangentImpulse[lane] / count : 0.0;
    const double totalShare = count > 0 ? block.totalTangent[lane] / count : 0.0;
    totals = StepImpulses{};
    for (int i = 0; i < count; ++i) {
        m.points[i].normalImpulse = block.points[i].normalImpulse[lane];
        m.points[i].tangentImpulse = share;
        totals.normal[i] = cold.totalNormal[i][lane];
        totals.tangent[i] = totalShare;
    }
}

}  // namespace physim
