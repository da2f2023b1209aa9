// Collision filtering and the contact hooks: the public API (setFilter, setPairFilter, setPreSolve) and what the
// step does with them. The broad phase's pairs obey the filters in WorldImpl::updatePairs (Contacts.cpp), the
// Continuous stage's in ContinuousStage.cpp, the rows' layout skips disabled contacts (ConstraintGraph.cpp).

#include "physim/core/World.hpp"

#include "Contacts.hpp"
#include "WorldImpl.hpp"

#include <utility>

namespace physim {

bool WorldImpl::pairAllowed(std::uint32_t a, std::uint32_t b) const {
    if (!shouldCollide(shapes[a].filter, shapes[b].filter)) return false;
    return !pairFilter || pairFilter(ShapeId{a, shapes[a].generation}, ShapeId{b, shapes[b].generation});
}

void WorldImpl::applyFilterChanges() {
    // Contacts the filters now refuse end as parted ones do: an end event if they touched, and their bodies wake.
    auto recheck = [&](std::uint32_t index) {
        const ContactData& c = contacts[index];
        if (pairAllowed(c.shapeA(), c.shapeB())) return;
        const Manifold& m = c.manifold;
        if (c.touching) events.end.push_back({m.bodyA, m.bodyB, m.shapeA, m.shapeB});
        destroyContact(index, true);
    };
    // Pairs the filters now allow are offered again: a refused pair was taken and dropped, so the broad phase would
    // offer it only when a proxy moves. A movable proxy's query meets both trees, so those suffice for every pair.
    if (refilterAll) {
        for (std::uint32_t i = 0; i < contacts.size(); ++i)
            if (contacts[i].alive) recheck(i);
        for (const ShapeData& s : shapes)
            if (s.alive && s.proxy != kNullIndex && !broadPhase.isStatic(s.proxy)) broadPhase.requery(s.proxy);
    } else {
        for (const std::uint32_t slot : refiltered) {
            if (!shapes[slot].alive) continue;  // destroyed since: its contacts went with it
            forEachContactOfShape(slot, recheck);
            if (shapes[slot].proxy != kNullIndex) broadPhase.requery(shapes[slot].proxy);
        }
    }
    refiltered.clear();
    refilterAll = false;
    touchingValid = false;
}

void WorldImpl::runPreSolve() {
    for (std::size_t i = 0; i < awakeContacts.size(); ++i) {
        ContactData& c = contacts[awakeContacts[i]];
        std::uint8_t& flag = contactFlags[i];
        if (flag == kParted || flag == kDeferred) continue;  // destroyed after this
        const bool had = c.disabled;
        c.disabled = c.manifold.pointCount > 0 && !preSolve(c.manifold);
        // The rows' layout holds the contacts with points that are not disabled: a change of either is a new layout
        // (the narrow phase reported the points' change already).
        if (had != c.disabled && c.manifold.pointCount > 0) solver.layoutChanged();
        if (!c.disabled) continue;
        // Not touching this step: the flag says what changed since the last step, as the narrow phase's does.
        const bool touchedBefore = flag == kBegan ? false : flag == kEnded ? true : c.touching;
        c.touching = false;
        flag = touchedBefore ? kEnded : kNone;
        // Solved again later, it starts without the impulses of a step it was not solved in.
        for (int p = 0; p < c.manifold.pointCount; ++p)
            c.manifold.points[p].normalImpulse = c.manifold.points[p].tangentImpulse = 0.0;
        contactImpulses[awakeContacts[i]] = StepImpulses{};
    }
}

// --- World -------------------------------------------------------------------------------------------

void World::setFilter(ShapeId id, const Filter& filter) {
    const std::uint32_t slot = shapeSlot(id);
    WorldImpl& w = *impl_;
    w.requireNotStepping("setFilter");
    ShapeData& s = w.shapes[slot];
    if (s.filter == filter) return;
    s.filter = filter;
    w.refiltered.push_back(slot);
    // New pairs need an awake body: the shape's, or for a static shape whatever sleeps in its box.
    const BodyData& b = w.bodies[s.body];
    if (b.type == BodyType::Static) {
        if (s.proxy != kNullIndex) w.wakeOverlapping(w.broadPhase.fatBox(s.proxy));
    } else {
        w.wakeBody(s.body);
    }
}

const Filter& World::filter(ShapeId id) const { return impl_->shapes[shapeSlot(id)].filter; }

void World::setFilter(BodyId id, const Filter& filter) {
    at(id);
    impl_->requireNotStepping("setFilter");
    for (const ShapeId s : shapes(id)) setFilter(s, filter);
}

const Filter& World::filter(BodyId id) const { return impl_->shapes[firstShape(id)].filter; }

void World::setPairFilter(PairFilterCallback callback) {
    WorldImpl& w = *impl_;
    w.requireNotStepping("setPairFilter");
    w.pairFilter = std::move(callback);
    w.refilterAll = true;
}

void World::setPreSolve(PreSolveCallback callback) {
    WorldImpl& w = *impl_;
    w.requireNotStepping("setPreSolve");
    w.preSolve = std::move(callback);
    // No contact starts disabled: the hook decides anew at the next step, and the layout follows.
    for (ContactData& c : w.contacts) c.disabled = false;
    w.solver.layoutChanged();
}

}  // namespace physim
