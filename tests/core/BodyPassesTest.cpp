// The passes over bodies run four bodies at a time (src/core/BodyPasses.cpp). Each body must get bit for bit what
// the scalar rules (integratePosition, integrateVelocity) give it, on every build of the loop (baseline x86-64,
// AVX2, AVX-512), in a chunk of any length and whatever shares its four: otherwise a scene's bits would depend on
// the processor and on how the threads cut the bodies into chunks.

#include "BodyPasses.hpp"
#include "support/WideCodes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

namespace physim {
namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

::testing::AssertionResult sameRecord(const SolverBody& x, const SolverBody& y) {
    const double fx[] = {x.v.x(), x.v.y(), x.w, x.dAngle, x.dp.x(), x.dp.y(), x.dq.c, x.dq.s};
    const double fy[] = {y.v.x(), y.v.y(), y.w, y.dAngle, y.dp.x(), y.dp.y(), y.dq.c, y.dq.s};
    for (int i = 0; i < 8; ++i)
        if (!sameBits(fx[i], fy[i]))
            return ::testing::AssertionFailure() << "field " << i << ": " << fx[i] << " against " << fy[i];
    return ::testing::AssertionSuccess();
}

TEST(BodyPasses, PositionsIntegrateAsTheScalarRuleOnEveryBuildAndChunk) {
    const std::vector<WideCode> codes = test::runnableWideCodes();
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> kind(0, 5);
    const double h = 1.0 / 480.0;  // a substep of a 60 Hz step in 8
    int turned = 0, still = 0, wide = 0;
    for (int trial = 0; trial < 300; ++trial) {
        // Bodies that do not turn (w = 0, also -0), turn a little, or turn past the series' range (0.2 rad in h).
        const std::size_t n = 1 + static_cast<std::size_t>(trial % 13);
        std::vector<SolverBody> start(n);
        for (SolverBody& s : start) {
            s.v = {3.0 * u(rng), 3.0 * u(rng)};
            const int k = kind(rng);
            s.w = k == 0 ? 0.0 : k == 1 ? -0.0 : k == 5 ? 200.0 * u(rng) : 5.0 * u(rng);
            s.dAngle = k == 1 ? -0.0 : 0.1 * u(rng);
            s.dp = {0.01 * u(rng), 0.01 * u(rng)};
            s.dq = rotationBy(s.dAngle);
            (s.w == 0.0 ? still : turned) += 1;
            wide += std::abs(h * s.w) > 0.2 ? 1 : 0;
        }
        // Listed in a shuffled order: a pass reaches its bodies through a group's list.
        std::vector<std::uint32_t> list(n);
        for (std::size_t i = 0; i < n; ++i) list[i] = static_cast<std::uint32_t>(i);
        std::shuffle(list.begin(), list.end(), rng);
        std::vector<SolverBody> expected = start;
        for (SolverBody& s : expected) integratePosition(s, h);
        for (WideCode code : codes) {
            std::vector<SolverBody> got = start;
            integratePositions(got.data(), list.data(), n, h, code);
            for (std::size_t i = 0; i < n; ++i)
                EXPECT_TRUE(sameRecord(got[i], expected[i])) << "trial " << trial << " body " << i << " code "
                                                             << static_cast<int>(code);
        }
    }
    EXPECT_GT(still, 100);  // every path ran: still lanes beside turning ones, and turns past the series
    EXPECT_GT(turned, 500);
    EXPECT_GT(wide, 50);
}

bool sameMotion(const Vec2& v, double w, const Vec2& v2, double w2) {
    return sameBits(v.x(), v2.x()) && sameBits(v.y(), v2.y()) && sameBits(w, w2);
}

TEST(BodyPasses, VelocitiesIntegrateAsTheScalarRuleOnEveryBuildAndChunk) {
    const std::vector<WideCode> codes = test::runnableWideCodes();
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::uniform_int_distribution<int> kind(0, 3);
    const double h = 1.0 / 480.0;
    int dynamicTurning = 0, dynamicLocked = 0, immovable = 0;
    for (int trial = 0; trial < 300; ++trial) {
        // Dynamic bodies that turn or have rotation locked, and kinematic ones (not dynamic: left alone); -0 speeds.
        const std::size_t n = 1 + static_cast<std::size_t>(trial % 13);
        std::vector<SolverBody> start(n);
        std::vector<SolverBodySim> sims(n);
        std::vector<RowsBase> bases(n);
        std::vector<WarmStartVelocity> warms(n);
        for (std::size_t i = 0; i < n; ++i) {
            SolverBody& s = start[i];
            const int k = kind(rng);
            s.v = {k == 3 ? -0.0 : 3.0 * u(rng), 3.0 * u(rng)};
            s.w = k == 3 ? -0.0 : 5.0 * u(rng);
            s.dAngle = 0.1 * u(rng);
            s.dp = {0.01 * u(rng), 0.01 * u(rng)};
            s.dq = rotationBy(s.dAngle);
            SolverBodySim& sim = sims[i];
            sim.dynamic = k != 2;
            sim.turns = k != 1;
            sim.acceleration = sim.dynamic ? Vec2(u(rng), -10.0 + u(rng)) : Vec2::Zero();
            sim.angularAcceleration = sim.dynamic ? 4.0 * u(rng) : 0.0;
            bases[i] = {{s.v.x() + 0.1 * u(rng), s.v.y() + 0.1 * u(rng)}, s.w + 0.1 * u(rng)};
            warms[i] = {{u(rng), u(rng)}, u(rng)};
            (!sim.dynamic ? immovable : sim.turns ? dynamicTurning : dynamicLocked) += 1;
        }
        std::vector<std::uint32_t> list(n);
        for (std::size_t i = 0; i < n; ++i) list[i] = static_cast<std::uint32_t>(i);
        std::shuffle(list.begin(), list.end(), rng);
        // A group that reads no bases (keepBase false: no warm start on the bodies, no contact rows) keeps none.
        for (const bool again : {false, true})
            for (const bool keepWarm : {false, true})
                for (const bool keepBase : {true, false}) {
                    if (again && !keepBase) continue;
                    std::vector<SolverBody> expected = start;
                    std::vector<RowsBase> expectedBases = bases;
                    std::vector<WarmStartVelocity> expectedWarms = warms;
                    for (std::size_t i = 0; i < n; ++i)
                        if (sims[i].dynamic)
                            integrateVelocity(expected[i], keepBase ? &expectedBases[i] : nullptr,
                                              keepWarm ? &expectedWarms[i] : nullptr,
                                              h * sims[i].acceleration, h * sims[i].angularAcceleration, sims[i].turns,
                                              again);
                    for (WideCode code : codes) {
                        std::vector<SolverBody> got = start;
                        std::vector<RowsBase> gotBases = bases;
                        std::vector<WarmStartVelocity> gotWarms = warms;
                        integrateVelocities(got.data(), keepBase ? gotBases.data() : nullptr,
                                            keepWarm ? gotWarms.data() : nullptr,
                                            sims.data(), list.data(), n, h, again, code);
                        for (std::size_t i = 0; i < n; ++i) {
                            EXPECT_TRUE(sameRecord(got[i], expected[i]))
                                << "trial " << trial << " body " << i << " code " << static_cast<int>(code);
                            EXPECT_TRUE(sameMotion(gotBases[i].v, gotBases[i].w,
                                                   expectedBases[i].v, expectedBases[i].w))
                                << "trial " << trial << " body " << i << " base";
                            EXPECT_TRUE(sameMotion(gotWarms[i].v, gotWarms[i].w,
                                                   expectedWarms[i].v, expectedWarms[i].w))
                                << "trial " << trial << " body " << i << " warm start";
                        }
                    }
                }
    }
    EXPECT_GT(dynamicTurning, 500);  // every kind of lane ran, beside the others
    EXPECT_GT(dynamicLocked, 200);
    EXPECT_GT(immovable, 200);
}

}  // namespace
}  // namespace physim
