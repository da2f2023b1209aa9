#pragma once
// Newtonian gravitation between the attracting bodies (physim/core/Gravitation.hpp), every substep: summed
// directly for few bodies, with a Barnes-Hut quadtree for many. Internal.

#include "BarnesHut.hpp"
#include "Members.hpp"

#include "physim/core/Gravitation.hpp"

#include <vector>

namespace physim {

struct WorldImpl;

class GravitationEffect {
public:
    void setSettings(const GravitationSettings& settings) { settings_ = settings; }
    const GravitationSettings& settings() const { return settings_; }
    void add(std::uint32_t slot) { members_.add(slot); }
    void remove(std::uint32_t slot) { members_.remove(slot); }
    bool contains(std::uint32_t slot) const { return members_.contains(slot); }
    std::size_t count() const { return members_.size(); }
    const std::vector<std::uint32_t>& members() const { return members_.items(); }
    /// It takes two to pull.
    bool active() const { return members_.size() >= 2 && settings_.G > 0.0; }
    bool usesTree() const { return members_.size() >= settings_.directBelow; }

    /// Before a substep's velocity kick: every awake dynamic member's velocity gains h times its pull from all
    /// the others at the substep's positions (sleeping, static and kinematic members pull with the mass they
    /// have: none for the last two). Each body's sum is its own, in a fixed order: any thread count gives the
    /// same bits. Direct sums of pairwise central forces keep the total momentum and angular momentum to
    /// rounding.
    void apply(WorldImpl& w, double h);

private:
    template <class> friend struct StateFields;  // the snapshot file's serializer (SnapshotFile.cpp)
    Members members_;
    GravitationSettings settings_;
    std::vector<Vec2> positions_;  // per member, this substep
    std::vector<double> masses_;
    std::vector<Vec2> accelerations_;  // the tree's, in its order (BarnesHutTree::order)
    BarnesHutTree tree_;
};

}  // namespace physim
