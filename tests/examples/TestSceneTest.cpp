// test_scene (the paper's "test"): the tilted box must end lying on a face of the ground, still.

#include "RunProgram.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace {

TEST(TestScene, TiltedBoxComesToRestOnAFace) {
    const auto dir = std::filesystem::temp_directory_path() / "physim_test_scene";
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(PHYSIM_TEST_SCENE, "--headless --seconds 5 --hz 60 --out " + dir.string());
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(dir / "summary.json");
    const nlohmann::json s = nlohmann::json::parse(in);
    const auto& box = s["entities"][1];
    // A 1.5 m x 1 m box: resting on a long face its centre is 0.5 m up, on a short face 0.75 m. The 30 degree
    // tilt tips it onto the long face. 1 cm covers the solver's allowed overlap (5 mm slop).
    EXPECT_NEAR(box["position"][1].get<double>(), 0.5, 0.01);
    const double angle = box["angle"].get<double>();
    EXPECT_NEAR(std::remainder(angle, M_PI), 0.0, 0.01) << "lying flat, angle " << angle;
    EXPECT_LT(std::hypot(box["velocity"][0].get<double>(), box["velocity"][1].get<double>()), 1e-3);
    EXPECT_LT(std::abs(box["angularVelocity"].get<double>()), 1e-3);
    std::filesystem::remove_all(dir);
}

}  // namespace
