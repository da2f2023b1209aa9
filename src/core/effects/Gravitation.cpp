#include "Gravitation.hpp"

#include "Effects.hpp"

#include "../WorldImpl.hpp"

#include "physim/core/Validate.hpp"

#include <stdexcept>
#include <string>

namespace physim {

void validate(const GravitationSettings& s) {
    requireNonNegative("gravitation G", s.G);
    requireNonNegative("gravitation softening", s.softening);
    requireInRange("gravitation theta", s.theta, 0.0, 1.0);
}

namespace {

constexpr std::size_t kGrain = 64;

}  // namespace

void GravitationEffect::apply(WorldImpl& w, double h) {
    const std::vector<std::uint32_t>& slots = members_.items();
    const std::size_t n = slots.size();
    positions_.resize(n);
    masses_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        positions_[k] = bodyNow(w, slots[k]).center;
        masses_[k] = w.bodies[slots[k]].mass;
    }
    const double G = settings_.G, eps2 = settings_.softening * settings_.softening, theta = settings_.theta;
    const bool tree = usesTree();
    if (tree) tree_.build(positions_, masses_);
    w.executor.parallelFor(n, kGrain, [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t k = begin; k < end; ++k) {
            const BodyData& b = w.bodies[slots[k]];
            if (!b.awake() || b.type != BodyType::Dynamic) continue;
            const Vec2 a = tree ? tree_.acceleration(k, G, eps2, theta)
                                : directAcceleration(positions_, masses_, k, G, eps2);
            w.solver.states()[static_cast<std::size_t>(b.awakeIndex)].v += h * a;
        }
    });
}

}  // namespace physim
