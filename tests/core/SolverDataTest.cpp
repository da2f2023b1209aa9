// The solver's small-angle rotation (src/core/SolverData.hpp) against the library's sine and cosine.

#include "SolverData.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace physim {
namespace {

// Over the series' whole range, and past it where the library takes over: within 4e-16 of std::cos and std::sin
// (a couple of units in the last place of values up to 1), and still a rotation (c^2 + s^2 = 1 to the same). One
// more term left out would miss by 0.2^10 / 10! = 2.8e-14; the series used up to 0.5 missed by 5e-13 there.
TEST(SolverData, RotationByMatchesSineAndCosine) {
    for (int k = -600; k <= 600; ++k) {
        const double theta = k * (0.3 / 600.0);
        const Rotation q = rotationBy(theta);
        EXPECT_NEAR(q.c, std::cos(theta), 4e-16) << theta;
        EXPECT_NEAR(q.s, std::sin(theta), 4e-16) << theta;
        EXPECT_NEAR(q.c * q.c + q.s * q.s, 1.0, 4e-16) << theta;
    }
    // The turns of a substep: tiny angles keep their relative accuracy.
    for (const double theta : {1e-3, 1e-6, 1e-9, -2.5e-4}) {
        EXPECT_NEAR(rotationBy(theta).s / std::sin(theta), 1.0, 1e-15) << theta;
        EXPECT_EQ(rotationBy(theta).c, std::cos(theta)) << theta;
    }
}

}  // namespace
}  // namespace physim
