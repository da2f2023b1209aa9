// Scenes keep their subject: run headless for several seconds (long past the moment their bodies used to leave),
// the bodies are where the scene promises to keep them. Positions from summary.json, SI units.

#include "RunProgram.hpp"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

// The final state of `program` after `seconds` headless at the example's own rate.
nlohmann::json finalState(const std::string& program, const std::string& name, double seconds) {
    const auto dir = std::filesystem::temp_directory_path() / ("physim_subject_" + name);
    std::filesystem::remove_all(dir);
    const auto r = physim::test::runProgram(program, "--headless --seconds " + std::to_string(seconds) + " --out " +
                                                         dir.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(dir / "summary.json");
    nlohmann::json s = nlohmann::json::parse(in);
    std::filesystem::remove_all(dir);
    return s;
}

double x(const nlohmann::json& e) { return e["position"][0].get<double>(); }
double y(const nlohmann::json& e) { return e["position"][1].get<double>(); }
double speed(const nlohmann::json& e) {
    return std::hypot(e["velocity"][0].get<double>(), e["velocity"][1].get<double>());
}

// The three blocks above the angle of repose slide down and rest against the stop at their slope's foot (it
// used to be a fall to y = -330 m). Entities per slope: slab, stop, block; slopes 10 m apart in rows of four,
// 9 m between the rows; the slab 11 m long and 1 m thick, the stop 0.4 m, the block 1 m. Within 1 cm: the
// contact slop (5 mm) and the corners' rounding.
TEST(SubjectInView, InclineBlocksAreCaughtAtTheFoot) {
    const nlohmann::json s = finalState(PHYSIM_INCLINE, "incline", 6.0);
    const double degrees[] = {35.0, 40.0, 45.0};
    for (int k = 4; k < 7; ++k) {
        const double theta = degrees[k - 4] * M_PI / 180.0;
        const double cx = (k % 4) * 10.0, cy = -(k / 4) * 9.0;
        const double along = -(5.5 - 0.4 - 0.5);  // block centre, m up the slope from the slab's centre
        const double across = 0.5 + 0.5;          // half the slab plus half the block
        const nlohmann::json& block = s["entities"][3 * k + 2];
        EXPECT_NEAR(x(block), cx + along * std::cos(theta) - across * std::sin(theta), 0.01) << degrees[k - 4];
        EXPECT_NEAR(y(block), cy + along * std::sin(theta) + across * std::cos(theta), 0.01) << degrees[k - 4];
        EXPECT_LT(speed(block), 1e-2) << "at rest";
    }
}

// The ball lands on the ground (top 0.5 m below the launch) and rolls into the wall 4 m past the landing
// point: it stops there, its centre one radius (0.2 m) above the ground and off the wall. A rigid ball has no
// rolling resistance, so the few cm/s the wall's contact leaves it (1.8 cm/s measured, rolling back) last:
// 5 cm/s and 10 cm from the wall over 3 s allow that and still fail a ball that bounced off or never arrived.
TEST(SubjectInView, ProjectileLandsOnGroundAndStopsAtTheWall) {
    const nlohmann::json s = finalState(PHYSIM_PROJECTILE, "projectile", 8.0);
    const nlohmann::json& ball = s["entities"][0];
    const double range = 20.0 * 20.0 * std::sin(2 * 60.0 * M_PI / 180.0) / 9.81;
    EXPECT_NEAR(y(ball), -0.5 + 0.2, 0.01);
    EXPECT_NEAR(x(ball), range + 4.0 - 0.2, 0.1);
    EXPECT_LT(speed(ball), 5e-2);
}

// The discs are launched again once one passes 6 m from the middle: at any moment every disc is within that,
// plus one frame of travel (at most 3 m/s for 1/40 s).
TEST(SubjectInView, CollisionDiscsStayInTheirLanes) {
    for (const double seconds : {3.0, 6.5, 10.0}) {
        const nlohmann::json s = finalState(PHYSIM_COLLISIONS, "collisions", seconds);
        for (const auto& disc : s["entities"]) EXPECT_LT(std::abs(x(disc)), 6.0 + 3.0 / 40.0) << seconds << " s";
    }
}

// The striker strikes again once the last ball is 2 m past the row's end (3.003 m): every ball stays between
// the striker's start (-2 m) and that, plus one frame at 2 m/s.
TEST(SubjectInView, CradleBallsStayInView) {
    for (const double seconds : {2.4, 6.0, 10.0}) {
        const nlohmann::json s = finalState(PHYSIM_NEWTONS_CRADLE, "newtons_cradle", seconds);
        for (const auto& ball : s["entities"]) {
            EXPECT_GT(x(ball), -2.0 - 1e-9) << seconds << " s";
            EXPECT_LT(x(ball), 3.003 + 2.0 + 2.0 / 40.0) << seconds << " s";
        }
    }
}

}  // namespace
