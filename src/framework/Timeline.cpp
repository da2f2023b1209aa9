#include "physim/framework/Timeline.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace physim {
namespace {

// What a simulation snapshot holds, bytes (its world's and its branch's arrays, and its own results).
std::size_t bytesOf(const Simulation::Snapshot& s) {
    return s.world.bytes() + s.branch.bytes() + s.results.size() * sizeof(Simulation::Result) +
           s.graphPoints.size() * sizeof(std::size_t) + sizeof(Simulation::Snapshot);
}

}  // namespace

double Timeline::start() const { return entries_.empty() ? 0.0 : entries_.front().snapshot.time; }
double Timeline::end() const { return entries_.empty() ? 0.0 : end_; }

void Timeline::clear() {
    entries_.clear();
    changes_.clear();
    bytes_ = 0;
    end_ = 0.0;
    interval_ = 0;
    sinceLast_ = 0;
    stepSeconds_ = 0.0;
    lastStep_ = 0;
}

void Timeline::countSteps(const Simulation& sim) {
    if (!entries_.empty() && sim.time < entries_.back().snapshot.time) clear();  // restarted
    if (!entries_.empty()) {
        const std::uint64_t steps = sim.world().stepCount() - lastStep_;
        sinceLast_ += static_cast<int>(std::min<std::uint64_t>(steps, 1 << 20));
        stepSeconds_ += static_cast<double>(steps) * sim.world().profile().total();  // the last step's, for each
        end_ = std::max(end_, sim.time);
    }
    lastStep_ = sim.world().stepCount();
}

bool Timeline::snapshotDue() const {
    return entries_.empty() || sinceLast_ >= std::max(interval_, settings_.minInterval);
}

bool Timeline::holdsStep(const Simulation& sim) const {
    return !entries_.empty() && entries_.back().snapshot.time == sim.time;
}

void Timeline::record(const Simulation& sim) {
    countSteps(sim);
    if (!snapshotDue()) return;
    const auto before = std::chrono::steady_clock::now();
    Entry e{sim.snapshot(), 0, false};
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
    // The next interval: enough steps that this snapshot's cost is at most costShare of theirs.
    if (sinceLast_ > 0 && stepSeconds_ > 0.0) {
        const double perStep = stepSeconds_ / sinceLast_;
        interval_ = static_cast<int>(std::min(1e6, std::ceil(took / (settings_.costShare * perStep))));
    }
    keep(std::move(e), sim.time);
}

void Timeline::mark(const Simulation& sim) {
    countSteps(sim);
    markCounted(sim);
}

void Timeline::noteChange(const Simulation& sim) {
    countSteps(sim);
    // A snapshot of this step was taken before the change: it must be taken again (a scrub replays from it).
    if (snapshotDue() || holdsStep(sim)) return markCounted(sim);
    noteMoment(sim.time);
}

void Timeline::markCounted(const Simulation& sim) {
    if (holdsStep(sim)) {  // taken before the change
        bytes_ -= entries_.back().bytes;
        entries_.pop_back();
    }
    noteMoment(sim.time);
    keep(Entry{sim.snapshot(), 0, true}, sim.time);
}

void Timeline::noteMoment(double time) {
    if (changes_.empty() || changes_.back() < time) changes_.push_back(time);
}

void Timeline::keep(Entry e, double time) {
    e.bytes = bytesOf(e.snapshot);
    sinceLast_ = 0;
    stepSeconds_ = 0.0;
    end_ = std::max(end_, time);
    bytes_ += e.bytes;
    entries_.push_back(std::move(e));
    while (bytes_ > settings_.budgetBytes && entries_.size() > 2 && thin()) {
    }
}

// Drops every other snapshot of the older half (never the first, nor a marked one): the recent past stays dense.
// With too few to thin that way, the oldest after the first goes, unmarked ones first, never the latest. Returns
// false when there is nothing it may drop.
bool Timeline::thin() {
    const std::size_t before = entries_.size(), half = before / 2;
    std::vector<Entry> kept;
    kept.reserve(before);
    for (std::size_t i = 0; i < before; ++i) {
        if (i > 0 && i < half && i % 2 == 1 && !entries_[i].marked) {
            bytes_ -= entries_[i].bytes;
            continue;
        }
        kept.push_back(std::move(entries_[i]));
    }
    entries_ = std::move(kept);
    if (entries_.size() < before) return true;
    for (const bool marked : {false, true})
        for (std::size_t i = 1; i + 1 < entries_.size(); ++i)
            if (entries_[i].marked == marked) {
                bytes_ -= entries_[i].bytes;
                entries_.erase(entries_.begin() + static_cast<std::ptrdiff_t>(i));
                return true;
            }
    return false;
}

double Timeline::scrubTo(Simulation& sim, double time, const std::function<void()>& step) {
    if (entries_.empty()) throw std::logic_error("physim: Timeline::scrubTo: nothing is recorded");
    const double target = std::clamp(time, start(), end_);
    // The last snapshot at or before the target.
    auto it = std::upper_bound(entries_.begin(), entries_.end(), target,
                               [](double t, const Entry& e) { return t < e.snapshot.time; });
    if (it != entries_.begin()) --it;
    sim.restore(it->snapshot);
    // Step on to the last step at or before the target (a millionth of a step's rounding allowed: `time` sums dt),
    // or to the first change after the snapshot, which the replay cannot make: the state just before it.
    const double from = sim.time;
    const auto change = std::upper_bound(changes_.begin(), changes_.end(), from);
    const double until = change != changes_.end() ? std::min(target, *change) : target;
    changes_.erase(change, changes_.end());  // the replay makes none of them: this run's future has none yet
    const double dt = sim.fixedTimeStep();
    const auto steps = static_cast<long long>(std::floor((until - from) / dt + 1e-6));
    for (long long i = 0; i < steps; ++i) step();
    const std::size_t keep = static_cast<std::size_t>(it - entries_.begin()) + 1;
    for (std::size_t i = keep; i < entries_.size(); ++i) bytes_ -= entries_[i].bytes;
    entries_.resize(keep);
    end_ = sim.time;
    sinceLast_ = static_cast<int>(std::min<long long>(steps, 1 << 20));
    stepSeconds_ = 0.0;
    lastStep_ = sim.world().stepCount();
    return sim.time;
}

}  // namespace physim
