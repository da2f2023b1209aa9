#pragma once
// A World's whole state at one moment (World::snapshot), for going back in time: bodies, shapes, joints, contacts
// with their warm-start impulses, islands and sleep, sensors, filters and hooks, effects and force callbacks,
// settings and the step count. World::restore puts it back; stepping on then gives, bit for bit, the states the
// original run had, on any thread count. A snapshot is immutable and cheap to copy (copies share it); it outlives
// the world it came from and may be restored into another.
//
// A snapshot also goes to a file and back (write, read): physim's snapshot format, little-endian, version
// WorldSnapshot::kFormatVersion:
//   8 bytes   magic "PHYSNAP" and a zero byte
//   4 bytes   format version
//   8 bytes   layout fingerprint: the sizes of the build's internal records; a file from a build whose records
//             differ is refused (as is one from another format version)
//   8 bytes   payload length, bytes
//   8 bytes   payload checksum (64-bit FNV-1a's step over 8-byte words in four lanes, SnapshotFile.cpp)
//   payload   the state, record by record, member by member (never an address), then its stateHash()
// What cannot go in a file stays out: force callbacks, the pair filter and the pre-solve hook (std::function) and
// the continuous solver. A snapshot read from a file restores into a world keeping that world's own (or none): a
// program that set them up when it built its scene sets them up again, then restores. Nor does a file hold the
// step's scratch or its profile, which every step rebuilds. The checksum guards against damage (a byte changed, a
// file cut short), not against a file made to pass it: read files you or your programs wrote.

#include <cstddef>
#include <cstdint>
#include <iosfwd>
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

    /// The file format's version: a file of another version is refused.
    static constexpr std::uint32_t kFormatVersion = 6;
    /// Writes the snapshot in the format above to `out` (a stream opened in binary mode). Throws
    /// std::invalid_argument for an empty snapshot and std::runtime_error if the stream fails.
    void write(std::ostream& out) const;
    /// Reads a snapshot that write() wrote, whole, and checks it before returning it: a wrong magic, another format
    /// version or layout, a truncated or corrupt file (checksum) or a stream that fails throw std::runtime_error
    /// naming the problem (and the versions). Nothing is restored until World::restore is called with the result.
    static WorldSnapshot read(std::istream& in);
    /// Read from a file: a restore keeps the receiving world's callbacks and hooks (above).
    bool fromFile() const { return fromFile_; }

private:
    friend class World;
    std::shared_ptr<const WorldState> state_;
    std::uint64_t stateHash_ = 0;
    bool fromFile_ = false;
};

}  // namespace physim
