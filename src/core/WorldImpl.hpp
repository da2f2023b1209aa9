#pragma once
// Everything a World holds, as plain data shared by the step's stages (one file each). Internal.
//
//   World.cpp          the public API: bodies, settings, step()
//   WorldShapes.cpp    the public API of shapes: several per body, their mass, chains
//   BroadPhase.cpp     dynamic trees, new candidate pairs
//   Contacts.cpp       persistent contacts: creation, the narrow-phase update, begin / end
//   Islands.cpp        persistent islands: merging, splitting, sleeping and waking
//   Solver.cpp         the soft step: gather, substeps, restitution, finalize (its scratch in Solver.hpp)
//   ConstraintGraph.cpp the rows' layout: colours, this step's islands and groups, the halves of two threads
//   ContactSolver.cpp  the contact constraint rows
//   joints/            one file per joint kind (Joints.hpp: what a kind provides; WorldJoints.cpp: their API)
//   ContinuousStage.cpp time of impact for fast bodies
//   Sensors.cpp        sensors' overlaps and events
//   WorldEffects.cpp   the public API of the effects
//   WorldSnapshots.cpp snapshots, restores and the state hash: copies of WorldState
//   SnapshotFile.cpp   snapshots to files and back: WorldState member by member
//   WorldFilters.cpp   collision filters and the contact hooks (pair filter, pre-solve): their API and step work
//   effects/           the force effects (effects/Effects.hpp), each run only while the world uses it

#include "BodyData.hpp"
#include "BroadPhase.hpp"
#include "ContactData.hpp"
#include "ContinuousStage.hpp"
#include "Executor.hpp"
#include "IslandData.hpp"
#include "JointData.hpp"
#include "Joints.hpp"
#include "PairSet.hpp"
#include "Sensors.hpp"
#include "ShapeData.hpp"
#include "Solver.hpp"
#include "effects/Effects.hpp"

#include "physim/core/Contact.hpp"
#include "physim/core/ContactHooks.hpp"
#include "physim/core/StepProfile.hpp"
#include "physim/core/WorldSettings.hpp"

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace physim {

class ContinuousSolver;

/// Margin (m) by which a proxy's box exceeds its body's box, so small motions never touch the broad phase: at most
/// kAabbMargin, and at most kMarginPerExtent of the body's extent, so a crowd of small bodies pairs only with near
/// neighbours, not with every body within 0.1 m. A quarter leaves bodies of 0.4 m extent or more at 0.1 m: a car's
/// wheel with less moves its proxy more often than its fewer pairs save (docs/collision.md, "Proxies").
constexpr double kAabbMargin = 0.1;
constexpr double kMarginPerExtent = 0.25;
/// Steps of its present travel a proxy's box reaches ahead of its body, no further than kLookAheadReach (m) nor the
/// body's extent (or the one step's travel where that is longer): a body moving steadily (a car's wheel at 0.06 m
/// a step) leaves its box every few steps, not every one or two, for a box a little longer (the pairs it finds are
/// more, each cheap while apart). The reach is short so that a fast body does not sweep a long box through a crowd
/// (Box2D v3's smash ram). A box grown more than kAabbMargin past what the body's motion now asks for (it slowed
/// down) is made anew, so a pile that came to rest keeps no long boxes from its fall.
constexpr double kLookAheadSteps = 3.0;
constexpr double kLookAheadReach = 2.0 * kAabbMargin;

// The world's state: everything a snapshot copies (World::snapshot) and a restore puts back, so that stepping on
// gives bit for bit what the original run gave. Values only, so that a copy is a snapshot; the few pointers in it
// (the solver's into its own scratch) are set again by every step before they are read.
struct WorldState {
    WorldSettings settings;

    // Bodies: one slot per id; freed slots are reused (their generation makes old ids stale).
    std::vector<BodyData> bodies;
    std::vector<std::uint32_t> freeBodies;
    std::size_t liveCount = 0;
    std::size_t dynamicCount = 0;
    std::size_t continuousCount = 0;  // bodies whose detection is not Discrete
    std::uint64_t shapeRevision = 1;  // changes whenever a shape slot's geometry may have (create, destroy)
    std::vector<std::uint32_t> awake;   // awake movable bodies (dynamic and kinematic): the solver's bodies

    // Shapes: one slot per id, as bodies. A world whose bodies have one shape each gives body and shape the same slot.
    std::vector<ShapeData> shapes;
    std::vector<std::uint32_t> freeShapes;
    std::size_t shapeLiveCount = 0;

    // Contacts: one slot per overlapping pair of proxies (shapes of two bodies).
    std::vector<ContactData> contacts;
    std::vector<std::uint32_t> freeContacts;
    std::vector<std::uint32_t> awakeContacts;  // contacts with an awake body: the narrow phase's work list
    // Per awake contact (awakeContacts' order): its manifold has points, so it may have a row. The layout reads
    // these bytes instead of every awake contact's record; most awake contacts on a terrain have none.
    std::vector<std::uint8_t> awakeHasPoints;
    PairSet contactPairs;                      // shape slots (a, b) of every contact, a < b
    // Per contact slot, its surface terms: empty until some contact has one (surfaceMaterials), then kept for every
    // contact mixed since (those mixed before had none: a slot past the end reads as zero terms).
    std::vector<ContactSurface> contactSurfaces;
    std::vector<ContactCores> contactCores;  // per contact slot: its sides' rounding (ContactData.hpp)
    std::vector<StepImpulses> contactImpulses;  // per contact slot: its last solved step's totals (contacts())

    // Joints and islands.
    std::vector<JointData> joints;
    std::vector<std::uint32_t> freeJoints;
    std::size_t jointCount = 0;
    std::size_t rowJointCount = 0;  // joints solved as rows (all but springs)
    std::size_t breakableJoints = 0;  // joints with a finite breakForce or breakTorque: the step checks them
    JointEvents jointEvents;
    std::vector<IslandData> islands;
    std::vector<std::uint32_t> freeIslands;

    BroadPhase broadPhase;
    Solver solver;
    ContinuousStage continuous;
    Effects effects;
    SensorStage sensors;  // Sensors.cpp: the sensor shapes, their overlaps and events

    // Step scratch, kept between steps so a running scene allocates nothing.
    std::vector<ShapePair> newPairs;
    std::vector<std::uint8_t> contactFlags;      // per awake contact: what the narrow phase found changed
    std::vector<std::pair<std::uint32_t, std::uint8_t>> changedContacts;
    // The narrow phase tests each awake contact's proxies for overlap only when a box or the awake contacts changed
    // since it last did (Contacts.cpp): every contact it then kept overlapped, and still does.
    bool awakeContactsChanged = true;
    std::uint64_t checkedBoxRevision = 0;
    std::vector<std::uint32_t> touched;          // bodies changed since the last step: proxies to check
    std::vector<double> islandSleep;             // per island: least sleep time of its awake bodies
    std::vector<std::uint32_t> splitStack;
    std::vector<std::uint32_t> splitMembers;
    std::vector<std::uint32_t> found;             // broad-phase query results
    std::vector<std::uint32_t> sleepy;           // islands ready to sleep this step

    // Filters and contact hooks (WorldFilters.cpp): each costs a flag test per step while unused.
    PairFilterCallback pairFilter;          // null: the shapes' filters alone decide
    PreSolveCallback preSolve;              // null: no contact is asked
    std::vector<std::uint32_t> refiltered;  // shape slots whose filter changed since the last step
    bool refilterAll = false;               // the pair filter changed: every contact is asked again

    StepProfile profile;
    ContactEvents events;
    mutable std::vector<Manifold> touchingManifolds;  // contacts()' answer, built on demand
    mutable bool touchingValid = false;
    double dt = 0.0;
    bool stepping = false;
    std::uint64_t stepCount = 0;
    // Some contact has had rolling resistance or a belt speed: from then on the solver runs its material terms
    // (ContactBlockMaterial); a world that never uses them runs the loops it always has.
    bool surfaceMaterials = false;
};

/// World::stateHash's hash of a state (WorldSnapshots.cpp).
std::uint64_t stateHashOf(const WorldState& s);

struct WorldImpl : WorldState {
    Executor executor;  // the threads: the machine's, not the state's
    EnergyLedger ledger;  // World::setEnergyLedger: an observer's, not the state's (a restore starts it again)
    GravitationPotential gravitationPotential;  // the ledger's last all-pairs sum (EnergyTally.hpp)

    // --- helpers shared by the stages (defined in the file of their concern) ----------------------------
    BodyData& body(std::uint32_t slot) { return bodies[slot]; }

    // WorldEnergy.cpp: the ledger's energy now (kinetic + potential), and a step's close from the energy before it
    double ledgerEnergy();
    void closeLedgerStep(double before, bool solved);

    // World.cpp
    void requireNotStepping(const char* call) const;
    void wakeOverlapping(const Aabb& box);  // sleeping bodies whose proxies overlap the box wake
    /// Takes a joint slot for `data`, links it to its bodies (and their islands) and wakes them.
    std::uint32_t addJoint(const JointData& data);
    /// Unlinks and frees joint `index`, waking its bodies; a joint that kept them apart lets their shapes pair again.
    void removeJoint(std::uint32_t index);
    /// Whether a joint between the two bodies keeps them from colliding (one without collideConnected).
    bool jointKeepsApart(std::uint32_t a, std::uint32_t b) const;
    /// Destroys the joints whose last step's reaction crossed their break thresholds, recording each.
    void breakJoints();
    /// A body's motion over the next step as its boxes take it: the displacement at its present velocity (a
    /// Discrete body's at most its extent), that displacement's length (m), and how far its turn reaches (m).
    struct StepTravel {
        Vec2 travel;
        double length, turn;
    };
    StepTravel stepTravel(const BodyData& b) const;
    /// The box a proxy needs for a shape whose tight box is `box` on body b, at b's pose and velocity (`t`): the next
    /// step's motion and turn. A proxy that no longer holds it moves.
    Aabb neededBox(const BodyData& b, const StepTravel& t, const Aabb& box) const {
        return sweptBox(b, t, box, 1.0, 0.0);
    }
    /// The box a proxy gets: the needed box reaching kLookAheadSteps of travel ahead, grown by proxyMargin. A static
    /// body's shapes stay put (a user's move makes their proxies anew), and a partner's box already covers the
    /// partner's motion: theirs grow only by the speculative distance, the farthest apart a point is kept at rest,
    /// as Box2D v3's do. A terrain's many pieces then pair with fewer of the pieces beside the ones a body is on.
    Aabb proxyBox(const BodyData& b, const StepTravel& t, const Aabb& box) const {
        if (b.type == BodyType::Static) return box.fattened(speculativeDistance());
        return sweptBox(b, t, box, kLookAheadSteps, proxyMargin(b));
    }
    /// The margin of a movable body's proxies, m (kMarginPerExtent).
    static double proxyMargin(const BodyData& b) { return std::min(kAabbMargin, kMarginPerExtent * b.extent); }
    Aabb proxyBox(const BodyData& b, const Aabb& box) const { return proxyBox(b, stepTravel(b), box); }
    /// How far apart (m) the narrow phase keeps a pair's points even when the pair does not close (4 linear slops).
    double speculativeDistance() const { return 4.0 * settings.linearSlop; }
    /// The shape's box swept over `steps` of b's travel `t` (more steps: at most kLookAheadReach and b's extent, or
    /// the one step), grown by the turn's reach and by margin (m).
    Aabb sweptBox(const BodyData& b, const StepTravel& t, const Aabb& box, double steps, double margin) const;
    /// f(slot, shape) for each of the body's shapes, in the order they were added; f must not relink the list.
    template <class F>
    void forEachShape(const BodyData& b, F&& f) {
        for (std::int32_t s = b.shapeHead; s != kNullIndex; s = shapes[static_cast<std::size_t>(s)].next)
            f(static_cast<std::uint32_t>(s), shapes[static_cast<std::size_t>(s)]);
    }
    template <class F>
    void forEachShape(const BodyData& b, F&& f) const {
        for (std::int32_t s = b.shapeHead; s != kNullIndex; s = shapes[static_cast<std::size_t>(s)].next)
            f(static_cast<std::uint32_t>(s), shapes[static_cast<std::size_t>(s)]);
    }
    /// A body that collides (has proxies) whose motion left one of its shapes' proxy boxes, or whose box is more
    /// than kAabbMargin wider or taller than the one proxyBox gives it now.
    bool proxyOutgrown(const BodyData& b) const {
        const StepTravel travel = stepTravel(b);
        bool outgrown = false;
        forEachShape(b, [&](std::uint32_t, const ShapeData& shape) {
            if (outgrown || shape.proxy == kNullIndex) return;
            const Aabb& box = broadPhase.fatBox(shape.proxy);
            const Aabb wanted = proxyBox(b, travel, shape.aabb);
            const Vec2 excess = (box.upper - box.lower) - (wanted.upper - wanted.lower);
            outgrown = !box.contains(neededBox(b, travel, shape.aabb)) || excess.maxCoeff() > kAabbMargin;
        });
        return outgrown;
    }
    /// Every shape's proxy gets the box the body's motion needs.
    void moveProxies(const BodyData& b) {
        const StepTravel travel = stepTravel(b);
        forEachShape(b, [&](std::uint32_t, const ShapeData& shape) {
            if (shape.proxy != kNullIndex) broadPhase.moveProxy(shape.proxy, proxyBox(b, travel, shape.aabb));
        });
    }
    /// The tight boxes of the body's shapes, and of the body, at its pose. A step keeps them only for bodies that
    /// collide (the broad phase, sensors and queries read them through proxies): bodyBounds and shapeBounds give
    /// any body's at its pose now.
    void updateBoxes(BodyData& b);
    Aabb bodyBounds(const BodyData& b) const;
    Aabb shapeBounds(const ShapeData& shape) const;
    /// Proxies for every shape of the body (it collides; its boxes brought up to date first), or none.
    void createProxies(std::uint32_t body);
    void destroyProxies(std::uint32_t body);
    /// The contacts of the body that involve the shape (by slot), for materials and destruction.
    template <class F>
    void forEachContactOfShape(std::uint32_t shape, F&& f);
    /// Mass, centre of mass, inertia, extent and core radius from the body's shapes (a dynamic body's mass throws,
    /// naming the value, unless positive, the body unchanged); the origin stays.
    void updateMass(std::uint32_t body);
    /// A static body's shapes wake the sleepers their proxies overlap.
    void wakeShapesOverlapping(std::uint32_t body);
    /// The body's mean width over all directions, m (drag): its shape's, or that of the convex hull of its shapes.
    double meanWidth(std::uint32_t body) const;
    /// Gives the body this drag (DragEffect::set, which measures the body's mean width only where the drag reads
    /// it: a ground of many shapes added one by one would otherwise pay a hull of all of them per shape).
    void setDrag(std::uint32_t body, const DragDef& def);
    /// Sets a shape's material and mixes it again into its contacts.
    void setShapeMaterial(std::uint32_t shape, double restitution, double staticFriction, double dynamicFriction);
    /// Sets a shape's rolling resistance and tangent speed (validated) and mixes them again into its contacts.
    void setShapeSurface(std::uint32_t shape, double rollingResistance, double tangentSpeed);
    /// Mixes every contact's material again from its shapes' (a mixing rule changed).
    void remixContacts();
    /// Mixes contact c's material from its shapes' (mixMaterials), noting whether it needs the material terms.
    void mixContact(std::uint32_t c);

    // Contacts.cpp
    void createContact(std::uint32_t shapeA, std::uint32_t shapeB);
    void destroyContact(std::uint32_t contact, bool wakeBodies);
    bool contactExists(std::uint32_t shapeA, std::uint32_t shapeB) const;
    void updatePairs();      // broad phase's new pairs become contacts
    void updateContacts();   // the narrow phase over the awake contacts
    void addAwakeContact(std::uint32_t contact);
    void removeAwakeContact(std::uint32_t contact);

    // WorldFilters.cpp
    /// Whether shapes a and b (slots, of two bodies) may make a contact: their filters, then the pair filter.
    bool pairAllowed(std::uint32_t a, std::uint32_t b) const;
    /// At the step's start, after a filter change: the contacts now refused end (end events; their bodies wake) and
    /// the changed shapes' pairs are offered again.
    void applyFilterChanges();
    /// After the narrow phase (preSolve set): each awake contact with points is asked, in the awake list's order; a
    /// disabled one does not touch and has no row this step.
    void runPreSolve();

    // Islands.cpp
    void createIsland(std::uint32_t bodySlot);
    void removeFromIsland(std::uint32_t bodySlot);
    void linkBodies(std::uint32_t a, std::uint32_t b);    // a constraint began between two dynamic bodies
    void unlinkBodies(std::uint32_t a, std::uint32_t b);  // a constraint between them ended
    void wakeBody(std::uint32_t slot);                     // wakes its island (or the body, if it has none)
    /// A setter's change(kind) to joint `id` (its record `joint`, checked live), which must be a Kind (else
    /// std::invalid_argument naming `call`), its bodies woken. A change that moves the joint's row into or out of
    /// lanes (jointLanes) lays the rows out again: a kept layout keeps its rows' places in blocks.
    template <class Kind, class Change>
    void changeJoint(const JointData& joint, JointId id, const char* call, Change&& change) {
        requireNotStepping(call);
        if (!std::holds_alternative<Kind>(joint.params))
            throw std::invalid_argument(std::string("physim: ") + call + " needs a " + Kind::kName + " joint");
        JointData& j = joints[id.index];
        wakeBody(j.a);
        wakeBody(j.b);
        const RowLanes before = jointLanes(j);
        change(std::get<Kind>(j.params));
        if (jointLanes(j) != before) solver.layoutChanged();
    }
    void wakeIsland(std::uint32_t island);
    void addAwakeBody(std::uint32_t slot);
    void removeAwakeBody(std::uint32_t slot);
    void rebuildIslands();   // from the touching contacts and joints (sleep turned on)
    void updateSleep();      // the Sleep stage
    void splitIsland(std::uint32_t island);
    void sleepIsland(std::uint32_t island);
};

// The mass rules of a body over its shapes (WorldShapes.cpp).
/// Mass and inertia of a dynamic body with `mass` kg spread over its shapes, by the one mass rule (MassData.hpp).
/// Throws (naming the value) unless the mass and the inertia come out positive and finite.
void assignMass(BodyData& b, double mass);
void clearMass(BodyData& b);
/// Largest distance from `center` to the shape (how far a point moves per radian of turn about it), m.
double extentAbout(const Geometry& g, const Vec2& center);
/// Radius (m) of the largest circle about the shape's centroid inside it (for a circle, its radius).
double coreRadius(const Geometry& g);

template <class F>
void WorldImpl::forEachContactOfShape(std::uint32_t shape, F&& f) {
    const BodyData& b = bodies[shapes[shape].body];
    for (std::int32_t key = b.contactHead; key != kNullIndex;) {
        const std::uint32_t c = static_cast<std::uint32_t>(key >> 1);
        key = contacts[c].next[key & 1];  // f may destroy the contact
        if (contacts[c].shapeA() == shape || contacts[c].shapeB() == shape) f(c);
    }
}

// Inline: the step asks for every moving body's (Solver::finishBody, proxyOutgrown).
inline WorldImpl::StepTravel WorldImpl::stepTravel(const BodyData& b) const {
    // Where the body is and where its velocity takes it over the next step, and how far its turn reaches: the
    // speculative contacts then see what it will meet. A discrete body's reach is capped at its own size: a body
    // that moves farther in a step is the Continuous stage's (against static bodies), and sweeping it across the
    // world would pair it with everything on the way. However fast it spins, the shape stays within its extent of
    // the centre of mass, which stays inside the box of the path: the turn moves the outline no further than its
    // reach (BodyData::turnReach), which a wheel's, turning onto itself, does not move at all.
    StepTravel t{b.v * dt, 0.0, std::min(std::abs(b.w) * dt * b.turnReach, b.turnReach)};
    t.length = t.travel.norm();
    if (b.detection == CollisionDetection::Discrete && t.length > b.extent) {
        t.travel *= b.extent / t.length;
        t.length = b.extent;
    }
    return t;
}

inline Aabb WorldImpl::sweptBox(const BodyData& b, const StepTravel& t, const Aabb& aabb, double steps,
                                double margin) const {
    if (b.type == BodyType::Static) return aabb.fattened(margin);
    // Further ahead, up to kLookAheadReach and the body's extent: a body that travels that far in a step gets no
    // more than the step.
    Vec2 travel = t.travel;
    const double length = t.length;
    if (steps > 1.0 && length > 0.0)
        travel *= std::min(steps * length, std::max(length, std::min(b.extent, kLookAheadReach))) / length;
    Aabb box = aabb;
    box.lower = box.lower.cwiseMin(aabb.lower + travel);
    box.upper = box.upper.cwiseMax(aabb.upper + travel);
    return box.fattened(margin + t.turn);
}

}  // namespace physim
