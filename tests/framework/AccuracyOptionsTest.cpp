// The accuracy knobs on the command line (--substeps, --iterations, --ccd, --precision): parsed, refused with a
// message naming the value, and applied by the runner to the world and to every dynamic body, later ones too.

#include <physim/core/CircleShape.hpp>
#include <physim/framework/Object.hpp>
#include <physim/framework/Runner.hpp>

#include <gtest/gtest.h>

namespace physim {
namespace {

std::string errorOf(const std::vector<std::string>& args) {
    try {
        parseRunOptions(args);
    } catch (const UsageError& e) {
        return e.what();
    }
    return "";
}

TEST(AccuracyOptions, Parsed) {
    const RunOptions o = parseRunOptions({"--substeps", "3", "--iterations", "5", "--ccd", "exact"});
    EXPECT_EQ(o.substeps, 3);
    EXPECT_EQ(o.iterations, 5);
    EXPECT_EQ(o.ccd, CollisionDetection::ContinuousExact);
    EXPECT_FALSE(o.precision);
    EXPECT_EQ(parseRunOptions({"--ccd", "discrete"}).ccd, CollisionDetection::Discrete);
    const RunOptions sampled = parseRunOptions({"--precision", "0.25"});  // a precision means sampled
    EXPECT_EQ(sampled.ccd, CollisionDetection::ContinuousSampled);
    EXPECT_EQ(sampled.precision, 0.25);
    const RunOptions none = parseRunOptions({});
    EXPECT_FALSE(none.substeps || none.iterations || none.ccd || none.precision);
}

TEST(AccuracyOptions, BadValuesNameTheValue) {
    EXPECT_NE(errorOf({"--substeps", "0"}).find("--substeps"), std::string::npos);
    EXPECT_NE(errorOf({"--substeps", "2.5"}).find("2.5"), std::string::npos);
    EXPECT_NE(errorOf({"--substeps", "1001"}).find("1001"), std::string::npos);
    EXPECT_NE(errorOf({"--substeps", "1001"}).find(std::to_string(WorldSettings::maxSubsteps)), std::string::npos)
        << "the core's bound, named in the message";
    EXPECT_NE(errorOf({"--iterations", "x"}).find("'x'"), std::string::npos);
    EXPECT_NE(errorOf({"--iterations"}).find("needs a value"), std::string::npos);
    EXPECT_NE(errorOf({"--ccd", "fast"}).find("'fast'"), std::string::npos);
    EXPECT_NE(errorOf({"--precision", "0"}).find("(0, 1]"), std::string::npos);
    EXPECT_NE(errorOf({"--precision", "1.5"}).find("1.5"), std::string::npos);
    EXPECT_NE(errorOf({"--precision", "nan"}).find("nan"), std::string::npos);
    EXPECT_NE(errorOf({"--ccd", "exact", "--precision", "0.5"}).find("sampled only"), std::string::npos);
    EXPECT_NE(usage("p", "t").find("--ccd MODE"), std::string::npos);
}

// A static ground and a dynamic ball at creation; a second ball spawned on the first fixed update.
class TwoBalls : public Simulation {
public:
    Object* ground = nullptr;
    Object* first = nullptr;
    Object* later = nullptr;
    void onCreate() override {
        ground = &spawn<Object>(Vec2(4, 1));
        ground->rb.setMass(0.0);
        first = &spawn<Object>(Mesh::CircleMesh(0.1, sf::Color::Red), CircleShape(0.1));
        first->setPosition({0, 2});
        WorldSettings s = world().settings();
        s.substeps = 8;  // the simulation's own choice; the command line must win
        world().setSettings(s);
    }
    void onUpdate() override {
        if (time > 0.0 && !later) later = &spawn<Object>(Mesh::CircleMesh(0.1, sf::Color::Red), CircleShape(0.1));
    }
};

TEST(AccuracyOptions, RunnerAppliesThemToTheWorldAndEveryDynamicBody) {
    RunOptions o = parseRunOptions({"--headless", "--substeps", "3", "--iterations", "5", "--precision", "0.2"});
    Runner runner([] { return std::make_unique<TwoBalls>(); }, o);
    runner.restart();
    auto& sim = static_cast<TwoBalls&>(runner.simulation());
    EXPECT_EQ(sim.world().settings().substeps, 3);
    EXPECT_EQ(sim.world().settings().velocityIterations, 5);
    EXPECT_EQ(sim.world().collisionDetection(sim.first->rb.bodyId()), CollisionDetection::ContinuousSampled);
    EXPECT_EQ(sim.world().collisionPrecision(sim.first->rb.bodyId()), 0.2);
    EXPECT_EQ(sim.world().collisionDetection(sim.ground->rb.bodyId()), CollisionDetection::Discrete);
    runner.frame(sim.fixedTimeStep(), nullptr);
    runner.frame(sim.fixedTimeStep(), nullptr);
    ASSERT_NE(sim.later, nullptr);
    EXPECT_EQ(sim.world().collisionDetection(sim.later->rb.bodyId()), CollisionDetection::ContinuousSampled);
}

TEST(AccuracyOptions, WithoutThemTheSimulationKeepsItsOwn) {
    RunOptions o;
    o.headless = true;
    Runner runner([] { return std::make_unique<TwoBalls>(); }, o);
    runner.restart();
    auto& sim = static_cast<TwoBalls&>(runner.simulation());
    EXPECT_EQ(sim.world().settings().substeps, 8);
    EXPECT_EQ(sim.world().settings().velocityIterations, WorldSettings{}.velocityIterations);
    EXPECT_EQ(sim.world().collisionDetection(sim.first->rb.bodyId()), CollisionDetection::Discrete);
}

}  // namespace
}  // namespace physim
