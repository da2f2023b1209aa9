#include "Gravitation.hpp"

#include "Effects.hpp"

#include "../WorldImpl.hpp"

#include "physim/core/Validate.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace physim {

void validate(const GravitationSettings& s) {
    requireNonNegative("gravitation G", s.G);
    requireNonNegative("gravitation softening", s.softening);
    requireInRange("gravitation theta", s.theta, 0.0, 1.0);
}

namespace {

constexpr std::size_t kGrain = 64;      // bodies per task, direct sum
constexpr std::size_t kGroupGrain = 4;  // tree groups per task (up to 64 bodies each)

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
    auto kick = [&](std::uint32_t member, const Vec2& a) {
        const BodyData& b = w.bodies[slots[member]];
        w.solver.states()[static_cast<std::size_t>(b.awakeIndex)].v += h * a;
    };
    auto pulled = [&](std::uint32_t member) {
        const BodyData& b = w.bodies[slots[member]];
        return b.awake() && b.type == BodyType::Dynamic;
    };
    if (!usesTree()) {
        w.executor.parallelFor(n, kGrain, [&](std::size_t begin, std::size_t end, int) {
            for (std::size_t k = begin; k < end; ++k)
                if (pulled(static_cast<std::uint32_t>(k)))
                    kick(static_cast<std::uint32_t>(k), directAcceleration(positions_, masses_, k, G, eps2));
        });
        return;
    }
    tree_.build(positions_, masses_);
    accelerations_.resize(n);
    const std::vector<std::uint32_t>& order = tree_.order();
    w.executor.parallelFor(tree_.groupCount(), kGroupGrain, [&](std::size_t begin, std::size_t end, int) {
        for (std::size_t g = begin; g < end; ++g) {
            const std::uint32_t first = tree_.groupBegin(g), last = tree_.groupEnd(g);
            if (std::none_of(order.begin() + first, order.begin() + last, pulled)) continue;
            tree_.groupAccelerations(g, G, eps2, theta, accelerations_.data() + first);
            for (std::uint32_t k = first; k < last; ++k)
                if (pulled(order[k])) kick(order[k], accelerations_[k]);
        }
    });
}

}  // namespace physim
