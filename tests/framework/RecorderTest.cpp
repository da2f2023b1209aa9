// --record through the runner, headless: a box dropped from rest in uniform gravity has, after n steps of the
// semi-implicit Euler method, the velocity g n dt exactly (constant acceleration integrates without error), so
// its recorded kinetic energy is m (g t)^2 / 2 at every step until it lands; records.csv holds those rows.

#include "Recorder.hpp"

#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

#include <filesystem>
#include <cstdio>
#include <fstream>
#include <string>

namespace physim {
namespace {

class Drop : public Simulation {
public:
    void onCreate() override {
        auto& floor = spawn<Object>(Vec2(20.0, 1.0));
        floor.rb.setMass(0.0);
        floor.setPosition({0.0, -50.0});  // far below: 3 s of free fall, 44 m, never reach it
        box = &spawn<Object>(Vec2(1.0, 1.0));
        box->rb.setMass(2.0);
    }
    Object* box = nullptr;
};

RunOptions recordOptions(const std::string& out, int id) {
    RunOptions o = parseRunOptions({"--headless", "--seconds", "3", "--quiet", "--out", out, "--record",
                                    std::to_string(id) + ":kinetic_energy", "--record", std::to_string(id) + ":vy"});
    return o;
}

TEST(Recorder, FreeFallKineticEnergyIsHalfMTimesGTSquaredAtEveryStep) {
    const std::filesystem::path out = std::filesystem::temp_directory_path() / "physim_recorder_test";
    std::filesystem::remove_all(out);
    const int boxId = 2;  // ids count from 1 in spawn order: the floor's 1, the box's 2
    Runner runner([] { return std::make_unique<Drop>(); }, recordOptions(out.string(), boxId));
    ASSERT_EQ(runner.run(), 0);
    const Drop& sim = static_cast<const Drop&>(runner.simulation());
    ASSERT_EQ(sim.box->id(), boxId);
    const double g = -sim.world().settings().gravity.y(), m = 2.0;
    std::ifstream csv(out / "records.csv");
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "t (s),kinetic_energy_" + std::to_string(boxId) + " (J),vy_" + std::to_string(boxId) + " (m/s)");
    int rows = 0;
    while (std::getline(csv, line)) {
        double t = 0.0, e = 0.0, vy = 0.0;
        ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf", &t, &e, &vy), 3) << line;
        // 1e-12 relative: the rounding of summing g dt over up to 120 steps and 8 substeps each.
        EXPECT_NEAR(vy, -g * t, 1e-12 * (1.0 + g * t)) << t;
        EXPECT_NEAR(e, 0.5 * m * g * g * t * t, 1e-11 * (1.0 + e)) << t;
        ++rows;
    }
    EXPECT_EQ(rows, 121);  // t = 0 and every one of 120 steps
    std::filesystem::remove_all(out);
}

// A box resting on a floor: its recorded contact force is its weight (the contacts' impulses over the whole step,
// over the step): 1e-7 relative after 2 s (the soft contact has settled to 8e-9 by then); it has no joint, so its
// joint force is 0.
class Rest : public Simulation {
public:
    void onCreate() override {
        auto& floor = spawn<Object>(Vec2(20.0, 1.0));
        floor.rb.setMass(0.0);
        floor.setPosition({0.0, -0.5});
        box = &spawn<Object>(Vec2(1.0, 1.0));
        box->rb.setMass(3.0);
        box->setPosition({0.0, 0.5});
    }
    Object* box = nullptr;
};

TEST(Recorder, ARestingBoxsContactForceIsItsWeight) {
    RunOptions o = parseRunOptions({"--headless", "--seconds", "2", "--quiet"});
    Runner runner([] { return std::make_unique<Rest>(); }, o);
    runner.restart();
    for (int i = 0; i < 80; ++i) runner.frame(1.0 / 40.0, nullptr);
    const Simulation& sim = runner.simulation();
    const double weight = 3.0 * -sim.world().settings().gravity.y();
    EXPECT_NEAR(recordValue(sim, {2, "contact_force"}), weight, 1e-7 * weight);
    EXPECT_EQ(recordValue(sim, {2, "joint_force"}), 0.0);
}

TEST(Recorder, AnIdNoEntityHasOrAnEntityWithoutABodyIsRefused) {
    Drop sim;
    sim.onCreate();
    EXPECT_THROW(Recorder({RecordSpec{999, "x"}}, sim), std::invalid_argument);
    class Plain : public Entity {};
    const int plain = sim.spawn<Plain>().id();
    try {
        Recorder({RecordSpec{plain, "x"}}, sim);
        FAIL() << "an entity without a body";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("has no body"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace physim
