#include "Effects.hpp"

#include "../WorldImpl.hpp"

#include <chrono>

namespace physim {

BodyNow bodyNow(const WorldImpl& w, std::uint32_t slot) {
    const BodyData& b = w.bodies[slot];
    BodyNow now;
    if (!b.awake()) {
        now.center = b.center;
        now.q = b.xf.q;
        now.v = b.v;
        now.w = b.w;
        return now;
    }
    const std::size_t i = static_cast<std::size_t>(b.awakeIndex);
    const SolverBody& s = w.solver.states()[i];
    const SolverBodySim& sim = w.solver.sim(i);
    now.center = sim.center0 + s.dp;
    now.q = compose(s.dq, sim.q0);
    now.v = s.v;
    now.w = s.w;
    now.index = b.awakeIndex;
    if (sim.dynamic) {
        now.invMass = b.invMass;
        now.invInertia = b.invInertia;
    }
    return now;
}

void recordEffect(StepProfile& profile, Effect e, double seconds) {
    profile.secondsOf(Stage::Forces) += seconds;
    profile.ran[static_cast<std::size_t>(Stage::Forces)] = true;
    profile.effectSeconds[static_cast<std::size_t>(e)] += seconds;
    profile.effectRan[static_cast<std::size_t>(e)] = true;
}

void Effects::substep(WorldImpl& w, double h) {
    auto timed = [&](Effect e, auto&& work) {
        const auto start = std::chrono::steady_clock::now();
        work();
        const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
        recordEffect(w.profile, e, elapsed.count());
    };
    // Explicit forces first; drag last, as it is implicit in the velocity they and the kick leave.
    // While the energy ledger is on, each effect's impulses are told apart (EnergyTally::markEffect).
    auto mark = [&](LedgerEffect e) {
        if (w.ledger.enabled) w.solver.tally().markEffect(e, w.solver.states(), w.awake.size());
    };
    if (gravitation.active()) timed(Effect::Gravitation, [&] { gravitation.apply(w, h); }), mark(LedgerEffect::Gravitation);
    if (springs.active()) timed(Effect::Springs, [&] { springs.apply(w, h); }), mark(LedgerEffect::Springs);
    if (drag.active()) timed(Effect::Drag, [&] { drag.apply(w, h); }), mark(LedgerEffect::Drag);
}

void Effects::bodyDestroyed(std::uint32_t slot) {
    drag.remove(slot);
    gravitation.remove(slot);
}

}  // namespace physim
