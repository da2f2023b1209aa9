#include "BranchChanges.hpp"

#include "physim/core/World.hpp"

#include <algorithm>

namespace physim {
namespace {

// Small enough to leave a calm scene calm, large enough to show a chaotic one diverging within seconds.
constexpr double kVelocityNudge = 1e-3;  // m/s along x
constexpr double kRestitutionStep = 0.1;

template <class Change>
void forEveryShape(World& w, Change&& change) {
    for (const BodyId body : w.bodies())
        for (const ShapeId shape : w.shapes(body)) change(shape);
}

}  // namespace

const char* describe(BranchChange change) {
    switch (change) {
        case BranchChange::Velocity: return "the last body added +1 mm/s along x";
        case BranchChange::Restitution: return "restitutions +0.1 (at most 1)";
        case BranchChange::Friction: return "frictions halved";
        case BranchChange::Substeps: return "substeps doubled";
    }
    return "";
}

std::function<void(World&)> branchChangeFor(BranchChange change) {
    switch (change) {
        case BranchChange::Velocity:
            return [](World& w) {
                const std::vector<BodyId> bodies = w.bodies();
                const auto last = std::find_if(bodies.rbegin(), bodies.rend(),
                                               [&](BodyId id) { return w.inverseMass(id) > 0.0; });
                if (last != bodies.rend()) w.setVelocity(*last, w.velocity(*last) + Vec2(kVelocityNudge, 0.0));
            };
        case BranchChange::Restitution:
            return [](World& w) {
                forEveryShape(w, [&](ShapeId s) {
                    w.setMaterial(s, std::min(1.0, w.restitution(s) + kRestitutionStep), w.staticFriction(s),
                                  w.dynamicFriction(s));
                });
            };
        case BranchChange::Friction:
            return [](World& w) {
                forEveryShape(w, [&](ShapeId s) {
                    w.setMaterial(s, w.restitution(s), 0.5 * w.staticFriction(s), 0.5 * w.dynamicFriction(s));
                });
            };
        case BranchChange::Substeps:
            return [](World& w) {
                WorldSettings settings = w.settings();
                settings.substeps = std::min(2 * settings.substeps, WorldSettings::maxSubsteps);
                w.setSettings(settings);
            };
    }
    return {};
}

}  // namespace physim
