#include "Engine.hpp"
#include "PhysimScene.hpp"

#include "physim/core/World.hpp"

#include <string>
#include <thread>
#include <vector>

namespace peers {

namespace {

class PhysimRun final : public EngineRun {
public:
    PhysimRun(const Scene& scene, int threads, int substeps)
        : world_(physimSettings(threads, substeps)), ids_(buildPhysim(world_, scene)) {}

    void step() override { world_.step(kTimeStep); }

    Point position(std::size_t index) const override {
        const physim::Vec2 p = world_.position(ids_[index]);
        return {p.x(), p.y()};
    }

    double angle(std::size_t index) const override { return world_.angle(ids_[index]); }

    std::vector<std::pair<std::string, double>> lastStepStages() const override {
        std::vector<std::pair<std::string, double>> out;
        const physim::StepProfile& p = world_.profile();
        for (std::size_t i = 0; i < physim::StepProfile::stageCount; ++i) {
            const auto stage = static_cast<physim::Stage>(i);
            out.emplace_back(std::string(physim::stageName(stage)), p.secondsOf(stage));
        }
        return out;
    }

private:
    physim::World world_;
    std::vector<physim::BodyId> ids_;
};

Engine physim(const std::string& name, int threads, int reported, int substeps) {
    return {name, reported,
            [threads, substeps](const Scene& s) { return std::make_unique<PhysimRun>(s, threads, substeps); },
            substeps};
}

}  // namespace

std::vector<Engine> physimEngines(const std::vector<int>& substeps) {
    const int defaultSubsteps = physim::WorldSettings{}.substeps;
    std::vector<Engine> out{physim("physim", 1, 1, defaultSubsteps)};
    const int all = static_cast<int>(std::thread::hardware_concurrency());
    if (all > 1) out.push_back(physim("physim", 0, all, defaultSubsteps));  // 0: every hardware thread
    for (int n : substeps) out.push_back(physim("physim-substeps" + std::to_string(n), 1, 1, n));
    return out;
}

}  // namespace peers
