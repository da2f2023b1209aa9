#include "Drag.hpp"

#include "../WorldImpl.hpp"
#include "../shapes/ShapeKinds.hpp"

#include "physim/core/Validate.hpp"

#include <cmath>

namespace physim {
namespace {

constexpr std::size_t kGrain = 256;

}  // namespace

void validate(const DragDef& d) {
    requireNonNegative("drag linear coefficient", d.linear);
    requireNonNegative("drag coefficient", d.dragCoefficient);
    requireNonNegative("drag fluid density", d.fluidDensity);
    requireNonNegative("drag width", d.width);
    requireNonNegative("drag angular coefficient", d.angular);
}

void DragEffect::set(std::uint32_t slot, const DragDef& def, const std::function<double()>& shapeWidth) {
    if (isNone(def)) {
        remove(slot);
        return;
    }
    // With C_d or rho zero the quadratic term is zero for any finite width, so 0 stands in for it.
    const bool readsWidth = def.dragCoefficient != 0.0 && def.fluidDensity != 0.0;
    const double width = def.width > 0.0 ? def.width : readsWidth ? shapeWidth() : 0.0;
    const Coefficients c{def.linear, 0.5 * def.fluidDensity * def.dragCoefficient * width, def.angular};
    const std::size_t at = members_.add(slot);
    if (at == defs_.size()) {
        defs_.push_back(def);
        coefficients_.push_back(c);
    } else {
        defs_[at] = def;
        coefficients_[at] = c;
    }
}

DragDef DragEffect::get(std::uint32_t slot) const {
    const std::int32_t at = members_.positionOf(slot);
    return at == Members::kAbsent ? DragDef{} : defs_[static_cast<std::size_t>(at)];
}

void DragEffect::remove(std::uint32_t slot) {
    const std::int32_t at = members_.remove(slot);
    if (at == Members::kAbsent) return;
    defs_[static_cast<std::size_t>(at)] = defs_.back();
    coefficients_[static_cast<std::size_t>(at)] = coefficients_.back();
    defs_.pop_back();
    coefficients_.pop_back();
}

void DragEffect::apply(WorldImpl& w, double h) const {
    const std::vector<std::uint32_t>& slots = members_.items();
    w.executor.parallelFor(slots.size(), kGrain, [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t k = begin; k < end; ++k) {
            const BodyData& b = w.bodies[slots[k]];
            if (!b.awake() || b.type != BodyType::Dynamic) continue;
            const std::size_t i = static_cast<std::size_t>(b.awakeIndex);
            SolverBody& s = w.solver.states()[i];
            const SolverBodySim& sim = w.solver.sim(i);
            const Coefficients& c = coefficients_[k];
            // The velocity the substep's kick is about to give (the other effects' kicks are in s.v already).
            const Vec2 v = s.v + h * sim.acceleration;
            const double speed = v.norm();
            if (speed > 0.0) {
                // Backward Euler: the new speed u solves u (1 + h (linear + quadratic u) / m) = |v|.
                const double lin = 1.0 + h * b.invMass * c.linear, quad = h * b.invMass * c.quadratic;
                s.v += (2.0 / (lin + std::sqrt(lin * lin + 4.0 * quad * speed)) - 1.0) * v;
            }
            const double w0 = s.w + h * sim.angularAcceleration;
            s.w += (1.0 / (1.0 + h * b.invInertia * c.angular) - 1.0) * w0;
        }
    });
}

}  // namespace physim
