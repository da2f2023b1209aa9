#pragma once
// An engine as peer_bench sees it: something that builds a Scene, steps it at kTimeStep and reports where each
// dynamic body is. physim and each peer engine implement it in their own file.

#include "Scenes.hpp"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace peers {

struct Point {
    double x = 0.0;
    double y = 0.0;
};

/// One engine's world holding one scene.
class EngineRun {
public:
    virtual ~EngineRun() = default;
    virtual void step() = 0;
    /// Centre of scene.dynamics[index], m.
    virtual Point position(std::size_t index) const = 0;
    /// Angle of scene.dynamics[index], rad, counter-clockwise from its start.
    virtual double angle(std::size_t index) const = 0;
    /// Seconds spent in each named stage of the last step; empty when the engine does not say.
    virtual std::vector<std::pair<std::string, double>> lastStepStages() const { return {}; }
};

struct Engine {
    std::string name;  ///< "physim", "box2d-2.4.1", ...
    int threads = 1;   ///< threads the engine was asked to use
    std::function<std::unique_ptr<EngineRun>(const Scene&)> start;
    int substeps = 0;  ///< physim's substeps per step; 0 for a peer, whose solver counts differently
    /// Why the engine does not run a scene (empty, or no function: it does).
    std::function<std::string(const Scene&)> skips;
};

/// physim at its default settings with one thread, and (when the machine has more than one) with every hardware
/// thread; then one single-thread physim per count in `substeps`, named physim-substeps<n>: the same world with
/// WorldSettings::substeps = n, its contact spring at min(contactHertz, a quarter of the substep rate) as always.
std::vector<Engine> physimEngines(const std::vector<int>& substeps = {});

/// The engines physim is measured against in this build. `missing` says why there are none.
struct Peers {
    std::vector<Engine> engines;
    std::string missing;
};
Peers peerEngines();

}  // namespace peers
