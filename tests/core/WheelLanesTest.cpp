// Wheel joints solved four at a time (joints/WheelLanes): every lane must give the bits the scalar row gives
// (WheelJoint's warmStart and solve through Joints.hpp, which share no code with the lanes), in every build of the
// four-lane loops, with the motor and the spring each on or off, a motor held at its cap, and fixed or kinematic
// ends, so that which rows go in lanes never changes a result.

#include "joints/WheelLanes.hpp"
#include "support/JointLanes.hpp"
#include "support/WideCodes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace physim {
namespace {

constexpr double kH = 1.0 / 240.0;

test::JointLaneCase makeCase(unsigned seed) {
    return test::makeJointLaneCase(seed, kH, [](JointConstraint& row, JointData& joint, int next, auto& u) {
        const double turn = M_PI * u();
        row.axis = {std::cos(turn), std::sin(turn)};
        row.axialMass = 1.0 / (row.invIA + row.invIB);
        WheelJoint wheel;
        // The motor on in two rows of three; one in four of those capped so low that it saturates.
        wheel.setMotor(next % 3 != 2, 10.0 * u(), next % 4 == 1 ? 1e-3 : 50.0 * std::abs(u()));
        // The spring on in most rows; off, or on at 0 Hz (no spring), in a few.
        wheel.setSpring(next % 5 != 3, next % 7 == 5 ? 0.0 : 1.0 + 5.0 * std::abs(u()), std::abs(u()));
        row.maxImpulse = wheel.maxMotorTorque * kH;
        row.spring = wheel.enableSpring && wheel.hertz > 0.0 ? makeSoftness(wheel.hertz, wheel.dampingRatio, kH)
                                                           : Softness{};
        wheel.normalImpulse = u();
        if (wheel.enableSpring) wheel.springImpulse = u();
        if (wheel.enableMotor) wheel.motorImpulse = 0.5 * row.maxImpulse * u();
        joint.params = wheel;
    });
}

bool sameBits(const test::JointLaneCase& a, const test::JointLaneCase& b) {
    if (!test::sameBodyBits(a, b)) return false;
    for (std::size_t j = 0; j < a.joints.size(); ++j) {
        const WheelJoint& x = std::get<WheelJoint>(a.joints[j].params);
        const WheelJoint& y = std::get<WheelJoint>(b.joints[j].params);
        if (!test::sameBits(x.normalImpulse, y.normalImpulse) || !test::sameBits(x.springImpulse, y.springImpulse) ||
            !test::sameBits(x.motorImpulse, y.motorImpulse) || !test::sameBits(x.lastAxis, y.lastAxis))
            return false;
    }
    return true;
}

// Each build of the loops on a copy of `start`, `perColour` blocks to a call: its bits must be the scalar rows'.
void expectScalarBits(const test::JointLaneCase& scalar, const test::JointLaneCase& start, std::size_t perColour,
                      const std::string& what) {
    for (const WideCode code : test::runnableWideCodes()) {
        test::JointLaneCase lanes = start;
        std::vector<WheelBlock> blocks = test::packJointBlocks<WheelBlock>(lanes, packWheels);
        for (int substep = 0; substep < 2; ++substep) {
            test::byColour(blocks, perColour, [&](WheelBlock* b, WheelBlock* e) {
                warmStartWheels(b, e, lanes.states(), code);
            });
            for (const bool useBias : {true, false})
                test::byColour(blocks, perColour, [&](WheelBlock* b, WheelBlock* e) {
                    solveWheels(b, e, lanes.states(), useBias, code);
                });
        }
        storeWheels(blocks.data(), blocks.data() + blocks.size(), lanes.joints);
        EXPECT_TRUE(sameBits(scalar, lanes)) << what << ", build " << static_cast<int>(code);
    }
}

// The scalar rows run warm start, solve and relax passes over all rows; the lanes a colour (a call) at a time.
// Side by side, two blocks go to each call, which the loops take together (inPairs).
TEST(WheelJointLanes, EveryBuildGivesTheScalarRowsBits) {
    int saturated = 0;  // motors at their cap after the passes: the clamp's rule was exercised
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const test::JointLaneCase start = makeCase(seed);
        test::JointLaneCase scalar = start;
        test::solveJointRowsOneByOne(scalar, 2);
        for (const JointConstraint& row : scalar.rows) {
            const WheelJoint& wheel = std::get<WheelJoint>(scalar.joints[row.joint].params);
            if (wheel.enableMotor && std::abs(wheel.motorImpulse) == row.maxImpulse) ++saturated;
        }
        expectScalarBits(scalar, start, 1, "seed " + std::to_string(seed));
        const test::JointLaneCase pairs = test::sideBySide(start, makeCase(seed + 100));
        test::JointLaneCase pairsScalar = pairs;
        test::solveJointRowsOneByOne(pairsScalar, 2);
        expectScalarBits(pairsScalar, pairs, 2, "side by side, seed " + std::to_string(seed));
    }
    EXPECT_GT(saturated, 0);
}

TEST(WheelJointLanes, ALimitKeepsTheRowAlone) {
    WheelJoint wheel;
    EXPECT_TRUE(wheel.solvesInLanes());
    wheel.setLimits(true, -0.1, 0.1);
    EXPECT_FALSE(wheel.solvesInLanes());
    JointData joint;
    joint.params = wheel;
    EXPECT_EQ(jointLanes(joint), RowLanes::None);
}

}  // namespace
}  // namespace physim
