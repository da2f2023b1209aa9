#pragma once
// Persistent islands: groups of dynamic bodies joined by touching contacts and joints. Internal.
//
// An island merges when a constraint begins between two of its bodies' islands and splits only when it is about
// to sleep and has lost a constraint since it last split (splitting then is a walk over the island). The island
// sleeps and wakes as a whole, so a resting pile costs nothing until something touches it.

#include "BodyData.hpp"

#include <cstdint>

namespace physim {

struct IslandData {
    std::int32_t head = kNullIndex;  // first body slot; bodies link through BodyData::islandNext
    std::int32_t tail = kNullIndex;
    std::int32_t bodyCount = 0;
    std::int32_t constraintRemoveCount = 0;  // constraints lost since the last split: it may have fallen apart
    std::uint32_t generation = 0;
    bool awake = true;
    bool alive = false;
};

}  // namespace physim
