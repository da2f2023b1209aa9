#include "FixedStepAccumulator.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace physim {
namespace {

// Over many frames of any length the number of steps equals floor(total time / step) (no time is lost or
// invented) as long as no frame hits the cap.
TEST(FixedStepAccumulator, StepsMatchTotalTime) {
    FixedStepAccumulator acc(1.0 / 40.0, 100);
    double total = 0.0;
    long steps = 0;
    for (int i = 0; i < 10000; ++i) {
        const double frame = 0.001 + 0.03 * std::abs(std::sin(i * 0.7));  // 1 to 31 ms, uneven
        total += frame;
        steps += acc.advance(frame);
        ASSERT_GE(acc.remainder(), 0.0);
        ASSERT_LT(acc.remainder(), acc.step());
    }
    EXPECT_NEAR(static_cast<double>(steps), std::floor(total / acc.step()), 1.0);
    EXPECT_EQ(acc.droppedSteps(), 0u);
}

TEST(FixedStepAccumulator, FrameOfExactlyOneStepGivesOneStep) {
    FixedStepAccumulator acc(1.0 / 60.0);
    for (int i = 0; i < 100000; ++i) ASSERT_EQ(acc.advance(1.0 / 60.0), 1) << "frame " << i;
}

TEST(FixedStepAccumulator, CapDropsTheBacklog) {
    FixedStepAccumulator acc(0.01, 5);
    EXPECT_EQ(acc.advance(0.1), 5);
    EXPECT_EQ(acc.droppedSteps(), 5u);
    EXPECT_EQ(acc.advance(0.0), 0);
    EXPECT_EQ(acc.advance(1e300), 5) << "an absurd frame is capped, not overflowed";
    EXPECT_EQ(acc.advance(0.0), 0);
}

TEST(FixedStepAccumulator, BadInputIsRejected) {
    EXPECT_THROW(FixedStepAccumulator(0.0), std::invalid_argument);
    EXPECT_THROW(FixedStepAccumulator(NAN), std::invalid_argument);
    EXPECT_THROW(FixedStepAccumulator(0.01, 0), std::invalid_argument);
    FixedStepAccumulator acc(0.01);
    EXPECT_THROW(acc.advance(-0.01), std::invalid_argument);
    EXPECT_THROW(acc.advance(NAN), std::invalid_argument);
}

}  // namespace
}  // namespace physim
