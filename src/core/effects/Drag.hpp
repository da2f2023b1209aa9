#pragma once
// Air drag (physim/core/Drag.hpp) on the bodies that have it, every substep. Internal.

#include "Members.hpp"

#include "physim/core/Drag.hpp"
#include "physim/core/Geometry.hpp"

#include <functional>
#include <vector>

namespace physim {

struct WorldImpl;

class DragEffect {
public:
    /// Gives the body at `slot` this drag (a definition asking for none removes it); `shapeWidth()` (m) is the body's
    /// mean width, asked for only where the definition gives none and its quadratic term reads one (it can cost a
    /// convex hull of all the body's parts).
    void set(std::uint32_t slot, const DragDef& def, const std::function<double()>& shapeWidth);
    DragDef get(std::uint32_t slot) const;
    void remove(std::uint32_t slot);
    bool active() const { return !members_.empty(); }
    std::size_t count() const { return members_.size(); }

    /// Before a substep's velocity kick, after the other effects': each awake dynamic member whose velocity the
    /// substep would bring to v (its velocity now, plus the kick to come) ends the substep at v' along v with
    ///   v' (1 + h (linear + quadratic |v'|) / m) = v,   and likewise w' (1 + h angular / I) = w for its turn:
    /// backward Euler in the drag (a quadratic for |v'|), applied as the change v' - v. Stable for any drag, and
    /// a body held at v' by a constant force F keeps it exactly when F = (linear + quadratic |v'|) v' (the
    /// terminal velocity).
    void apply(WorldImpl& w, double h) const;

private:
    template <class> friend struct StateFields;  // the snapshot file's serializer (SnapshotFile.cpp)
    struct Coefficients {
        double linear = 0.0;     // N s/m
        double quadratic = 0.0;  // kg/m: 1/2 rho C_d width
        double angular = 0.0;    // N m s
    };
    Members members_;
    std::vector<DragDef> defs_;              // parallel to members_.items()
    std::vector<Coefficients> coefficients_; // parallel to members_.items()
};

}  // namespace physim
