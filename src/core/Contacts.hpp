#pragma once
// The narrow phase's loop over the awake contacts (Contacts.cpp), apart from the world so that tests can run each of
// its builds. Internal.

#include "Wide.hpp"

#include <atomic>
#include <cstddef>
#include <cstdint>

namespace physim {

struct BodyData;
struct ContactData;
struct ShapeData;
class BroadPhase;

/// What the narrow phase found changed about an awake contact.
enum ContactChange : std::uint8_t { kNone = 0, kBegan = 1, kEnded = 2, kParted = 4, kDeferred = 8, kReached = 16 };

/// One narrow phase: contact i of the loop is contacts[awakeContacts[i]], its change goes to flags[i].
struct RefreshPass {
    ContactData* contacts = nullptr;
    const std::uint32_t* awakeContacts = nullptr;
    const BodyData* bodies = nullptr;
    const ShapeData* shapes = nullptr;
    const BroadPhase* broadPhase = nullptr;  // read only where !overlapsKnown
    std::uint8_t* flags = nullptr;           // ContactChange, kNone on entry
    std::uint8_t* hasPoints = nullptr;       // per contact of the loop: its manifold has points (kept up); or null
    double speculative = 0.0;                // m: points this far apart are kept
    double tolerance = 0.0;                  // m: a kept manifold is rebuilt while its pair moved less than this
    double dt = 0.0;                         // s
    bool overlapsKnown = false;              // every pair's enlarged boxes still overlap: no need to test them
    bool prefetch = false;                   // ask for records ahead (large scenes)
    std::atomic<bool>* pointsChanged = nullptr;  // set when a contact gains its first point or loses its last
};

/// Refreshes contacts [begin, end) of the pass: their manifolds at the present poses, touching and flags. `code`
/// picks the build (WideCode::Avx2 and Avx512 both run the AVX2 one, only where avx2CodeRuns()); every build gives
/// the same bits.
void refreshContacts(const RefreshPass& pass, std::size_t begin, std::size_t end, WideCode code = WideCode::Best);

}  // namespace physim
