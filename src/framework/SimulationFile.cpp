// Simulation snapshot files (Simulation::writeSnapshot, readSnapshot). Little-endian:
//   8 bytes   magic "PHYSIMSM"
//   4 bytes   format version (Simulation::kSnapshotFormatVersion)
//   8 bytes   body length, bytes
//   8 bytes   the body's first part's length, bytes
//   8 bytes   that part's checksum (64-bit FNV-1a)
//   body      first part: time, physics rate (f64); results (count; each: name, measured, has predicted, predicted,
//             unit); entity ids (count; i32 each); the subclass's writeState bytes; the lengths of the world's
//             snapshot file and the branch's (0: no branch). Then those files, which carry their own checksums.
// Strings are a u64 length and their bytes. A read takes the whole file and checks it before changing anything.

#include "physim/framework/Simulation.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <istream>
#include <memory>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace physim {
namespace {

constexpr char kMagic[8] = {'P', 'H', 'Y', 'S', 'I', 'M', 'S', 'M'};
constexpr std::size_t kHeaderBytes = 8 + 4 + 8 + 8 + 8;

std::uint64_t fnv1a(const char* bytes, std::size_t n) {
    std::uint64_t h = 1469598103934665603ull;
    for (std::size_t i = 0; i < n; ++i) {
        h ^= static_cast<unsigned char>(bytes[i]);
        h *= 1099511628211ull;
    }
    return h;
}

template <class T>
void put(std::string& out, T value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof value);
}
void putString(std::string& out, const std::string& s) {
    put(out, static_cast<std::uint64_t>(s.size()));
    out += s;
}

std::string hertz(double hz) {
    char text[32];
    std::snprintf(text, sizeof text, "%g Hz", hz);
    return text;
}

[[noreturn]] void refuse(const std::string& why) { throw std::runtime_error("physim: snapshot file: " + why); }

// The body, read front to back; running past its end is a body this format did not write.
class Body {
public:
    explicit Body(const std::string& bytes) : bytes_(bytes) {}
    template <class T>
    T take() {
        T value;
        need(sizeof value);
        std::memcpy(&value, bytes_.data() + at_, sizeof value);
        at_ += sizeof value;
        return value;
    }
    std::string takeString() {
        const auto n = take<std::uint64_t>();
        need(n);
        std::string s = bytes_.substr(at_, static_cast<std::size_t>(n));
        at_ += static_cast<std::size_t>(n);
        return s;
    }
    std::size_t left() const { return bytes_.size() - at_; }

private:
    void need(std::uint64_t n) const {
        if (n > left()) refuse("its body ends before the simulation's state does (not written by this format)");
    }
    const std::string& bytes_;
    std::size_t at_ = 0;
};

WorldSnapshot readWorld(const std::string& bytes) {
    std::istringstream in(bytes, std::ios::binary);
    return WorldSnapshot::read(in);
}

}  // namespace

void Simulation::writeSnapshot(std::ostream& out) const {
    std::ostringstream world(std::ios::binary), branch(std::ios::binary);
    world_.snapshot().write(world);
    if (branch_) branch_->snapshot().write(branch);
    StateWriter own;
    writeState(own);

    std::string body;
    put(body, time);
    put(body, physicsRate());
    put(body, static_cast<std::uint64_t>(results_.size()));
    for (const Result& r : results_) {
        putString(body, r.name);
        put(body, r.measured);
        put(body, static_cast<std::uint8_t>(r.predicted.has_value()));
        put(body, r.predicted.value_or(0.0));
        putString(body, r.unit);
    }
    put(body, static_cast<std::uint64_t>(entities_.size()));
    for (const std::unique_ptr<Entity>& e : entities_) put(body, static_cast<std::int32_t>(e->id()));
    putString(body, own.bytes());
    const std::string worldBytes = world.str(), branchBytes = branch.str();
    put(body, static_cast<std::uint64_t>(worldBytes.size()));
    put(body, static_cast<std::uint64_t>(branchBytes.size()));

    std::string header(kMagic, sizeof kMagic);
    put(header, kSnapshotFormatVersion);
    put(header, static_cast<std::uint64_t>(body.size() + worldBytes.size() + branchBytes.size()));
    put(header, static_cast<std::uint64_t>(body.size()));
    put(header, fnv1a(body.data(), body.size()));
    const std::string* parts[] = {&header, &body, &worldBytes, &branchBytes};
    for (const std::string* part : parts)
        out.write(part->data(), static_cast<std::streamsize>(part->size()));
    out.flush();
    if (!out) throw std::runtime_error("physim: Simulation::writeSnapshot: the stream failed");
}

void Simulation::readSnapshot(std::istream& in) {
    char header[kHeaderBytes];
    in.read(header, sizeof header);
    const auto got = static_cast<std::size_t>(in.gcount());
    if (got >= sizeof kMagic && std::memcmp(header, kMagic, sizeof kMagic) != 0)
        refuse("not a physim simulation snapshot (wrong magic)");
    if (got < sizeof header)
        refuse("truncated: its header is " + std::to_string(got) + " of " + std::to_string(sizeof header) + " bytes");
    std::uint32_t version = 0;
    std::uint64_t length = 0, firstLength = 0, checksum = 0;
    std::memcpy(&version, header + 8, 4);
    std::memcpy(&length, header + 12, 8);
    std::memcpy(&firstLength, header + 20, 8);
    std::memcpy(&checksum, header + 28, 8);
    if (version != kSnapshotFormatVersion)
        refuse("simulation format version " + std::to_string(version) + ", this build reads version " +
               std::to_string(kSnapshotFormatVersion));
    std::string body;
    constexpr std::size_t kChunk = std::size_t{1} << 20;  // a length the stream does not hold fails as truncated
    while (body.size() < length) {
        const std::size_t want = static_cast<std::size_t>(std::min<std::uint64_t>(kChunk, length - body.size()));
        const std::size_t before = body.size();
        body.resize(before + want);
        in.read(&body[before], static_cast<std::streamsize>(want));
        const auto read = static_cast<std::size_t>(in.gcount());
        if (read < want)
            refuse("truncated: its body is " + std::to_string(before + read) + " of " + std::to_string(length) +
                   " bytes");
    }
    if (firstLength > length || fnv1a(body.data(), static_cast<std::size_t>(firstLength)) != checksum)
        refuse("corrupt: its simulation state's checksum differs from its header's");

    const std::string first = body.substr(0, static_cast<std::size_t>(firstLength));
    Body b(first);
    const auto savedTime = b.take<double>();
    const auto rate = b.take<double>();
    std::vector<Result> results(static_cast<std::size_t>(std::min<std::uint64_t>(b.take<std::uint64_t>(), b.left())));
    for (Result& r : results) {
        r.name = b.takeString();
        r.measured = b.take<double>();
        const bool hasPredicted = b.take<std::uint8_t>() != 0;
        const auto predicted = b.take<double>();
        if (hasPredicted) r.predicted = predicted;
        r.unit = b.takeString();
    }
    std::vector<int> savedIds(static_cast<std::size_t>(std::min<std::uint64_t>(b.take<std::uint64_t>(), b.left())));
    for (int& id : savedIds) id = b.take<std::int32_t>();
    StateReader own(b.takeString());
    const auto worldLength = b.take<std::uint64_t>(), branchLength = b.take<std::uint64_t>();
    if (b.left() != 0) refuse(std::to_string(b.left()) + " bytes follow the simulation's state");
    if (worldLength > length - firstLength || branchLength != length - firstLength - worldLength)
        refuse("its worlds' lengths do not add up to its body's");
    const WorldSnapshot world = readWorld(body.substr(static_cast<std::size_t>(firstLength),
                                                      static_cast<std::size_t>(worldLength)));
    const WorldSnapshot branch =
        branchLength == 0 ? WorldSnapshot{}
                          : readWorld(body.substr(static_cast<std::size_t>(firstLength + worldLength)));

    if (rate != physicsRate())
        throw std::logic_error("physim: snapshot file: written at a physics rate of " + hertz(rate) +
                               ", this run steps at " + hertz(physicsRate()));
    std::vector<int> ids;
    for (const std::unique_ptr<Entity>& e : entities_) ids.push_back(e->id());
    if (ids != savedIds)
        throw std::logic_error("physim: snapshot file: its entities are not this simulation's (" +
                               std::to_string(savedIds.size()) + " in the file, " + std::to_string(ids.size()) +
                               " here, or other ids): it comes from another scene or parameters");

    world_.restore(world);
    if (branch.empty()) {
        branch_.reset();
    } else {
        if (!branch_) branch_ = std::make_unique<World>(world_.settings());
        branch_->restore(branch);
    }
    time = savedTime;
    results_ = std::move(results);
    readState(own);
    if (own.left() != 0)
        throw std::runtime_error("physim: snapshot file: readState left " + std::to_string(own.left()) +
                                 " bytes of the simulation's own state unread");
}

}  // namespace physim
