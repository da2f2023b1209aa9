#pragma once
// Persistent contacts: one record per pair of shapes (of two bodies) whose enlarged boxes overlap, except a pair with a moving
// continuous body that cannot meet within the step (the broad phase asks about it again each step). Internal.
//
// The broad phase creates a record when two proxies start to overlap and the narrow phase destroys it when they
// no longer do (or when the pair becomes one of those). In between, the record keeps its manifold (points keyed
// by feature id, with their impulses) from step to step, so warm starting carries over and begin / end events are
// exact.

#include "BodyData.hpp"
#include "ShapeData.hpp"

#include "physim/core/Contact.hpp"
#include "physim/core/WorldSettings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace physim {

/// The shapes' last full collision, kept in the bodies' own frames (about their centres of mass): while the pair
/// has moved less than a tolerance relative to itself, the manifold is rebuilt from it (a few products) instead of
/// colliding the shapes again (Contacts.cpp).
struct ManifoldCache {
    double margin = -1.0;           // speculative distance the shapes were collided with, m; < 0: nothing kept
    std::int16_t pointCount = 0;
    // With pointCount 0, how long the routine's empty answer holds (StaysEmpty, Manifolds.hpp): while the point of
    // b it measured, `quietArm` (m, rounded up) from b's centre of mass, moves less than `quiet` (m) in a's frame
    // (`quietAtAnyMargin`), or while the margin plus that move stays below it. In the record's padding.
    bool quietAtAnyMargin = false;
    float quietArm = 0.0f;
    Vec2 offset = Vec2::Zero();     // b's centre of mass in a's frame, m
    double angle = 0.0;             // b's angle minus a's, rad
    double quiet = 0.0;
    Vec2 normal = Vec2::Zero();     // in a's frame
    struct Point {
        Vec2 onA = Vec2::Zero();    // the point on a's surface, in a's frame about its centre of mass, m
        Vec2 onB = Vec2::Zero();    // the point on b's surface, in b's frame
        std::uint32_t id = 0;
        // The larger rounding radius (m) of the two surfaces here (0: both sharp). A round surface's point does not
        // turn with its body as it rolls: it stays where the other surface is, so a cached point would slip back
        // by turn x rounding (Contacts.cpp: the cache holds only while that stays below rollToleranceFor).
        float rounding = 0.0f;
    };
    std::array<Point, 2> points{};
};

/// The pair's material, mixed from its shapes' by WorldSettings' rules (by default the paper's: restitution min,
/// friction coefficients averaged) when the contact is made, and again when either shape's material or a rule
/// changes.
struct ContactMaterial {
    double staticFriction = 0.0;
    double dynamicFriction = 0.0;
    double restitution = 0.0;
};

/// The pair's surface terms (rolling resistance, belt speed), mixed like ContactMaterial. Kept beside the contacts
/// (WorldImpl::contactSurfaces) rather than in them: a contact is six cache lines, full, and only a world that uses
/// these reads them.
struct ContactSurface {
    double rolling = 0.0;       // m: the rolling row's angular bound per unit normal impulse (coefficient x radius)
    double tangentSpeed = 0.0;  // m/s: the friction row holds the bodies' tangential speed at -tangentSpeed
};

/// What a contact's points carried over the last step that solved it, N s: each the sum of the substeps' final
/// impulses (bounces' blows included), so divided by the step it is the mean force. Kept beside the contacts
/// (WorldImpl::contactImpulses): the manifold's own impulses are the last substep's, the solver's warm start, and a
/// contact is full. Zero until solved; a sleeping pair's keep their last values. The tangent's is shared evenly
/// between the points, as the one friction row at the manifold's centre acts.
struct StepImpulses {
    double normal[2] = {0.0, 0.0};
    double tangent[2] = {0.0, 0.0};
};

/// Line-aligned: the solver's preparation reads a record up to `cache`, in colour order (at random), and that part
/// is then three lines, never four; what only the narrow phase and the bookkeeping read comes after. Six lines in
/// all (the fields fill the padding the vectors' alignment leaves).
struct alignas(64) ContactData {
    ContactMaterial material;
    bool sliding = false;           // its friction slid at the end of the last step (ContactSolver.hpp)
    bool keepsPush = false;         // a shape can bounce (restitution > 0): its row keeps its push-out apart
    bool touching = false;          // a manifold point within the speculative distance (islands, events)
    bool alive = false;
    std::int32_t awakeIndex = kNullIndex;  // position in World's awake contact list; kNullIndex while both sleep
    Manifold manifold;              // its ids name the pair's bodies and shapes (shape slots: shapeA() < shapeB());
                                    // the normal points from body a to body b
    ManifoldCache cache;            // only the narrow phase reads it, the solver's preparation does not
    // Intrusive lists through each body's contacts: side 0 is in a's list, side 1 in b's.
    std::int32_t prev[2] = {kNullIndex, kNullIndex};
    std::int32_t next[2] = {kNullIndex, kNullIndex};
    std::uint32_t generation = 0;
    // The shapes' proxy keys, fixed while the contact lives (a shape's proxy is remade only after its contacts end).
    std::int32_t proxyA = kNullIndex, proxyB = kNullIndex;
    // The pre-solve hook disabled it this step (World::setPreSolve): no row although it has points. Read only while
    // a hook is set.
    bool disabled = false;

    std::uint32_t a() const { return manifold.bodyA.index; }  // body slots
    std::uint32_t b() const { return manifold.bodyB.index; }
    std::uint32_t shapeA() const { return manifold.shapeA.index; }
    std::uint32_t shapeB() const { return manifold.shapeB.index; }
};

static_assert(sizeof(ContactData) == 6 * 64, "six lines: see the field order");

/// Two shapes' coefficients combined by `rule` (validated: WorldSettings). Average and Min are the expressions
/// the default rules have always used, so their bits do not change.
inline double mixCoefficients(MixingRule rule, double a, double b) {
    switch (rule) {
        case MixingRule::GeometricMean: return std::sqrt(a * b);
        case MixingRule::Min: return b < a ? b : a;  // std::min's rule
        case MixingRule::Max: return a < b ? b : a;  // std::max's rule
        case MixingRule::Multiply: return a * b;
        case MixingRule::Average: break;
    }
    return 0.5 * (a + b);
}

/// The radius a shape rolls on, m: a circle's or a capsule's, a rounded polygon's rounding; 0 for what has no
/// round part (a sharp polygon, a segment), which tips or slides rather than rolls.
inline double rollingRadius(const Geometry& g) {
    if (const auto* c = std::get_if<Circle>(&g)) return c->radius;
    if (const auto* c = std::get_if<Capsule>(&g)) return c->radius;
    if (const auto* p = std::get_if<Polygon>(&g)) return p->radius;
    return 0.0;
}

/// The pair's rounded sides, for the solver's separation (RoundedRows.hpp): each shape's rounding radius (its
/// rollingRadius, m) and whether its core has straight sides (a polygon's, segment's, capsule's or chain piece's;
/// a circle's core is a point). Kept beside the contacts (WorldImpl::contactCores), set when the contact is mixed.
struct ContactCores {
    double radiusA = 0.0, radiusB = 0.0;
    bool facesA = false, facesB = false;
};

inline ContactCores coresOf(const ShapeData& a, const ShapeData& b) {
    return {rollingRadius(a.geometry), rollingRadius(b.geometry), !std::holds_alternative<Circle>(a.geometry),
            !std::holds_alternative<Circle>(b.geometry)};
}

/// The contact's material from its shapes' (a the contact's shape a), by the world's mixing rules.
inline void mixMaterials(ContactData& c, const ShapeData& a, const ShapeData& b, const WorldSettings& settings) {
    c.material.staticFriction = mixCoefficients(settings.frictionMixing, a.staticFriction, b.staticFriction);
    c.material.dynamicFriction = mixCoefficients(settings.frictionMixing, a.dynamicFriction, b.dynamicFriction);
    c.material.restitution = mixCoefficients(settings.restitutionMixing, a.restitution, b.restitution);
    c.keepsPush = a.restitution > 0.0 || b.restitution > 0.0;
}

/// The pair's surface terms. Rolling resistance takes the larger coefficient (either surface that deforms resists)
/// on the rounder shape's radius. Tangent speeds add, each shape's surface running clockwise around it: along the
/// pair's tangent t = perp(n) (n from a to b), a's surface moves at -sA and b's at +sB, so the faces rest on each
/// other when b's material point moves at -(sA + sB) along t relative to a's.
inline ContactSurface mixSurfaces(const ShapeData& a, const ShapeData& b) {
    const double radiusA = rollingRadius(a.geometry), radiusB = rollingRadius(b.geometry);
    return {std::max(a.rollingResistance, b.rollingResistance) * std::max(radiusA, radiusB),
            a.tangentSpeed + b.tangentSpeed};
}


}  // namespace physim
