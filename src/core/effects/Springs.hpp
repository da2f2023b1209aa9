#pragma once
// Spring joints (physim/core/Joint.hpp, SpringJointDef; joints/SpringJoint.hpp): Hooke's law with damping, a force
// every substep. Their storage is the world's joints (so they link islands and go with their bodies); this keeps
// the list of the spring joints, so a step visits only them. Internal.

#include "Members.hpp"

namespace physim {

struct WorldImpl;

class SpringEffect {
public:
    void add(std::uint32_t joint) { members_.add(joint); }
    void remove(std::uint32_t joint) { members_.remove(joint); }
    bool active() const { return !members_.empty(); }
    std::size_t count() const { return members_.size(); }
    const std::vector<std::uint32_t>& members() const { return members_.items(); }

    /// Before a substep's velocity kick, from the substep's starting poses and velocities (symplectic Euler, as
    /// gravity's kick): each spring's force (and its
    /// torques at the anchors) times h changes the momenta of the awake dynamic bodies it joins. Serial, in the
    /// list's order, so the result does not depend on the thread count.
    void apply(WorldImpl& w, double h) const;

private:
    template <class> friend struct StateFields;  // the snapshot file's serializer (SnapshotFile.cpp)
    Members members_;
};

}  // namespace physim
