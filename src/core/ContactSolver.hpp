#pragma once
// Contact rows of the soft step (Catto's "Solver2D" soft step, written for physim). Internal.
//
// A contact is prepared once per step from its manifold: lever arms from the centres of mass, the separation at
// the step's start, effective masses. Each substep then
//   - warm starts it with the impulses of the last substep,
//   - solves it with a soft bias: the separation is updated from the bodies' displacement since the step began
//     (no new collision detection), and overlap is pushed out as a damped spring of `contactHertz`, so deep
//     overlaps separate smoothly instead of exploding; points still apart are speculative: they act only if the
//     bodies would close the gap within the substep, and then stop them exactly at contact;
//   - relaxes it without the bias, removing the velocity the push-out added (so pushing out adds no energy).
// A row's points are solved one at a time, each as a spring of its own effective mass (stiffer than the 2x2 block
// where a box straddles two others), the first alternating by substep so that neither side of a face leads.
// A point that meets its partner faster than the restitution threshold bounces in that substep: its normal speed
// becomes e times the meeting speed, placed so that an elastic bounce is an exact reflection (ContactSolver.cpp).
// Friction is one row per manifold at the manifold's centre, bounded by the sum of the points' normal impulses
// (in 2D the tangential impulses at points of one face all have the same lever arm about the normal, so one row is
// exact, and the static/dynamic decision sees the whole load, not how it is shared between the points), and solved
// in the relax pass only, where that load holds no push-out (docs/dynamics.md has why both hold pyramids). A face
// sticks (bound mu_s times the load) until a relax pass leaves it slipping faster than a tenth of the linear slop
// per step; then it slides (bound mu_d) until a relax pass slows it below that. Deciding on the relax pass, the
// substep's last word, and on a speed, keeps one pass's transient from breaking a face loose.
//
// The passes run on blocks of kLanes rows of one colour (ContactBlock), every operation on the four lanes at once;
// each lane gives bit for bit what the scalar formula gives for its row (docs/architecture.md, "Rows four at a
// time").

#include "Impulse.hpp"
#include "Softness.hpp"
#include "SolverData.hpp"
#include "Wide.hpp"

#include "physim/core/Contact.hpp"
#include "physim/core/WorldSettings.hpp"

#include <cstdint>
#include <vector>

namespace physim {

struct ContactCores;
struct ContactData;
struct ContactSurface;
struct StepImpulses;
struct ShapeData;

struct ContactConstraintPoint {
    Vec2 anchorA = Vec2::Zero(), anchorB = Vec2::Zero();  // lever arms from the centres of mass at the start, m
    double rnA = 0.0, rnB = 0.0;  // anchorA x n, anchorB x n: a unit normal impulse's moments, m
    double ndA = 0.0, ndB = 0.0;  // n . anchorA, n . anchorB, m (with rnA, rnB: the turned anchors' reach along n)
    double baseSeparation = 0.0;  // separation - n . (anchorB - anchorA), m: the rest comes from displacements
    double normalImpulse = 0.0;   // N s, this substep's (warm started)
    double normalMass = 0.0;      // kg
    double relativeVelocity = 0.0;  // m/s along the normal at its fastest meeting in this step (events)
    bool engaged = false;
};

/// One contact row, scalar: what the bounce path works on (row() reads one from a lane; setRow puts one into a lane,
/// as tests build blocks). The passes run on ContactBlock, which holds kLanes of these field by field.
struct ContactConstraint {
    std::uint32_t contact = 0;
    std::int32_t indexA = kNullIndex, indexB = kNullIndex;  // awake body indices; kNullIndex: immovable
    Vec2 normal = Vec2::Zero();
    double invMassA = 0.0, invIA = 0.0, invMassB = 0.0, invIB = 0.0;
    double staticFriction = 0.0, dynamicFriction = 0.0, restitution = 0.0;
    double normalAcceleration = 0.0;  // m/s^2, B's minus A's along the normal from gravity and forces
    Vec2 frictionAnchorA = Vec2::Zero(), frictionAnchorB = Vec2::Zero();
    double rtA = 0.0, rtB = 0.0;  // the friction anchors x t
    double tangentMass = 0.0;
    double tangentImpulse = 0.0;
    bool sliding = false;         // friction bound mu_d (true) or mu_s (false); the relax pass decides
    bool turns = true;            // a body can turn: false skips the angular terms (both stay unturned)
    bool keepsPush = false;       // a body can bounce (restitution > 0): the row keeps its push-out apart (holdPushes)
    int pointCount = 0;
    ContactConstraintPoint points[2];
    // Two points' normal mass matrix, for a bounce of both at once; invDet 0: nearly singular, one at a time.
    double k11 = 0.0, k12 = 0.0, k22 = 0.0, invDet = 0.0;
};

/// kLanes rows of one colour (no two share a dynamic body), field by field, so a pass solves them at once: what
/// every pass reads. A lane not in use is an empty row (no bodies, no points, zero masses): every pass leaves it as
/// it is. A one-point row has a second point with zero mass, which never takes an impulse. Line-aligned: threads
/// solve neighbouring blocks, and a line holding the ends of two would pass between their cores on every write.
struct alignas(64) ContactBlock {
    // A's inverse mass and lever-arm moments, and the points' normal masses, are kept negated (-x, exactly): an
    // impulse acts on A with the opposite sign, and opposes the approach; the passes' hottest products then need no
    // negation.
    struct Point {
        Wide negRnA, rnB, negNdA, ndB, baseSeparation, normalImpulse, negNormalMass;
    };
    Wide nx, ny;
    Wide negInvMassA, invIA, invMassB, invIB;
    Point points[2];
    Wide negRtA, rtB, tangentMass, tangentImpulse;
    Wide staticFriction, dynamicFriction, sliding;  // sliding: 1 or 0
    std::int32_t indexA[kLanes], indexB[kLanes];
    std::uint8_t writes = 0;  // the sides the rows can move: bit k lane k's A, bit kLanes + k its B
    bool turns = false;       // some lane's body can turn (else the angular terms are skipped for all)
    bool friction = false;    // some lane has friction
    bool twoPoints = false;   // some lane has a second point (else the passes skip the second point's work)
    bool keepsPushes = false;  // some lane keeps its push-out apart (a body can bounce)
    bool holdsPush = false;    // some lane's point holds push-out recorded on its bodies (ContactBlockCold::push)
    const struct ContactBlockEnds* ends = nullptr;  // where some lane's rounded side is on a straight side
    // N s of friction given over the step so far (ContactBlockCold::totalNormal's rule): in the last line's padding,
    // a line every pass reads anyway.
    Wide totalTangent;
};
static_assert(sizeof(ContactBlock) == 15 * 64, "the friction total fills padding: the block keeps its 15 lines");

/// The rest of a block's rows, read only by the bounce path and at the step's end, and the step's normal totals
/// (kept apart so that the passes stream less memory). What preparation computes four lanes at once is stored the same way, field by field (one
/// vector store each, where a lane at a time took an extraction and a store per value). Line-aligned, like the blocks.
struct alignas(64) ContactBlockCold {
    // Per point, N s given over the step so far (each substep's final impulse, bounces' blows included), what
    // contacts() reports; only ContactPass::total passes and bounces write them, nothing in the step reads them, so
    // the warm start and the motion are as without them. One line, the only one of the block the relax pass touches
    // on every substep.
    Wide totalNormal[2];
    Wide anchorAx[2], anchorAy[2], anchorBx[2], anchorBy[2];  // per point: lever arms from the centres of mass, m
    Wide k11, k12, k22, invDet;  // ContactConstraint's (a bounce of both points at once)
    Wide restitution, normalAcceleration;
    Wide relativeVelocity[2];  // per point
    Wide push[2];  // per point: N s of this substep's solve-pass push-out it holds, still in its bodies' record
    struct Lane {
        std::uint32_t contact = 0;
        int pointCount = 0;
        bool engaged[2] = {false, false};
        bool keepsPush = false;  // the row's ContactConstraint::keepsPush
    } lanes[kLanes];
};

/// The ends of the straight sides a block's rounded sides rest on (RoundedRows.hpp), in an array beside the cold
/// blocks written only for a block that has some (ContactBlock::ends): per point, the interval of the centre of
/// curvature's travel along the tangent (m, from the step's start) within which it is over its side (-inf, +inf in
/// a lane without one), how the surface turns past each end (cosine and sine, RoundedRows.cpp), and the lane's sum
/// of rounding radii, m.
struct alignas(64) ContactBlockEnds {
    Wide lo[2], hi[2], loCos[2], loSin[2], hiCos[2], hiSin[2], rounding;
};

/// A block's surface-material terms, kept in an array of their own that only a world using rolling resistance or
/// belt speeds has (WorldImpl::surfaceMaterials): a world without them runs the passes it always has. In the relax
/// pass, after the normal rows, a rolling row drives the bodies' relative angular velocity wB - wA to zero with an
/// angular impulse of at most `rolling` times the row's normal impulse (so a torque of at most C_rr r N), opposing
/// the rolling and never reversing it; then the friction row drives the faces' tangential speed to -tangentSpeed
/// instead of zero (a belt). A lane without them has zeros there, and moves as it would without the array.
struct alignas(64) ContactBlockMaterial {
    Wide tangentSpeed;    // m/s, ContactMaterial's
    Wide rolling;         // m, ContactMaterial's: angular bound per unit normal impulse
    Wide rollingMass;     // kg m^2: 1 / (IA^-1 + IB^-1); 0 where neither side turns
    Wide rollingImpulse;  // N m s, accumulated over the step (from zero: the bodies' warm start carries it on)
};

/// Which rows a block holds: [first, first + count) of the rows in colour order.
struct BlockRows {
    std::uint32_t first = 0, count = 0;
};

/// Puts row c into the block's lane and marks the block (turns, friction, solve kinds, write bits); row() reads a
/// lane back (its `turns` is the block's).
void setRow(ContactBlock& block, ContactBlockCold& cold, int lane, const ContactConstraint& c);
ContactConstraint row(const ContactBlock& block, const ContactBlockCold& cold, int lane);
/// Readies a block for `lanes` rows: its marks cleared, the lanes from `lanes` on empty rows; setRow fills the rest.
void startBlock(ContactBlock& block, ContactBlockCold& cold, int lanes);

/// What preparing blocks found.
struct PreparedRows {
    std::size_t turning = 0;  // rows a body of which turns
    bool bounce = false;      // some row can bounce (restitution > 0)
    bool rounded = false;     // some row has a rounded side on a straight one (RoundedRows.hpp)
};
struct RoundedSides;
/// Prepares blocks [0, count): block j's lanes from rows refs[rows[j].first ..] (rows[j].count of them; the other
/// lanes empty rows), each from its contact's manifold and its bodies (lever arms at the centres of mass): an awake
/// side (index >= 0) from the solver's copy in sims, a static or sleeping one (kNullIndex) from its record in
/// bodies. Four lanes at once; a lane's bits never depend on the others or on `code` (as for the passes below).
/// With `cores` (per contact, ContactCores), the shapes and `ends` (ends[j] beside block j), a rounded side's rows
/// on a straight side are measured from its centres of curvature (RoundedRows.hpp); without, from the contact
/// points. With `sides` (per contact slot), those sides are found again only where what they follow from changed.
PreparedRows prepareContacts(ContactBlock* blocks, ContactBlockCold* cold, const BlockRows* rows, std::size_t count,
                             const RowRef* refs, const ContactData* contacts, const SolverBodySim* sims,
                             const BodyData* bodies, WideCode code = WideCode::Best,
                             const ContactCores* cores = nullptr, const ShapeData* shapes = nullptr,
                             ContactBlockEnds* ends = nullptr, RoundedSides* sides = nullptr);
/// After prepareContacts, in a world that uses surface materials: blocks [0, count)'s terms (material[j] block j's),
/// from surfaces[i] for contact i (ContactSurface). A pass of its own, so preparation without them is as it was.
void prepareMaterials(const ContactBlock* blocks, const ContactBlockCold* cold, ContactBlockMaterial* material,
                      const BlockRows* rows, std::size_t count, const ContactSurface* surfaces);
/// The passes over blocks [begin, end); cold[i] belongs to begin[i]. states[i] is awake body i, and states[-1]
/// (kNullIndex) a still body that the rows read for an immovable side and never write.
static_assert(kNullIndex == -1, "the rows read an immovable side at states[kNullIndex]");
/// `code` picks the loops' build; WideCode::Avx2 only where avx2CodeRuns(), WideCode::Avx512 where avx512CodeRuns().
void warmStartContacts(ContactBlock* begin, ContactBlock* end, SolverBody* states, WideCode code = WideCode::Best);
/// What one pass over the rows needs.
struct ContactPass {
    double h = 0.0, invH = 0.0;       // the substep, s, and its inverse
    int substep = 0;
    bool useBias = true;              // solve: push overlap out softly; false: relax, no push
    Softness softness;
    double maxPushVelocity = 0.0;     // m/s
    double restitutionThreshold = 0.0;  // m/s
    double slipSpeed = 0.0;           // m/s: faces moving against each other faster than this slide
    PushVelocity* pushes = nullptr;   // per awake body, what this substep's push-out gave it (solve passes)
    RowsBase* rowsBase = nullptr;     // per awake body, when the warm start runs on the bodies: bounces go here
    const WarmStartVelocity* warmStarts = nullptr;  // per awake body, what this substep's warm start gave it: read
                                                    // only by rows that can bounce (restitution > 0)
    bool holdPushes = false;  // rows that keep their push-out apart do (needs a relax pass: it takes the push back)
    bool total = false;       // the substep's last pass: its rows add their impulses to their step totals
};
/// With `material` (material[i] belongs to begin[i]), the relax pass adds the blocks' surface-material terms.
void solveContacts(ContactBlock* begin, ContactBlock* end, ContactBlockCold* cold, SolverBody* states,
                   const ContactPass& pass, WideCode code = WideCode::Best, ContactBlockMaterial* material = nullptr);
/// Where the rows warm start a substep after the step's first (warmStartContacts), their rolling impulses too.
void warmStartRolling(const ContactBlock* begin, const ContactBlock* end, const ContactBlockMaterial* material,
                      SolverBody* states);
/// Writes a lane's impulses back into its manifold (the last substep's: the next step's warm start) and its step
/// totals into `totals` (what contacts() reports).
void storeImpulses(const ContactBlock& block, const ContactBlockCold& cold, int lane, ContactData& contact,
                   StepImpulses& totals);

}  // namespace physim
