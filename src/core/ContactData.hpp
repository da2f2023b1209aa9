#pragma once
// Persistent contacts: one record per pair of bodies whose enlarged boxes overlap, except a pair with a moving
// continuous body that cannot meet within the step (the broad phase asks about it again each step). Internal.
//
// The broad phase creates a record when two proxies start to overlap and the narrow phase destroys it when they
// no longer do (or when the pair becomes one of those). In between, the record keeps its manifold (points keyed
// by feature id, with their impulses) from step to step, so warm starting carries over and begin / end events are
// exact.

#include "BodyData.hpp"

#include "physim/core/Contact.hpp"

#include <array>
#include <cstdint>

namespace physim {

/// The shapes' last full collision, kept in the bodies' own frames (about their centres of mass): while the pair
/// has moved less than a tolerance relative to itself, the manifold is rebuilt from it (a few products) instead of
/// colliding the shapes again (Contacts.cpp).
struct ManifoldCache {
    double margin = -1.0;           // speculative distance the shapes were collided with, m; < 0: nothing kept
    Vec2 offset = Vec2::Zero();     // b's centre of mass in a's frame, m
    double angle = 0.0;             // b's angle minus a's, rad
    Vec2 normal = Vec2::Zero();     // in a's frame
    struct Point {
        Vec2 onA = Vec2::Zero();    // the point on a's surface, in a's frame about its centre of mass, m
        Vec2 onB = Vec2::Zero();    // the point on b's surface, in b's frame
        std::uint32_t id = 0;
    };
    std::array<Point, 2> points{};
    int pointCount = 0;
};

/// Line-aligned: the solver's preparation reads a record up to `cache`, in colour order (at random), and that part
/// is then three lines, never four.
struct alignas(64) ContactData {
    std::uint32_t a = 0, b = 0;     // body slots, a < b; the manifold's normal points from a to b
    Manifold manifold;
    // Intrusive lists through each body's contacts: side 0 is in a's list, side 1 in b's.
    std::int32_t prev[2] = {kNullIndex, kNullIndex};
    std::int32_t next[2] = {kNullIndex, kNullIndex};
    std::int32_t awakeIndex = kNullIndex;  // position in World's awake contact list; kNullIndex while both sleep
    std::uint32_t generation = 0;
    bool alive = false;
    bool touching = false;          // a manifold point within the speculative distance (islands, events)
    bool sliding = false;           // its friction slid at the end of the last step (ContactSolver.hpp)
    ManifoldCache cache;            // last: only the narrow phase reads it, the solver's preparation does not
};

/// Contact begin / end events of one step, by pair of bodies.
struct ContactPair {
    std::uint32_t a = 0, b = 0;
};

}  // namespace physim
