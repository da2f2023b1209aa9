#include "AccuracyOptions.hpp"

#include "NumberOption.hpp"

#include "physim/core/WorldSettings.hpp"
#include "physim/framework/RigidBody.hpp"
#include "physim/framework/Simulation.hpp"

namespace physim {
bool parseAccuracyOption(const std::string& flag, const std::function<const std::string&()>& value, RunOptions& o) {
    if (flag == "--substeps") {
        o.substeps = parseCountOption(flag, value(), 1, WorldSettings::maxSubsteps);
    } else if (flag == "--iterations") {
        o.iterations = parseCountOption(flag, value(), 1, WorldSettings::maxIterations);
    } else if (flag == "--ccd") {
        const std::string& text = value();
        if (text == "discrete") o.ccd = CollisionDetection::Discrete;
        else if (text == "sampled") o.ccd = CollisionDetection::ContinuousSampled;
        else if (text == "exact") o.ccd = CollisionDetection::ContinuousExact;
        else throw UsageError("--ccd must be discrete, sampled or exact, got '" + text + "'");
    } else if (flag == "--precision") {
        const std::string& text = value();
        const double p = parseNumberOption(flag, text);
        if (!(p > 0.0 && p <= 1.0)) throw UsageError("--precision must be in (0, 1] (a fraction of the step), got " + text);
        o.precision = p;
    } else {
        return false;
    }
    return true;
}

void checkAccuracyOptions(RunOptions& o) {
    if (!o.precision) return;
    if (!o.ccd) o.ccd = CollisionDetection::ContinuousSampled;  // a precision only means something when sampled
    if (*o.ccd != CollisionDetection::ContinuousSampled)
        throw UsageError("--precision applies to --ccd sampled only, got --ccd " +
                         std::string(*o.ccd == CollisionDetection::Discrete ? "discrete" : "exact"));
}

std::string accuracyUsage() {
    return "  --substeps N             substeps per physics step (default: the simulation's, 8)\n"
           "  --iterations N           solver velocity iterations per substep (default 1)\n"
           "  --ccd MODE               collision detection of every dynamic body: discrete, sampled or exact\n"
           "  --precision P            sampled detection's spacing, a fraction of the step in (0, 1]\n"
           "                           (default 0.1; implies --ccd sampled)\n";
}

void applyAccuracyOptions(const RunOptions& o, Simulation& sim) {
    if (o.substeps || o.iterations) {
        WorldSettings s = sim.world().settings();
        if (o.substeps) s.substeps = *o.substeps;
        if (o.iterations) s.velocityIterations = *o.iterations;
        sim.world().setSettings(s);
    }
    if (!o.ccd) return;
    for (const auto& entity : sim.entities()) {
        RigidBody* rb = entity->TryGetBehavior<RigidBody>();
        if (!rb || !rb->attached() || rb->mass() <= 0.0 || rb->isKinematic()) continue;  // dynamic bodies only
        if (*o.ccd == CollisionDetection::Discrete)
            rb->setCollisionDetectionMode(CollisionDetectionMode::DISCRETE);
        else
            rb->setCollisionDetectionMode(CollisionDetectionMode::CONTINUOUS,
                                          *o.ccd == CollisionDetection::ContinuousExact ? ContinuousMethod::EXACT
                                                                                       : ContinuousMethod::SAMPLED,
                                          o.precision.value_or(kDefaultPrecision));
    }
}

}  // namespace physim
