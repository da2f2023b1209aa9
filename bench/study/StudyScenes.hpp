#pragma once
// The accuracy study's reference scenes: each builds bodies on a core World, watches every step, and states its
// error against a trusted answer (closed form, or the same scene run at a 16x finer step). Units: m, kg, s, rad.

#include "physim/core/World.hpp"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace study {

/// One run of a scene. build() places the bodies; observe() sees the world after every step (t: simulated
/// seconds so far); error() is the scene's error at the end of the run.
class SceneRun {
public:
    virtual ~SceneRun() = default;
    virtual void build(physim::World& world) = 0;
    virtual void observe(const physim::World&, double /*t*/) {}
    virtual double error(const physim::World& world) const = 0;
    /// The state compared with the finer run, for scenes judged against a 16x finer step (same units each).
    virtual std::vector<double> state(const physim::World&) const { return {}; }

    /// The collision detection every dynamic body of the scene gets (the study's `ccd` family).
    physim::CollisionDetection detection = physim::CollisionDetection::Discrete;
    double precision = physim::kDefaultPrecision;

protected:
    /// createBody, with `detection` and `precision` on dynamic bodies.
    physim::BodyId add(physim::World& world, physim::BodyDef def) const;
};

struct SceneInfo {
    std::string name;
    double seconds;            ///< simulated; a multiple of 1/30 s so every rate ends at the same instant
    std::string error;         ///< what error() measures, with its unit
    bool finerReference;       ///< true: no closed form, error is the distance of state() to a 16x finer run
    std::vector<std::string> families;  ///< the setting families worth sweeping on this scene
    std::function<std::unique_ptr<SceneRun>()> make;
};

const std::vector<SceneInfo>& scenes();
/// Throws std::invalid_argument naming an unknown scene.
const SceneInfo& scene(const std::string& name);

}  // namespace study
