#include "Engine.hpp"

#include "physim/core/World.hpp"

#include <string>
#include <thread>
#include <vector>

namespace peers {

namespace {

class PhysimRun final : public EngineRun {
public:
    PhysimRun(const Scene& scene, int threads, int substeps)
        : world_(settings(threads, substeps)), collides_(scene.collisions) {
        std::vector<physim::BodyId> statics;
        for (const ShapeSpec& s : scene.statics) statics.push_back(add(s, physim::BodyType::Static));
        if (!scene.chain.empty()) addChain(scene.chain);
        ids_.reserve(scene.dynamics.size());
        for (const ShapeSpec& s : scene.dynamics) ids_.push_back(add(s, physim::BodyType::Dynamic));
        auto body = [&](const BodyRef& r) { return r.isStatic ? statics[r.index] : ids_[r.index]; };
        for (const PinSpec& p : scene.pins) {
            physim::RevoluteJointDef d;
            d.bodyA = body(p.a);
            d.bodyB = body(p.b);
            d.anchor = {p.x, p.y};
            world_.createRevoluteJoint(d);
        }
        for (const WheelSpec& w : scene.wheels) {
            physim::WheelJointDef d;
            d.bodyA = ids_[w.chassis];
            d.bodyB = ids_[w.wheel];
            d.anchor = {w.x, w.y};
            d.axis = {w.axisX, w.axisY};
            d.hertz = w.hertz;
            d.dampingRatio = w.dampingRatio;
            d.enableMotor = w.enableMotor;
            d.motorSpeed = w.motorSpeed;
            d.maxMotorTorque = w.maxMotorTorque;
            world_.createWheelJoint(d);
        }
    }

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
    static physim::WorldSettings settings(int threads, int substeps) {
        physim::WorldSettings s;  // iterations, springs and slop stay at physim's defaults
        s.gravity = {0.0, kGravity};
        s.enableSleep = false;
        s.threads = threads;
        s.substeps = substeps;
        return s;
    }

    physim::BodyId add(const ShapeSpec& s, physim::BodyType type) {
        physim::BodyDef d;
        d.type = type;
        d.position = {s.x, s.y};
        if (s.isCircle())
            d.shape = physim::makeCircle(s.radius);
        else if (s.isCapsule())
            d.shape = physim::makeCapsule({-s.halfLength, 0.0}, {s.halfLength, 0.0}, s.radius);
        else
            d.shape = physim::makeBox(s.halfWidth, s.halfHeight);
        d.density = kDensity;
        d.staticFriction = kFriction;
        d.dynamicFriction = kFriction;
        d.collides = collides_;
        return world_.createBody(d);
    }

    void addChain(const std::vector<ChainPoint>& points) {
        physim::BodyDef d;
        d.type = physim::BodyType::Static;
        d.withShape = false;
        physim::ChainDef chain;
        for (const ChainPoint& p : points) chain.points.emplace_back(p.x, p.y);
        chain.staticFriction = chain.dynamicFriction = kFriction;
        world_.createChain(world_.createBody(d), chain);
    }

    physim::World world_;
    bool collides_ = true;
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
