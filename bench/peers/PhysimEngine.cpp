#include "Engine.hpp"
#include "PhysimScene.hpp"

#include "physim/core/World.hpp"

#include <cmath>
#include <string>
#include <thread>
#include <vector>

namespace peers {

namespace {

class PhysimRun final : public EngineRun {
public:
    PhysimRun(const Scene& scene, int threads, int substeps)
        : world_(physimSettings(threads, substeps)), scene_(scene), bodies_(buildPhysimBodies(world_, scene)) {}

    void step() override {
        physimBeforeStep(world_, scene_, bodies_, steps_++);
        world_.step(kTimeStep);
    }

    // A wave's body before its wave first came: NaN.
    Point position(std::size_t index) const override {
        const physim::BodyId id = bodies_.dynamics[index];
        if (id.isNull()) return {std::nan(""), std::nan("")};
        const physim::Vec2 p = world_.position(id);
        return {p.x(), p.y()};
    }

    double angle(std::size_t index) const override {
        const physim::BodyId id = bodies_.dynamics[index];
        return id.isNull() ? std::nan("") : world_.angle(id);
    }

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
    Scene scene_;  // a copy: what it does between steps
    PhysimBodies bodies_;
    long steps_ = 0;
};

Engine physim(const std::string& name, int threads, int reported, int substeps) {
    return {name, reported,
            [threads, substeps](const Scene& s) { return std::make_unique<PhysimRun>(s, threads, substeps); },
            substeps, {}};
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
