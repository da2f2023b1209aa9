// Persistent islands and sleeping. While sleep is enabled every dynamic body belongs to one island; islands
// merge when a touching contact or a joint begins between two of them, and split (lazily) only when one is about
// to sleep after losing a constraint. With sleep off no island bookkeeping runs at all; turning it on rebuilds
// them from the contacts and joints.

#include "Slots.hpp"
#include "WorldImpl.hpp"

#include <algorithm>
#include <limits>

namespace physim {
namespace {

constexpr std::int32_t kUnvisited = -2;

// Calls f(other body slot) for each dynamic body joined to `slot` by a touching contact or a joint.
template <class F>
void forEachLinked(const WorldImpl& w, std::uint32_t slot, F&& f) {
    for (std::int32_t e = w.bodies[slot].contactHead; e != kNullIndex;) {
        const ContactData& c = w.contacts[static_cast<std::size_t>(e >> 1)];
        const int side = e & 1;
        const std::uint32_t other = side == 0 ? c.b() : c.a();
        if (c.touching && w.bodies[other].type == BodyType::Dynamic) f(other);
        e = c.next[side];
    }
    for (std::int32_t e = w.bodies[slot].jointHead; e != kNullIndex;) {
        const JointData& j = w.joints[static_cast<std::size_t>(e >> 1)];
        const int side = e & 1;
        if (j.twoBodies()) {
            const std::uint32_t other = side == 0 ? j.b : j.a;
            if (w.bodies[other].type == BodyType::Dynamic) f(other);
        }
        e = j.next[side];
    }
}

}  // namespace

void WorldImpl::createIsland(std::uint32_t slot) {
    const std::uint32_t index = takeSlot(islands, freeIslands);
    IslandData& island = islands[index];
    island.head = island.tail = static_cast<std::int32_t>(slot);
    island.bodyCount = 1;
    island.awake = bodies[slot].awake();
    BodyData& b = bodies[slot];
    b.island = static_cast<std::int32_t>(index);
    b.islandPrev = b.islandNext = kNullIndex;
}

void WorldImpl::removeFromIsland(std::uint32_t slot) {
    BodyData& b = bodies[slot];
    if (b.island == kNullIndex) return;
    IslandData& island = islands[static_cast<std::size_t>(b.island)];
    if (b.islandPrev != kNullIndex) bodies[static_cast<std::size_t>(b.islandPrev)].islandNext = b.islandNext;
    else island.head = b.islandNext;
    if (b.islandNext != kNullIndex) bodies[static_cast<std::size_t>(b.islandNext)].islandPrev = b.islandPrev;
    else island.tail = b.islandPrev;
    if (--island.bodyCount == 0) {
        island.alive = false;
        freeIslands.push_back(static_cast<std::uint32_t>(b.island));
    } else {
        ++island.constraintRemoveCount;  // the rest may have fallen apart
    }
    b.island = b.islandPrev = b.islandNext = kNullIndex;
}

void WorldImpl::linkBodies(std::uint32_t a, std::uint32_t b) {
    if (!settings.enableSleep) return;
    std::int32_t big = bodies[a].island, small = bodies[b].island;
    if (big == small || big == kNullIndex || small == kNullIndex) return;
    // An awake body linking to a sleeping island wakes it first: merged into an awake island, its bodies would
    // otherwise count as awake without being simulated (an awake ram struck a grid created asleep and bounced off).
    if (islands[static_cast<std::size_t>(big)].awake != islands[static_cast<std::size_t>(small)].awake)
        wakeIsland(static_cast<std::uint32_t>(islands[static_cast<std::size_t>(big)].awake ? small : big));
    if (islands[static_cast<std::size_t>(big)].bodyCount < islands[static_cast<std::size_t>(small)].bodyCount)
        std::swap(big, small);
    IslandData& to = islands[static_cast<std::size_t>(big)];
    IslandData& from = islands[static_cast<std::size_t>(small)];
    for (std::int32_t s = from.head; s != kNullIndex; s = bodies[static_cast<std::size_t>(s)].islandNext)
        bodies[static_cast<std::size_t>(s)].island = big;
    bodies[static_cast<std::size_t>(to.tail)].islandNext = from.head;
    bodies[static_cast<std::size_t>(from.head)].islandPrev = to.tail;
    to.tail = from.tail;
    to.bodyCount += from.bodyCount;
    to.constraintRemoveCount += from.constraintRemoveCount;
    from.alive = false;
    freeIslands.push_back(static_cast<std::uint32_t>(small));
}

void WorldImpl::unlinkBodies(std::uint32_t a, std::uint32_t b) {
    if (!settings.enableSleep) return;
    const std::int32_t island = bodies[a].island;
    if (island != kNullIndex && island == bodies[b].island)
        ++islands[static_cast<std::size_t>(island)].constraintRemoveCount;
}

void WorldImpl::rebuildIslands() {
    for (BodyData& b : bodies) b.island = b.islandPrev = b.islandNext = kNullIndex;
    islands.clear();
    freeIslands.clear();
    if (!settings.enableSleep) return;
    for (std::uint32_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].alive && bodies[i].type == BodyType::Dynamic) createIsland(i);
    for (std::uint32_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].alive && bodies[i].type == BodyType::Dynamic)
            forEachLinked(*this, i, [&](std::uint32_t other) { linkBodies(i, other); });
}

void WorldImpl::addAwakeBody(std::uint32_t slot) {
    BodyData& b = bodies[slot];
    if (b.awake() || b.type == BodyType::Static) return;
    b.awakeIndex = static_cast<std::int32_t>(awake.size());
    awake.push_back(slot);
    solver.layoutChanged();
}

void WorldImpl::removeAwakeBody(std::uint32_t slot) {
    BodyData& b = bodies[slot];
    if (!b.awake()) return;
    const std::uint32_t last = awake.back();
    awake[static_cast<std::size_t>(b.awakeIndex)] = last;
    bodies[last].awakeIndex = b.awakeIndex;
    awake.pop_back();
    b.awakeIndex = kNullIndex;
    solver.layoutChanged();
}

void WorldImpl::wakeBody(std::uint32_t slot) {
    BodyData& b = bodies[slot];
    b.sleepTime = 0.0;
    if (b.island != kNullIndex) wakeIsland(static_cast<std::uint32_t>(b.island));
    else if (!b.awake() && b.movable()) {
        addAwakeBody(slot);
        for (std::int32_t e = b.contactHead; e != kNullIndex;) {
            const std::uint32_t index = static_cast<std::uint32_t>(e >> 1);
            if (contacts[index].awakeIndex == kNullIndex) addAwakeContact(index);
            e = contacts[index].next[e & 1];
        }
    }
}

void WorldImpl::wakeIsland(std::uint32_t index) {
    IslandData& island = islands[index];
    if (island.awake) return;
    island.awake = true;
    for (std::int32_t s = island.head; s != kNullIndex; s = bodies[static_cast<std::size_t>(s)].islandNext) {
        addAwakeBody(static_cast<std::uint32_t>(s));
        bodies[static_cast<std::size_t>(s)].sleepTime = 0.0;
    }
    for (std::int32_t s = island.head; s != kNullIndex; s = bodies[static_cast<std::size_t>(s)].islandNext)
        for (std::int32_t e = bodies[static_cast<std::size_t>(s)].contactHead; e != kNullIndex;) {
            const std::uint32_t c = static_cast<std::uint32_t>(e >> 1);
            if (contacts[c].awakeIndex == kNullIndex) addAwakeContact(c);
            e = contacts[c].next[e & 1];
        }
}

void WorldImpl::sleepIsland(std::uint32_t index) {
    IslandData& island = islands[index];
    island.awake = false;
    for (std::int32_t s = island.head; s != kNullIndex; s = bodies[static_cast<std::size_t>(s)].islandNext) {
        BodyData& b = bodies[static_cast<std::size_t>(s)];
        removeAwakeBody(static_cast<std::uint32_t>(s));
        b.v.setZero();
        b.w = 0.0;
    }
    // A contact stays in the awake list while one of its bodies is awake.
    for (std::int32_t s = island.head; s != kNullIndex; s = bodies[static_cast<std::size_t>(s)].islandNext)
        for (std::int32_t e = bodies[static_cast<std::size_t>(s)].contactHead; e != kNullIndex;) {
            const std::uint32_t c = static_cast<std::uint32_t>(e >> 1);
            const ContactData& contact = contacts[c];
            if (contact.awakeIndex != kNullIndex && !bodies[contact.a()].awake() && !bodies[contact.b()].awake())
                removeAwakeContact(c);
            e = contact.next[e & 1];
        }
}

void WorldImpl::splitIsland(std::uint32_t index) {
    // Walk the island's constraints from each body not reached yet; each walk is a new island.
    splitStack.clear();
    std::vector<std::uint32_t>& members = splitMembers;
    members.clear();
    for (std::int32_t s = islands[index].head; s != kNullIndex; s = bodies[static_cast<std::size_t>(s)].islandNext)
        members.push_back(static_cast<std::uint32_t>(s));
    for (const std::uint32_t s : members) bodies[s].island = kUnvisited;
    islands[index].alive = false;
    freeIslands.push_back(index);
    for (const std::uint32_t seed : members) {
        if (bodies[seed].island != kUnvisited) continue;
        createIsland(seed);
        const std::int32_t piece = bodies[seed].island;
        splitStack.push_back(seed);
        while (!splitStack.empty()) {
            const std::uint32_t s = splitStack.back();
            splitStack.pop_back();
            forEachLinked(*this, s, [&](std::uint32_t other) {
                if (bodies[other].island != kUnvisited) return;
                IslandData& island = islands[static_cast<std::size_t>(piece)];
                BodyData& o = bodies[other];
                o.island = piece;
                o.islandPrev = island.tail;
                o.islandNext = kNullIndex;
                bodies[static_cast<std::size_t>(island.tail)].islandNext = static_cast<std::int32_t>(other);
                island.tail = static_cast<std::int32_t>(other);
                ++island.bodyCount;
                splitStack.push_back(other);
            });
        }
    }
}

void WorldImpl::updateSleep() {
    // Each awake island's least rested body decides; a moving kinematic body touching a body keeps its island
    // awake. Only the islands of awake bodies are visited, so sleeping piles cost nothing.
    constexpr double kUnset = std::numeric_limits<double>::infinity();
    if (islandSleep.size() < islands.size()) islandSleep.resize(islands.size(), kUnset);
    for (const std::uint32_t s : awake)
        if (bodies[s].island != kNullIndex) islandSleep[static_cast<std::size_t>(bodies[s].island)] = kUnset;
    for (const std::uint32_t s : awake) {
        const BodyData& b = bodies[s];
        if (b.island == kNullIndex) continue;
        double& least = islandSleep[static_cast<std::size_t>(b.island)];
        least = std::min(least, b.sleepTime);
    }
    for (const std::uint32_t c : awakeContacts) {
        const ContactData& contact = contacts[c];
        if (!contact.touching) continue;
        const BodyData& A = bodies[contact.a()];
        const BodyData& B = bodies[contact.b()];
        auto moving = [](const BodyData& k) {
            return k.type == BodyType::Kinematic && (k.v != Vec2::Zero() || k.w != 0.0);
        };
        if (moving(A) && B.island != kNullIndex) islandSleep[static_cast<std::size_t>(B.island)] = 0.0;
        if (moving(B) && A.island != kNullIndex) islandSleep[static_cast<std::size_t>(A.island)] = 0.0;
    }
    sleepy.clear();
    for (const std::uint32_t s : awake) {
        const std::int32_t island = bodies[s].island;
        if (island == kNullIndex) continue;
        double& least = islandSleep[static_cast<std::size_t>(island)];
        if (least >= settings.timeToSleep && least != kUnset) sleepy.push_back(static_cast<std::uint32_t>(island));
        least = -1.0;  // visited: listed at most once
    }
    for (const std::uint32_t island : sleepy) {
        if (islands[island].constraintRemoveCount == 0) {
            sleepIsland(island);
            continue;
        }
        // It may have fallen apart since it last split: sleep each piece (each is at least as rested).
        splitIsland(island);
        for (const std::uint32_t s : splitMembers)
            if (bodies[s].island != kNullIndex && islands[static_cast<std::size_t>(bodies[s].island)].awake)
                sleepIsland(static_cast<std::uint32_t>(bodies[s].island));
    }
}

}  // namespace physim
