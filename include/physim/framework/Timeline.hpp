#pragma once
// A run's record for going back in time in the window: snapshots of the simulation (Simulation::snapshot) taken as
// it runs, within a memory budget. When the budget is full, every other snapshot of the older half goes, so the
// record thins out towards the past but always reaches back to its start. scrubTo puts the simulation back at any
// recorded moment: from the nearest snapshot before it, the steps in between are run again, which (the step being
// deterministic) lands on exactly the state the run had then; changes made by hand between steps are marked (mark),
// and no replay crosses one. The runner keeps one in a window (keys Left, Right and Home; the gallery's time
// slider) and marks drags, keys the scene answers, and branches.

#include "physim/framework/Simulation.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace physim {

class Timeline {
public:
    struct Settings {
        std::size_t budgetBytes = std::size_t{256} << 20;  ///< memory the snapshots may hold
        /// A snapshot may cost at most this share of the steps between two snapshots (their measured times): the
        /// interval grows where snapshots are dear against steps (a small scene's step costs little).
        double costShare = 0.05;
        int minInterval = 10;  ///< steps between snapshots, at least
    };

    Timeline() = default;
    explicit Timeline(const Settings& settings) : settings_(settings) {}

    /// After each frame that stepped `sim` (and once before the first), when its hooks have run: keeps a snapshot
    /// when one is due. A simulation whose time went back (a restart) starts the record again.
    void record(const Simulation& sim);
    /// After `sim` was changed outside its steps (a branch, a drag, a key the scene handles): notes the moment and
    /// keeps a snapshot of it (replacing one of the same step), which the thinning drops last. Steps replayed from
    /// an earlier snapshot cannot repeat the change, so no scrub replays across it: a scrub to a later moment starts
    /// from this snapshot or a later one, or, once the budget thinned it out, stops at the moment of the change
    /// (the state just before it).
    void mark(const Simulation& sim);
    /// The same for a change made often (a dragged body's target, each frame): its moment is noted, but a snapshot
    /// is kept only where record would keep one (or one of this step is already kept), so the cost stays within
    /// the record's. A scrub then stops at the first such change after the snapshot it starts from.
    void noteChange(const Simulation& sim);
    /// Puts `sim` back at the last recorded step at or before `time` (s), within what was recorded, by restoring the
    /// snapshot before it and calling `step` (which must advance `sim` by one fixed step: the runner's one-step
    /// frame, so the simulation's hooks run as they did) until there, or until a marked change on the way; later
    /// snapshots and marks go (they are taken again as the run goes on). Returns the simulation's time after.
    /// Throws std::logic_error when nothing is recorded.
    double scrubTo(Simulation& sim, double time, const std::function<void()>& step);
    void clear();

    bool empty() const { return entries_.empty(); }
    std::size_t size() const { return entries_.size(); }
    double start() const;  ///< s, the earliest recorded time (0 when empty)
    double end() const;    ///< s, the latest time the run reached while recording
    std::size_t bytes() const { return bytes_; }
    int interval() const { return interval_; }

private:
    struct Entry {
        Simulation::Snapshot snapshot;
        std::size_t bytes = 0;
        bool marked = false;  // mark's: the thinning drops it last
    };
    void countSteps(const Simulation& sim);  // the steps since the last call, for the spacing; a restart clears
    bool snapshotDue() const;                 // record's spacing allows a snapshot now
    bool holdsStep(const Simulation& sim) const;  // the latest snapshot is of sim's present step
    void markCounted(const Simulation& sim);      // mark, its steps counted
    void noteMoment(double time);                 // a change's moment (s), once
    void keep(Entry e, double time);
    bool thin();

    Settings settings_;
    std::vector<Entry> entries_;
    std::vector<double> changes_;  // s, mark's moments, in order
    std::size_t bytes_ = 0;
    double end_ = 0.0;
    int interval_ = 0;          // steps between snapshots now (0: not measured yet)
    int sinceLast_ = 0;         // steps since the last snapshot
    double stepSeconds_ = 0.0;  // wall time of those steps
    std::uint64_t lastStep_ = 0;  // the world's step count at the last record
};

}  // namespace physim
