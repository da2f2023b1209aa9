#pragma once
// Everything a World holds, as plain data shared by the step's stages (one file each). Internal.
//
//   World.cpp          the public API: bodies, settings, step()
//   BroadPhase.cpp     dynamic trees, new candidate pairs
//   Contacts.cpp       persistent contacts: creation, the narrow-phase update, begin / end
//   Islands.cpp        persistent islands: merging, splitting, sleeping and waking
//   Solver.cpp         the soft step: gather, colour, substeps, restitution, finalize
//   ContactSolver.cpp  the contact constraint rows
//   joints/            one file per joint kind (Joints.hpp: what a kind provides; WorldJoints.cpp: their API)
//   ContinuousStage.cpp time of impact for fast bodies
//   WorldEffects.cpp   the public API of the effects
//   effects/           the force effects (effects/Effects.hpp), each run only while the world uses it

#include "BodyData.hpp"
#include "BroadPhase.hpp"
#include "ContactData.hpp"
#include "ContactSolver.hpp"
#include "ContinuousStage.hpp"
#include "Executor.hpp"
#include "IslandData.hpp"
#include "JointData.hpp"
#include "PairSet.hpp"
#include "SolverData.hpp"
#include "effects/Effects.hpp"

#include "physim/core/Contact.hpp"
#include "physim/core/StepProfile.hpp"
#include "physim/core/WorldSettings.hpp"

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace physim {

class ContinuousSolver;

/// Margin (m) by which a proxy's box exceeds its body's box, so small motions never touch the broad phase.
constexpr double kAabbMargin = 0.1;

struct WorldImpl {
    WorldSettings settings;
    Executor executor;

    // Bodies: one slot per id; freed slots are reused (their generation makes old ids stale).
    std::vector<BodyData> bodies;
    std::vector<std::uint32_t> freeBodies;
    std::size_t liveCount = 0;
    std::size_t dynamicCount = 0;
    std::size_t continuousCount = 0;  // bodies whose detection is not Discrete
    std::uint64_t shapeRevision = 1;  // changes whenever a body slot's shape may have (create, destroy)
    std::vector<std::uint32_t> awake;   // awake movable bodies (dynamic and kinematic): the solver's bodies

    // Contacts: one slot per overlapping pair of proxies.
    std::vector<ContactData> contacts;
    std::vector<std::uint32_t> freeContacts;
    std::vector<std::uint32_t> awakeContacts;  // contacts with an awake body: the narrow phase's work list
    PairSet contactPairs;                      // (a, b) of every contact, a < b

    // Joints and islands.
    std::vector<JointData> joints;
    std::vector<std::uint32_t> freeJoints;
    std::size_t jointCount = 0;
    std::size_t rowJointCount = 0;  // joints solved as rows (all but springs)
    std::vector<IslandData> islands;
    std::vector<std::uint32_t> freeIslands;

    BroadPhase broadPhase;
    ContinuousStage continuous;
    Effects effects;

    // Step scratch, kept between steps so a running scene allocates nothing.
    std::vector<BodyPair> newPairs;
    std::vector<std::uint8_t> contactFlags;      // per awake contact: what the narrow phase found changed
    std::vector<std::pair<std::uint32_t, std::uint8_t>> changedContacts;
    std::vector<SolverBody> solverBodies;        // a still body, then one per awake body
    SolverBody* states = nullptr;                // &solverBodies[1]: states[i] is awake body i, states[-1] still
    std::vector<PushVelocity> pushVelocities;    // per awake body: the solve passes' push-out (ContactSolver)
    std::vector<RowsBase> rowsBase;              // per awake body: velocity before the substep's rows (Solver)
    std::vector<WarmStartVelocity> warmStarts;   // per awake body: what the substep's warm start gave it (bounces)
    std::vector<SolverBodySim> sims;
    // The awake bodies are solved in groups of whole islands (Solver.cpp); a segment is one group's rows of one
    // colour, or its overflow: segment g * (colours + 1) + c.
    std::vector<std::int32_t> bodyRoot;          // per awake body: union-find parent, then its island's root
    std::vector<std::uint32_t> islandSize;       // per root: its island's bodies
    std::vector<std::uint32_t> bodyGroup;        // per awake body: its group
    // Per awake body, then per island root: its island keeps the warm start as a pass over the rows (it has a joint
    // or an exact-continuous bullet; Solver.cpp); such islands are grouped apart from the others.
    std::vector<std::uint8_t> rowsWarmStart;
    std::vector<std::uint8_t> groupRowsWarmStart;  // per group: the same for all its islands
    std::vector<std::uint32_t> groupBodies;      // awake indices, group by group
    std::vector<std::uint32_t> groupBodyStart;   // group g's bodies: [groupBodyStart[g], groupBodyStart[g + 1])
    std::vector<std::uint32_t> groupJointStart;  // group g's joint rows in jointConstraints, likewise
    std::vector<RowRef> rowContacts;             // the contact of each row, segment by segment
    std::vector<std::uint32_t> segmentStart;     // rows of segment s: [segmentStart[s], segmentStart[s + 1])
    // The rows, kLanes to a block (an overflow row alone), and the rest of each block's rows: a group's blocks live
    // only while it is solved, in a region of `regionBlocks` blocks per worker (Solver.cpp), reused group after group.
    std::vector<ContactBlock> contactBlocks;
    std::vector<ContactBlockCold> contactCold;
    std::size_t regionBlocks = 0;
    std::vector<std::uint32_t> blockStart;       // blocks of segment s: [blockStart[s], blockStart[s + 1])
    std::vector<BlockRows> blockRows;            // per block: its first row and how many lanes it uses
    std::vector<std::uint32_t> shareHeads;       // on two threads, per group and colour: where the halves' heads end
    std::vector<std::uint8_t> bodyShares;        // markShareHeads: which halves touch each awake body (bits)
    std::vector<std::size_t> headBlocks;         // markShareHeads: per group, blocks in heads and all blocks
    std::vector<std::uint32_t> shareBodies;      // on two threads, each group's bodies by half: head, first, second
    std::vector<std::uint32_t> shareBodyCuts;    // per group: where the first half's head ends, and the second's starts
    std::vector<std::int8_t> rowImpact;          // per block lane in use: its impact event's point; -1: none
    std::vector<double> rowImpactSpeed;          // per block lane with an impact: how fast it met, m/s
    std::vector<std::uint32_t> segmentFill;      // counting sorts' next free place
    ContactPass contactPassSettings;             // this step's pass constants
    std::vector<std::uint32_t> bodyColours;      // per awake body, a bit per colour its rows already have
    std::vector<std::int32_t> constraintColour;  // per awake contact with points; -1: none
    std::vector<RowRef> rowRefs;                 // per awake contact with points: its row's contact and bodies
    std::vector<std::uint32_t> rowOrder;         // layOutRows' counting sort: per awake body, where its rows go
    std::vector<std::uint32_t> sortedRows;       // the coloured rows (as rowRefs' indices) by first body
    std::vector<JointConstraint> jointConstraints;  // group by group
    // The rows' layout above (colours, rows, blocks, groups) depends only on the awake bodies and contacts (their
    // order, the bodies' types and detection, which contacts have points), the joints and the thread count: while
    // none of that changes, a step keeps the last one's (layOutRows). Whatever changes it sets rowsStale.
    bool rowsStale = true;
    bool rowsByIsland = true;  // the layout's byIsland
    // The narrow phase tests each awake contact's proxies for overlap only when a box or the awake contacts changed
    // since it last did (Contacts.cpp): every contact it then kept overlapped, and still does.
    bool awakeContactsChanged = true;
    std::uint64_t checkedBoxRevision = 0;
    std::vector<JointConstraint> groupedJoints;
    std::vector<std::int32_t> deferredKeys;  // moveDeferredProxies' proxies and their new boxes
    std::vector<Aabb> deferredBoxes;
    std::vector<std::uint8_t> enlarged;  // per awake body (solver order): proxy outgrown (bit 0), fast (bit 1),
                                         // proxy to move after the Continuous stage (bit 2)
    bool fastBodies = false;                     // a dynamic body moved more than half its core radius
    std::vector<std::uint32_t> touched;          // bodies changed since the last step: proxies to check
    std::vector<double> islandSleep;             // per island: least sleep time of its awake bodies
    std::vector<std::uint32_t> splitStack;
    std::vector<std::uint32_t> splitMembers;
    std::vector<std::uint32_t> found;             // broad-phase query results
    std::vector<std::uint32_t> sleepy;           // islands ready to sleep this step

    StepProfile profile;
    ContactEvents events;
    mutable std::vector<Manifold> touchingManifolds;  // contacts()' answer, built on demand
    mutable bool touchingValid = false;
    double dt = 0.0;
    bool stepping = false;
    std::uint64_t stepCount = 0;

    // --- helpers shared by the stages (defined in the file of their concern) ----------------------------
    BodyData& body(std::uint32_t slot) { return bodies[slot]; }

    // World.cpp
    void requireNotStepping(const char* call) const;
    void wakeOverlapping(const Aabb& box);  // sleeping bodies whose proxies overlap the box wake
    /// Takes a joint slot for `data`, links it to its bodies (and their islands) and wakes them.
    std::uint32_t addJoint(const JointData& data);
    /// The box a proxy needs at the body's pose and velocity (the next step's motion and turn), grown by margin.
    Aabb proxyBox(const BodyData& b, double margin) const;
    /// A body that collides (has a proxy) whose motion left its proxy's box.
    bool proxyOutgrown(const BodyData& b) const {
        return b.proxy != kNullIndex && !broadPhase.fatBox(b.proxy).contains(proxyBox(b, 0.0));
    }
    void moveProxy(const BodyData& b) { broadPhase.moveProxy(b.proxy, proxyBox(b, kAabbMargin)); }

    // Contacts.cpp
    void createContact(std::uint32_t a, std::uint32_t b);
    void destroyContact(std::uint32_t contact, bool wakeBodies);
    bool contactExists(std::uint32_t a, std::uint32_t b) const;
    void updatePairs();      // broad phase's new pairs become contacts
    void updateContacts();   // the narrow phase over the awake contacts
    void addAwakeContact(std::uint32_t contact);
    void removeAwakeContact(std::uint32_t contact);

    // Islands.cpp
    void createIsland(std::uint32_t bodySlot);
    void removeFromIsland(std::uint32_t bodySlot);
    void linkBodies(std::uint32_t a, std::uint32_t b);    // a constraint began between two dynamic bodies
    void unlinkBodies(std::uint32_t a, std::uint32_t b);  // a constraint between them ended
    void wakeBody(std::uint32_t slot);                     // wakes its island (or the body, if it has none)
    void wakeIsland(std::uint32_t island);
    void addAwakeBody(std::uint32_t slot);
    void removeAwakeBody(std::uint32_t slot);
    void rebuildIslands();   // from the touching contacts and joints (sleep turned on)
    void updateSleep();      // the Sleep stage
    void splitIsland(std::uint32_t island);
    void sleepIsland(std::uint32_t island);

    // Solver.cpp
    void solve();            // the Forces, Solve and Integrate stages
    /// Colours the rows and sorts them into groups and blocks; returns the rows (jointConstraints: the joint rows).
    std::size_t layOutRows(bool byIsland, double h, const Softness& rodSoftness);
    void markShareHeads();
    bool halvesInOrder(std::size_t g) const;  // on two threads, group g's halves meet in few blocks: run in order
    bool spreads(std::size_t g) const;  // group g's loops are spread over the threads (else it goes to one whole)
    /// Joint `joint`'s row for this step (substep h).
    JointConstraint jointRow(std::uint32_t joint, double h, const Softness& rodSoftness) const;
    void joinBodies(std::int32_t a, std::int32_t b);  // awake indices: one island (kNullIndex: no-op)
    void groupIslands(bool byIsland);  // bodyGroup, groupBodies; one group unless byIsland
    void startBody(std::size_t i);   // awake body i's solver state and sims from its record
    void finishBody(std::size_t i);  // its record from the solver's state: pose, box, sleep timer, enlarged
    /// A group's rows, substeps and impulses, its blocks in `worker`'s region; returns its turning rows.
    std::size_t solveGroup(std::size_t g, bool timed, int worker);
    void moveDeferredProxies();  // after the Continuous stage: the proxies of bodies it may have put back
};

}  // namespace physim
