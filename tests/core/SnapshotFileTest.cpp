// Snapshot files (WorldSnapshot::write, WorldSnapshot::read): a snapshot read back from its file and restored gives,
// step after step, the state hashes an in-memory restore gives (exact: the step is deterministic, so any difference
// is state the file missed), on one and two threads and into another world. Bad files (wrong magic, another version
// or layout, a flipped byte, any truncation, a payload that does not parse) are refused with a message naming the
// problem, and the world that was to receive them is untouched.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "physim/core/World.hpp"
#include "support/EverythingScene.hpp"
#include "support/Scenes.hpp"

namespace physim {
namespace {

constexpr double kDt = 1.0 / 40.0;

std::string fileOf(const WorldSnapshot& s) {
    std::ostringstream out(std::ios::binary);
    s.write(out);
    return out.str();
}

WorldSnapshot readBytes(const std::string& bytes) {
    std::istringstream in(bytes, std::ios::binary);
    return WorldSnapshot::read(in);
}

std::vector<std::uint64_t> hashesOver(World& world, int steps) {
    std::vector<std::uint64_t> hashes;
    for (int i = 0; i < steps; ++i) {
        world.step(kDt);
        hashes.push_back(world.stateHash());
    }
    return hashes;
}

WorldSettings sleepy(int threads) {
    WorldSettings s;
    s.enableSleep = true;
    s.threads = threads;
    return s;
}

// Snapshot after `before` steps; the hashes of `after` more steps after an in-memory restore, after a restore from the
// snapshot's file into the same world and into `other` (built like it): all the same, step by step.
void expectFileReplays(World& world, World& other, int before, int after) {
    for (int i = 0; i < before; ++i) world.step(kDt);
    const WorldSnapshot s = world.snapshot();
    const std::string bytes = fileOf(s);
    const WorldSnapshot back = readBytes(bytes);
    EXPECT_TRUE(back.fromFile());
    EXPECT_EQ(back.stateHash(), s.stateHash());
    EXPECT_EQ(back.stepCount(), s.stepCount());
    EXPECT_EQ(fileOf(back), bytes) << "what was read back writes the same file";

    const std::vector<std::uint64_t> first = hashesOver(world, after);
    ASSERT_NE(first.back(), s.stateHash()) << "the scene stood still: the test would prove nothing";
    world.restore(s);
    EXPECT_EQ(hashesOver(world, after), first) << "in memory";
    // The contacts as users read them, impulses over the step included, come back too.
    world.restore(s);
    const std::vector<Manifold> contacts = world.contacts();
    ASSERT_FALSE(contacts.empty()) << "nothing touches: the check below would prove nothing";
    other.restore(back);
    ASSERT_EQ(other.contacts().size(), contacts.size());
    for (std::size_t c = 0; c < contacts.size(); ++c)
        for (int p = 0; p < contacts[c].pointCount; ++p) {
            EXPECT_EQ(other.contacts()[c].points[p].normalImpulse, contacts[c].points[p].normalImpulse) << c;
            EXPECT_EQ(other.contacts()[c].points[p].tangentImpulse, contacts[c].points[p].tangentImpulse) << c;
        }
    world.restore(back);
    EXPECT_EQ(world.stateHash(), s.stateHash());
    EXPECT_EQ(hashesOver(world, after), first) << "from the file, same world";
    other.restore(back);
    EXPECT_EQ(other.stepCount(), s.stepCount());
    EXPECT_EQ(hashesOver(other, after), first) << "from the file, another world";
}

TEST(SnapshotFile, RoundTripReplaysTheDeterminismScene) {
    for (const int threads : {1, 2}) {
        WorldSettings settings = test::awakeSettings();
        settings.threads = threads;
        World world(settings), other(settings);
        test::buildDeterminismScene(world);
        test::buildDeterminismScene(other);
        expectFileReplays(world, other, 150, 120);
    }
}

// Every shape and joint kind, sleep, sensors, filters, the hooks, effects and a bullet; the other world runs on the
// other thread count and has stepped elsewhere (its hooks, the same as the first's, stay).
TEST(SnapshotFile, RoundTripReplaysEverything) {
    for (const int threads : {1, 2}) {
        World world(sleepy(threads)), other(sleepy(3 - threads));
        test::buildEverything(world);
        test::buildEverything(other);
        for (int i = 0; i < 17; ++i) other.step(kDt);
        expectFileReplays(world, other, 60, 160);
    }
}

// A file holds no callbacks: the receiving world keeps its own, here none, so the callback of the world that wrote
// the file no longer runs.
TEST(SnapshotFile, RestoreKeepsTheReceivingWorldsCallbacks) {
    World writer(sleepy(1));
    const BodyId box = test::addBox(writer, Vec2(0.0, 5.0), 0.5, 0.5);
    int calls = 0;
    writer.addForceCallback([&calls](World&, double) { ++calls; });
    writer.step(kDt);
    const std::string bytes = fileOf(writer.snapshot());
    World reader(sleepy(1));
    reader.restore(readBytes(bytes));
    calls = 0;
    reader.step(kDt);
    EXPECT_EQ(calls, 0);
    EXPECT_TRUE(reader.contains(box));
    writer.restore(readBytes(bytes));
    writer.step(kDt);
    EXPECT_EQ(calls, 1) << "the writer's own callback stays with it";
}

// A small world whose file the bad-file tests spoil.
struct Spoiled {
    World source{test::awakeSettings()};
    World target{test::awakeSettings()};
    std::string bytes;
    std::uint64_t targetHash = 0;

    Spoiled() {
        test::addGround(source, 5.0);
        test::addBox(source, Vec2(0.0, 0.6), 0.5, 0.5);
        test::addBox(source, Vec2(0.2, 1.7), 0.5, 0.5);
        for (int i = 0; i < 30; ++i) source.step(kDt);  // resting: contacts with impulses
        bytes = fileOf(source.snapshot());
        test::addBox(target, Vec2(3.0, 2.0), 0.3, 0.3);
        target.step(kDt);
        targetHash = target.stateHash();
    }

    // Restoring `file` into the target throws std::runtime_error naming each of `words`; the target is untouched.
    void expectRefused(const std::string& file, const std::vector<std::string>& words, const std::string& what) {
        try {
            target.restore(readBytes(file));
            ADD_FAILURE() << what << ": no exception";
        } catch (const std::runtime_error& e) {
            for (const std::string& w : words)
                EXPECT_NE(std::string(e.what()).find(w), std::string::npos) << what << ": " << e.what();
        }
        EXPECT_EQ(target.stateHash(), targetHash) << what;
    }
};

constexpr std::size_t kHeader = 36;  // magic 8, version 4, fingerprint 8, length 8, checksum 8

// The payload's checksum as the format defines it (Snapshot.hpp), written anew from its definition: 8-byte words in
// four interleaved lanes of FNV-1a's step and a shift, the tail byte by byte, then the lanes and the length.
std::uint64_t formatChecksum(const std::string& payload) {
    constexpr std::uint64_t basis = 1469598103934665603ull, prime = 1099511628211ull;
    std::vector<std::uint64_t> lanes{basis, basis + 1, basis + 2, basis + 3};
    const std::size_t whole = payload.size() / 32 * 32;
    for (std::size_t word = 0; word < whole / 8; ++word) {
        std::uint64_t w = 0;
        for (int b = 7; b >= 0; --b) w = (w << 8) | static_cast<unsigned char>(payload[8 * word + b]);
        std::uint64_t& l = lanes[word % 4];
        l = (l ^ w) * prime;
        l ^= l >> 32;
    }
    std::uint64_t h = basis;
    for (std::size_t i = whole; i < payload.size(); ++i) h = (h ^ static_cast<unsigned char>(payload[i])) * prime;
    for (const std::uint64_t l : lanes) h = (h ^ l) * prime;
    return (h ^ payload.size()) * prime;
}

// The header as Snapshot.hpp documents it, and the checksum as the format defines it.
TEST(SnapshotFile, TheHeaderIsTheDocumentedFormat) {
    Spoiled s;
    EXPECT_EQ(s.bytes.substr(0, 8), std::string("PHYSNAP\0", 8));
    std::uint32_t version = 0;
    std::uint64_t length = 0, checksum = 0;
    std::memcpy(&version, &s.bytes[8], 4);
    std::memcpy(&length, &s.bytes[20], 8);
    std::memcpy(&checksum, &s.bytes[28], 8);
    EXPECT_EQ(version, WorldSnapshot::kFormatVersion);
    EXPECT_EQ(length, s.bytes.size() - kHeader);
    EXPECT_EQ(checksum, formatChecksum(s.bytes.substr(kHeader)));
}

TEST(SnapshotFile, WrongMagicVersionOrLayoutIsRefused) {
    Spoiled s;
    std::string magic = s.bytes;
    magic[0] = 'Q';
    s.expectRefused(magic, {"magic"}, "magic");
    s.expectRefused("just some text that is longer than a header of a snapshot", {"magic"}, "text");
    std::string version = s.bytes;
    version[8] = 7;
    s.expectRefused(version, {"version 7", "version " + std::to_string(WorldSnapshot::kFormatVersion)}, "version");
    std::string layout = s.bytes;
    layout[12] ^= 0x10;
    s.expectRefused(layout, {"layout"}, "layout");
}

TEST(SnapshotFile, AFlippedByteIsRefused) {
    Spoiled s;
    ASSERT_GT(s.bytes.size(), kHeader + 1000);  // a payload worth flipping
    for (std::size_t i = kHeader; i < s.bytes.size(); ++i) {
        std::string flipped = s.bytes;
        flipped[i] ^= 0x01;
        s.expectRefused(flipped, {"checksum"}, "byte " + std::to_string(i));
        if (::testing::Test::HasFailure()) break;
    }
    std::string sum = s.bytes;
    sum[kHeader - 1] ^= 0x80;
    s.expectRefused(sum, {"checksum"}, "the checksum itself");
}

TEST(SnapshotFile, EveryTruncationIsRefused) {
    Spoiled s;
    for (std::size_t n = 0; n < s.bytes.size(); ++n) {
        s.expectRefused(s.bytes.substr(0, n), {"truncated"}, "cut at " + std::to_string(n));
        if (::testing::Test::HasFailure()) break;
    }
    // A length that promises more than the stream holds: truncated, without allocating the promise.
    std::string longer = s.bytes;
    longer[20 + 6] = 0x01;
    s.expectRefused(longer, {"truncated"}, "a huge length");
}

// A payload whose checksum matches but which this format does not read as written (as from a faulty writer): its
// first array's length promises more than there is, or bytes are left over.
TEST(SnapshotFile, APayloadThatDoesNotParseIsRefused) {
    Spoiled s;
    const auto resum = [](std::string file) {
        const std::uint64_t h = formatChecksum(file.substr(kHeader));
        const std::uint64_t length = file.size() - kHeader;
        std::memcpy(&file[20], &length, 8);
        std::memcpy(&file[28], &h, 8);
        return file;
    };
    EXPECT_NO_THROW((void)readBytes(resum(s.bytes))) << "resum itself keeps a good file good";
    std::string extra = resum(s.bytes + std::string(3, '\0'));
    s.expectRefused(extra, {"3 bytes follow"}, "bytes left over");
    std::string shorter = resum(s.bytes.substr(0, s.bytes.size() - 9));
    s.expectRefused(shorter, {"payload"}, "a payload cut short with its checksum");
}

TEST(SnapshotFile, AnEmptySnapshotIsNotWritten) {
    std::ostringstream out;
    EXPECT_THROW(WorldSnapshot{}.write(out), std::invalid_argument);
}

}  // namespace
}  // namespace physim
