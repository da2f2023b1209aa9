#pragma once
// A World's whole state at one moment (World::snapshot), for going back in time: bodies, shapes, joints, contacts
// with their warm-start impulses, islands and sleep, sensors, filters and hooks, effects and force callbacks,
// settings and the step count. World::restore puts it back; stepping on then gives, bit for bit, the states the
// original run had, on any thread count. A snapshot is immutable and cheap to copy (copies share it); it outlives
// the world it came from and may be restored into another.

#include <cstddef>
#include <cstdint>
#include <memory>

namespace physim {

struct WorldState;  // internal, src/core/WorldImpl.hpp

class WorldSnapshot {
public:
    /// An empty snapshot: restoring it throws.
    WorldSnapshot() = default;

    bool empty() const { return state_ == nullptr; }
    /// The world's World::stepCount() when taken (0 for an empty snapshot).
    std::uint64_t stepCount() const;
    /// The world's World::stateHash() when taken (0 for an empty snapshot).
    std::uint64_t stateHash() const;
    /// Memory the snapshot holds, bytes (approximate: its arrays' capacities).
    std::size_t bytes() const;

private:
    friend class World;
    std::shared_ptr<const WorldState> state_;
    std::uint64_t stateHash_ = 0;
};

}  // namespace physim
