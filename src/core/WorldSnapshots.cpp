// The public API of time travel (World.hpp, "time travel"; Snapshot.hpp): a snapshot is a copy of the world's
// state (WorldState, everything but the threads), shared and never changed; a restore copies it back. Files of
// snapshots: SnapshotFile.cpp.

#include <cstring>
#include <stdexcept>

#include "WorldImpl.hpp"
#include "physim/core/World.hpp"

namespace physim {
namespace {

void requireBetweenSteps(const WorldImpl& w, const char* call) {
    w.requireNotStepping(call);
    if (w.effects.callbacks.running())
        throw std::logic_error(std::string("physim: World::") + call + " called from a force callback");
}

template <class T>
std::size_t held(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}

// FNV-1a over the bytes of one value.
struct Fnv {
    std::uint64_t h = 1469598103934665603ull;
    template <class T>
    void mix(const T& value) {
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &value, sizeof(T));
        for (const unsigned char b : bytes) {
            h ^= b;
            h *= 1099511628211ull;
        }
    }
};

}  // namespace

std::uint64_t stateHashOf(const WorldState& s) {
    Fnv f;
    f.mix(s.stepCount);
    for (const BodyData& b : s.bodies) {
        if (!b.alive) continue;
        for (const double v : {b.xf.p.x(), b.xf.p.y(), b.xf.q.c, b.xf.q.s, b.angle, b.v.x(), b.v.y(), b.w}) f.mix(v);
        f.mix(static_cast<std::uint8_t>(b.awakeIndex != kNullIndex));
    }
    return f.h;
}

std::uint64_t WorldSnapshot::stepCount() const { return state_ ? state_->stepCount : 0; }
std::uint64_t WorldSnapshot::stateHash() const { return stateHash_; }
std::size_t WorldSnapshot::bytes() const {
    if (!state_) return 0;
    const WorldState& s = *state_;
    return sizeof(WorldState) + held(s.bodies) + held(s.shapes) + held(s.contacts) + held(s.joints) + held(s.islands) +
           held(s.awake) + held(s.awakeContacts) + held(s.awakeHasPoints) + held(s.contactSurfaces) +
           held(s.contactCores) + held(s.contactImpulses);
}

WorldSnapshot World::snapshot() const {
    const WorldImpl& w = *impl_;
    requireBetweenSteps(w, "snapshot");
    WorldSnapshot s;
    s.state_ = std::make_shared<const WorldState>(static_cast<const WorldState&>(w));
    s.stateHash_ = stateHashOf(w);
    return s;
}

void World::restore(const WorldSnapshot& snapshot) {
    WorldImpl& w = *impl_;
    requireBetweenSteps(w, "restore");
    if (snapshot.empty()) throw std::invalid_argument("physim: World::restore: the snapshot is empty");
    const int threads = w.settings.threads;
    if (snapshot.fromFile()) {
        // A file holds no callbacks, hooks or continuous solver (Snapshot.hpp): the world keeps its own.
        ForceCallbacks callbacks = std::move(w.effects.callbacks);
        PairFilterCallback pairFilter = std::move(w.pairFilter);
        PreSolveCallback preSolve = std::move(w.preSolve);
        std::shared_ptr<ContinuousSolver> solver = w.continuous.solver();
        static_cast<WorldState&>(w) = *snapshot.state_;
        w.effects.callbacks = std::move(callbacks);
        w.pairFilter = std::move(pairFilter);
        w.preSolve = std::move(preSolve);
        w.continuous.setSolver(std::move(solver));
    } else {
        static_cast<WorldState&>(w) = *snapshot.state_;
    }
    w.settings.threads = threads;
    w.solver.layoutChanged();  // the rows' groups depend on the thread count
    w.solver.forgetRoundedSides();
    if (w.ledger.enabled) setEnergyLedger(true);  // the ledger starts again from the restored state
}

std::uint64_t World::stateHash() const { return stateHashOf(*impl_); }

}  // namespace physim
