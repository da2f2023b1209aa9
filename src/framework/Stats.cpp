#include "Stats.hpp"

#include "physim/core/World.hpp"
#include "physim/framework/DebugDraw.hpp"

#include <cstdio>
#include <stdexcept>

namespace physim {

WorldStats computeStats(const World& world) {
    WorldStats s;
    const Vec2 g = world.settings().gravity;
    for (BodyId id : world.bodies()) {
        ++s.bodies;
        if (world.type(id) != BodyType::Dynamic) {
            ++s.immovable;
            continue;
        }
        ++(world.isAwake(id) ? s.awake : s.asleep);
        const double m = world.mass(id);
        const Vec2 x = world.centerOfMass(id), p = m * world.velocity(id);
        s.kinetic += world.kineticEnergy(id);
        s.potential -= m * g.dot(x);
        s.momentum += p;
        s.angularMomentum += cross(x, p) + world.inertia(id) * world.angularVelocity(id);
    }
    s.contacts = world.contacts().size();
    for (const Manifold& m : world.contacts()) s.contactPoints += static_cast<std::size_t>(m.pointCount);
    s.restingContacts = restingContacts(world).size();
    s.joints = world.jointCount();
    return s;
}

StepTimes::StepTimes(std::size_t window) : window_(window) {
    if (window == 0) throw std::invalid_argument("physim: StepTimes needs a window of at least one step");
}

void StepTimes::record(const StepProfile& profile) {
    if (samples_.size() < window_) {
        samples_.push_back(profile);
    } else {
        samples_[next_] = profile;
        next_ = (next_ + 1) % window_;
    }
}

void StepTimes::clear() {
    samples_.clear();
    next_ = 0;
}

StepProfile StepTimes::mean() const {
    StepProfile m;
    if (samples_.empty()) return m;
    for (const StepProfile& p : samples_)
        for (std::size_t s = 0; s < StepProfile::stageCount; ++s) {
            m.seconds[s] += p.seconds[s] / static_cast<double>(samples_.size());
            m.ran[s] = m.ran[s] || p.ran[s];
        }
    return m;
}

std::string formatStats(const WorldStats& stats, const StepTimes& times) {
    char line[160];
    std::string text;
    std::snprintf(line, sizeof line, "bodies %zu: %zu awake, %zu asleep, %zu static/kinematic\n", stats.bodies,
                  stats.awake, stats.asleep, stats.immovable);
    text += line;
    std::snprintf(line, sizeof line, "contacts %zu (%zu points) + %zu at rest, joints %zu\n", stats.contacts,
                  stats.contactPoints, stats.restingContacts, stats.joints);
    text += line;
    std::snprintf(line, sizeof line, "energy: kinetic %.4g J, potential %.4g J, sum %.6g J\n", stats.kinetic,
                  stats.potential, stats.kinetic + stats.potential);
    text += line;
    std::snprintf(line, sizeof line, "momentum (%.4g, %.4g) kg m/s, angular momentum %.4g kg m^2/s about the origin\n",
                  stats.momentum.x(), stats.momentum.y(), stats.angularMomentum);
    text += line;
    const StepProfile mean = times.mean();
    std::snprintf(line, sizeof line, "step %.3f ms (mean of %zu)", 1e3 * mean.total(), times.samples());
    text += line;
    for (std::size_t s = 0; s < StepProfile::stageCount; ++s) {
        if (!mean.ran[s]) continue;
        const std::string_view name = stageName(static_cast<Stage>(s));
        std::snprintf(line, sizeof line, "\n  %-12.*s %.3f ms", static_cast<int>(name.size()), name.data(),
                      1e3 * mean.seconds[s]);
        text += line;
    }
    return text;
}

}  // namespace physim
