#pragma once
// A log of lifecycle calls owned by a test (no global state): entities and simulations append to it.

#include <physim/framework/Entity.hpp>
#include <physim/framework/Simulation.hpp>

#include <memory>
#include <string>
#include <vector>

namespace physim::test {

using CallLog = std::vector<std::string>;

class RecordingEntity : public Entity {
public:
    explicit RecordingEntity(CallLog& log) : log_(log) {}
    void update() override { log_.push_back("update " + std::to_string(id())); }
    void beforeFixedUpdate() override { log_.push_back("beforeFixedUpdate " + std::to_string(id())); }
    void checkCollisions() override { log_.push_back("checkCollisions " + std::to_string(id())); }
    void fixedUpdate() override { log_.push_back("fixedUpdate " + std::to_string(id())); }
    void render(sf::RenderWindow*) override { log_.push_back("render " + std::to_string(id())); }

private:
    CallLog& log_;
};

class RecordingSimulation : public Simulation {
public:
    explicit RecordingSimulation(CallLog& log) : log_(log) {}
    void onCreate() override {
        log_.push_back("onCreate");
        spawn<RecordingEntity>(log_);
        spawn<RecordingEntity>(log_);
    }
    void onEvent(sf::Event) override { log_.push_back("onEvent"); }
    void onUpdate() override { log_.push_back("onUpdate"); }
    void onDrawGraphs() override { log_.push_back("onDrawGraphs"); }
    void onRender(sf::RenderWindow*) override { log_.push_back("onRender"); }

private:
    CallLog& log_;
};

}  // namespace physim::test
