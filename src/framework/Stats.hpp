#pragma once
// Statistics of a running world, shown on demand in the window: bodies awake and asleep, contacts, the cost
// of a step per stage (World::profile, averaged over recent steps), the mechanical energy and the momenta.

#include "physim/core/Math.hpp"
#include "physim/core/StepProfile.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace physim {

class World;

struct WorldStats {
    std::size_t bodies = 0;        ///< all live bodies
    std::size_t awake = 0;         ///< dynamic bodies awake
    std::size_t asleep = 0;        ///< dynamic bodies asleep
    std::size_t immovable = 0;     ///< static and kinematic bodies
    std::size_t contacts = 0;      ///< manifolds of the last step (pairs that touch and are simulated)
    std::size_t contactPoints = 0;
    std::size_t restingContacts = 0;  ///< touching pairs at rest the step skips (DebugDraw's restingContacts)
    std::size_t joints = 0;
    double kinetic = 0.0;          ///< J: sum of m v^2 / 2 + I w^2 / 2 over dynamic bodies
    double potential = 0.0;        ///< J: sum of -m g . x over dynamic bodies (x their centres of mass; zero at the origin)
    Vec2 momentum = Vec2::Zero();  ///< kg m/s: sum of m v over dynamic bodies
    double angularMomentum = 0.0;  ///< kg m^2/s about the world origin: sum of x cross m v + I w
};

WorldStats computeStats(const World& world);

/// Mean cost per stage over the last `window` steps recorded.
class StepTimes {
public:
    explicit StepTimes(std::size_t window = 60);
    void record(const StepProfile& profile);
    void clear();
    /// The mean seconds per stage, and ran[s] when the stage ran in any of the steps averaged.
    StepProfile mean() const;
    std::size_t samples() const { return samples_.size(); }

private:
    std::size_t window_;
    std::vector<StepProfile> samples_;  // ring buffer
    std::size_t next_ = 0;
};

/// The statistics as lines of text for the window.
std::string formatStats(const WorldStats& stats, const StepTimes& times);

}  // namespace physim
